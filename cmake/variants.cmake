# hwinterp_core_variant(CORE <core> NAME <variant> PARAMS K=V... [DEFAULTS K=V...])
#
# Declares one parameter set of a core. PARAMS are the RTL parameters: the same
# values go to Verilator (-G), to the generated C++ header the HLS core, the
# model and the testbench read (<variant>_cfg.h, struct <variant>_cfg), and to
# the synthesis script (variants.txt). DEFAULTS are testbench-only settings
# (run-time timing defaults) that appear in the header but not in the RTL.
# Keeping one list here is what stops the three faces disagreeing on a width.
set(HWINTERP_GENERATED_DIR ${CMAKE_BINARY_DIR}/generated)
file(MAKE_DIRECTORY ${HWINTERP_GENERATED_DIR})
set_property(GLOBAL PROPERTY HWINTERP_VARIANTS "")
file(WRITE ${HWINTERP_GENERATED_DIR}/variants.txt.in "")
file(WRITE ${HWINTERP_GENERATED_DIR}/blocks.txt.in "")

# hwinterp_write_generated(<name> <text>...): writes the texts, concatenated,
# to ${HWINTERP_GENERATED_DIR}/<name>, touching the file only when it changed,
# so a re-configure rebuilds nothing. (ARGV<i>, not ARGN: the texts are C++
# and ARGN would split them at every ';'.)
function(hwinterp_write_generated name)
  set(text "")
  math(EXPR last "${ARGC} - 1")
  foreach(i RANGE 1 ${last})
    string(APPEND text "${ARGV${i}}")
  endforeach()
  file(WRITE ${HWINTERP_GENERATED_DIR}/${name}.tmp "${text}")
  file(COPY_FILE ${HWINTERP_GENERATED_DIR}/${name}.tmp ${HWINTERP_GENERATED_DIR}/${name}
       ONLY_IF_DIFFERENT)
endfunction()

function(hwinterp_core_variant)
  cmake_parse_arguments(V "" "CORE;NAME" "PARAMS;DEFAULTS" ${ARGN})
  if(NOT V_CORE OR NOT V_NAME OR NOT V_PARAMS)
    message(FATAL_ERROR "hwinterp_core_variant needs CORE, NAME and PARAMS")
  endif()
  set(members "")
  set(gflags "")
  set(pnames "")
  set(pvalues "")
  foreach(kv IN LISTS V_PARAMS)
    string(REPLACE "=" ";" kvl "${kv}")
    list(GET kvl 0 k)
    list(GET kvl 1 v)
    string(APPEND members "  static constexpr int ${k} = ${v};\n")
    string(APPEND pnames "\"${k}\", ")
    string(APPEND pvalues "${v}, ")
    list(APPEND gflags "-G${k}=${v}")
  endforeach()
  list(LENGTH V_PARAMS pcount)
  # Every RTL parameter by name, for code that is not a template over Cfg.
  string(APPEND members "  static constexpr int kParamCount = ${pcount};\n"
    "  static constexpr const char* kParamNames[] = {${pnames}};\n"
    "  static constexpr int kParamValues[] = {${pvalues}};\n")
  foreach(kv IN LISTS V_DEFAULTS)
    string(REPLACE "=" ";" kvl "${kv}")
    list(GET kvl 0 k)
    list(GET kvl 1 v)
    string(APPEND members "  static constexpr int ${k} = ${v};\n")
  endforeach()
  hwinterp_write_generated(${V_NAME}_cfg.h
    "// Generated from cmake/cores.cmake; do not edit.\n#pragma once\n\n"
    "struct ${V_NAME}_cfg {\n"
    "  static constexpr const char* kCore = \"${V_CORE}\";\n"
    "  static constexpr const char* kVariant = \"${V_NAME}\";\n"
    "${members}};\n")
  # The testbench's binding of the variant to its Verilated classes.
  hwinterp_write_generated(${V_NAME}_rtl.h
    "// Generated from cmake/cores.cmake; do not edit.\n#pragma once\n\n"
    "#include \"${V_NAME}_cfg.h\"\n#include \"V${V_NAME}_cc.h\"\n#include \"V${V_NAME}_sc.h\"\n\n"
    "namespace hwinterp {\ntemplate <class Cfg>\nstruct RtlOf;  // the Verilated classes of a variant\n}\n\n"
    "template <>\nstruct hwinterp::RtlOf<${V_NAME}_cfg> {\n"
    "  using Cc = V${V_NAME}_cc;  // verilator --cc: the direct lockstep mode\n"
    "  using Sc = V${V_NAME}_sc;  // verilator --sc: the SystemC mode\n};\n")
  set_property(GLOBAL APPEND PROPERTY HWINTERP_CORE_${V_CORE}_VARIANTS ${V_NAME})
  set_property(GLOBAL APPEND PROPERTY HWINTERP_CORES ${V_CORE})
  string(REPLACE ";" " " params_line "${V_PARAMS}")
  file(APPEND ${HWINTERP_GENERATED_DIR}/variants.txt.in "${V_NAME} ${V_CORE} ${params_line}\n")
  set_property(GLOBAL APPEND PROPERTY HWINTERP_VARIANTS ${V_NAME})
  set_property(GLOBAL PROPERTY HWINTERP_VARIANT_${V_NAME}_CORE ${V_CORE})
  set_property(GLOBAL PROPERTY HWINTERP_VARIANT_${V_NAME}_GFLAGS "${gflags}")
endfunction()

# hwinterp_synth_block(CORE <module> NAME <name> PARAMS K=V...)
#
# Declares a block that is synthesized (scripts/synth.sh) but is not a
# lockstep core: no testbench adapter, no conformance suite, no regression
# case. It goes to blocks.txt (the format of variants.txt: name, top module,
# parameters), never to variants.txt or the testbench's X-macros. Its RTL
# files are rtl/<module>.f, as a core's. HWINTERP_BLOCK_<name>_GFLAGS holds
# its -G flags for a Verilated build at the same widths.
function(hwinterp_synth_block)
  cmake_parse_arguments(B "" "CORE;NAME" "PARAMS" ${ARGN})
  if(NOT B_CORE OR NOT B_NAME OR NOT B_PARAMS)
    message(FATAL_ERROR "hwinterp_synth_block needs CORE, NAME and PARAMS")
  endif()
  set(gflags "")
  foreach(kv IN LISTS B_PARAMS)
    list(APPEND gflags "-G${kv}")
  endforeach()
  string(REPLACE ";" " " params_line "${B_PARAMS}")
  file(APPEND ${HWINTERP_GENERATED_DIR}/blocks.txt.in "${B_NAME} ${B_CORE} ${params_line}\n")
  set_property(GLOBAL PROPERTY HWINTERP_BLOCK_${B_NAME}_GFLAGS "${gflags}")
endfunction()

# Called once after cores.cmake: publishes variants.txt (and blocks.txt) for scripts/synth.sh
# and hwinterp_variants.h: the Verilated classes of every variant and an
# X-macro over (core, variant) pairs, plus hwinterp_core_adapters.h, which
# includes every core's testbench adapter (tb/cores/<core>/<core>_adapter.h),
# so the testbench instantiates every core and variant without a hand-kept list.
function(hwinterp_finish_variants)
  get_property(cores GLOBAL PROPERTY HWINTERP_CORES)
  list(REMOVE_DUPLICATES cores)
  set(configs "// Generated from cmake/cores.cmake; do not edit.\n#pragma once\n\n")
  set(body "// Generated from cmake/cores.cmake; do not edit.\n#pragma once\n\n#include \"hwinterp_configs.h\"\n")
  set(adapters "// Generated from cmake/cores.cmake; do not edit.\n#pragma once\n\n")
  set(xs "")
  set(core_xs "")
  foreach(core IN LISTS cores)
    get_property(vs GLOBAL PROPERTY HWINTERP_CORE_${core}_VARIANTS)
    foreach(v IN LISTS vs)
      string(APPEND configs "#include \"${v}_cfg.h\"\n")
      string(APPEND body "#include \"${v}_rtl.h\"\n")
      string(APPEND xs " X(${core}, ${v})")
    endforeach()
    string(APPEND adapters "#include \"tb/cores/${core}/${core}_adapter.h\"\n")
    string(APPEND core_xs " X(${core})")
  endforeach()
  string(APPEND configs "\n// X(core, variant) for every variant, in cores.cmake order.\n"
    "#define HWINTERP_VARIANTS(X)${xs}\n"
    "// X(core) for every core, in cores.cmake order.\n#define HWINTERP_CORES(X)${core_xs}\n")
  # hwinterp_configs.h: every variant's configuration and the X-macros (no
  # Verilated code: what the fuzzers and the models need); hwinterp_variants.h
  # adds the Verilated classes of every variant.
  hwinterp_write_generated(hwinterp_configs.h "${configs}")
  hwinterp_write_generated(hwinterp_variants.h "${body}")
  hwinterp_write_generated(hwinterp_core_adapters.h "${adapters}")
  file(COPY_FILE ${HWINTERP_GENERATED_DIR}/variants.txt.in
       ${HWINTERP_GENERATED_DIR}/variants.txt ONLY_IF_DIFFERENT)
  file(COPY_FILE ${HWINTERP_GENERATED_DIR}/blocks.txt.in
       ${HWINTERP_GENERATED_DIR}/blocks.txt ONLY_IF_DIFFERENT)
endfunction()
