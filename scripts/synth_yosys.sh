#!/usr/bin/env bash
# 7-series synthesis check with yosys: synth_xilinx -family xc7 of a top
# module; fails on any error or latch; writes a utilization report.
#   scripts/synth_yosys.sh [top] [outdir]      (default: sc_axis_core build/synth)
# SC_SYNTH_PARAMS="Name=Value ..." sets the top's parameters (chparam), e.g.
# SC_SYNTH_PARAMS="Servo=1" for the closed-loop capable multi-axis core.
# Area budget (fails when over): SC_LUT_BUDGET / SC_DSP_BUDGET in the
# environment; the single-axis cores (sc_axis_core, sc_servo_axis) default
# to 9700 LUT (logic + LUTs used as memory) and 8 DSP48E1: with the
# controlled-stop generator (about 3500 LUT in the servo axis, docs/stop.md),
# the row stream with retarget and the HOLD count and the soft-limit
# look-ahead's row reach evaluator (about 1500 LUT with its FIFO read port
# and reach column), the closed-loop axis measures 9163 (7622 before the
# look-ahead; the board top 10905 of the xc7a35t's 20800: 52.4 %). The
# margin covers yosys' own spread: the
# same sc_profile_exec source came out at 1138 or 1578 LUT inside
# sc_servo_axis when only the servo and sc_pkg changed elsewhere (the
# executor synthesized alone gives 5902 both times).
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
# both gave more LUTs on the open-loop core: 1070 and 1019 against 873).
# Logic depth: the longest combinational path through the mapped netlist in
# cells (LUT, MUXF7/8, CARRY4, DSP48E1) from one flop or port to the next:
# on a flattened copy without flops, LUT RAMs (their write side is a
# register; a read counts as a path start) and clock primitives (whose
# feedback is a loop), so ltp sees only the logic between registers.
chparams=""
for p in ${SC_SYNTH_PARAMS:-}; do
  chparams="$chparams chparam -set ${p%%=*} ${p#*=} $top;"
done
yosys -q -l "$log" -p "
  $xlib
  read_verilog -sv $(echo $srcs | tr '\n' ' ');
  $chparams
  hierarchy -check -top $top;
  proc;
  select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr;
  synth_xilinx -family xc7 -top $top;
  select -assert-none t:LD* t:LDC* t:LDP*;
  tee -o $out/$top.stat.txt stat;
  write_verilog -noattr $out/$top.netlist.v;
  flatten;
  delete t:FD* t:RAM32M t:RAM64M t:RAM32X1D t:RAM64X1D t:RAM128X1D t:RAM16X1D t:RAM32M16 t:RAM64X1S t:RAM32X1S t:MMCME2_BASE t:BUFG;
  tee -o $out/$top.depth.txt ltp -noff;
" >/dev/null
# A hierarchical design's stat lists every module and then the totals under
# "design hierarchy": count only the totals (else everything counts twice).
cell() { awk -v c="$1" '/=== design hierarchy ===/ {s=0} $1==c {s+=$2} END {print s+0}' "$out/$top.stat.txt"; }
luts=0; for l in LUT1 LUT2 LUT3 LUT4 LUT5 LUT6; do luts=$((luts + $(cell $l))); done
ffs=0; for f in FDRE FDSE FDCE FDPE; do ffs=$((ffs + $(cell $f))); done
lutram=0; for r in RAM32M RAM64M RAM32X1D RAM64X1D RAM128X1D RAM16X1D RAM32M16 RAM64X1S RAM32X1S; do lutram=$((lutram + $(cell $r))); done
# LUTs used as memory (Vivado's "LUT as Memory"): LUTs per LUTRAM primitive
lut_mem=$(( 4 * $(cell RAM32M) + 4 * $(cell RAM64M) + 8 * $(cell RAM32M16) + 2 * $(cell RAM32X1D) \
          + 2 * $(cell RAM64X1D) + 4 * $(cell RAM128X1D) + 2 * $(cell RAM16X1D) + $(cell RAM64X1S) + $(cell RAM32X1S) ))
carry=$(cell CARRY4); dsp=$(cell DSP48E1); bram=$(( $(cell RAMB18E1) + $(cell RAMB36E1) ))
depth=$(grep -o 'length=[0-9]*' "$out/$top.depth.txt" | head -1 | cut -d= -f2)
printf '{"top":"%s","lut":%d,"lut_mem":%d,"lut_total":%d,"ff":%d,"carry4":%d,"dsp48e1":%d,"bram":%d,"lutram":%d,"logic_depth":%s}\n' \
  "$top" "$luts" "$lut_mem" "$((luts + lut_mem))" "$ffs" "$carry" "$dsp" "$bram" "$lutram" "${depth:-0}" | tee "$out/$top.util.json"
# ---- area budget ---------------------------------------------------------------
lut_budget=${SC_LUT_BUDGET:-}; dsp_budget=${SC_DSP_BUDGET:-}
# the single-axis cores: open loop and with the closed loop
case "$top" in
  sc_axis_core|sc_servo_axis) lut_budget=${lut_budget:-9700}; dsp_budget=${dsp_budget:-8} ;;
  # two open-loop axes (its default Axes = 2): 13299 LUT, two single cores
  # and the one shared row reach evaluator; two closed-loop axes (Servo = 1):
  # 17663 LUT, 8 DSP, two servo axes and the evaluator
  sc_multi_axis_core)
    case " ${SC_SYNTH_PARAMS:-} " in
      *" Servo=1 "*) lut_budget=${lut_budget:-18500}; dsp_budget=${dsp_budget:-16} ;;
      *) lut_budget=${lut_budget:-14500}; dsp_budget=${dsp_budget:-0} ;;
    esac ;;
  # the two-axis board top: it must fit the xc7a35t (20800 LUT, 90 DSP48E1)
  sc_board_xy_top) lut_budget=${lut_budget:-20800}; dsp_budget=${dsp_budget:-90} ;;
esac
# the budget counts every LUT: logic and LUTs used as memory
if [ -n "$lut_budget" ] && [ "$((luts + lut_mem))" -gt "$lut_budget" ]; then
  echo "synth_yosys: $top uses $((luts + lut_mem)) LUT ($luts logic + $lut_mem memory) > budget $lut_budget" >&2; exit 1
fi
if [ -n "$dsp_budget" ] && [ "$dsp" -gt "$dsp_budget" ]; then
  echo "synth_yosys: $top uses $dsp DSP48E1 > budget $dsp_budget" >&2; exit 1
fi
