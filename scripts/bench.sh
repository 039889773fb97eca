#!/usr/bin/env bash
# Throughput benchmark (Google Benchmark): lockstep, RTL only, model only and
# the model's fast-forward on the same move. Prints simulated clocks per wall
# second and the ratio to real time (20 M clocks/s); writes build/bench.json.
# Run on a quiet machine: other processes on the same core skew the figures.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
"$here/scripts/build.sh" >/dev/null
"$here/build/bin/bench_sim" --benchmark_out="$here/build/bench.json" --benchmark_out_format=json \
  --benchmark_counters_tabular=true "$@"
