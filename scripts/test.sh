#!/usr/bin/env bash
# The test command: install what is missing, build, run the default ctest
# suite (every area except the nightly-size `long` campaigns). Writes
# build/test-results.xml (JUnit). Arguments replace the default selection and
# go to ctest, e.g. scripts/test.sh -L long  or  scripts/test.sh -L core
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
"$here/scripts/build.sh"
cd "$here/build"
if [ $# -eq 0 ]; then set -- -LE long; fi
ctest --output-on-failure -j"$(nproc)" --output-junit test-results.xml "$@"
