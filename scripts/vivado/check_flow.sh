#!/usr/bin/env bash
# ctest vivado_flow_dry_run: build.tcl + XDC run under tclsh with stubbed
# Vivado commands for both board tops, and build.tcl reads exactly the files
# rtl_deps.py lists for each.
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:-$(mktemp -d)}
for top in sc_board_top sc_board_xy_top; do
  got=$(tclsh "$here/scripts/vivado/stub_check.tcl" "$out/$top" "$top" | sed -n 's/^RTL //p')
  want=$(python3 "$here/scripts/rtl_deps.py" "$here/rtl" "$top" | sed "s#^rtl/#$here/rtl/#")
  if [ "$got" != "$want" ]; then
    echo "scripts/vivado/build.tcl reads for $top:"; echo "$got"; echo "rtl_deps.py $top:"; echo "$want"
    exit 1
  fi
  echo "$top: build.tcl and its XDC run clean under tclsh; $(echo "$got" | wc -l) RTL files match rtl_deps.py"
done
