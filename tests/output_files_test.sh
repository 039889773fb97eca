#!/usr/bin/env bash
# Output files of scurve sim, sc_bench and sc_bench_pin (FST waveforms,
# kinematics traces): a path that cannot be written is refused before the
# run (exit 2, one stderr line naming the flag); a write that fails during
# the run (a file-size limit, a full disk) is exit 2 with one line and leaves
# neither the file nor its .part behind; a waveform has a bounded default
# window; a good run writes whole files that read back.
set -euo pipefail
scurve=$(realpath "$1") bench=$(realpath "$2")
# The pin-accurate bench is optional: the sanitizer build leaves it out (a
# short move takes a minute there).
pin_bench=
if [ -n "${3:-}" ]; then pin_bench=$(realpath "$3"); else echo "note: no sc_bench_pin given, its cases not run"; fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
fails=0
fail() { echo "FAIL: $*" >&2; fails=$((fails + 1)); }
move="--distance 300 --v-cruise 3000 --a-max 50000 --j-max 500000"

# expect2 <limit-kb|-> <substring> <tool> <args...>: exit 2, one stderr line
# containing <substring>, no file left in the scratch directory. The time
# limit catches a hang; it is wide because under the sanitizers a bench
# run that fails its write late takes minutes.
expect2() {
  local limit=$1 want=$2; shift 2
  mkdir -p out && rm -f out/*
  set +e
  if [ "$limit" = - ]; then
    timeout 600 "$@" > stdout 2> stderr
  else
    (ulimit -f "$limit"; exec timeout 600 "$@" > /dev/null 2> stderr)
  fi
  local rc=$?
  set -e
  # The sanitizer build: ASan's three-line note on SystemC's coroutine stacks
  # (an exception thrown in an SC_THREAD) is not the tool's output.
  sed -i '/^==[0-9]*==WARNING: ASan is ignoring requested __asan_handle_no_return/,+2d' stderr
  local lines; lines=$(wc -l < stderr)
  if [ "$rc" -ne 2 ] || [ "$lines" -ne 1 ] || ! grep -qF -- "$want" stderr; then
    fail "$* -> rc=$rc, $lines stderr lines: $(head -c 600 stderr)"
  fi
  if [ -n "$(ls -A out)" ]; then fail "$* left files: $(ls -A out)"; fi
}

for tool in "$scurve sim" "$bench"; do
  # shellcheck disable=SC2086
  set -- $tool
  expect2 - "fst=/nonexistent/x.fst: directory /nonexistent does not exist" "$@" $move --fst /nonexistent/x.fst
  expect2 - "fst=out: is a directory" "$@" $move --fst out
  expect2 - "fst=/dev/full: exists and is not a regular file" "$@" $move --fst /dev/full
  expect2 - "fst-from=-1" "$@" $move --fst out/w.fst --fst-from -1
  expect2 - "fst-to=10: must be greater than fst-from=100" "$@" $move --fst out/w.fst --fst-from 100 --fst-to 10
  expect2 - "fst-from=010" "$@" $move --fst out/w.fst --fst-from 010
  expect2 - "--fst-to: sets the window of --fst" "$@" $move --fst-to 100
  expect2 1 "fst=out/w.fst: writing the waveform failed" "$@" $move --fst out/w.fst
done
expect2 - "fst=out/w.fst: --engine model-fast runs no RTL" "$scurve" sim $move --engine model-fast --fst out/w.fst
expect2 - "fst=out/w.fst: --engine model runs no RTL" "$scurve" sim $move --engine model --fst out/w.fst
cl="--closed-loop --tail 0.01"
expect2 - "--fst: trace one run at a time" "$scurve" sim $cl --compare --group 1 --fst out/w.fst
expect2 - "fst=out/w.fst: --engine model runs no RTL" "$scurve" sim $cl $move --engine model --fst out/w.fst
expect2 1 "fst=out/w.fst: writing the waveform failed" "$scurve" sim $cl $move --fst out/w.fst
expect2 - "fst-model=out: is a directory" "$bench" $move --fst-model out
expect2 1 "fst-model=out/m.fst: writing the waveform failed" "$bench" $move --fst-model out/m.fst
for tool in "$bench" ${pin_bench:+"$pin_bench"}; do
  expect2 - "trace-rtl=/nonexistent/r.csv" "$tool" $move --trace-rtl /nonexistent/r.csv
  expect2 - "trace-model=out" "$tool" $move --trace-model out
  expect2 1 "trace-rtl=out/r.csv" "$tool" $move --trace-rtl out/r.csv --trace-decimate 1
  expect2 - "group=010" "$tool" --group 010
  expect2 - "trace-decimate=0x10" "$tool" $move --trace-decimate 0x10
done
expect2 - "quantum=-1" "$bench" $move --quantum -1

# Good runs: the default window is bounded and said in --help; the files read
# back (the RTL's and the model's waveform compare equal port by port).
# (help captured first: grep -q closing the pipe early would fail the pipeline)
help=$("$scurve" sim --help)
grep -q "default: --fst-from + 200000" <<< "$help" || fail "sim --help does not give the default window"
"$scurve" sim $move --fst rtl.fst --fst-from 1000 > /dev/null || fail "sim --fst run failed"
"$scurve" sim $cl $move --fst cl.fst --fst-to 5000 > /dev/null || fail "closed-loop sim --fst run failed"
"$scurve" diff cl.fst cl.fst > /dev/null || fail "closed-loop waveform does not read back"
"$bench" $move --fst b_rtl.fst --fst-model b_model.fst --trace-rtl r.csv --trace-model m.csv > /dev/null \
  || fail "sc_bench run with outputs failed"
"$scurve" diff b_rtl.fst b_model.fst > /dev/null || fail "sc_bench RTL and model waveforms differ"
"$scurve" diff r.csv m.csv > /dev/null || fail "sc_bench RTL and model traces differ"
report=$("$scurve" diff rtl.fst b_model.fst --json) && fail "a window from clock 1000 compared equal to one from 0"
echo "$report" | python3 -c '
import json, sys
r = json.load(sys.stdin)
assert r["a_last_clock"] == 1000 + 200000 - 1, r["a_last_clock"]' || fail "waveform window is not the default 200000 clocks: $report"
ls ./*.part 2> /dev/null && fail ".part files left behind"
[ "$fails" -eq 0 ] || { echo "$fails failures" >&2; exit 1; }
echo "output files ok"
