# RTL file lists and Verilator builds, one helper for every top.
#
# sc_rtl_files(<out-var> <top>): the files <top> needs, in read order, as
# scripts/rtl_deps.py lists them; yosys (scripts/synth_yosys.sh) and Vivado
# (scripts/vivado/build.tcl, checked by synth.vivado_flow_dry_run) read the
# same list, so every tool sees one set of files per top.
#
# sc_verilate(<target> TOP <module> [PREFIX <p>] [TRACE] [SYSTEMC] [OPT <flag>]):
# verilate() with the project's flags. Every --cc top goes into one library
# (tb/sc_rtl), so the Verilator runtime is compiled once.

# Mutation testing (scripts/mutation.py, docs/mutation.md): with
# SC_RTL_FROZEN_DIR set, every top not named in SC_RTL_LIVE_TOPS is Verilated
# from that unmodified copy of rtl/, so a mutant rebuilds only the tops its
# tests run. Both empty (the default): every top from rtl/.
set(SC_RTL_FROZEN_DIR "" CACHE PATH "mutation testing: Verilate the tops not in SC_RTL_LIVE_TOPS from here")
set(SC_RTL_LIVE_TOPS "" CACHE STRING "mutation testing: the tops Verilated from rtl/ when SC_RTL_FROZEN_DIR is set")
# The Verilated code's optimisation level (empty: -O3), for builds whose
# time goes into compiling rather than running it: a mutant's build, the CI
# coverage build (scripts/mutation.py, scripts/coverage.py).
set(SC_VERILATE_OPT "" CACHE STRING "the Verilated code's -O level instead of -O3 (mutation, CI coverage builds)")
# The CI coverage profile (scripts/coverage.py --profile ci): the tops (by
# PREFIX) that no test of its selection runs, Verilated without coverage
# points and compiled at -O0 (they only have to link).
set(SC_COVERAGE_PLAIN_TOPS "" CACHE STRING "coverage build: PREFIXes of tops built plain at -O0 (not run)")
# A mutant that leaves a signal unread (a stuck right side, a dropped term)
# is still a wrong design for the tests to find, not a build error.
option(SC_VERILATE_WARN_NOT_FATAL "mutation testing: Verilator -Wall warnings do not stop the build" OFF)

set(SC_RTL_DIR ${PROJECT_SOURCE_DIR}/rtl)
set(SC_RTL_DEPS ${PROJECT_SOURCE_DIR}/scripts/rtl_deps.py)
set(SC_VERILATOR_WAIVER ${SC_RTL_DIR}/lint/verilator_waiver.vlt)
# The lists are computed at configure time: re-configure when any RTL file
# (a new instantiation) or the script changes.
file(GLOB SC_RTL_ALL CONFIGURE_DEPENDS ${SC_RTL_DIR}/*.sv)
# (Not in a mutation build, SC_RTL_FROZEN_DIR above: a mutant never changes an
# instantiation, and re-configuring per mutant would cost more than its build.)
if(NOT SC_RTL_FROZEN_DIR)
  set_property(DIRECTORY ${PROJECT_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
               ${SC_RTL_ALL} ${SC_RTL_DEPS})
endif()

function(sc_rtl_files out top)
  set(dir ${SC_RTL_DIR})
  if(ARGC GREATER 2)
    set(dir ${ARGV2})
  endif()
  execute_process(
    COMMAND ${Python3_EXECUTABLE} ${SC_RTL_DEPS} ${dir} ${top}
    OUTPUT_VARIABLE files ERROR_VARIABLE err RESULT_VARIABLE rc
    OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(rc)
    message(FATAL_ERROR "rtl_deps.py ${top}: ${err}")
  endif()
  string(REPLACE "\n" ";" files "${files}")
  set(${out} ${files} PARENT_SCOPE)
endfunction()

# OPT_FAST -O3: Verilator's default -Os halves the throughput (DESIGN.md);
# -fno-tree-slp-vectorize: measured faster on the wide 128-bit state.
function(sc_verilate target)
  cmake_parse_arguments(A "TRACE;SYSTEMC" "TOP;PREFIX;OPT" "PARAMS" ${ARGN})
  if(NOT A_TOP)
    message(FATAL_ERROR "sc_verilate(${target}): TOP is required")
  endif()
  if(NOT A_PREFIX)
    set(A_PREFIX V${A_TOP})
  endif()
  if(NOT A_OPT)
    set(A_OPT -O3)
  endif()
  if(SC_VERILATE_OPT)
    set(A_OPT ${SC_VERILATE_OPT})
  endif()
  # The sanitizer build: the generated code and the Verilator runtime are not
  # ours to check and dominate its build time; compiled quickly and left
  # uninstrumented (the wrappers around them are instrumented).
  set(fast ${A_OPT} -fno-tree-slp-vectorize)
  set(slow -O1)
  if(SC_SANITIZE)
    set(A_OPT -O1 -fno-sanitize=all)
    set(fast ${A_OPT})
    set(slow ${A_OPT})
  endif()
  set(flags)
  if(A_TRACE)
    list(APPEND flags TRACE_FST)
  endif()
  if(A_SYSTEMC)
    list(APPEND flags SYSTEMC)
  endif()
  set(warn_args)
  if(SC_VERILATE_WARN_NOT_FATAL)
    set(warn_args -Wno-fatal)
  endif()
  set(cover_args)
  if(SC_COVERAGE AND A_PREFIX IN_LIST SC_COVERAGE_PLAIN_TOPS)
    set(A_OPT -O0)
    set(fast -O0)
    set(slow -O0)
  elseif(SC_COVERAGE)
    # The kinds of SC_COVERAGE_KINDS (line, toggle, user); SC_COVER enables
    # the RTL's cover points. Toggle points make a run ~20x slower, line and
    # user ones barely: scripts/coverage.py builds them apart.
    set(cover_args -DSC_COVER)
    foreach(kind IN LISTS SC_COVERAGE_KINDS)
      if(NOT kind MATCHES "^(line|toggle|user)$")
        message(FATAL_ERROR "SC_COVERAGE_KINDS: '${kind}' is not one of line, toggle, user")
      endif()
      list(APPEND cover_args --coverage-${kind})
    endforeach()
  endif()
  if(SC_RTL_FROZEN_DIR AND NOT A_TOP IN_LIST SC_RTL_LIVE_TOPS)
    sc_rtl_files(files ${A_TOP} ${SC_RTL_FROZEN_DIR})
  else()
    sc_rtl_files(files ${A_TOP})
  endif()
  # PARAMS Name=Value ...: the top's parameters (-G), for a second build of
  # one top under its own PREFIX
  set(param_args)
  foreach(p IN LISTS A_PARAMS)
    list(APPEND param_args -G${p})
  endforeach()
  verilate(${target} ${flags}
    SOURCES ${files}
    TOP_MODULE ${A_TOP}
    PREFIX ${A_PREFIX}
    VERILATOR_ARGS -Wall ${SC_VERILATOR_WAIVER} --x-assign fast --x-initial fast ${warn_args} ${cover_args}
                   ${param_args}
    OPT_FAST ${fast}
    OPT_SLOW ${slow}
    OPT_GLOBAL ${A_OPT})
endfunction()

# Lint (Verilator -Wall, the verilator CMake found), Icarus compile and
# yosys synth_xilinx of one top, labelled lint / synth.
function(sc_rtl_checks top)
  cmake_parse_arguments(A "NO_SYNTH" "" "" ${ARGN})
  sc_rtl_files(files ${top})
  add_test(NAME lint.verilator.${top}
    COMMAND ${VERILATOR_BIN} --lint-only -Wall ${SC_VERILATOR_WAIVER} ${files} --top-module ${top})
  add_test(NAME lint.icarus.${top}
    COMMAND ${SC_IVERILOG} -g2012 -s ${top} -o ${CMAKE_BINARY_DIR}/icarus/${top}.vvp ${files})
  set_tests_properties(lint.verilator.${top} lint.icarus.${top} PROPERTIES LABELS lint)
  if(NOT A_NO_SYNTH)
    add_test(NAME synth.yosys.${top}
      COMMAND ${PROJECT_SOURCE_DIR}/scripts/synth_yosys.sh ${top} ${CMAKE_BINARY_DIR}/synth/${top})
    set_tests_properties(synth.yosys.${top} PROPERTIES LABELS synth TIMEOUT 900)
  endif()
endfunction()
