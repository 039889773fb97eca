#!/usr/bin/env bash
# 7-series synthesis check with yosys: synth_xilinx -family xc7 of a top
# module; fails on any error or latch; writes a utilization report.
#   scripts/synth_yosys.sh [top] [outdir]      (default: sc_axis_core build/synth)
# Area budget (fails when over): SC_LUT_BUDGET / SC_DSP_BUDGET in the
# environment; sc_axis_core defaults to 3000 LUT and 8 DSP48E1 (issue 5).
# Sources: the files the top instantiates (scripts/rtl_deps.py), so a
# half-written module elsewhere in rtl/ does not break this check.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
top=${1:-sc_axis_core}
out=${2:-$here/build/synth}
mkdir -p "$out"
srcs=$(python3 "$here/scripts/rtl_deps.py" "$here/rtl" "$top")
# Xilinx primitives instantiated by the RTL (MMCME2_BASE, BUFG) as black boxes
xlib="read_verilog -lib -specify +/xilinx/cells_sim.v; read_verilog -lib +/xilinx/cells_xtra.v;"
log="$out/$top.yosys.log"
# read_verilog -sv (not the slang/surelog front ends): yosys 0.23 needs the
# package first. synth_xilinx keeps the hierarchy (no -flatten, no -abc9:
# both give more LUTs on the open-loop core, 1070 and 1019 against 813).
# Logic depth: the longest combinational path through the mapped netlist in
# cells (LUT, MUXF7/8, CARRY4, DSP48E1) from one flop or port to the next:
# on a flattened copy without flops (and the clock primitives, whose
# feedback is a loop), so ltp sees only the logic between registers.
yosys -q -l "$log" -p "
  $xlib
  read_verilog -sv $(echo $srcs | tr '\n' ' ');
  hierarchy -check -top $top;
  proc;
  select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr;
  synth_xilinx -family xc7 -top $top;
  select -assert-none t:LD* t:LDC* t:LDP*;
  tee -o $out/$top.stat.txt stat;
  write_verilog -noattr $out/$top.netlist.v;
  flatten;
  delete t:FD* t:MMCME2_BASE t:BUFG;
  tee -o $out/$top.depth.txt ltp -noff;
" >/dev/null
# A hierarchical design's stat lists every module and then the totals under
# "design hierarchy": count only the totals (else everything counts twice).
cell() { awk -v c="$1" '/=== design hierarchy ===/ {s=0} $1==c {s+=$2} END {print s+0}' "$out/$top.stat.txt"; }
luts=0; for l in LUT1 LUT2 LUT3 LUT4 LUT5 LUT6; do luts=$((luts + $(cell $l))); done
ffs=0; for f in FDRE FDSE FDCE FDPE; do ffs=$((ffs + $(cell $f))); done
lutram=0; for r in RAM32M RAM64M RAM32X1D RAM64X1D RAM128X1D RAM16X1D RAM32M16 RAM64X1S RAM32X1S; do lutram=$((lutram + $(cell $r))); done
carry=$(cell CARRY4); dsp=$(cell DSP48E1); bram=$(( $(cell RAMB18E1) + $(cell RAMB36E1) ))
depth=$(grep -o 'length=[0-9]*' "$out/$top.depth.txt" | head -1 | cut -d= -f2)
printf '{"top":"%s","lut":%d,"ff":%d,"carry4":%d,"dsp48e1":%d,"bram":%d,"lutram":%d,"logic_depth":%s}\n' \
  "$top" "$luts" "$ffs" "$carry" "$dsp" "$bram" "$lutram" "${depth:-0}" | tee "$out/$top.util.json"
# ---- area budget ---------------------------------------------------------------
lut_budget=${SC_LUT_BUDGET:-}; dsp_budget=${SC_DSP_BUDGET:-}
if [ "$top" = sc_axis_core ]; then lut_budget=${lut_budget:-3000}; dsp_budget=${dsp_budget:-8}; fi
if [ -n "$lut_budget" ] && [ "$luts" -gt "$lut_budget" ]; then
  echo "synth_yosys: $top uses $luts LUT > budget $lut_budget" >&2; exit 1
fi
if [ -n "$dsp_budget" ] && [ "$dsp" -gt "$dsp_budget" ]; then
  echo "synth_yosys: $top uses $dsp DSP48E1 > budget $dsp_budget" >&2; exit 1
fi
