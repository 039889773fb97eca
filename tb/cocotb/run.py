#!/usr/bin/env python3
"""Build sc_axi_axis with Icarus and run the cocotb tests of
test_sc_axi_axis.py through cocotb's Python runner.

Usage: run.py --build-dir DIR [--python-path DIR] [--waves] [--test NAME]
  --build-dir    where Icarus's build, the log and results.xml (JUnit) go
  --python-path  where `import scurve` is found (the build's python/ folder)
Exit status: 0 when every test passed, 1 when one failed, 2 on bad usage.
The RTL file list comes from scripts/rtl_deps.py (package first).
"""
import argparse
import subprocess
import sys
from pathlib import Path

from cocotb_tools.check_results import get_results
from cocotb_tools.runner import get_runner

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent
TOP = "sc_axi_axis"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build-dir", required=True, type=Path)
    ap.add_argument("--python-path", type=Path, default=ROOT / "build" / "python")
    ap.add_argument("--waves", action="store_true", help="write an FST trace (sim_build/sc_axi_axis.fst)")
    ap.add_argument("--test", action="append", help="run only this test (repeatable)")
    args = ap.parse_args()
    if not any(args.python_path.glob("scurve*.so")):
        ap.error(f"--python-path: no scurve module in {args.python_path} (build the project first)")

    sources = subprocess.run([sys.executable, str(ROOT / "scripts" / "rtl_deps.py"), str(ROOT / "rtl"), TOP],
                             check=True, capture_output=True, text=True).stdout.split()
    runner = get_runner("icarus")
    build = args.build_dir.resolve()
    runner.build(sources=sources, hdl_toplevel=TOP, build_dir=build / "sim_build", build_args=["-g2012"],
                 timescale=("1ns", "1ps"), waves=args.waves, always=True)
    results = build / "results.xml"
    results.unlink(missing_ok=True)   # a crashed run must not leave the last run's verdict
    # The runner hands its sys.path to the simulator's Python as PYTHONPATH.
    sys.path[:0] = [str(HERE), str(args.python_path.resolve())]
    runner.test(hdl_toplevel=TOP, test_module="test_sc_axi_axis", test_dir=build, build_dir=build / "sim_build",
                results_xml=str(results), waves=args.waves,
                test_filter="|".join(rf"(^|\.){t}$" for t in args.test) if args.test else None)
    tests, failed = get_results(results)
    print(f"cocotb: {tests - failed} of {tests} passed ({results})")
    return 1 if failed or tests == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
