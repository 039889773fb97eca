#!/usr/bin/env bash
# The main job: the four paper groups (paper 000 Table 2: L = 30,000 pulses,
# a = 500 pulses/s^2, j = 2500 pulses/s^3) in full at 20 MHz, RTL and model
# in lockstep, results table on stdout and build/paper_groups.json.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
"$here/scripts/build.sh"
exec "$here/build/bin/scurve" sim --group 1 2 3 4 --json-out "$here/build/paper_groups.json" "$@"
