#!/usr/bin/env bash
# The host driver end to end over a pseudo-terminal: `scurve virtual-board`
# (the Verilated board top with the plant on its pins) driven by
# `scurve board --port`: identify, a move read back, a stream, a stop, an
# e-stop, homing, line noise the retries mend, a CRC error on every frame, a
# board that stops answering, a board that resets in the middle of a stream,
# a port that answers garbage, and ports that are no board.
#   board_pty_test.sh SCURVE SOURCE_DIR [paper|xy]
# With `paper`: paper 000's group 1 (30,000 pulses) over the line instead.
# With `xy`: the two-axis board (the multi-axis map, 2-byte frames) instead:
# the map detected, paths with exact stops and blends on both axes, a stop,
# an e-stop, and what the one map refuses that the other takes.
set -euo pipefail
scurve=$1
src=$2
mode=${3:-}
tmp=$(mktemp -d)
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill -CONT "$p" 2>/dev/null || true; kill -TERM "$p" 2>/dev/null || true; done
  wait 2>/dev/null || true
  rm -rf "$tmp"
}
trap cleanup EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
# Each command's guard; paper group 1 runs 280 M board clocks at whatever
# speed the machine gives the virtual board (127-150 s alone on 2 cores).
T="timeout 300"
[ "$mode" = paper ] && T="timeout 1800"

# start_board NAME [virtual-board flags...]: a board behind $tmp/NAME (its
# pid in $board); stop_board: ends it (a virtual board runs flat out).
start_board() {
  local name=$1; shift
  "$scurve" virtual-board --speed 0 --pty-link "$tmp/$name" "$@" > "$tmp/$name.out" 2> "$tmp/$name.err" &
  board=$!
  pids+=("$board")
  for _ in $(seq 100); do [ -e "$tmp/$name" ] && return 0; sleep 0.1; done
  fail "virtual board $name did not come up: $(cat "$tmp/$name.err")"
}
stop_board() { kill -TERM "$board"; wait "$board" || true; }
# run_rc WANT CMD...: the exit code must be WANT; stdout in $tmp/out, stderr in $tmp/err.
run_rc() {
  local want=$1; shift
  local t0
  t0=$(date +%s%N)
  set +e
  $T "$@" > "$tmp/out" 2> "$tmp/err"
  local rc=$?
  set -e
  echo "$(( ($(date +%s%N) - t0) / 1000000 )) ms: ${*:2}"
  [ "$rc" -eq "$want" ] || fail "$* -> exit $rc, want $want: $(cat "$tmp/err")"
  if [ "$want" -ne 0 ]; then
    [ "$(wc -l < "$tmp/err")" -eq 1 ] || fail "$* -> stderr is not one line: $(cat "$tmp/err")"
  fi
}
json() { python3 -c "import json,sys; d=json.load(open('$tmp/out')); print($1)"; }

if [ "$mode" = xy ]; then
  start_board xy --axes 2
  X=(board --port "$tmp/xy")
  run_rc 0 "$scurve" "${X[@]}" --json info
  [ "$(json 'd["axes"]')" = 2 ] || fail "xy info axes: $(cat "$tmp/out")"
  [ "$(json 'd["map"]')" = multi ] || fail "xy info map: $(cat "$tmp/out")"
  [ "$(json 'd["closed_loop"]')" = True ] || fail "xy info closed loop: $(cat "$tmp/out")"
  # a path with exact stops, relative moves in mm (100 pulses/mm), the pins on the targets
  printf 'G21 G91\nG1 X2 Y1 F1200\nG1 X1 Y-2.5\nG1 X-1.5 Y0.5\n' > "$tmp/p.gcode"
  run_rc 0 "$scurve" "${X[@]}" --json path "$tmp/p.gcode" --accel 2000 --jerk 100000
  [ "$(json 'd["pass"]')" = True ] || fail "xy path: $(cat "$tmp/out")"
  [ "$(json '[a["status"]["ref_pos"] for a in d["axes"]]')" = "[150, -100]" ] || fail "xy path REF_POS: $(cat "$tmp/out")"
  [ "$(json '[a["status"]["pulse_count"] for a in d["axes"]]')" = "[150, -100]" ] || fail "xy PULSE_COUNT: $(cat "$tmp/out")"
  [ "$(json '[a["status"]["enc_pos"] for a in d["axes"]]')" = "[150, -100]" ] || fail "xy plant: $(cat "$tmp/out")"
  [ "$(json 'd["boundaries_checked"] > 0')" = True ] || fail "xy boundaries: $(cat "$tmp/out")"
  # the same path blended, planned from where the axes are: back by the sum
  printf 'G21 G91\nG1 X-1 Y-1 F1200\nG1 X-0.5 Y2\n' > "$tmp/q.gcode"
  run_rc 0 "$scurve" "${X[@]}" --json path "$tmp/q.gcode" --accel 2000 --jerk 100000 --blend 0.1
  [ "$(json 'd["junction"]')" = blend ] || fail "xy blend: $(cat "$tmp/out")"
  [ "$(json '[a["status"]["ref_pos"] for a in d["axes"]]')" = "[0, 0]" ] || fail "xy blend REF_POS: $(cat "$tmp/out")"
  run_rc 0 "$scurve" "${X[@]}" --json status
  [ "$(json '[a["enc_pos"] for a in d["axes"]]')" = "[0, 0]" ] || fail "xy status: $(cat "$tmp/out")"
  # a long move stopped under control by CMD.STOP from the host: both axes at rest, short of the target
  printf 'G21 G91\nG1 X40 Y30 F600\n' > "$tmp/long.gcode"
  run_rc 0 "$scurve" "${X[@]}" --json path "$tmp/long.gcode" --accel 500 --jerk 10000 --no-wait
  [ "$(json 'd["started"] and not d["pass"]')" = True ] || fail "xy path --no-wait: $(cat "$tmp/out")"
  sleep 2
  run_rc 0 "$scurve" "${X[@]}" --json stop
  [ "$(json '[a["busy"] for a in d["axes"]]')" = "[False, False]" ] || fail "xy stop: $(cat "$tmp/out")"
  [ "$(json '0 < d["axes"][0]["ref_pos"] < 4000 and 0 < d["axes"][1]["ref_pos"] < 3000')" = True ] ||
    fail "xy stop position: $(cat "$tmp/out")"
  [ "$(json 'all(a["ref_pos"] == a["pulse_count"] for a in d["axes"])')" = True ] || fail "xy stop counts: $(cat "$tmp/out")"
  # an e-stop from the group window disables both axes until clear
  run_rc 0 "$scurve" "${X[@]}" --json estop
  [ "$(json '[a["enabled"] for a in d["axes"]]')" = "[False, False]" ] || fail "xy estop: $(cat "$tmp/out")"
  run_rc 0 "$scurve" "${X[@]}" --json clear
  [ "$(json '[a["faults"] for a in d["axes"]]')" = "[[], []]" ] || fail "xy clear: $(cat "$tmp/out")"
  # what this map refuses, one line each
  run_rc 2 "$scurve" "${X[@]}" run --distance 100 --v-cruise 1000 --a-max 1e5 --j-max 1e7
  grep -q "multi-axis map" "$tmp/err" || fail "xy run: $(cat "$tmp/err")"
  printf 'G21\nG1 X1 M3\n' > "$tmp/bad.gcode"
  run_rc 2 "$scurve" "${X[@]}" path "$tmp/bad.gcode"
  grep -q "line 2" "$tmp/err" || fail "xy bad G-code: $(cat "$tmp/err")"
  printf 'G21\nG1 X1 Y1 Z1 F600\n' > "$tmp/xyz.gcode"
  run_rc 2 "$scurve" "${X[@]}" path "$tmp/xyz.gcode" --pulses-per-mm 100 100 100
  run_rc 2 "$scurve" "${X[@]}" --map axis --timeout-ms 50 --retries 0 info
  stop_board
  # and the one-axis board: no path
  start_board one
  run_rc 2 "$scurve" board --port "$tmp/one" path "$tmp/p.gcode"
  grep -q "one-axis map" "$tmp/err" || fail "path on the one-axis board: $(cat "$tmp/err")"
  run_rc 0 "$scurve" board --port "$tmp/one" --map axis --json info
  [ "$(json 'd["axes"]')" = 1 ] || fail "one-axis info: $(cat "$tmp/out")"
  echo "PASS (two-axis board over the line)"
  exit 0
fi

start_board b --home-at -700
B=(board --port "$tmp/b")

if [ "$mode" = paper ]; then
  # Group 1: 1500 -> 3000 -> 0 pulses/s, 30,000 pulses, a = 500, j = 2500 (about 14 s of board time).
  # --timeout: seconds of the host's clock, and the board runs at a fraction of real time here.
  run_rc 0 "$scurve" "${B[@]}" --json run --distance 30000 --v-start 1500 --v-cruise 3000 --v-end 0 \
    --a-max 500 --j-max 2500 --timeout 3000
  [ "$(json 'd["pass"]')" = True ] || fail "group 1: $(cat "$tmp/out")"
  [ "$(json 'd["status"]["pulse_count"]')" = 30000 ] || fail "group 1 PULSE_COUNT: $(cat "$tmp/out")"
  [ "$(json 'd["status"]["ref_pos"]')" = 30000 ] || fail "group 1 REF_POS: $(cat "$tmp/out")"
  echo "PASS (paper group 1 over the line: 30000 pulses)"
  exit 0
fi

# ---- identify -------------------------------------------------------------------
run_rc 0 "$scurve" "${B[@]}" --json info
[ "$(json 'd["id"] >> 16')" = 21315 ] || fail "info: $(cat "$tmp/out")"
[ "$(json 'd["axes"]')" = 1 ] || fail "info axes: $(cat "$tmp/out")"
[ "$(json 'd["closed_loop"]')" = True ] || fail "info closed loop: $(cat "$tmp/out")"

# ---- a move, read back: PULSE_COUNT, REF_POS and the encoder on the plant -------
run_rc 0 "$scurve" "${B[@]}" --json run --distance 2000 --v-cruise 100000 --a-max 1e7 --j-max 1e10
[ "$(json 'd["status"]["pulse_count"]')" = 2000 ] || fail "run: $(cat "$tmp/out")"
[ "$(json 'd["status"]["ref_pos"]')" = 2000 ] || fail "run REF_POS: $(cat "$tmp/out")"
[ "$(json 'd["link"]["retries"]')" = 0 ] || fail "run retried on a clean line: $(cat "$tmp/out")"
run_rc 0 "$scurve" "${B[@]}" --json run --distance -2500 --v-cruise 60000 --a-max 5e6 --j-max 5e9
[ "$(json 'd["status"]["ref_pos"]')" = -500 ] || fail "run back: $(cat "$tmp/out")"
# settled: the encoder on the reference (one count per pulse)
run_rc 0 "$scurve" "${B[@]}" --json status
[ "$(json 'd["enc_pos"]')" = -500 ] || fail "encoder after the moves: $(cat "$tmp/out")"

# ---- a stream, the FIFO topped up over the line ----------------------------------
run_rc 0 "$scurve" "${B[@]}" --json stream "$src/tests/streams/uart_paced.json" --timeout 600
[ "$(json 'd["end_ref"] == d["expected_end"] == -500 + 1100')" = True ] || fail "stream: $(cat "$tmp/out")"
[ "$(json 'd["boundaries_checked"] > 0')" = True ] || fail "stream boundaries: $(cat "$tmp/out")"

# ---- homing against the switch at -700 ------------------------------------------
run_rc 0 "$scurve" "${B[@]}" --json home --direction -1 --seek-speed 20000 --a-max 1e7 --j-max 1e10 --max-travel 100000
python3 - "$tmp/out" <<'PY' || fail "home: $(cat "$tmp/out")"
import json, sys
h = json.load(open(sys.argv[1]))
assert h["home_ref"] == h["release_ref"] == -699, h   # the first position off the switch
PY

# ---- a stop during a move: controlled, at rest short of the target ----------------
run_rc 0 "$scurve" "${B[@]}" run --distance 200000 --v-cruise 50000 --a-max 1e6 --j-max 1e9 --no-wait
run_rc 0 "$scurve" "${B[@]}" --json stop
python3 - "$tmp/out" <<'PY' || fail "stop: $(cat "$tmp/out")"
import json, sys
s = json.load(open(sys.argv[1]))["status"]
assert not s["busy"], s
start = s["ref_pos"] - s["pulse_count"]              # PULSE_COUNT counts from the START
assert start < s["ref_pos"] < start + 200000, s      # stopped on the way
assert s["faults"] == [], s
PY

# ---- an e-stop: refused START until cleared ----------------------------------------
run_rc 0 "$scurve" "${B[@]}" estop
run_rc 1 "$scurve" "${B[@]}" run --distance 100 --v-cruise 10000 --a-max 1e6 --j-max 1e9
grep -q "SLVERR" "$tmp/err" || fail "a START after an e-stop: $(cat "$tmp/err")"
run_rc 0 "$scurve" "${B[@]}" clear
run_rc 0 "$scurve" "${B[@]}" run --distance 100 --v-cruise 10000 --a-max 1e6 --j-max 1e9

# ---- bad ports --------------------------------------------------------------------
run_rc 2 "$scurve" board --port "$tmp/missing" info
grep -q "port=.*missing" "$tmp/err" || fail "missing port: $(cat "$tmp/err")"
run_rc 2 "$scurve" board --port /dev/null info
grep -q "not a terminal" "$tmp/err" || fail "/dev/null: $(cat "$tmp/err")"
touch "$tmp/plain"
run_rc 2 "$scurve" board --port "$tmp/plain" info
run_rc 2 "$scurve" board --port "$tmp/b" --timeout-ms 0 info
grep -q "timeout" "$tmp/err" || fail "timeout 0: $(cat "$tmp/err")"
run_rc 2 "$scurve" board --port "$tmp/b" --baud 115201 info
grep -q "baud=115201" "$tmp/err" || fail "baud: $(cat "$tmp/err")"

# ---- a board that stops answering: the driver times out, no hang ------------------
kill -STOP "${pids[0]}"
start=$(date +%s%N)
run_rc 2 "$scurve" "${B[@]}" --timeout-ms 100 --retries 2 status
ms=$(( ($(date +%s%N) - start) / 1000000 ))
kill -CONT "${pids[0]}"
grep -q "no answer.*3 tries of 100 ms" "$tmp/err" || fail "silent board: $(cat "$tmp/err")"
[ "$ms" -lt 5000 ] || fail "silent board: took $ms ms"
run_rc 0 "$scurve" "${B[@]}" info   # and the board answers again (its late answers drained)
stop_board

# ---- line noise: a bit flipped in every 23rd byte, mended by the retries ----------
# (a 1 s timeout: the retries mend corrupted frames; a sanitizer build on a
# loaded machine can take longer than 100 ms to answer a clean one)
start_board noisy --corrupt-every 41
run_rc 0 "$scurve" board --port "$tmp/noisy" --timeout-ms 1000 --json run --distance 1500 --v-cruise 100000 --a-max 1e7 --j-max 1e10
[ "$(json 'd["status"]["pulse_count"]')" = 1500 ] || fail "noisy line: $(cat "$tmp/out")"
[ "$(json 'd["link"]["retries"] > 0')" = True ] || fail "no retry: $(cat "$tmp/out")"
stop_board

# ---- a CRC error on every frame (a read frame is 4 bytes: every CRC byte
# flipped): a clear error, no hang --------------------------------------------------
start_board broken --corrupt-every 4
run_rc 2 "$scurve" board --port "$tmp/broken" info
grep -q "CRC error) after 4 tries" "$tmp/err" || fail "broken line: $(cat "$tmp/err")"
stop_board

# ---- a board that resets in the middle of a stream --------------------------------
start_board resets --reset-after-bytes 3000
run_rc 1 "$scurve" board --port "$tmp/resets" stream "$src/tests/streams/uart_paced.json" --timeout 600
grep -q "went idle after move" "$tmp/err" || fail "reset mid-stream: $(cat "$tmp/err")"
stop_board

# ---- a port that answers garbage ---------------------------------------------------
python3 - "$tmp/garbage" <<'PY' &
import os, sys, time, select
master, slave = os.openpty()
os.symlink(os.ttyname(slave), sys.argv[1])
end = time.time() + 60
while time.time() < end:
    r, _, _ = select.select([master], [], [], 0.1)
    if r:
        os.read(master, 256)
        os.write(master, bytes([0x13, 0x37, 0x5A, 0x00, 0x42]))  # a sync byte, then a wrong CRC
PY
pids+=($!)
for _ in $(seq 50); do [ -e "$tmp/garbage" ] && break; sleep 0.1; done
run_rc 2 "$scurve" board --port "$tmp/garbage" info
grep -q "garbled answer" "$tmp/err" || fail "garbage: $(cat "$tmp/err")"

echo "PASS"
