# Board / host interface (issue 5): AXI4-Lite register file, UART bridge,
# Arty A7 board top; their model, Verilated benches, tests and checks.
# Included from the top-level CMakeLists.txt.

set(SC_AXI_RTL_SOURCES
  ${SC_RTL_SOURCES}
  ${RTL_DIR}/sc_axi_regs.sv
  ${RTL_DIR}/sc_axi_axis.sv)
# closed-loop axis behind the register file (sc_axi_servo)
set(SC_AXI_SERVO_RTL_SOURCES
  ${RTL_DIR}/sc_pkg.sv
  ${RTL_DIR}/sc_profile_exec.sv
  ${RTL_DIR}/sc_step_gen.sv
  ${RTL_DIR}/sc_quad_decoder.sv
  ${RTL_DIR}/sc_neuron_pi.sv
  ${RTL_DIR}/sc_step_nco.sv
  ${RTL_DIR}/sc_servo_axis.sv
  ${RTL_DIR}/sc_axi_regs.sv
  ${RTL_DIR}/sc_axi_servo.sv)
set(SC_BOARD_RTL_SOURCES
  ${SC_AXI_SERVO_RTL_SOURCES}
  ${RTL_DIR}/sc_sync.sv
  ${RTL_DIR}/sc_rst_sync.sv
  ${RTL_DIR}/sc_clkgen.sv
  ${RTL_DIR}/sc_uart_rx.sv
  ${RTL_DIR}/sc_uart_tx.sv
  ${RTL_DIR}/sc_uart_bridge.sv
  ${RTL_DIR}/sc_board_top.sv)

# ---- register map: C++ table (docs/regmap.md is committed and checked) -------
add_custom_command(
  OUTPUT ${GEN_DIR}/sc_regmap.h
  COMMAND ${CMAKE_COMMAND} -E make_directory ${GEN_DIR}
  COMMAND Python3::Interpreter ${CMAKE_SOURCE_DIR}/scripts/gen_regmap.py ${RTL_DIR}/sc_pkg.sv --header ${GEN_DIR}/sc_regmap.h
  DEPENDS ${RTL_DIR}/sc_pkg.sv ${CMAKE_SOURCE_DIR}/scripts/gen_regmap.py
  COMMENT "sc_regmap.h from sc_pkg.sv")
add_custom_target(sc_regmap DEPENDS ${GEN_DIR}/sc_regmap.h)

# ---- model of the register file + host-side encoding ---------------------------
add_library(sc_board_model STATIC
  cmodel/axi_regs.cpp
  cmodel/reg_encode.cpp)
add_dependencies(sc_board_model sc_regmap sc_params)
target_include_directories(sc_board_model PUBLIC cmodel ${GEN_DIR})
target_link_libraries(sc_board_model PUBLIC sc_model sc_cl_model fmt::fmt)
target_compile_options(sc_board_model PRIVATE ${SC_WARN})

# ---- Verilated sc_axi_axis and sc_board_top -------------------------------------
add_library(sc_board_rtl STATIC tb/rtl_axi_axis.cpp tb/axi_bench.cpp)
target_include_directories(sc_board_rtl PUBLIC tb)
target_link_libraries(sc_board_rtl PUBLIC sc_board_model sc_cl_tb)
verilate(sc_board_rtl
  SOURCES ${SC_AXI_RTL_SOURCES}
  TOP_MODULE sc_axi_axis
  PREFIX Vsc_axi_axis
  VERILATOR_ARGS ${SC_VERILATOR_ARGS}
  OPT_FAST -O3 -fno-tree-slp-vectorize
  OPT_SLOW -O1
  OPT_GLOBAL -O3)
verilate(sc_board_rtl
  SOURCES ${SC_AXI_SERVO_RTL_SOURCES}
  TOP_MODULE sc_axi_servo
  PREFIX Vsc_axi_servo
  VERILATOR_ARGS ${SC_VERILATOR_ARGS}
  OPT_FAST -O3 -fno-tree-slp-vectorize
  OPT_SLOW -O1
  OPT_GLOBAL -O3)
verilate(sc_board_rtl
  SOURCES ${SC_BOARD_RTL_SOURCES}
  TOP_MODULE sc_board_top
  PREFIX Vsc_board_top
  VERILATOR_ARGS ${SC_VERILATOR_ARGS}
  OPT_FAST -O2
  OPT_SLOW -O1
  OPT_GLOBAL -O2)

# `scurve regs`: a planned move as register writes / UART frames
add_library(sc_regs_cli STATIC tb/regs_cli.cpp)
target_include_directories(sc_regs_cli PUBLIC tb)
target_link_libraries(sc_regs_cli PUBLIC sc_board_model sc_model sc_cl_tb nlohmann_json::nlohmann_json)
target_compile_options(sc_regs_cli PRIVATE ${SC_WARN})
target_link_libraries(scurve PRIVATE sc_regs_cli)

# ---- tests ----------------------------------------------------------------------------
add_executable(board_tests tests/test_board.cpp tests/test_board_servo.cpp)
target_link_libraries(board_tests PRIVATE sc_board_rtl sc_tb GTest::gtest_main)
target_compile_options(board_tests PRIVATE ${SC_WARN})

add_test(NAME board_axi_regs COMMAND board_tests --gtest_filter=AxiRegs.*)
add_test(NAME board_uart_bridge COMMAND board_tests --gtest_filter=BoardUart.*)
add_test(NAME board_axi_paper_group COMMAND board_tests --gtest_filter=BoardLong.*)
add_test(NAME board_axi_servo COMMAND board_tests --gtest_filter=AxiServo.*)
set_tests_properties(board_axi_regs board_uart_bridge board_axi_servo PROPERTIES TIMEOUT 600)
set_tests_properties(board_axi_paper_group PROPERTIES TIMEOUT 1800 LABELS long)

add_test(NAME regmap_docs_in_sync
  COMMAND Python3::Interpreter ${CMAKE_SOURCE_DIR}/scripts/gen_regmap.py ${RTL_DIR}/sc_pkg.sv
          --check ${CMAKE_SOURCE_DIR}/docs/regmap.md)
# the committed generated section of sc_pkg.sv and docs/regmap.md match the tags
add_test(NAME layout_in_sync
  COMMAND Python3::Interpreter ${CMAKE_SOURCE_DIR}/scripts/gen_layout.py --pkg ${RTL_DIR}/sc_pkg.sv
          --doc ${CMAKE_SOURCE_DIR}/docs/regmap.md --check)
add_test(NAME scurve_regs_cli
  COMMAND sh -c "$<TARGET_FILE:scurve> regs --distance 1000 --v-cruise 20000 --a-max 1e6 --j-max 1e9 --uart | grep -q '^A5 01 08 01 00 00 00 '")

add_test(NAME scurve_regs_cli_closed_loop
  COMMAND sh -c "$<TARGET_FILE:scurve> regs --distance 1000 --v-cruise 20000 --a-max 1e6 --j-max 1e9 --closed-loop | grep -q '^0x04 CTRL         0x00000003'")

add_test(NAME rtl_lint_board
  COMMAND verilator --lint-only -Wall ${RTL_DIR}/lint/verilator_waiver.vlt
          ${SC_BOARD_RTL_SOURCES} --top-module sc_board_top)
add_test(NAME rtl_lint_axi_servo
  COMMAND verilator --lint-only -Wall ${RTL_DIR}/lint/verilator_waiver.vlt
          ${SC_AXI_SERVO_RTL_SOURCES} --top-module sc_axi_servo)
add_test(NAME rtl_compile_icarus_board
  COMMAND iverilog -g2012 -s sc_board_top -o ${CMAKE_BINARY_DIR}/sc_board_top.vvp ${SC_BOARD_RTL_SOURCES})
# yosys synth_xilinx of the board top (no latches); the core's area budget is
# checked by synth_yosys_core (scripts/synth_yosys.sh sc_axis_core).
add_test(NAME synth_yosys
  COMMAND ${CMAKE_SOURCE_DIR}/scripts/synth_yosys.sh sc_board_top ${CMAKE_BINARY_DIR}/synth)
set_tests_properties(synth_yosys PROPERTIES TIMEOUT 600)

# Vivado is not installed here: dry-run build.tcl + the XDC under tclsh with
# stubbed Vivado commands, and check build.tcl's file list against rtl_deps.py.
find_program(SC_TCLSH tclsh)
if(SC_TCLSH)
  add_test(NAME vivado_flow_dry_run
    COMMAND ${CMAKE_SOURCE_DIR}/scripts/vivado/check_flow.sh ${CMAKE_BINARY_DIR}/vivado-dry-run)
endif()
