# The tool tests: CLI contracts, output files, trace diff, regression runner,
# the parsers and their fuzz corpora. Included by tests/CMakeLists.txt and by
# the sanitizer build's tests/sanitize/CMakeLists.txt, which runs them under
# ASan+UBSan; names are <area>.<what>, labelled by area.
set(SC_TESTS_DIR ${PROJECT_SOURCE_DIR}/tests)
# Debian's python3 (python3-matplotlib lives there, not in a pyenv python).
find_program(SC_SYSTEM_PYTHON python3 PATHS /usr/bin NO_DEFAULT_PATH REQUIRED)

add_executable(tools_tests ${SC_TESTS_DIR}/tools/test_tools.cpp)
target_link_libraries(tools_tests PRIVATE sc_tools GTest::gtest_main)
target_compile_definitions(tools_tests PRIVATE
  SC_BENCH="$<TARGET_FILE:sc_bench>" SCURVE="$<TARGET_FILE:scurve>" SOURCE_DIR="${PROJECT_SOURCE_DIR}")
add_dependencies(tools_tests sc_bench scurve)
gtest_discover_tests(tools_tests TEST_FILTER "-ScBench.*" TEST_PREFIX "tools." DISCOVERY_TIMEOUT 120
                     PROPERTIES LABELS tools TIMEOUT 600)
gtest_discover_tests(tools_tests TEST_FILTER "ScBench.*" TEST_PREFIX "systemc." DISCOVERY_TIMEOUT 120
                     PROPERTIES LABELS systemc TIMEOUT 600)

# The parsers of user and list-author files (no binaries needed) and their
# fuzz corpora (libFuzzer harnesses in the sanitizer build).
add_executable(parser_tests ${SC_TESTS_DIR}/tools/test_parsers.cpp)
target_link_libraries(parser_tests PRIVATE sc_parsers sc_scenario GTest::gtest_main)
target_compile_definitions(parser_tests PRIVATE SOURCE_DIR="${PROJECT_SOURCE_DIR}")
gtest_discover_tests(parser_tests TEST_PREFIX "tools." DISCOVERY_TIMEOUT 120 PROPERTIES LABELS tools TIMEOUT 600)
add_subdirectory(${SC_TESTS_DIR}/fuzz ${CMAKE_CURRENT_BINARY_DIR}/fuzz)

add_test(NAME tools.cli_contract COMMAND ${SC_TESTS_DIR}/cli_test.sh $<TARGET_FILE:scurve>)
add_test(NAME tools.cli_contract_closed_loop
  COMMAND ${SC_TESTS_DIR}/cl_cli_test.sh $<TARGET_FILE:scurve> ${PROJECT_SOURCE_DIR})
add_test(NAME tools.cli_bad_input_closed_loop
  COMMAND ${SC_TESTS_DIR}/cl_bad_input_test.sh $<TARGET_FILE:scurve>)
add_test(NAME tools.cli_clock_hz COMMAND ${PROJECT_SOURCE_DIR}/sw/tests/cli_clock_test.sh $<TARGET_FILE:scurve> sim)
add_test(NAME tools.regs_cli_uart_frames
  COMMAND sh -c "$<TARGET_FILE:scurve> regs --distance 1000 --v-cruise 20000 --a-max 1e6 --j-max 1e9 --uart | grep -q '^A5 01 02 01 00 00 00 [0-9A-F][0-9A-F]  # CMD (0x008) = 0x00000001$'")
add_test(NAME tools.regs_cli_closed_loop
  COMMAND sh -c "$<TARGET_FILE:scurve> regs --distance 1000 --v-cruise 20000 --a-max 1e6 --j-max 1e9 --closed-loop | grep -q '^0x004 CTRL         0x00000003'")
# The pin-accurate bench (per-clock SystemC scheduling) is left out of the
# sanitizer build: a short move takes a minute there.
set(pin_bench $<TARGET_FILE:sc_bench_pin>)
if(SC_SANITIZE)
  set(pin_bench)
endif()
add_test(NAME tools.output_files_whole_or_refused
  COMMAND ${SC_TESTS_DIR}/output_files_test.sh $<TARGET_FILE:scurve> $<TARGET_FILE:sc_bench> ${pin_bench})
add_test(NAME tools.board_driver_over_a_pty
  COMMAND ${SC_TESTS_DIR}/board_pty_test.sh $<TARGET_FILE:scurve> ${PROJECT_SOURCE_DIR})
add_test(NAME tools.board_driver_drives_the_two_axis_board_over_a_pty
  COMMAND ${SC_TESTS_DIR}/board_pty_test.sh $<TARGET_FILE:scurve> ${PROJECT_SOURCE_DIR} xy)
add_test(NAME tools.regress_shards_cover_list
  COMMAND ${SC_SYSTEM_PYTHON} ${SC_TESTS_DIR}/systemc/check_regress.py shards $<TARGET_FILE:scurve>
          ${SC_TESTS_DIR}/systemc/shard_list.json ${CMAKE_BINARY_DIR}/regress-shards)
set_tests_properties(tools.cli_contract tools.cli_contract_closed_loop tools.cli_bad_input_closed_loop tools.cli_clock_hz
                     tools.regs_cli_uart_frames tools.regs_cli_closed_loop tools.output_files_whole_or_refused
                     tools.regress_shards_cover_list tools.board_driver_over_a_pty
                     tools.board_driver_drives_the_two_axis_board_over_a_pty PROPERTIES LABELS tools TIMEOUT 600)
# Paper 000's group 1 over the pseudo-terminal: 278 M clocks of the board
# top (almost 4 minutes): label long (the nightly size), as the lockstep
# benches of the paper groups; not in the sanitizer build.
if(NOT SC_SANITIZE)
  add_test(NAME tools.board_paper_group_over_a_pty
    COMMAND ${SC_TESTS_DIR}/board_pty_test.sh $<TARGET_FILE:scurve> ${PROJECT_SOURCE_DIR} paper)
  set_tests_properties(tools.board_paper_group_over_a_pty PROPERTIES LABELS "tools;long" TIMEOUT 2400)
endif()
# Under the sanitizers its bench runs take minutes (about 250 s in all). In
# the default build it is an `extended` test (CI's stage after the default
# suite), since it runs there anyway, instrumented.
set_tests_properties(tools.output_files_whole_or_refused PROPERTIES TIMEOUT 1800)
# The CLI contract's lockstep runs take about ten times their release time
# under the sanitizers (65 s release, more than 600 s instrumented).
if(SC_SANITIZE)
  set_tests_properties(tools.cli_contract PROPERTIES TIMEOUT 1800)
endif()
# The `extended` tier of the default build (CI runs it after the default
# suite): the output-file checks, the whole CLI contract (about 90 s; the
# default suite keeps the closed-loop CLI contract and the bad-input tests)
# and the host driver against the virtual boards over a pty (about 60 s and
# 40 s; board.BoardUart.* and board.BoardXY.* send the same frames).
if(NOT SC_SANITIZE)
  set_tests_properties(tools.output_files_whole_or_refused tools.cli_contract tools.board_driver_over_a_pty
                       tools.board_driver_drives_the_two_axis_board_over_a_pty
                       PROPERTIES LABELS "tools;extended" COST 1000)
endif()
# The tests the sanitizer stage runs again with the same command and files,
# instrumented: labelled `sanitized` in the default build, so that CI's
# release run (scripts/test.sh with SC_SANITIZE=1) leaves them to that stage
# instead of running them twice. A plain ctest run, any tier, still runs them.
set(SC_SANITIZED_TESTS tools.cli_contract tools.cli_contract_closed_loop tools.cli_bad_input_closed_loop
    tools.cli_clock_hz tools.regs_cli_uart_frames tools.regs_cli_closed_loop tools.regress_shards_cover_list
    tools.board_driver_over_a_pty tools.board_driver_drives_the_two_axis_board_over_a_pty)
if(NOT SC_SANITIZE)
  foreach(name IN LISTS SC_SANITIZED_TESTS)
    set_property(TEST ${name} APPEND PROPERTY LABELS sanitized)
  endforeach()
endif()
