#!/usr/bin/env bash
# Run the RTL regression: every test of tests/regress_list.json through the
# SystemC bench, in parallel, with a summary table, JUnit XML and JSON in
# build/regress/ (arguments are passed to `scurve regress`, for example
# --shard 1/2, --label quick, --jobs 1, --rerun-failing-with-waves).
# Builds first if needed. Slurm array job: see README "Regression".
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
if [ ! -x "$build/bin/scurve" ] || [ ! -x "$build/bin/sc_bench" ]; then
  cmake -S . -B "$build" >/dev/null
  cmake --build "$build" -j"${BUILD_JOBS:-2}" --target scurve sc_bench
fi
exec "$build/bin/scurve" regress --list tests/regress_list.json --out-dir "$build/regress" "$@"
