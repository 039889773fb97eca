# RTL coverage closure: scripts/coverage.py builds the two coverage
# configurations inside this build tree (cov-line: line and user points over
# the default suite; cov-toggle: toggle points over its short runs), merges
# them and holds the floors (95 % line, 90 % toggle, every cover point).
# Label `coverage` and `long`, so the default suite leaves it out.
add_test(NAME coverage.floors_hold_over_the_default_regression
  COMMAND Python3::Interpreter ${PROJECT_SOURCE_DIR}/scripts/coverage.py --build-dir ${CMAKE_BINARY_DIR}/cov
          --json ${CMAKE_BINARY_DIR}/coverage.json)
set_tests_properties(coverage.floors_hold_over_the_default_regression PROPERTIES LABELS "coverage;long" TIMEOUT 5400)
