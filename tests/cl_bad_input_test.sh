#!/usr/bin/env bash
# scurve sim --closed-loop: every bad plant, controller or scenario value is
# exit 2 with one stderr line naming the parameter (never a hang, a silent
# default or a run).
set -euo pipefail
scurve=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
move="--closed-loop --distance 300 --v-cruise 3000 --a-max 50000 --j-max 500000 --engine model"
fails=0
expect2() {  # expect2 <substring> <args...>
  local want=$1; shift
  set +e
  timeout 60 "$scurve" sim $move "$@" > "$tmp/out" 2> "$tmp/err"
  local rc=$?
  set -e
  local lines; lines=$(wc -l < "$tmp/err")
  if [ "$rc" -ne 2 ] || [ "$lines" -ne 1 ] || ! grep -qF -- "$want" "$tmp/err"; then
    echo "FAIL: $* -> rc=$rc, $lines stderr lines: $(cat "$tmp/err")"; fails=$((fails + 1))
  fi
}
for a in "tail=-1:--tail -1" "tail=nan:--tail nan" "tail=1e308:--tail 1e308" \
         "inertia=-1:--inertia -1" "inertia=nan:--inertia nan" "pulses-per-rev=0:--pulses-per-rev 0" \
         "enc-noise=nan:--enc-noise nan" "enc-noise=1e308:--enc-noise 1e308" \
         "enc-glitch-rate=-1:--enc-glitch-rate -1" "enc-glitch-clocks=-1:--enc-glitch-clocks -1" \
         "enc-glitch-clocks=010:--enc-glitch-clocks 010" "plant-seed=-1:--plant-seed -1" \
         "f-n=0:--f-n 0" "f-n=-1:--f-n -1" "f-n=inf:--f-n inf" "zeta=0:--zeta 0" "zeta=nan:--zeta nan" \
         "tau=0:--tau 0" "v-lim=-1:--v-lim -1" "ferr-lim=-1:--ferr-lim -1" "settle-rate=-1:--settle-rate -1" \
         "w-p1-max=1:--w-min 10 --w-p1-max 1" "k-p=nan:--k-p nan"; do
  expect2 "${a%%:*}" ${a#*:}
done
scenario() { printf '%s' "$2" > "$tmp/s.json"; expect2 "$1" --scenario "$tmp/s.json"; }
scenario 'scenario.plant.f_nn' '{"plant":{"f_nn":100}}'
scenario 'scenario.plantt' '{"plantt":{}}'
scenario 'scenario=[]' '[]'
scenario 'scenario=null' 'null'
scenario 'scenario="str"' '"str"'
scenario 'scenario.plant=[]' '{"plant":[],"controller":5}'
scenario "scenario.plant.kind='rocket'" '{"plant":{"kind":"rocket"}}'
scenario 'scenario.plant.glitch_clocks=-5' '{"plant":{"glitch_clocks":-5}}'
scenario 'scenario.plant.glitch_clocks=1e+30' '{"plant":{"glitch_clocks":1e30}}'
scenario 'scenario.plant.seed=-1' '{"plant":{"seed":-1}}'
scenario 'scenario.plant.seed=1.5' '{"plant":{"seed":1.5}}'
scenario 'scenario.controller.learn_shift=1e+30' '{"controller":{"learn_shift":1e30}}'
scenario 'not JSON' '{not json'
expect2 "--scenario $tmp: cannot read" --scenario "$tmp"
[ "$fails" -eq 0 ] || { echo "$fails bad-input cases broke the contract"; exit 1; }
echo "closed-loop bad input: every case exit 2 with one line naming the parameter"
