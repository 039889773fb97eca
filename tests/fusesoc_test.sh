#!/usr/bin/env bash
# The FuseSoC core (scurve_servo.core) as a user runs it: it parses, the
# lint target (Verilator -Wall on the board top), the sim target (the Icarus
# smoke test: two moves, pin monitor) and the synth target (yosys
# synth_xilinx of the servo axis) run and pass; the arty target sets up a
# Vivado project for the right part with the constraints (Vivado itself is
# not installed here). The sim target must also fail, with FuseSoC's exit
# code, when the smoke test's check is broken.
#   tests/fusesoc_test.sh <source dir> <work dir>
set -euo pipefail
src=$(realpath "$1") work=$2
fusesoc=$src/.venv/bin/fusesoc
[ -x "$fusesoc" ] || { echo "FAIL: $fusesoc missing (scripts/setup.sh installs it)"; exit 1; }
rm -rf "$work"; mkdir -p "$work"; cd "$work"
vlnv=scurve:motion:servo
run() {  # run <target> [fusesoc run options]: log in <target>.log
  local t=$1; shift
  if ! "$fusesoc" --cores-root "$src" run "$@" --target "$t" "$vlnv" > "$t.log" 2>&1; then
    echo "FAIL: fusesoc run --target $t"; tail -20 "$t.log"; exit 1
  fi
}
"$fusesoc" --cores-root "$src" core show "$vlnv" > show.log 2>&1 \
  || { echo "FAIL: the core does not parse"; cat show.log; exit 1; }
for t in lint sim synth arty; do grep -q "^ *$t\b" show.log || { echo "FAIL: target $t not listed"; cat show.log; exit 1; }; done
run lint
run sim
grep -q "PASS: sc_axis_core smoke test, net 63 steps" sim.log || { echo "FAIL: no PASS line"; cat sim.log; exit 1; }
run synth
edif=build/scurve_motion_servo_0.1.0/synth-yosys/scurve_motion_servo_0.1.0.edif
[ -s "$edif" ] || { echo "FAIL: synth wrote no netlist"; exit 1; }
grep -q "Executing SYNTH_XILINX pass" build/scurve_motion_servo_0.1.0/synth-yosys/yosys.log \
  || { echo "FAIL: synth did not run synth_xilinx"; exit 1; }
run arty --setup
tcl=$(ls build/scurve_motion_servo_0.1.0/arty-vivado/*.tcl | tr '\n' ' ')
grep -q "xc7a35ticsg324-1L" $tcl || { echo "FAIL: arty project not for xc7a35ticsg324-1L"; exit 1; }
grep -q "arty_a7_35t.xdc" $tcl || { echo "FAIL: arty project without the constraints"; exit 1; }
grep -q "sc_board_top" $tcl || { echo "FAIL: arty project without its top"; exit 1; }
# A broken check must fail the sim target: a copy of the tree whose smoke
# test expects one step more.
broken=$work/broken
mkdir -p "$broken/tb/sv"
cp -r "$src/rtl" "$src/constraints" "$src/scurve_servo.core" "$broken/"
sed 's/if (monitor_steps - start_steps != (forward ? pulses : -pulses))/if (monitor_steps - start_steps != (forward ? pulses + 1 : -pulses))/' \
  "$src/tb/sv/sc_axis_core_smoke_tb.sv" > "$broken/tb/sv/sc_axis_core_smoke_tb.sv"
cmp -s "$src/tb/sv/sc_axis_core_smoke_tb.sv" "$broken/tb/sv/sc_axis_core_smoke_tb.sv" \
  && { echo "FAIL: the broken variant is not broken (the check line changed?)"; exit 1; }
if (cd "$broken" && "$fusesoc" --cores-root "$broken" run --target sim "$vlnv" > "$work/broken.log" 2>&1); then
  echo "FAIL: the sim target passed with a broken check"; tail -5 "$work/broken.log"; exit 1
fi
grep -q "pin monitor saw 100 steps" "$work/broken.log" \
  || { echo "FAIL: the broken variant failed for another reason"; tail -5 "$work/broken.log"; exit 1; }
echo "fusesoc ok: core parses; lint, sim, synth pass; arty set up; a broken check fails the sim"
