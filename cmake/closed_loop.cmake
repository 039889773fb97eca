# Closed loop (issue 3): quadrature decoder, neuron-PI cascade, step NCO,
# sc_servo_axis top; their bit-exact models; plant; closed-loop runner and
# CLI; tests. Included at the end of the top-level CMakeLists.txt.

set(SC_CL_RTL_SOURCES
  ${RTL_DIR}/sc_pkg.sv
  ${RTL_DIR}/sc_profile_exec.sv
  ${RTL_DIR}/sc_step_gen.sv
  ${RTL_DIR}/sc_axis_core.sv
  ${RTL_DIR}/sc_sync.sv
  ${RTL_DIR}/sc_quad_decoder.sv
  ${RTL_DIR}/sc_neuron_pi.sv
  ${RTL_DIR}/sc_step_nco.sv
  ${RTL_DIR}/sc_servo_axis.sv)

# ---- bit-exact model of the closed-loop modules -------------------------------
add_library(sc_cl_model STATIC
  cmodel/neuron_pi.cpp
  cmodel/servo_axis.cpp)
add_dependencies(sc_cl_model sc_params)
target_include_directories(sc_cl_model PUBLIC cmodel ${GEN_DIR})
target_link_libraries(sc_cl_model PUBLIC sc_model)
target_compile_options(sc_cl_model PRIVATE ${SC_WARN})

# ---- Verilated sc_servo_axis ------------------------------------------------------
add_library(sc_rtl_servo STATIC tb/rtl_servo.cpp)
target_include_directories(sc_rtl_servo PUBLIC tb)
target_link_libraries(sc_rtl_servo PUBLIC sc_cl_model)
verilate(sc_rtl_servo
  SOURCES ${SC_CL_RTL_SOURCES}
  TOP_MODULE sc_servo_axis
  PREFIX Vsc_servo_axis
  TRACE_FST
  VERILATOR_ARGS ${SC_VERILATOR_ARGS}
  OPT_FAST -O3 -fno-tree-slp-vectorize
  OPT_SLOW -O1
  OPT_GLOBAL -O3)

# ---- plant, closed-loop runner, reports, CLI glue -------------------------------------
add_library(sc_cl_tb STATIC
  tb/plant.cpp
  tb/closed_loop_run.cpp
  tb/closed_loop_cli.cpp)
target_include_directories(sc_cl_tb PUBLIC tb)
target_link_libraries(sc_cl_tb PUBLIC sc_rtl_servo sc_cl_model sc_tb fmt::fmt nlohmann_json::nlohmann_json Threads::Threads)
target_compile_options(sc_cl_tb PRIVATE ${SC_WARN})
target_link_libraries(scurve PRIVATE sc_cl_tb)

# ---- tests -------------------------------------------------------------------------------
add_executable(cl_tests
  tests/test_quad_decoder.cpp
  tests/test_neuron_pi.cpp
  tests/test_closed_loop.cpp)
target_link_libraries(cl_tests PRIVATE sc_cl_tb GTest::gtest_main)
target_compile_options(cl_tests PRIVATE ${SC_WARN})
gtest_discover_tests(cl_tests DISCOVERY_TIMEOUT 60 TEST_PREFIX "cl." PROPERTIES LABELS "closed_loop")

# sc_neuron_pi alone vs sc::NeuronPi, every clock: random configurations and
# inputs reaching the controller's corner paths (tests/test_neuron_pi_rtl.cpp).
set(SC_NPI_RTL_SOURCES
  ${RTL_DIR}/sc_pkg.sv
  ${RTL_DIR}/sc_neuron_pi.sv)
add_library(sc_rtl_neuron_pi STATIC)
target_link_libraries(sc_rtl_neuron_pi PUBLIC sc_cl_model)
verilate(sc_rtl_neuron_pi
  SOURCES ${SC_NPI_RTL_SOURCES}
  TOP_MODULE sc_neuron_pi
  PREFIX Vsc_neuron_pi
  VERILATOR_ARGS ${SC_VERILATOR_ARGS}
  OPT_FAST -O3 -fno-tree-slp-vectorize
  OPT_SLOW -O1
  OPT_GLOBAL -O3)

add_executable(cl_neuron_pi_rtl_tests tests/test_neuron_pi_rtl.cpp)
target_link_libraries(cl_neuron_pi_rtl_tests PRIVATE sc_rtl_neuron_pi sc_cl_model fmt::fmt GTest::gtest_main)
target_compile_options(cl_neuron_pi_rtl_tests PRIVATE ${SC_WARN})
gtest_discover_tests(cl_neuron_pi_rtl_tests DISCOVERY_TIMEOUT 60 TEST_PREFIX "cl." PROPERTIES LABELS "closed_loop" TIMEOUT 300)

# Full-length paper groups in closed loop, RTL and model in lockstep.
# Group 2 (the shortest) stays in the default suite; all four carry "long".
add_test(NAME cl.paper_group2_lockstep
  COMMAND scurve sim --closed-loop --group 2)
set_tests_properties(cl.paper_group2_lockstep PROPERTIES LABELS "closed_loop" TIMEOUT 900)
add_test(NAME cl.paper_groups_lockstep_all
  COMMAND scurve sim --closed-loop --group 1 2 3 4 --jobs 2)
set_tests_properties(cl.paper_groups_lockstep_all PROPERTIES LABELS "long;closed_loop" TIMEOUT 3600)
add_test(NAME cl.comparison
  COMMAND scurve sim --closed-loop --compare --group 1 --jobs 2)
set_tests_properties(cl.comparison PROPERTIES LABELS "long;closed_loop" TIMEOUT 3600)

# RTL hygiene for the closed-loop top: Verilator -Wall lint, Icarus compile,
# yosys synth_xilinx (no latches; utilisation in build/synth-servo).
add_test(NAME cl.rtl_lint_verilator
  COMMAND verilator --lint-only -Wall ${CMAKE_SOURCE_DIR}/rtl/lint/verilator_waiver.vlt
          ${SC_CL_RTL_SOURCES} --top-module sc_servo_axis)
add_test(NAME cl.rtl_compile_icarus
  COMMAND iverilog -g2012 -o ${CMAKE_BINARY_DIR}/sc_servo_axis.vvp -s sc_servo_axis ${SC_CL_RTL_SOURCES})
add_test(NAME cl.synth_yosys_servo
  COMMAND ${CMAKE_SOURCE_DIR}/scripts/synth_yosys.sh sc_servo_axis ${CMAKE_BINARY_DIR}/synth-servo)
set_tests_properties(cl.rtl_lint_verilator cl.rtl_compile_icarus cl.synth_yosys_servo PROPERTIES LABELS "closed_loop")

add_test(NAME cl.cli_contract
  COMMAND ${CMAKE_SOURCE_DIR}/tests/cl_cli_test.sh $<TARGET_FILE:scurve> ${CMAKE_SOURCE_DIR})
set_tests_properties(cl.cli_contract PROPERTIES LABELS "closed_loop")
