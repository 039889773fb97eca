#!/usr/bin/env python3
"""Area of every synthesizable top: runs scripts/synth_yosys.sh on each (two at
a time), prints a Markdown table (the README's) and writes one JSON file.

    scripts/area_report.py [--out build/synth-report] [--tops sc_axis_core ...]

LUT counts: "lut" = LUT1..LUT6 (logic), "lut_mem" = LUTs used as memory
(RAM32M = 4), "lut_total" = both (what Vivado calls Slice LUTs).
"""
import argparse
import concurrent.futures
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
# A top with parameters: "top:Name=Value,..." (synth_yosys.sh's SC_SYNTH_PARAMS).
TOPS = ["sc_axis_core", "sc_multi_axis_core", "sc_multi_axis_core:Servo=1", "sc_servo_axis", "sc_neuron_pi",
        "sc_axi_regs", "sc_uart_bridge", "sc_axi_axis", "sc_axi_servo", "sc_board_top"]
COLUMNS = ["lut", "lut_mem", "lut_total", "ff", "carry4", "dsp48e1", "bram", "logic_depth"]


def synth(entry, out):
    top, _, params = entry.partition(":")
    env = dict(os.environ, SC_SYNTH_PARAMS=" ".join(p for p in params.split(",") if p))
    where = os.path.join(out, entry.replace(":", "_").replace("=", "").replace(",", "_"))
    run = subprocess.run([os.path.join(HERE, "synth_yosys.sh"), top, where], capture_output=True, text=True, env=env)
    if run.returncode != 0:
        raise RuntimeError(f"{entry}: synthesis failed\n{run.stderr[-2000:]}")
    with open(os.path.join(where, f"{top}.util.json")) as f:
        return json.load(f)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=os.path.join(ROOT, "build", "synth-report"))
    ap.add_argument("--tops", nargs="+", default=TOPS)
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    results = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = {pool.submit(synth, t, args.out): t for t in args.tops}
        for fut in concurrent.futures.as_completed(futures):
            top = futures[fut]
            results[top] = fut.result()
            print(f"  synthesized {top}: {results[top]['lut_total']} LUT", file=sys.stderr, flush=True)
    print("| top | " + " | ".join(COLUMNS) + " |")
    print("|---|" + "---|" * len(COLUMNS))
    for top in args.tops:
        r = results[top]
        print(f"| {top} | " + " | ".join(str(r[c]) for c in COLUMNS) + " |")
    with open(os.path.join(args.out, "area.json"), "w") as f:
        json.dump([results[t] for t in args.tops], f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
