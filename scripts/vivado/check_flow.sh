#!/usr/bin/env bash
# ctest vivado_flow_dry_run: build.tcl + XDC run under tclsh with stubbed
# Vivado commands, and build.tcl reads exactly the files rtl_deps.py lists.
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:-$(mktemp -d)}
got=$(tclsh "$here/scripts/vivado/stub_check.tcl" "$out" | sed -n 's/^RTL //p')
want=$(python3 "$here/scripts/rtl_deps.py" "$here/rtl" sc_board_top | sed "s#^rtl/#$here/rtl/#")
if [ "$got" != "$want" ]; then
  echo "scripts/vivado/build.tcl reads:"; echo "$got"; echo "rtl_deps.py sc_board_top:"; echo "$want"
  exit 1
fi
echo "build.tcl and the XDC run clean under tclsh; $(echo "$got" | wc -l) RTL files match rtl_deps.py"
