#!/usr/bin/env bash
# CLI contract: JSON fields, exit code 2 with one stderr line naming the
# parameter on bad input, a passing lockstep sim of a short move.
set -euo pipefail
scurve=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

"$scurve" plan --distance 30000 --v-start 1500 --v-cruise 3000 --v-end 0 --a-max 500 --j-max 2500 --json > "$tmp/plan.json"
python3 - "$tmp/plan.json" <<'PY'
import json, sys
p = json.load(open(sys.argv[1]))
for k in ("duration_s", "pulses", "peak_velocity", "peak_acceleration", "peak_jerk", "segments"):
    assert k in p, k
assert p["pulses"] == 30000
assert len(p["segments"]) == 7, len(p["segments"])
assert abs(p["peak_velocity"] - 3000) < 1e-3 and p["peak_acceleration"] <= 500 and p["peak_jerk"] <= 2500
PY

check_bad() {  # expected-parameter, args...
  local param=$1; shift
  set +e
  "$scurve" "$@" > "$tmp/out" 2> "$tmp/err"
  local rc=$?
  set -e
  [ "$rc" -eq 2 ] || fail "$* -> exit $rc, want 2"
  [ "$(wc -l < "$tmp/err")" -eq 1 ] || fail "$* -> stderr is not one line: $(cat "$tmp/err")"
  grep -q -- "$param" "$tmp/err" || fail "$* -> stderr does not name $param: $(cat "$tmp/err")"
}
check_bad distance plan --distance 0 --v-cruise 100 --a-max 500 --j-max 2500
check_bad v_cruise plan --distance 100 --v-cruise 1e6 --a-max 500 --j-max 2500
check_bad v_end plan --distance 5000 --v-cruise 3000 --v-end 3000 --a-max 500 --j-max 2500
check_bad a_max sim --distance 100 --v-cruise 100 --a-max -5 --j-max 2500
check_bad distance plan --distance abc --v-cruise 100 --a-max 500 --j-max 2500
check_bad group sim --group 7
# Numbers are decimal: no octal, hex, nan or inf reading, and the value as given.
check_bad "distance=0100" plan --distance 0100 --v-cruise 100 --a-max 500 --j-max 2500
check_bad "distance=09" plan --distance 09 --v-cruise 100 --a-max 500 --j-max 2500
check_bad "distance=18446744073709551616" plan --distance 18446744073709551616 --v-cruise 100 --a-max 500 --j-max 2500
check_bad "pulse-high=010" regs --distance 100 --v-cruise 100 --a-max 500 --j-max 2500 --pulse-high 010
check_bad "v-start=0x10" plan --distance 100 --v-start 0x10 --v-cruise 100 --a-max 500 --j-max 2500
check_bad "v-cruise=nan" plan --distance 100 --v-cruise nan --a-max 500 --j-max 2500
check_bad "v_start=200000.0001" plan --distance 100 --v-start 200000.0001 --v-cruise 1000 --a-max 1000 --j-max 10000
# Missing or meaningless flags are named, not defaulted or ignored.
check_bad "distance: required" plan --v-cruise 100 --a-max 500 --j-max 2500
check_bad "distance: required" sim --v-cruise 100 --a-max 500 --j-max 2500
check_bad "v-start='': required" plan --distance 100 --v-start "" --v-cruise 100 --a-max 500 --j-max 2500
check_bad "jerks" plan --distance 100 --v-cruise 100 --a-max 500 --profile trapezoid --jerks 1 2 3 4
check_bad "frob: unknown command (commands: plan" frob
check_bad "group=010" sim --group 010
check_bad "jobs=0x2" sim --group 1 --jobs 0x2
check_bad "clock-hz=0x10" plan --distance 100 --v-cruise 100 --a-max 500 --j-max 2500 --clock-hz 0x10
check_bad "context=-1" diff a.csv b.csv --context -1
check_bad "shard=01" regress --shard 01/2 --list-only
check_bad "json-out=$tmp: is a directory" plan --distance 100 --v-cruise 100 --a-max 500 --j-max 2500 --json-out "$tmp"
# "--flag=" is an empty value (never the next argument); a switch given a
# value is refused showing the value.
check_bad "distance=''" plan --distance= --v-cruise 100 --a-max 500 --j-max 2500
check_bad "distance=''" plan --distance= 100 --v-cruise 100 --a-max 500 --j-max 2500
check_bad "json=false: a switch takes no value" plan --distance 100 --v-cruise 100 --a-max 500 --j-max 2500 --json=false
# Soft limits: the window flags are decimal integers, min <= max; a target
# beyond the window is refused naming the axis, the target and the limit
# (sim plans through the same flags); a target on the limit is planned and
# the JSON reports the window and the target.
check_bad "soft-max=abc: must be an integer in" plan --distance 100 --v-cruise 100 --a-max 500 --j-max 2500 --soft-max abc
check_bad "soft-min=5: must be <= soft-max=1" plan --distance 100 --v-cruise 100 --a-max 500 --j-max 2500 \
  --soft-min 5 --soft-max 1
check_bad "start-pos=0x10" plan --distance 100 --v-cruise 100 --a-max 500 --j-max 2500 --start-pos 0x10
check_bad "axis=a b: must be 1 to 32 characters" plan --distance 100 --v-cruise 100 --a-max 500 --j-max 2500 \
  --soft-max 10 --axis "a b"
check_bad "axis x: target position 1200 is beyond soft limit max=1000 pulses (start 200, distance +1000)" \
  plan --distance 1000 --v-cruise 3000 --a-max 500 --j-max 2500 --start-pos 200 --soft-max 1000
check_bad "axis z: target position -1 is beyond soft limit min=0 pulses" \
  sim --distance -11 --v-cruise 3000 --a-max 500 --j-max 2500 --start-pos 10 --soft-min 0 --axis z
"$scurve" plan --distance 1000 --v-cruise 3000 --a-max 500 --j-max 2500 --start-pos 200 --soft-max 1200 --json \
  > "$tmp/plan_window.json"
python3 - "$tmp/plan_window.json" <<'PY'
import json, sys
p = json.load(open(sys.argv[1]))
assert p["pulses"] == 1000 and p["start_position"] == 200 and p["target_position"] == 1200, p
assert p["soft_limits"] == {"axis": "x", "min": None, "max": 1200}, p["soft_limits"]
PY

# --json-out: regs writes its JSON too; a failed write (file-size limit) is
# exit 2 and leaves no partial file.
"$scurve" regs --distance 1000 --v-cruise 20000 --a-max 1e6 --j-max 1e9 --json-out "$tmp/regs.json" > /dev/null
python3 -c 'import json,sys; w=json.load(open(sys.argv[1])); assert len(w) > 10 and w[0]["reg"], w' "$tmp/regs.json"
set +e
(ulimit -f 1; "$scurve" plan --distance 30000 --v-cruise 3000 --a-max 500 --j-max 2500 --json-out "$tmp/big.json" \
  > /dev/null 2> "$tmp/err")
rc=$?
set -e
[ "$rc" -eq 2 ] || fail "--json-out under a file-size limit -> exit $rc, want 2"
[ ! -e "$tmp/big.json" ] && [ ! -e "$tmp/big.json.part" ] || fail "--json-out left a partial file"

out=$("$scurve" sim --distance 300 --v-cruise 20000 --a-max 200000 --j-max 2e7)
echo "$out" | grep -q PASS || fail "short sim did not pass: $out"
"$scurve" sim --distance -300 --v-cruise 20000 --a-max 200000 --j-max 2e7 --json > "$tmp/sim.json"
python3 - "$tmp/sim.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
for k in ("clocks", "pulses", "duration_s", "final_error", "peak_velocity", "peak_acceleration",
          "peak_jerk", "mismatches", "wall_s", "clocks_per_s", "pass"):
    assert k in r, k
assert r["pulses"] == -300 and r["final_error"] == 0 and r["mismatches"] == 0 and r["pass"]
PY
# --stop-at: a controlled stop mid-move; every engine ends at the same
# position short of the target, at rest, and the regs sequence ends in
# CMD.STOP marked with its time.
move="--distance 4000 --v-cruise 40000 --a-max 2e6 --j-max 4e8"
for engine in lockstep model-fast; do
  "$scurve" sim $move --stop-at 0.03 --engine $engine --json > "$tmp/stop_$engine.json"
done
python3 - "$tmp/stop_lockstep.json" "$tmp/stop_model-fast.json" <<'PY'
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
for r in (a, b):
    s = r["stop"]
    assert r["pass"] and s["taken"] and not s["overshoot"], r
    assert 0 < s["end_position"] < 4000 and r["pulses"] == s["end_position"] and r["final_error"] == 0, r
    assert abs(s["distance"] - s["closed_form_distance"]) < 1, s
    assert s["v0"] > 0 and s["at_clock"] == 600000, s
assert a["stop"]["end_position"] == b["stop"]["end_position"], (a["stop"], b["stop"])
assert a["mismatches"] == 0 and a["matched_clocks"] > 0
PY
"$scurve" regs $move --stop-at 0.03 --stop-jerk 1e9 --json > "$tmp/stop_regs.json"
python3 - "$tmp/stop_regs.json" <<'PY'
import json, sys
w = json.load(open(sys.argv[1]))
assert w[-1]["reg"] == "CMD" and w[-1]["data"] == 2 and w[-1]["at_clock"] == 600000, w[-1]
assert w[-2]["reg"] == "CMD" and w[-2]["data"] == 1, w[-2]
names = [x["reg"] for x in w]
assert names.index("STOP_JERK_0") < names.index("ROW_PUSH"), names
assert not any(n.startswith("GUARD") for n in names), names
PY
# --guard: the row guards from the move's own limits, rounded up (at most a
# relative 2^-50 above the exact value), after the stop limits and before
# the table.
"$scurve" regs --distance 4000 --v-cruise 40000 --a-max 2e6 --j-max 4e8 --guard --json > "$tmp/guard_regs.json"
python3 - "$tmp/guard_regs.json" <<'PY'
import json, sys
w = json.load(open(sys.argv[1]))
names = [x["reg"] for x in w]
val = lambda base, n: sum(w[names.index(f"{base}_{i}")]["data"] << (32 * i) for i in range(n))
def up(got, num, den):
    exact = -(-num // den)
    assert exact <= got <= exact + (exact >> 49) + 1, (got, exact)
up(val("GUARD_VEL", 3), 2**80, 500)                 # 40000 / 20e6 pulses per clock
up(val("GUARD_ACC", 2), 2**80, 200_000_000)         # 2e6 / 20e6^2
up(val("GUARD_JERK", 2), 2**80, 20_000_000_000_000)  # 4e8 / 20e6^3
assert names.index("STOP_ACC_1") < names.index("GUARD_VEL_0") < names.index("ROW_PUSH"), names
PY
# --stop-at on the closed-loop axis: the reference stops under control, the
# controller settles where it came to rest, in position, RTL = model.
"$scurve" sim --distance 1200 --v-cruise 3000 --a-max 20000 --j-max 400000 --closed-loop --stop-at 0.2 \
  --json > "$tmp/stop_closed_loop.json"
python3 - "$tmp/stop_closed_loop.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))["runs"][0]
s = r["stop"]
assert r["pass"] and r["in_position"] and r["mismatches"] == 0, r
assert s["taken"] and 0 < s["end_position"] < 1200 and r["target"] == s["end_position"], s
assert r["final_error"] == 0 and abs(s["distance"] - s["closed_form_distance"]) < 1, (r["final_error"], s)
PY
check_bad "stop-at=0.5: must be below the move's duration" sim $move --stop-at 0.5
check_bad "stop-at=-1" sim $move --stop-at -1
check_bad "stop-jerk" sim $move --stop-at 0.01 --stop-jerk 0
check_bad "stop-acc" regs $move --stop-acc 1e300
check_bad "stop-at" regs $move --stop-at 0.01 --no-start
check_bad "checked on the model" sim $move --stop-at 0.01 --closed-loop --engine rtl
# scurve stream: the example stream (a junction limit, a direction change)
# ends every move on the running sum, faster than stopping at every
# junction, with the same boundaries on lockstep and model-fast; bad stream
# files are exit 2 naming the place.
example="$(dirname "$0")/streams/example.json"
"$scurve" stream "$example" --json > "$tmp/stream_lockstep.json"
"$scurve" stream "$example" --engine model-fast --json > "$tmp/stream_fast.json"
python3 - "$tmp/stream_lockstep.json" "$tmp/stream_fast.json" <<'PY'
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
for r in (a, b):
    assert r["pass"] and r["move_count"] == 4 and r["pulses"] == 2700, r
    ends = [m["end_position"] for m in r["moves"]]
    assert ends == [1000, 1500, 3500, 2700] == [m["expected_end_position"] for m in r["moves"]], ends
    assert r["moves"][0]["v_out"] > 0, "a nonzero junction speed"
    assert r["moves"][2]["v_out"] == 0, "zero at the direction change"
    assert 0 < r["moves"][1]["v_out"] <= 5000, "the junction limit of the third move"
    assert r["duration_s"] < r["stop_at_every_junction_s"], r
assert a["mismatches"] == 0 and a["matched_clocks"] > 0
assert [m["end_clock"] for m in a["moves"]] == [m["end_clock"] for m in b["moves"]]
PY
printf '{"limits": {"a_max": 2e5, "j_max": 2e7, "v_max": 2e4}, "moves": [{"distance": 5, "v_cruise": 100}, {"distance": 5, "v_cruise": "fast"}]}' > "$tmp/s1.json"
check_bad "moves\[1\].v_cruise" stream "$tmp/s1.json"
printf '{"limits": {"a_max": 2e5, "j_max": 2e7, "v_max": 2e4}, "moves": [{"distance": 5, "v_cruse": 100}]}' > "$tmp/s2.json"
check_bad "v_cruse" stream "$tmp/s2.json"
printf '{"limits": {"a_max": 2e5, "v_max": 2e4}, "moves": [{"distance": 5, "v_cruise": 100}]}' > "$tmp/s3.json"
check_bad "limits.j_max" stream "$tmp/s3.json"
printf '{"limits": {"a_max": 2e5, "j_max": 2e7, "v_max": 2e4}, "moves": [{"distance": 5, "v_cruise": 5e4}]}' > "$tmp/s4.json"
check_bad "moves\[0\]" stream "$tmp/s4.json"
printf '{"limits": {"a_max": 2e5, "j_max": 2e7, "v_max": 2e4}, "moves": [' > "$tmp/s5.json"
check_bad "not JSON" stream "$tmp/s5.json"
check_bad "FILE=$tmp/none.json: cannot read" stream "$tmp/none.json"
check_bad "no fast-forward" stream "$example" --closed-loop --engine model-fast
# A stream's window: the running sum from start_position must stay inside.
window='"start_position": 100, "soft_limits": {"min": 0, "max": MAX, "axis": "y"}'
printf '{"limits": {"a_max": 2e5, "j_max": 2e7, "v_max": 2e4}, %s, "moves": [{"distance": 1000, "v_cruise": 2e4}, {"distance": 2500, "v_cruise": 2e4}, {"distance": -3600, "v_cruise": 2e4}]}' \
  "${window/MAX/3600}" > "$tmp/s6.json"
"$scurve" stream "$tmp/s6.json" --engine model-fast > /dev/null || fail "a stream inside its window was refused"
printf '{"limits": {"a_max": 2e5, "j_max": 2e7, "v_max": 2e4}, %s, "moves": [{"distance": 1000, "v_cruise": 2e4}, {"distance": 2500, "v_cruise": 2e4}]}' \
  "${window/MAX/3599}" > "$tmp/s7.json"
check_bad "moves\[1\]: axis y: move 1: target position 3600 is beyond soft limit max=3599" stream "$tmp/s7.json"
printf '{"limits": {"a_max": 2e5, "j_max": 2e7, "v_max": 2e4}, "soft_limits": {"min": 5, "max": 1}, "moves": [{"distance": 5, "v_cruise": 100}]}' > "$tmp/s8.json"
check_bad "soft_limits.min=5: must be <= soft_limits.max=1" stream "$tmp/s8.json"
# scurve stream --closed-loop: the closed-loop example ends every move on the
# running sum, in position; its reference reaches every boundary at the same
# clock as the open-loop core's (the reference does not depend on the loop).
cl_example="$(dirname "$0")/streams/closed_loop.json"
"$scurve" stream "$cl_example" --closed-loop --engine model --json > "$tmp/stream_cl.json"
"$scurve" stream "$cl_example" --engine model-fast --json > "$tmp/stream_ol.json"
python3 - "$tmp/stream_cl.json" "$tmp/stream_ol.json" <<'PY'
import json, sys
c, o = (json.load(open(f)) for f in sys.argv[1:3])
assert c["pass"] and c["closed_loop"]["in_position"] and c["closed_loop"]["final_error"] == 0, c
assert o["closed_loop"] is None
ends = [m["end_position"] for m in c["moves"]]
assert ends == [800, 1400, 2900, 2000] == [m["expected_end_position"] for m in c["moves"]], ends
assert [m["end_clock"] for m in c["moves"]] == [m["end_clock"] for m in o["moves"]], (c["moves"], o["moves"])
PY
# scurve regs with a window: the hardware soft limits are written too (SOFT_EN
# in SW_CFG); a bound beyond REF_POS's 32 bits is exit 2 naming it.
"$scurve" regs --distance 1000 --v-cruise 3000 --a-max 500 --j-max 2500 --start-pos -200 --soft-min -500 --soft-max 900 --json > "$tmp/regs_soft.json"
python3 - "$tmp/regs_soft.json" <<'PY'
import json, sys
w = {x["reg"]: x["data"] for x in json.load(open(sys.argv[1]))}
assert w["SOFT_MIN"] == (-500) & 0xffffffff and w["SOFT_MAX"] == 900, w
assert w["SW_CFG"] & (1 << 6) and w["SW_CFG"] & (1 << 4), w
PY
check_bad "soft_limits.max_pos=5000000000" regs --distance 1000 --v-cruise 3000 --a-max 500 --j-max 2500 --soft-max 5000000000
# scurve home: the defaults home in lockstep onto the switch's release point;
# a latch speed past the exact bound still homes, to a zero that is off by
# the steps of the filter's latency; bad input names the field.
"$scurve" home --runs 2 --json > "$tmp/home.json"
"$scurve" home --engine model --seek-speed 150000 --latch-speed 100000 --a-max 1e7 --j-max 1e10 --json > "$tmp/home_fast.json"
python3 - "$tmp/home.json" "$tmp/home_fast.json" <<'PY'
import json, sys
h, f = (json.load(open(p)) for p in sys.argv[1:3])
assert h["pass"] and h["engine"] == "lockstep" and h["spread"] == 0 and h["zero_expected_exact"], h
for r in h["runs"]:
    assert r["home_ref"] == r["release_point"] and r["pins"] == r["ref_pos"], r
    assert r["matched_clocks"] == r["clocks"], r
assert f["pass"] and not f["zero_expected_exact"] and f["runs"][0]["zero_error"] > 0, f
PY
check_bad seek_speed home --seek-speed 1e7
check_bad latch_speed home --latch-speed 30000
check_bad debounce home --debounce -1
check_bad direction home --direction 0
check_bad max_backoff home --max-backoff 0
check_bad max_index_travel home --max-index-travel -1
# switch plus index: noisy bouncing switches, every run's zero the one index
"$scurve" home --engine model --runs 3 --index-period 4000 --bounce 500 --noise-rate 0.00005 --json > "$tmp/home_index.json"
python3 - "$tmp/home_index.json" <<'PY'
import json, sys
h = json.load(open(sys.argv[1]))
assert h["pass"] and h["spread"] == 0 and h["zero_expected_exact"], h
refs = {r["home_ref"] for r in h["runs"]}
assert len(refs) == 1, refs
for r in h["runs"]:
    assert r["home_ref"] == r["index_point"] == r["index_enc"] == r["zero_point"], r
PY
# scurve jog: velocity mode; each hold at exactly its target, a stop within
# a pulse of the closed form; bad input names the place.
"$scurve" jog --target 3000:0.01 --target -1500:0.01 --stop --json > "$tmp/jog.json"
"$scurve" jog --engine model-fast --target 5000:0.5 --target 0 --json > "$tmp/jog_fast.json"
python3 - "$tmp/jog.json" "$tmp/jog_fast.json" <<'PY'
import json, sys
j, f = (json.load(open(p)) for p in sys.argv[1:3])
assert j["pass"] and j["engine"] == "lockstep" and j["mismatches"] == 0 and j["stopped"], j
assert [c["v_held"] for c in j["commands"]] == [3000, -1500] and all(c["held"] for c in j["commands"]), j
assert abs(j["stop_distance"] - j["stop_closed_form_distance"]) < 1 and j["pulses"] == j["end_position"], j
assert f["pass"] and f["engine"] == "model-fast" and not f["stopped"] and f["pulses"] == f["end_position"], f
PY
check_bad "commands\[0\].v_target" jog --target 1e7
check_bad "commands\[0\].v_target" jog --target 100
check_bad "target\[1\].hold" jog --target 100 --target 0:-1
check_bad a_max jog --a-max 0
# --retarget-at: the running move redirected at a future zero-acceleration
# boundary ends exactly on the new distance; as register writes the replace
# is marked with its time; bad input names the flag.
"$scurve" sim --distance 4000 --v-cruise 40000 --a-max 2e6 --j-max 4e8 --retarget-at 0.03 --retarget-distance 5000 \
  --json > "$tmp/retarget.json"
"$scurve" regs --distance 4000 --v-cruise 40000 --a-max 2e6 --j-max 4e8 --retarget-at 0.03 --retarget-distance 5000 \
  --json > "$tmp/retarget_regs.json"
python3 - "$tmp/retarget.json" "$tmp/retarget_regs.json" <<'PY'
import json, sys
r, w = (json.load(open(p)) for p in sys.argv[1:3])
assert r["pass"] and r["pulses"] == 5000 and r["final_error"] == 0 and r["retarget"]["taken"], r
due = [x for x in w if "at_clock" in x]
assert len(due) == 1 and due[0]["reg"] == "RETARGET_ROW" and due[0]["data"] == r["retarget"]["row"], due
pushes = [x for x in w[w.index(due[0]):] if x["reg"] == "ROW_PUSH"]
assert pushes[0]["data"] & (1 << 4) and not any(p["data"] & (1 << 4) for p in pushes[1:]), pushes
PY
# A trapezoid's boundaries in motion all have a != 0 on one side: the new
# rows step the acceleration from the executor's (ACC_STEP).
"$scurve" sim --profile trapezoid --distance 4000 --v-cruise 40000 --a-max 2e6 --retarget-at 0.005 \
  --retarget-distance 5000 --json > "$tmp/retarget_trap.json"
python3 - "$tmp/retarget_trap.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
assert r["pass"] and r["pulses"] == 5000 and r["final_error"] == 0 and r["retarget"]["taken"], r
PY
check_bad retarget-distance sim --distance 4000 --v-cruise 40000 --a-max 2e6 --j-max 4e8 --retarget-at 0.03 --retarget-distance 100
check_bad retarget-distance sim --distance 4000 --v-cruise 40000 --a-max 2e6 --j-max 4e8 --retarget-at 0.03
check_bad retarget-at sim --distance 4000 --v-cruise 40000 --a-max 2e6 --j-max 4e8 --retarget-at 0.2 --retarget-distance 5000
check_bad retarget-at regs --distance 4000 --v-cruise 40000 --a-max 2e6 --j-max 4e8 --retarget-at 0.03 --retarget-distance 5000 --no-start
# scurve path: a G-code path on the multi-axis core in lockstep (every move
# on its target, pins agree, on the polyline); bad path files name the line.
cat > "$tmp/square.gcode" <<'GC'
G21 G90 ; mm, absolute
N10 G1 X2 Y1 F1200
N20 G91 X-1.5 Y0.75
N30 G90 X0 Y0
GC
"$scurve" path "$tmp/square.gcode" --json > "$tmp/path.json"
python3 - "$tmp/path.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
assert r["pass"] and r["mismatches"] == 0 and r["compared_clocks"] > 0, r
assert [m["end_position"] for m in r["moves"]] == [[200, 100], [50, 175], [0, 0]], r["moves"]
assert r["final_position"] == [0, 0] and r["pin_steps"] == [0, 0], r
assert r["contour_error_max_pulses"] < 0.01, r
PY
# --plot DIR: the decimated trace (CSV) and the two figures in one command;
# the trace has a row at every move end and at the end, where the run's
# positions are (REF_POS is the floor of the reference position).
"$scurve" path "$tmp/square.gcode" --engine model --plot "$tmp/plot/new" --json > "$tmp/path_plot.json"
python3 - "$tmp/path_plot.json" "$tmp/plot/new" <<'PY'
import json, math, os, sys
r, d = json.load(open(sys.argv[1])), sys.argv[2]
assert r["pass"], r
assert sorted(os.listdir(d)) == ["path_axes.png", "path_trace.csv", "path_xy.png"], os.listdir(d)
for name in ("path_xy.png", "path_axes.png"):
    with open(os.path.join(d, name), "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n", name
    assert os.path.getsize(os.path.join(d, name)) > 10000, name
lines = [l.strip() for l in open(os.path.join(d, "path_trace.csv")) if not l.startswith("#")]
head = lines[0].split(",")
assert head == ["t_s", "pos0_pulses", "pos1_pulses", "vel0_pulses_per_s", "vel1_pulses_per_s",
                "contour_error_pulses"], head
rows = [[float(x) for x in l.split(",")] for l in lines[1:]]
assert len(rows) == r["plot"]["samples"] and 100000 < len(rows) <= 200000 + len(r["moves"]) + 2, len(rows)
at = {round(row[0] * 20e6): [math.floor(row[1]), math.floor(row[2])] for row in rows}
for m in r["moves"]:
    assert at[m["end_clock"]] == m["end_position"], (m, at.get(m["end_clock"]))
assert round(rows[-1][0] * 20e6) == r["clocks"], (rows[-1], r["clocks"])
assert [math.floor(x) for x in rows[-1][1:3]] == r["final_position"], (rows[-1], r["final_position"])
assert max(row[5] for row in rows) <= r["contour_error_max_pulses"] * (1 + 1e-5), r["contour_error_max_pulses"]
PY
# Closed loop with paper 003's PID: the trace adds the measured position per
# axis (reference coordinates: at rest on the reference), the report the
# overshoot; the figures are drawn with the measured path and tracking error.
"$scurve" path "$tmp/square.gcode" --engine model --closed-loop --controller pid-aw --ctl-rate 1000 \
  --plot "$tmp/plot/loop" --json > "$tmp/path_loop.json"
python3 - "$tmp/path_loop.json" "$tmp/plot/loop" <<'PY'
import json, math, os, sys
r, d = json.load(open(sys.argv[1])), sys.argv[2]
assert r["pass"] and r["closed_loop"] and r["steady_state_error_pulses"] == [0, 0], r
assert len(r["overshoot_pulses"]) == 2 and len(r["overshoot_percent"]) == 2, r
lines = [l.strip() for l in open(os.path.join(d, "path_trace.csv")) if not l.startswith("#")]
head = lines[0].split(",")
assert head[-3:] == ["contour_error_pulses", "meas0_pulses", "meas1_pulses"], head
last = [float(x) for x in lines[-1].split(",")]
assert [math.floor(x) for x in last[6:8]] == [math.floor(x) for x in last[1:3]] == r["final_position"], last
assert max(abs(float(l.split(",")[1]) - float(l.split(",")[6])) for l in lines[1:]) <= \
    r["max_tracking_error_pulses"][0] + 1.0, r["max_tracking_error_pulses"]
for name in ("path_xy.png", "path_axes.png"):
    assert os.path.getsize(os.path.join(d, name)) > 10000, name
PY
# An unusable --plot directory, or no matplotlib, is refused before the run.
check_bad "--plot=$tmp/square.gcode/plot: cannot create the directory" path "$tmp/square.gcode" --engine model \
  --plot "$tmp/square.gcode/plot"
if [ "$(id -u)" -ne 0 ]; then  # root writes anywhere
  mkdir "$tmp/ro" && chmod 555 "$tmp/ro"
  check_bad "--plot=$tmp/ro: directory is not writable" path "$tmp/square.gcode" --engine model --plot "$tmp/ro"
fi
(export SCURVE_PYTHON=/nonexistent/python3
 check_bad "--plot=$tmp/plot/new: needs python3 with matplotlib" path "$tmp/square.gcode" --plot "$tmp/plot/new")
printf 'G1 X1 Y1 F600\nM3 S1000\n' > "$tmp/bad_word.gcode"
check_bad "line 2" path "$tmp/bad_word.gcode"
printf 'G1 X1 Y1 F0\n' > "$tmp/bad_feed.gcode"
check_bad "F" path "$tmp/bad_feed.gcode"
printf '{"axes": 2, "limits": {"feed": 10, "accel": 100, "jerk": 1000},\n "points": [[1, 2], [3,]]}\n' > "$tmp/bad.json"
check_bad "line 2" path "$tmp/bad.json"
printf 'G1 X30000000 F600\n' > "$tmp/far.gcode"
check_bad "X" path --engine model "$tmp/far.gcode"
check_bad "axes" path "$tmp/square.gcode" --axes 4
check_bad "tolerance=(none): --junction blend needs --tolerance" path "$tmp/square.gcode" --junction blend
check_bad "tolerance=0.5: only with --junction blend" path "$tmp/square.gcode" --tolerance 0.5
check_bad "junction=exact-stop-fine: needs --closed-loop" path "$tmp/square.gcode" --junction exact-stop-fine \
  --tolerance 0.01
check_bad "axes=3" path "$tmp/square.gcode" --axes 3 --closed-loop
check_bad "controller=pid-aw: needs --closed-loop" path "$tmp/square.gcode" --controller pid-aw
check_bad "pid-kp=10: a controller setting: needs --closed-loop" path "$tmp/square.gcode" --pid-kp 10
check_bad "pid-kp=1000000: 1000.* per control period of 0.001 s exceeds" path "$tmp/square.gcode" --closed-loop \
  --controller pid-aw --ctl-rate 1000 --pid-kp 1e6
check_bad "pid-kb=-1: must be a finite number in \[0," path "$tmp/square.gcode" --closed-loop --controller pid-aw \
  --pid-kb -1
check_bad "controller: pid not in" path "$tmp/square.gcode" --closed-loop --controller pid
check_bad "controller=pid-aw: --compare compares the neuron cascade" sim --closed-loop --compare --group 1 \
  --controller pid-aw
# A JSON point may carry its line's asymmetric jerks (Ts1 Ts2 Te1 Te2 along
# the path, mm/s^3): every move on its target (on the model: 15 M clocks,
# minutes in lockstep under the sanitizers; the rows are plain rows to the
# RTL, whose lockstep the path tests run); bad jerks name the point and the
# jerk, a jerk the planner cannot run names the move.
cat > "$tmp/jerks.json" <<'JS'
{"axes": 2, "limits": {"feed": 20, "accel": 1000, "jerk": 10000},
 "points": [{"to": [2, 1], "jerks": [2500, 10000, 8000, 1000]},
            {"to": [0.5, 1.75], "feed": 10, "jerks": [10000, 4000, 10000, 2500]}, [0, 0]]}
JS
"$scurve" path "$tmp/jerks.json" --engine model --json > "$tmp/path_jerks.json"
python3 - "$tmp/path_jerks.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
assert r["pass"], r["failures"]
assert [m["end_position"] for m in r["moves"]] == [[200, 100], [50, 175], [0, 0]], r["moves"]
assert r["final_position"] == [0, 0] and r["pin_steps"] == [0, 0], r
assert r["contour_error_max_pulses"] < 0.01, r
PY
jerks_file() {  # jerks of the second point
  printf '{"axes": 2, "limits": {"feed": 20, "accel": 1000, "jerk": 10000},\n%s\n' \
    " \"points\": [[1, 1], {\"to\": [2, 0], \"jerks\": $1}]}" > "$tmp/bad_jerks.json"
}
jerks_file '[1000, 0, 1000, 1000]'
check_bad 'points\[1\]\.jerks\[1\]=0: must be a finite number > 0 mm/s' path "$tmp/bad_jerks.json"
jerks_file '[1000, 1000, -5, 1000]'
check_bad 'points\[1\]\.jerks\[2\]=-5: must be a finite number > 0' path "$tmp/bad_jerks.json"
jerks_file '[1000, 1000, 1000, "NaN"]'
check_bad 'points\[1\]\.jerks\[3\]="NaN": must be a finite number' path "$tmp/bad_jerks.json"
jerks_file '[1e, 1000, 1000, 1000]'
check_bad 'line 2 col 48 JSON=.*not JSON' path "$tmp/bad_jerks.json"
jerks_file '[NaN, 1000, 1000, 1000]'
check_bad 'line 2 col 46 JSON=.*not JSON' path "$tmp/bad_jerks.json"
jerks_file '[1000, 1000, 1000]'
check_bad 'points\[1\]\.jerks=\[1000,1000,1000\]: needs 4 jerks' path "$tmp/bad_jerks.json"
jerks_file '[10000.5, 1000, 1000, 1000]'
check_bad 'points\[1\]\.jerks\[0\]=10000.5: must be <= limits.jerk=10000 mm/s' path "$tmp/bad_jerks.json"
jerks_file '[0.05, 1000, 1000, 1000]'
check_bad 'move 1 (point 1): lead axis 0 .*jerk_ts1=.*>= 10 pulses/s' path --engine model "$tmp/bad_jerks.json"
# scurve corner: paper 002's corner, the search's result never above the
# symmetric shape, the paper's figures beside ours; bad budgets named.
"$scurve" corner --budget 40 --engine none --json > "$tmp/corner.json"
python3 - "$tmp/corner.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
assert r["pass"] and r["evaluations"] <= 40 + 8, r
assert r["searched"]["fitness"] <= r["symmetric"]["fitness"], r
assert abs(r["paper"]["contour_error_m"] - 4.0348e-7) < 1e-12, r["paper"]
assert r["symmetric"]["duration_s"] > 2.39, r["symmetric"]
PY
check_bad "budget" corner --budget 5
check_bad "seed" corner --seed -1
check_bad "tolerance=0" path "$tmp/square.gcode" --junction blend --tolerance 0
check_bad "tolerance=-1" path "$tmp/square.gcode" --junction blend --tolerance -1
# Blended corners in lockstep: the same path within 0.02 mm (2 pulses) of
# its corners, every move's last row where the plan puts it, the path on its
# end, shorter than with exact stops.
"$scurve" path "$tmp/square.gcode" --junction blend --tolerance 0.02 --json > "$tmp/path_blend.json"
python3 - "$tmp/path_blend.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
assert r["pass"] and r["mismatches"] == 0, r["failures"]
assert r["final_position"] == [0, 0] and r["pin_steps"] == [0, 0], r
assert r["contour_error_max_pulses"] <= 2.0 + 1e-6 and r["max_corner_deviation_pulses"] <= 2.0 + 1e-6, r
assert r["duration_s"] < r["exact_stop_duration_s"], r
assert sum(m["blend_clocks"] for m in r["moves"]) > 0, r["moves"]
PY
echo "cli ok"
