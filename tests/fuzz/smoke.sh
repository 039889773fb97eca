#!/usr/bin/env bash
# A short fuzz run of one harness from its committed corpus:
#   smoke.sh HARNESS CORPUS WORK_DIR SECONDS
# New inputs go to WORK_DIR (emptied first), never into the committed corpus;
# a crash, a hang (-timeout), a sanitizer report or an abort fails the test
# and leaves the input in WORK_DIR/crash-* for a regression test.
set -euo pipefail
harness=$1 corpus=$2 work=$3 seconds=$4
rm -rf "$work"
mkdir -p "$work/new"
exec "$harness" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=4096 \
  -artifact_prefix="$work/" -print_final_stats=1 "$work/new" "$corpus"
