#!/usr/bin/env bash
# scurve sim --closed-loop: scenario file, JSON metric names, weight CSV,
# bad input (exit 2, one line naming the parameter).
set -euo pipefail
scurve=$1; src=$2; out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
move="--distance 1500 --v-start 0 --v-cruise 3000 --v-end 0 --a-max 20000 --j-max 400000"
"$scurve" sim --closed-loop $move --engine lockstep --scenario "$src/tb/scenarios/nema23_1000line.json" \
  --json --weights-csv "$out/w.csv" --json-out "$out/r2.json" > "$out/r.json"
cmp -s "$out/r.json" "$out/r2.json" || { echo "FAIL: --json-out differs from the printed JSON"; exit 1; }
python3 - "$out/r.json" "$out/w.csv" <<'PY'
import json, sys, csv
r = json.load(open(sys.argv[1]))
assert r["pass"], r
run = r["runs"][0]
for k in ["max_tracking_error", "rmse", "relative_error", "final_error", "positioning_accuracy",
          "settle_time_s", "peak_jerk_encoder", "mismatches", "clocks_per_s"]:
    assert k in run, k
assert run["mismatches"] == 0 and run["final_error"] == 0 and run["positioning_accuracy"] == 1.0
rows = list(csv.reader(open(sys.argv[2])))
assert rows[0][:5] == ["t_s", "w_p1", "w_p2", "w_v1", "w_v2"], rows[0]
assert len(rows) > 50
PY
set +e
"$scurve" sim --closed-loop $move --ctl-rate 50 2> "$out/err.txt"; rc=$?
set -e
[ "$rc" = 2 ] || { echo "bad --ctl-rate: exit $rc, want 2"; exit 1; }
grep -q "ctl-rate" "$out/err.txt" || { echo "error line does not name ctl-rate"; cat "$out/err.txt"; exit 1; }
[ "$(wc -l < "$out/err.txt")" = 1 ] || { echo "more than one error line"; exit 1; }
echo "closed-loop CLI ok"
