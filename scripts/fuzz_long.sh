#!/usr/bin/env bash
# The long fuzz campaign: each harness of build-san/ (scripts/build.sh
# --sanitize) for RUNS executions from its committed corpus, one after the
# other, at low priority so it only takes idle CPU.
#   scripts/fuzz_long.sh [RUNS] [harness ...]     (default 10000000, every harness)
# New inputs go to build-san/fuzz-long/<harness>/new (never into the
# committed corpus: merge them with -merge=1, docs/verification.md); a
# finding stops that harness and leaves build-san/fuzz-long/<harness>/crash-*.
# Writes build-san/fuzz-long/summary.json and prints a table; exit 1 when
# any harness found something.
set -uo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
runs=${1:-10000000}
shift || true
harnesses=("$@")
if [ ${#harnesses[@]} -eq 0 ]; then
  harnesses=(fuzz_uart_response fuzz_fst_trace fuzz_scenario_json fuzz_stream_json fuzz_regress_results
             fuzz_kin_trace fuzz_regress_list)
fi
case "$runs" in
  ''|*[!0-9]*) echo "error: RUNS must be a positive decimal integer, got '$runs'" >&2; exit 2 ;;
esac
bin=$here/build-san/bin
out=$here/build-san/fuzz-long
mkdir -p "$out"
rows=()
status=0
for h in "${harnesses[@]}"; do
  if [ ! -x "$bin/$h" ]; then
    echo "error: harness '$h' not built in $bin (scripts/build.sh --sanitize)" >&2; exit 2
  fi
  work=$out/$h
  rm -rf "$work"; mkdir -p "$work/new"
  echo "== $h: $runs executions" >&2
  start=$(date +%s)
  nice -n 19 "$bin/$h" -runs="$runs" -timeout=10 -rss_limit_mb=2048 -max_len=4096 \
    -artifact_prefix="$work/" -print_final_stats=1 "$work/new" "$here/tests/fuzz/corpus/$h" \
    >"$work/log.txt" 2>&1
  rc=$?
  secs=$(( $(date +%s) - start ))
  done_runs=$(awk '/stat::number_of_executed_units/ {print $2}' "$work/log.txt" | tail -1)
  new_units=$(find "$work/new" -type f | wc -l)
  findings=$(find "$work" -maxdepth 1 -name 'crash-*' -o -maxdepth 1 -name 'timeout-*' -o -maxdepth 1 -name 'leak-*' \
             -o -maxdepth 1 -name 'oom-*' | wc -l)
  result=pass
  if [ "$rc" -ne 0 ] || [ "$findings" -ne 0 ]; then result=finding; status=1; fi
  printf '%-22s %12s runs %7s s  %6s new  %s\n' "$h" "${done_runs:-0}" "$secs" "$new_units" "$result" >&2
  rows+=("{\"harness\":\"$h\",\"runs\":${done_runs:-0},\"seconds\":$secs,\"new_inputs\":$new_units,\"result\":\"$result\"}")
done
(IFS=,; echo "{\"target_runs\":$runs,\"harnesses\":[${rows[*]}]}") >"$out/summary.json.tmp" \
  && mv "$out/summary.json.tmp" "$out/summary.json"
echo "summary: $out/summary.json" >&2
exit "$status"
