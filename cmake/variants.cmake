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

function(hwinterp_core_variant)
  cmake_parse_arguments(V "" "CORE;NAME" "PARAMS;DEFAULTS" ${ARGN})
  if(NOT V_CORE OR NOT V_NAME OR NOT V_PARAMS)
    message(FATAL_ERROR "hwinterp_core_variant needs CORE, NAME and PARAMS")
  endif()
  set(members "")
  set(gflags "")
  foreach(kv IN LISTS V_PARAMS)
    string(REPLACE "=" ";" kvl "${kv}")
    list(GET kvl 0 k)
    list(GET kvl 1 v)
    string(APPEND members "  static constexpr int ${k} = ${v};\n")
    list(APPEND gflags "-G${k}=${v}")
  endforeach()
  foreach(kv IN LISTS V_DEFAULTS)
    string(REPLACE "=" ";" kvl "${kv}")
    list(GET kvl 0 k)
    list(GET kvl 1 v)
    string(APPEND members "  static constexpr int ${k} = ${v};\n")
  endforeach()
  file(WRITE ${HWINTERP_GENERATED_DIR}/${V_NAME}_cfg.h.tmp
    "// Generated from cmake/cores.cmake; do not edit.\n#pragma once\n\n"
    "struct ${V_NAME}_cfg {\n"
    "  static constexpr const char* kCore = \"${V_CORE}\";\n"
    "  static constexpr const char* kVariant = \"${V_NAME}\";\n"
    "${members}};\n")
  # Only touch the header when it changed, so a re-configure rebuilds nothing.
  file(COPY_FILE ${HWINTERP_GENERATED_DIR}/${V_NAME}_cfg.h.tmp
       ${HWINTERP_GENERATED_DIR}/${V_NAME}_cfg.h ONLY_IF_DIFFERENT)
  # The testbench's binding of the variant to its Verilated classes.
  file(WRITE ${HWINTERP_GENERATED_DIR}/${V_NAME}_rtl.h.tmp
    "// Generated from cmake/cores.cmake; do not edit.\n#pragma once\n\n"
    "#include \"${V_NAME}_cfg.h\"\n#include \"V${V_NAME}_cc.h\"\n#include \"V${V_NAME}_sc.h\"\n\n"
    "namespace hwinterp {\ntemplate <class Cfg>\nstruct RtlOf;  // the Verilated classes of a variant\n}\n\n"
    "template <>\nstruct hwinterp::RtlOf<${V_NAME}_cfg> {\n"
    "  using Cc = V${V_NAME}_cc;  // verilator --cc: the direct lockstep mode\n"
    "  using Sc = V${V_NAME}_sc;  // verilator --sc: the SystemC mode\n};\n")
  file(COPY_FILE ${HWINTERP_GENERATED_DIR}/${V_NAME}_rtl.h.tmp
       ${HWINTERP_GENERATED_DIR}/${V_NAME}_rtl.h ONLY_IF_DIFFERENT)
  set_property(GLOBAL APPEND PROPERTY HWINTERP_CORE_${V_CORE}_VARIANTS ${V_NAME})
  set_property(GLOBAL APPEND PROPERTY HWINTERP_CORES ${V_CORE})
  string(REPLACE ";" " " params_line "${V_PARAMS}")
  file(APPEND ${HWINTERP_GENERATED_DIR}/variants.txt.in "${V_NAME} ${V_CORE} ${params_line}\n")
  set_property(GLOBAL APPEND PROPERTY HWINTERP_VARIANTS ${V_NAME})
  set_property(GLOBAL PROPERTY HWINTERP_VARIANT_${V_NAME}_CORE ${V_CORE})
  set_property(GLOBAL PROPERTY HWINTERP_VARIANT_${V_NAME}_GFLAGS "${gflags}")
endfunction()

# Called once after cores.cmake: publishes variants.txt for scripts/synth.sh
# and, per core, <core>_variants.h: an X-macro over the core's variants so the
# testbench instantiates each one without a hand-kept list.
function(hwinterp_finish_variants)
  get_property(cores GLOBAL PROPERTY HWINTERP_CORES)
  list(REMOVE_DUPLICATES cores)
  foreach(core IN LISTS cores)
    get_property(vs GLOBAL PROPERTY HWINTERP_CORE_${core}_VARIANTS)
    set(body "// Generated from cmake/cores.cmake; do not edit.\n#pragma once\n\n"
             "namespace hwinterp {\ntemplate <class Cfg>\nstruct RtlOf;  // the Verilated classes of a variant\n}\n\n")
    set(xs "")
    foreach(v IN LISTS vs)
      string(APPEND body "#include \"${v}_rtl.h\"\n")
      string(APPEND xs " X(${v})")
    endforeach()
    string(TOUPPER ${core} CORE)
    string(APPEND body "\n#define HWINTERP_${CORE}_VARIANTS(X)${xs}\n")
    file(WRITE ${HWINTERP_GENERATED_DIR}/${core}_variants.h.tmp "${body}")
    file(COPY_FILE ${HWINTERP_GENERATED_DIR}/${core}_variants.h.tmp
         ${HWINTERP_GENERATED_DIR}/${core}_variants.h ONLY_IF_DIFFERENT)
  endforeach()
  file(COPY_FILE ${HWINTERP_GENERATED_DIR}/variants.txt.in
       ${HWINTERP_GENERATED_DIR}/variants.txt ONLY_IF_DIFFERENT)
endfunction()
