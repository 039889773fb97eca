#!/bin/sh
# scurve plan / regs (and sim, when given): --clock-hz is validated and
# changes the plan. Usage: cli_clock_test.sh <scurve> [sim]
set -u
exe=$1
with_sim=${2:-}
fail=0
move="--distance 30000 --v-start 1500 --v-cruise 3000 --v-end 0 --a-max 500 --j-max 2500"

expect_bad() {  # expect exit 2 and a one-line error naming clock-hz, the value and the bound
  out=$("$@" 2>&1 >/dev/null); rc=$?
  if [ $rc -ne 2 ]; then echo "FAIL (rc $rc, want 2): $*"; fail=1; return; fi
  case "$out" in
    *clock-hz=*) ;;
    *) echo "FAIL (no clock-hz= in error): $* -> $out"; fail=1; return ;;
  esac
  if [ "$(printf '%s\n' "$out" | wc -l)" -ne 1 ]; then echo "FAIL (not one line): $out"; fail=1; fi
}

for cmd in plan regs ${with_sim:+sim}; do
  for bad in 0 -25e6 nan inf 1e12 500000; do
    expect_bad "$exe" $cmd $move --clock-hz $bad
  done
  for bad in 500000 nan -1; do
    "$exe" $cmd $move --clock-hz $bad 2>&1 | grep -q "in \[1000000, 1000000000\]" \
      || { echo "FAIL: $cmd --clock-hz $bad: bound not named"; fail=1; }
  done
done

a=$("$exe" plan $move --json) || { echo "FAIL: plan"; fail=1; }
b=$("$exe" plan $move --json --clock-hz 20e6) || { echo "FAIL: plan 20e6"; fail=1; }
c=$("$exe" plan $move --json --clock-hz 25e6) || { echo "FAIL: plan 25e6"; fail=1; }
[ "$a" = "$b" ] || { echo "FAIL: --clock-hz 20e6 differs from the default"; fail=1; }
[ "$a" != "$c" ] || { echo "FAIL: --clock-hz 25e6 gives the 20 MHz table"; fail=1; }
printf '%s' "$c" | grep -q '"clock_hz": 25000000' || { echo "FAIL: clock_hz not in plan JSON"; fail=1; }
"$exe" regs $move --clock-hz 50e6 --closed-loop | grep -q '^0x004 CTRL' || { echo "FAIL: regs at 50 MHz"; fail=1; }
[ $fail -eq 0 ] && echo "cli clock checks passed"
exit $fail
