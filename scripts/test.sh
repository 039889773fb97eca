#!/usr/bin/env bash
# The test command: install what is missing, build, run the default ctest
# suite (unit tests, lockstep RTL runs, the four paper groups, lint, Icarus,
# yosys). Writes build/test-results.xml (JUnit). Extra args go to ctest,
# e.g. scripts/test.sh -L long   (the long label: nightly-size campaigns).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
"$here/scripts/build.sh"
cd "$here/build"
ctest --output-on-failure -j"$(nproc)" --output-junit test-results.xml -LE long "$@"
