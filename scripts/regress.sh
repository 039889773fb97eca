#!/usr/bin/env bash
# Run the RTL regression: every test of tests/regress_list.json through the
# SystemC bench, in parallel, with a summary table, JUnit XML and JSON in
# build/regress/. Arguments go to `scurve regress`, for example --shard 1/2,
# --label quick, --exclude-label long, --jobs 1, --rerun-failing-with-waves,
# --out-dir DIR. Builds first (scripts/build.sh) when the binaries are missing.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$here/build}
if [ ! -x "$build/bin/scurve" ] || [ ! -x "$build/bin/sc_bench" ]; then
  "$here/scripts/build.sh"
fi
exec "$build/bin/scurve" regress --list "$here/tests/regress_list.json" --out-dir "$build/regress" "$@"
