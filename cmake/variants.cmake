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
file(WRITE ${HWINTERP_GENERATED_DIR}/boards.txt.in "")
set_property(GLOBAL PROPERTY HWINTERP_BOARDS "")
set_property(GLOBAL PROPERTY HWINTERP_BOARD_SIMS "")

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
  set_property(GLOBAL PROPERTY HWINTERP_VARIANT_${V_NAME}_PARAMS "${V_PARAMS}")
endfunction()

# hwinterp_synth_block(NAME <row> TOP <module> FILES <list> [YOSYS debian|yowasp]
#                      [VARIANT <variant>] [PARAMS K=V...])
#
# Declares a block that scripts/synth.sh synthesizes beside the core variants
# (a row of the synthesis tables) but that is not a lockstep core: no
# configuration header, no testbench binding, no netlist check. TOP is its top
# module, FILES names its RTL file list rtl/<list>.f; its parameters are those
# of the core variant VARIANT (declared before it), then PARAMS;
# YOSYS the Yosys of its generic step and iCE40 mapping (default debian, as
# the cores; yowasp for RTL Debian's Yosys does not read). One line of
# generated/blocks.txt: <row> <module> <list> <yosys> K=V...; the global
# property HWINTERP_BLOCK_<row>_GFLAGS holds its -G flags.
function(hwinterp_synth_block)
  cmake_parse_arguments(B "" "NAME;TOP;FILES;YOSYS;VARIANT" "PARAMS" ${ARGN})
  if(NOT B_NAME OR NOT B_TOP OR NOT B_FILES)
    message(FATAL_ERROR "hwinterp_synth_block needs NAME, TOP and FILES")
  endif()
  if(NOT B_YOSYS)
    set(B_YOSYS debian)
  elseif(NOT B_YOSYS MATCHES "^(debian|yowasp)$")
    message(FATAL_ERROR "hwinterp_synth_block ${B_NAME}: YOSYS must be debian or yowasp")
  endif()
  if(NOT EXISTS ${PROJECT_SOURCE_DIR}/rtl/${B_FILES}.f)
    message(FATAL_ERROR "hwinterp_synth_block ${B_NAME}: no file list rtl/${B_FILES}.f")
  endif()
  set(params "")
  if(B_VARIANT)
    get_property(params GLOBAL PROPERTY HWINTERP_VARIANT_${B_VARIANT}_PARAMS)
    if(NOT params)
      message(FATAL_ERROR "hwinterp_synth_block ${B_NAME}: no variant ${B_VARIANT} before it")
    endif()
  endif()
  list(APPEND params ${B_PARAMS})
  # Its -G flags, for a Verilated build at the same widths (rtl/CMakeLists.txt).
  set(gflags "")
  foreach(kv IN LISTS params)
    list(APPEND gflags "-G${kv}")
  endforeach()
  set_property(GLOBAL PROPERTY HWINTERP_BLOCK_${B_NAME}_GFLAGS "${gflags}")
  string(REPLACE ";" " " params_line "${params}")
  file(APPEND ${HWINTERP_GENERATED_DIR}/blocks.txt.in
    "${B_NAME} ${B_TOP} ${B_FILES} ${B_YOSYS} ${params_line}\n")
endfunction()

# hwinterp_board(NAME <board> VARIANT <motion_top variant> LINK etherbone|uart
#                SYS_HZ <hz> [BAUD <baud>] [PARAMS K=V...])
#
# Declares a board (boards/, docs/boards.md): motion_soc_wb on a LiteX SoC's
# bus at the widths of a motion_top VARIANT (declared before it), then PARAMS
# (motion_soc's own: FIFO_DEPTH, PROFILE and the profile's widths), its
# system clock SYS_HZ (motion_soc's CLK_HZ) and its host link (BAUD for a
# UART). boards/hwinterp_litex/config.py reads these lines from
# cmake/cores.cmake for the gateware; here they give generated/boards.txt
# (<board> <link> <sys_hz> <baud> K=V...) and the simulated boards'
# builds (rtl/CMakeLists.txt).
function(hwinterp_board)
  cmake_parse_arguments(B "" "NAME;VARIANT;LINK;SYS_HZ;BAUD" "PARAMS" ${ARGN})
  if(NOT B_NAME OR NOT B_VARIANT OR NOT B_LINK OR NOT B_SYS_HZ)
    message(FATAL_ERROR "hwinterp_board needs NAME, VARIANT, LINK and SYS_HZ")
  endif()
  if(NOT B_LINK MATCHES "^(etherbone|uart)$")
    message(FATAL_ERROR "hwinterp_board ${B_NAME}: LINK must be etherbone or uart")
  endif()
  if(B_LINK STREQUAL "uart" AND NOT B_BAUD)
    message(FATAL_ERROR "hwinterp_board ${B_NAME}: a UART link needs BAUD")
  endif()
  if(NOT B_BAUD)
    set(B_BAUD 0)
  endif()
  get_property(params GLOBAL PROPERTY HWINTERP_VARIANT_${B_VARIANT}_PARAMS)
  if(NOT params)
    message(FATAL_ERROR "hwinterp_board ${B_NAME}: no variant ${B_VARIANT} before it")
  endif()
  list(APPEND params ${B_PARAMS})
  set_property(GLOBAL APPEND PROPERTY HWINTERP_BOARDS ${B_NAME})
  set_property(GLOBAL PROPERTY HWINTERP_BOARD_${B_NAME}_LINK ${B_LINK})
  set_property(GLOBAL PROPERTY HWINTERP_BOARD_${B_NAME}_SYS_HZ ${B_SYS_HZ})
  set_property(GLOBAL PROPERTY HWINTERP_BOARD_${B_NAME}_BAUD ${B_BAUD})
  set_property(GLOBAL PROPERTY HWINTERP_BOARD_${B_NAME}_PARAMS "${params}")
  string(REPLACE ";" " " params_line "${params}")
  file(APPEND ${HWINTERP_GENERATED_DIR}/boards.txt.in
    "${B_NAME} ${B_LINK} ${B_SYS_HZ} ${B_BAUD} ${params_line}\n")
  # Its simulation at its own clock.
  hwinterp_board_sim(BOARD ${B_NAME} SYS_HZ ${B_SYS_HZ} BAUD ${B_BAUD})
endfunction()

# hwinterp_board_sim(BOARD <board> SYS_HZ <hz> [BAUD <baud>] [NO_PROFILE])
#
# A simulated build of a board (hwinterp board-sim --board <board>
# --clock-hz <hz>): its gateware at another clock (and UART rate), so that
# whole programs simulate in less time than at the board's own clock. Every
# board has one at its own clock; cmake/cores.cmake adds others, and the
# cache variable HWINTERP_EXTRA_BOARD_SIMS (BOARD:HZ[:BAUD][:noprofile];...) more
# (scripts/board_sim.sh sets it). NO_PROFILE builds it with PROFILE = 0
# (FEED drives the feed; board-sim --no-profile), named <board>_<hz>_noprofile.
function(hwinterp_board_sim)
  cmake_parse_arguments(S "NO_PROFILE" "BOARD;SYS_HZ;BAUD" "" ${ARGN})
  get_property(link GLOBAL PROPERTY HWINTERP_BOARD_${S_BOARD}_LINK)
  if(NOT link)
    message(FATAL_ERROR "hwinterp_board_sim: no board ${S_BOARD} declared before it")
  endif()
  if(NOT S_SYS_HZ MATCHES "^[1-9][0-9]*$")
    message(FATAL_ERROR "hwinterp_board_sim ${S_BOARD}: SYS_HZ '${S_SYS_HZ}' is not a clock in Hz")
  endif()
  if(NOT S_BAUD)
    get_property(S_BAUD GLOBAL PROPERTY HWINTERP_BOARD_${S_BOARD}_BAUD)
  endif()
  set(name ${S_BOARD}_${S_SYS_HZ})
  set(profile 1)
  if(S_NO_PROFILE)
    set(name ${name}_noprofile)
    set(profile 0)
  endif()
  get_property(sims GLOBAL PROPERTY HWINTERP_BOARD_SIMS)
  if(name IN_LIST sims)
    return()
  endif()
  set_property(GLOBAL APPEND PROPERTY HWINTERP_BOARD_SIMS ${name})
  set_property(GLOBAL PROPERTY HWINTERP_BOARD_SIM_${name}_BOARD ${S_BOARD})
  set_property(GLOBAL PROPERTY HWINTERP_BOARD_SIM_${name}_SYS_HZ ${S_SYS_HZ})
  set_property(GLOBAL PROPERTY HWINTERP_BOARD_SIM_${name}_BAUD ${S_BAUD})
  set_property(GLOBAL PROPERTY HWINTERP_BOARD_SIM_${name}_PROFILE ${profile})
endfunction()

# Called once after cores.cmake: publishes variants.txt and blocks.txt for scripts/synth.sh
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
  file(COPY_FILE ${HWINTERP_GENERATED_DIR}/boards.txt.in
       ${HWINTERP_GENERATED_DIR}/boards.txt ONLY_IF_DIFFERENT)
  # Newer than cores.cmake even when unchanged: scripts/synth.sh configures
  # again only when cores.cmake is newer than these (nothing builds from them).
  file(TOUCH_NOCREATE ${HWINTERP_GENERATED_DIR}/variants.txt ${HWINTERP_GENERATED_DIR}/blocks.txt)
endfunction()
