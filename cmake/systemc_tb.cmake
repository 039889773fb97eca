# SystemC co-verification bench, trace tools (kinematics traces, `scurve diff`),
# regression runner (`scurve regress`) and their tests. Included at the end of
# the top-level CMakeLists.txt (it extends the `scurve` target defined there).
#
# Debian's libsystemc is built for C++17 and every file including <systemc>
# links against an API-check symbol named after the C++ standard, so the two
# bench executables are compiled as C++17 (SC_CPLUSPLUS left alone); all code
# that includes the C++20 model/checker headers lives in C++20 libraries
# behind tb/systemc/components.h, which is valid in both.

# ---- trace + regression tools (no SystemC): linked into scurve --------------
add_library(sc_kin_trace STATIC tb/tools/kin_trace.cpp)
target_include_directories(sc_kin_trace PUBLIC tb/tools)
target_link_libraries(sc_kin_trace PUBLIC sc_model fmt::fmt)
target_compile_options(sc_kin_trace PRIVATE ${SC_WARN})

# The FST reader (fstReaderOpen...) is not compiled here: Verilator's
# verilated_fst_c.cpp in sc_rtl's tracing build already contains
# gtkwave/fstapi.c, and a second copy would clash at link time.
add_library(sc_tools STATIC
  tb/tools/trace_diff.cpp
  tb/tools/regress.cpp
  tb/tools/tool_commands.cpp)
target_include_directories(sc_tools PUBLIC tb/tools PRIVATE ${VERILATOR_ROOT}/include/gtkwave)
target_link_libraries(sc_tools PUBLIC sc_kin_trace sc_tb sc_model fmt::fmt nlohmann_json::nlohmann_json
                      Threads::Threads)
target_compile_options(sc_tools PRIVATE ${SC_WARN})
# Default test list when scurve regress runs outside the source tree.
target_compile_definitions(sc_tools PRIVATE SCURVE_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
target_link_libraries(scurve PRIVATE sc_tools)

# ---- bench components (C++20, no SystemC, no Verilator runtime) --------------------
# The checker and pin monitor are compiled here again rather than taken from
# sc_tb: sc_tb drags in sc_rtl's --cc Verilator runtime, which the --sc bench
# cannot link next to its own (with LTO the archive members get pulled in
# for shared template instantiations and clash).
# The model's FST writer uses the fstapi.c that each bench's Verilator
# runtime carries (both benches are verilated with TRACE_FST).
add_library(sc_bench_parts STATIC
  tb/systemc/components.cpp
  tb/tools/model_fst.cpp
  tb/lockstep.cpp
  tb/pin_monitor.cpp)
target_include_directories(sc_bench_parts PUBLIC tb/systemc tb PRIVATE ${VERILATOR_ROOT}/include/gtkwave)
target_link_libraries(sc_bench_parts PUBLIC sc_kin_trace sc_model scurve::host_cli fmt::fmt nlohmann_json::nlohmann_json)
target_compile_options(sc_bench_parts PRIVATE ${SC_WARN})

# The --cc RTL as a bench core: only the batched bench links it.
add_library(sc_bench_rtlcc STATIC tb/systemc/rtl_cc_core.cpp)
target_link_libraries(sc_bench_rtlcc PUBLIC sc_bench_parts sc_rtl)
target_compile_options(sc_bench_rtlcc PRIVATE ${SC_WARN})

# ---- SystemC benches (C++17) -------------------------------------------------------
# Batched (temporally decoupled): sc_rtl's --cc model advanced in quanta.
add_executable(sc_bench tb/systemc/sc_bench_main.cpp)
set_target_properties(sc_bench PROPERTIES CXX_STANDARD 17)
target_link_libraries(sc_bench PRIVATE sc_bench_rtlcc sc_bench_parts)
target_compile_options(sc_bench PRIVATE ${SC_WARN})
verilator_link_systemc(sc_bench)

# Pin-accurate: the RTL verilated again with --sc and its own SystemC-enabled
# runtime; it must never link sc_rtl's --cc objects (see sc_bench_parts).
add_executable(sc_bench_pin tb/systemc/pin_bench_main.cpp)
set_target_properties(sc_bench_pin PROPERTIES CXX_STANDARD 17)
target_link_libraries(sc_bench_pin PRIVATE sc_bench_parts)
verilate(sc_bench_pin SYSTEMC
  SOURCES ${SC_RTL_SOURCES}
  TOP_MODULE sc_axis_core
  PREFIX Vsc_axis_core_pin
  TRACE_FST
  VERILATOR_ARGS ${SC_VERILATOR_ARGS}
  OPT_FAST -O3 -fno-tree-slp-vectorize
  OPT_SLOW -O1
  OPT_GLOBAL -O3)
verilator_link_systemc(sc_bench_pin)

# ---- tests -------------------------------------------------------------------------------
# Debian's python3 (python3-matplotlib lives there, not in a pyenv python).
find_program(SC_SYSTEM_PYTHON python3 PATHS /usr/bin NO_DEFAULT_PATH REQUIRED)

add_executable(sc_tools_tests tests/systemc/test_trace_tools.cpp)
target_link_libraries(sc_tools_tests PRIVATE sc_tools GTest::gtest_main)
target_compile_definitions(sc_tools_tests PRIVATE
  SC_BENCH="$<TARGET_FILE:sc_bench>" SCURVE="$<TARGET_FILE:scurve>" SOURCE_DIR="${CMAKE_SOURCE_DIR}")
add_dependencies(sc_tools_tests sc_bench scurve)
gtest_discover_tests(sc_tools_tests DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 600 LABELS systemc)

# The default regression list holds the four full paper groups (through the
# SystemC bench, in lockstep) besides seeded random moves and corner cases.
add_test(NAME regress_default_list
  COMMAND scurve regress --list ${CMAKE_SOURCE_DIR}/tests/regress_list.json --jobs 2
          --out-dir ${CMAKE_BINARY_DIR}/regress-ctest)
set_tests_properties(regress_default_list PROPERTIES
  FIXTURES_SETUP regress_out TIMEOUT 1800 LABELS systemc RUN_SERIAL TRUE)
add_test(NAME regress_junit_valid
  COMMAND ${SC_SYSTEM_PYTHON} ${CMAKE_SOURCE_DIR}/tests/systemc/check_regress.py junit
          ${CMAKE_BINARY_DIR}/regress-ctest)
set_tests_properties(regress_junit_valid PROPERTIES FIXTURES_REQUIRED regress_out LABELS systemc)
add_test(NAME regress_shards_cover_list
  COMMAND ${SC_SYSTEM_PYTHON} ${CMAKE_SOURCE_DIR}/tests/systemc/check_regress.py shards $<TARGET_FILE:scurve>
          ${CMAKE_SOURCE_DIR}/tests/systemc/shard_list.json ${CMAKE_BINARY_DIR}/regress-shards)
set_tests_properties(regress_shards_cover_list PROPERTIES TIMEOUT 600 LABELS systemc)

# The pin-accurate bench (per-clock sc_clock scheduling) on a short move.
add_test(NAME sc_bench_pin_short
  COMMAND sc_bench_pin --distance 300 --v-start 0 --v-cruise 3000 --v-end 0 --a-max 50000 --j-max 500000)
set_tests_properties(sc_bench_pin_short PROPERTIES TIMEOUT 600 LABELS systemc)

# Each paper group alone through the batched bench (the default suite runs
# them inside regress_default_list; these are for `ctest -L long`).
foreach(g 1 2 3 4)
  add_test(NAME sc_bench_group${g} COMMAND sc_bench --group ${g})
  set_tests_properties(sc_bench_group${g} PROPERTIES TIMEOUT 1800 LABELS "systemc;long")
endforeach()

# Figures of group 1 (full run through the bench); must show the four phases.
add_test(NAME plots_group1
  COMMAND ${SC_SYSTEM_PYTHON} ${CMAKE_SOURCE_DIR}/scripts/plot_run.py --group 1 --build-dir ${CMAKE_BINARY_DIR}
          --out-dir ${CMAKE_BINARY_DIR}/plots/group1 --require-phases rising,steady,falling,zero)
set_tests_properties(plots_group1 PROPERTIES TIMEOUT 1200 LABELS systemc)
