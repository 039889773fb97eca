# RTL coverage closure (scripts/coverage.py), inside this build tree.
# The full measure: two builds (cov-line: line and user points over the
# default suite; cov-toggle: toggle points over its short runs), merged and
# held to the floors (95 % line, 90 % toggle, every cover point). Label
# `coverage` and `long`, so the default suite leaves it out.
add_test(NAME coverage.floors_hold_over_the_default_regression
  COMMAND Python3::Interpreter ${PROJECT_SOURCE_DIR}/scripts/coverage.py --build-dir ${CMAKE_BINARY_DIR}/cov
          --json ${CMAKE_BINARY_DIR}/coverage.json)
set_tests_properties(coverage.floors_hold_over_the_default_regression PROPERTIES LABELS "coverage;long" TIMEOUT 5400)
# The CI stage: one build with line and user points, the tests of
# scripts/coverage_ci.json (a subset of the default suite, so its figures are
# lower bounds of the regression's). Label `coverage_ci` (and `long`). Toggle
# points make that build and its runs about 35 minutes on two cores instead of
# about 12: the toggle floor is held by the same selection with every kind
# (label `long`) and by the full measure above.
add_test(NAME coverage.floors_hold_on_the_ci_selection
  COMMAND Python3::Interpreter ${PROJECT_SOURCE_DIR}/scripts/coverage.py --profile ci --kinds line,user
          --build-dir ${CMAKE_BINARY_DIR}/cov --json ${CMAKE_BINARY_DIR}/coverage-ci.json)
set_tests_properties(coverage.floors_hold_on_the_ci_selection PROPERTIES LABELS "coverage_ci;long" TIMEOUT 3600)
add_test(NAME coverage.toggle_floor_holds_on_the_ci_selection
  COMMAND Python3::Interpreter ${PROJECT_SOURCE_DIR}/scripts/coverage.py --profile ci
          --build-dir ${CMAKE_BINARY_DIR}/cov-all --json ${CMAKE_BINARY_DIR}/coverage-ci-all.json)
set_tests_properties(coverage.toggle_floor_holds_on_the_ci_selection PROPERTIES LABELS "coverage;long" TIMEOUT 5400)
