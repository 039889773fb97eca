add_test([=[FixedPoint.ChooseMatchesDefinition]=]  /work/main/build/bin/unit_tests [==[--gtest_filter=FixedPoint.ChooseMatchesDefinition]==] --gtest_also_run_disabled_tests)
set_tests_properties([=[FixedPoint.ChooseMatchesDefinition]=]  PROPERTIES WORKING_DIRECTORY /work/main/build/tests SKIP_REGULAR_EXPRESSION [==[\[  SKIPPED \]]==])
set(  unit_tests_TESTS FixedPoint.ChooseMatchesDefinition)
