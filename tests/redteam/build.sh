#!/usr/bin/env bash
# Build a red-team probe against an existing build tree (default build-rt):
#   tests/redteam/build.sh probe_cases.cpp [build-dir]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
src=$1; b=${2:-$root/build-rt}
out=$b/redteam; mkdir -p "$out"
exe=$out/$(basename "${src%.cpp}")
c++ -O2 -flto=auto -std=gnu++20 -DFMT_SHARED -I"$root/tb" -I"$b/CMakeFiles/sc_rtl.dir/Vsc_axis_core.dir" \
  -I/usr/share/verilator/include -I/usr/share/verilator/include/vltstd -I"$root/cmodel" -I"$b/generated" \
  "$here/$src" -o "$exe" "$b/libsc_tb.a" "$b/libsc_rtl.a" "$b/libsc_model.a" \
  /usr/lib/x86_64-linux-gnu/libfmt.so -lz -pthread -latomic ${EXTRA_LIBS:-}
echo "$exe"
