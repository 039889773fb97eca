#!/usr/bin/env bash
# The GTKWave save files (docs/waves/) against real traces: every signal they
# show exists in the FST that scurve writes for the open-loop core and for
# the closed-loop servo axis.
#   tests/waves_test.sh <scurve> <source dir>
set -euo pipefail
scurve=$(realpath "$1") src=$(realpath "$2")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
move="--distance 300 --v-cruise 3000 --a-max 50000 --j-max 500000"
"$scurve" sim $move --fst "$tmp/open.fst" --fst-to 20000 > /dev/null
"$scurve" sim $move --closed-loop --fst "$tmp/closed.fst" --fst-to 20000 > /dev/null
python3 "$src/scripts/check_gtkw.py" "$src/docs/waves/sc_axis_core.gtkw" "$tmp/open.fst"
python3 "$src/scripts/check_gtkw.py" "$src/docs/waves/sc_servo_axis.gtkw" "$tmp/closed.fst"
