#!/usr/bin/env bash
# scurve sim --closed-loop: every bad plant, controller or scenario value,
# and a --weights-csv that cannot be written, is exit 2 with one stderr line
# naming the parameter (never a hang, a silent default, a run, or a file
# left behind).
set -euo pipefail
scurve=$(realpath "$1")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# Run from an empty directory: no case may leave a file behind (checked last).
mkdir "$tmp/cwd"; cd "$tmp/cwd"
move="--closed-loop --distance 300 --v-cruise 3000 --a-max 50000 --j-max 500000 --engine model"
fails=0
expect2() {  # expect2 <substring> <args...>
  local want=$1; shift
  set +e
  timeout 300 "$scurve" sim $move "$@" > "$tmp/out" 2> "$tmp/err"  # the --compare runs take a minute under ASan
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
# Every controller flag (the table in tb/closed_loop_cli.cpp): not a number,
# not finite, empty, below and above its range, octal-looking integers.
for f in k-p k-v kb eta-p1 eta-p2 eta-v1 eta-v2 learn-dz-p learn-dz-v v-lim u-lim inpos-win inpos-hold settle-rate \
         ctl-rate ferr-lim w-p1 fixed-w-p1 w-p2 w-v1 w-v2 w-min w-p1-max w-p2-max w-v1-max w-v2-max \
         learn-shift enc-filter tail; do
  for v in nan inf -inf 0x10 1e999 ten; do expect2 "$f=$v" "--$f" "$v"; done
  expect2 "$f=''" "--$f" ""
  expect2 "$f=''" "--$f="  # empty after '=': the value as given, not the next argument
done
for a in k-p=-1 k-p=16 k-v=-1 kb=-1 eta-p1=-1 eta-v2=16 learn-dz-p=-1 learn-dz-p=32768 learn-dz-v=-1 \
         v-lim=-1 v-lim=1e8 u-lim=-1 u-lim=1e8 inpos-win=-1 inpos-hold=-1 inpos-hold=7 settle-rate=1e8 \
         ctl-rate=305 ctl-rate=78126 ctl-rate=0 ctl-rate=-1 ferr-lim=0.5 ferr-lim=32768 \
         w-p1=128 w-p2=-128 w-min=-128 w-v2-max=128 learn-shift=-1 learn-shift=32 learn-shift=010 learn-shift=1e1 \
         learn-shift=1.5 enc-filter=16 enc-filter=-1 enc-filter=010 enc-filter=0x1; do
  expect2 "$a" "--${a%%=*}" "${a#*=}"
done
# Switches take no value (the message shows the value as given); of repeated
# numbers the last counts, each checked.
for a in no-ff=false no-ff=true fixed-gain=0 open-loop=no missed-steps=false compare=1 ferr-stop=0; do
  expect2 "$a: a switch takes no value" "--$a"
done
expect2 "no-ff='': a switch takes no value" --no-ff=
# "--k-p=" never takes the next argument as its value.
expect2 "k-p=''" --k-p= 0.004
expect2 "k-p=''" --k-p= --k-v 0.1
expect2 "k-p=nan" --k-p 0.004 --k-p nan
expect2 "k-p=nan" --k-p nan --k-p 0.004
expect2 "enc-filter=010" --enc-filter 010 --enc-filter 3
expect2 "weights-csv=''" --weights-csv "" --weights-csv w.csv
# Settings valid alone, not together: one line naming both.
expect2 "inpos-hold=1 s" --ctl-rate 78125 --inpos-hold 1
expect2 "ferr-lim=32767" --counts-per-step 4 --ferr-lim 32767
expect2 "u-lim=10000000" --u-lim 1e7
expect2 "w-v2-max=-1: below w-min=0" --w-v2-max -1

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
scenario 'scenario.controller.k_p=-1' '{"controller":{"k_p":-1}}'
scenario 'scenario.controller.k_v="0.02"' '{"controller":{"k_v":"0.02"}}'
scenario 'scenario.controller.rate_hz=100000' '{"controller":{"rate_hz":100000}}'
scenario 'scenario.controller.enc_filt=3.5' '{"controller":{"enc_filt":3.5}}'
scenario 'scenario.controller.w_p1_max=null' '{"controller":{"w_p1_max":null}}'
scenario 'scenario.controller.k_pp' '{"controller":{"k_pp":0.004}}'
scenario 'w-p1-max=1: below w-min=10' '{"controller":{"w_min":10,"w_p1_max":1}}'
scenario 'not JSON' '{not json'
expect2 "--scenario $tmp: cannot read" --scenario "$tmp"
# --weights-csv: refused before the run when it cannot be written, and
# written whole or not at all (a file-size limit fails the write, SIGXFSZ is
# ignored): exit 2, one line, no file, no "<path>.part".
w=$tmp/wcsv; mkdir "$w"; mkdir "$w/dir"
expect_no_csv() {
  local left; left=$(cd "$w" && ls -A | grep -v '^dir$' || true)
  [ -z "$left" ] || { echo "FAIL: $1 left files: $left"; fails=$((fails + 1)); rm -f "$w"/*.csv "$w"/*.part; }
}
expect2 "weights-csv=$w/nodir/w.csv: no directory" --weights-csv "$w/nodir/w.csv"; expect_no_csv "missing directory"
expect2 "weights-csv=$w/dir: $w/dir is a directory" --weights-csv "$w/dir"; expect_no_csv "directory as path"
expect2 "weights-csv=$w/dir/: $w/dir/ is a directory" --weights-csv "$w/dir/"; expect_no_csv "directory as path"
expect2 "weights-csv=$w/dir/: $w/dir/ is a directory" --compare --weights-csv "$w/dir/"; expect_no_csv "directory, several runs"
# Not a regular file (a FIFO here; the same check keeps a device such as
# /dev/null from being replaced by the renamed file).
mkfifo "$w/fifo"
expect2 "weights-csv=$w/fifo: $w/fifo exists and is not a regular file" --weights-csv "$w/fifo"
rm "$w/fifo"; expect_no_csv "FIFO as path"
# Under a file-size limit the subshell's own output goes to a fresh file,
# with SIGXFSZ ignored, so only the program under test meets the limit.
limited() {  # limited <kb> <expected> <args...>
  local kb=$1; shift
  set +e
  ( trap '' XFSZ; ulimit -f "$kb"; fails=0; expect2 "$@"; exit "$fails" ) > "$tmp/limited.log" 2>&1
  fails=$((fails + $?))
  set -e
  cat "$tmp/limited.log"
}
limited 1 "weights-csv=$w/w.csv: cannot write $w/w.csv.part: File too large" --weights-csv "$w/w.csv"
expect_no_csv "ulimit -f 1"
# Several runs, several files: the largest cannot be written, so none is.
"$scurve" sim $move --compare --jobs 2 --weights-csv "$w/c.csv" > /dev/null
n_csv=$(ls "$w"/c-*.csv | wc -l)
[ "$n_csv" -eq 8 ] || { echo "FAIL: --compare wrote $n_csv weight files, want 8"; fails=$((fails + 1)); }
max_kb=$(( $(stat -c %s "$w"/c-*.csv | sort -n | tail -1) / 1024 ))
rm -f "$w"/c-*.csv
limited "$max_kb" "File too large" --compare --jobs 2 --weights-csv "$w/c.csv"
expect_no_csv "--compare under ulimit -f $max_kb"
left=$(ls -A "$tmp/cwd")
[ -z "$left" ] || { echo "FAIL: files left in the working directory: $left"; fails=$((fails + 1)); }
[ "$fails" -eq 0 ] || { echo "$fails bad-input cases broke the contract"; exit 1; }
echo "closed-loop bad input: every case exit 2 with one line naming the parameter"
