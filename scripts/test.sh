#!/usr/bin/env bash
# The test command: install what is missing, build, run the default ctest
# suite (the short and directed runs of every area: not the `extended` or the
# nightly-size `long` tests). Writes build/test-results.xml (JUnit). With
# SC_SANITIZE=1 (CI) the same ctest run takes the `extended` tests too (one
# run keeps both cores busy to its end) and leaves out the `sanitized` ones
# (the tool scripts the sanitizer stage runs again, instrumented), then come the RTL
# line and cover-point floors on the CI selection (label coverage_ci: build/cov-ci/,
# build/coverage-ci.json, build/test-results-coverage.xml), builds the
# sanitizer configuration (build-san/: clang, ASan + UBSan; the Verilated
# RTL compiled uninstrumented) and runs its suite: the unit tests, the tool
# tests, the fuzz corpora and a 10 s fuzz run per harness
# (build-san/test-results.xml). Arguments replace the default selection and
# go to the first ctest only (no further stage), e.g.
#   scripts/test.sh -L long  or  scripts/test.sh -L core
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
# Each stage's start and the time spent so far, for the CI log.
stage() { echo "== test.sh: $1 (at $((SECONDS / 60)) min $((SECONDS % 60)) s)"; }
stage "build"
"$here/scripts/build.sh"
cd "$here/build"
if [ $# -gt 0 ]; then
  exec ctest --output-on-failure -j"$(nproc)" --output-junit test-results.xml "$@"
fi
rc=0
if [ "${SC_SANITIZE:-0}" != "1" ]; then
  stage "default suite"
  ctest --output-on-failure -j"$(nproc)" --output-junit test-results.xml -LE '^(long|extended)$' || rc=$?
else
  stage "default suite and extended tests"
  ctest --output-on-failure -j"$(nproc)" --output-junit test-results.xml -LE '^(long|sanitized)$' || rc=$?
  stage "coverage floors"
  ctest --output-on-failure --output-junit test-results-coverage.xml -L '^coverage_ci$' || rc=$?
  stage "sanitizer build"
  "$here/scripts/build.sh" --sanitize
  cd "$here/build-san"
  # Stop at the first report; leaks count (LeakSanitizer).
  export ASAN_OPTIONS=abort_on_error=1:detect_leaks=1:strict_string_checks=1
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  stage "sanitizer suite"
  ctest --output-on-failure -j"$(nproc)" --output-junit test-results.xml -LE long || rc=$?
fi
stage "done, exit $rc"
exit "$rc"
