#!/usr/bin/python3
"""Throughput of the SystemC bench next to the plain C++ lockstep harness.

  scripts/bench_systemc.py [--build-dir build] [--group 1] [--short]

Runs, one after the other on one core each:
  plain     scurve sim --engine lockstep   (tb/sim_run.cpp, no SystemC)
  batched   sc_bench, quantum 20,000 clocks per wait() (temporal decoupling)
  quantum   sc_bench with smaller quanta (1,000 and 1 clock per wait())
  pin       sc_bench_pin: --sc DUT on an sc_clock, every port an sc_signal
and prints simulated clocks per second of wall time and of CPU time (user +
sys of the child, steadier on a shared machine) with the ratio to the plain
harness. The paper group runs in full for plain and batched; the slow
variants run a shorter move (about 34 M clocks) and are compared with the
plain harness on that same move.
"""
import argparse
import json
import os
import resource
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHORT = ["--distance", "3000", "--v-start", "0", "--v-cruise", "3000", "--v-end", "0",
         "--a-max", "5000", "--j-max", "50000"]


def run(cmd):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.monotonic()
    out = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
                         env=dict(os.environ, SYSTEMC_DISABLE_COPYRIGHT_MESSAGE="1"))
    wall = time.monotonic() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    j = json.loads(out.stdout[out.stdout.index("{"):])
    if not j.get("pass", False):
        sys.exit(f"{' '.join(cmd)}: run failed: {j.get('failures')}")
    return j["total_clocks"], wall, cpu


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build-dir", default=os.path.join(ROOT, "build"))
    ap.add_argument("--group", default="1")
    ap.add_argument("--short", action="store_true", help="only the short move (quick check)")
    a = ap.parse_args()
    b = os.path.join(a.build_dir, "bin")
    rows = []
    sets = [("short move", SHORT)] if a.short else [(f"group {a.group}", ["--group", a.group]), ("short move", SHORT)]
    for label, move in sets:
        full = move[0] == "--group"
        cases = [("plain harness (scurve sim)", [f"{b}/scurve", "sim", "--engine", "lockstep", "--json"] + move),
                 ("SystemC batched, quantum 20000", [f"{b}/sc_bench", "--json"] + move)]
        if not full:
            cases += [("SystemC batched, quantum 1000", [f"{b}/sc_bench", "--json", "--quantum", "1000",
                                                         "--sync-period", "1000"] + move),
                      ("SystemC batched, quantum 1", [f"{b}/sc_bench", "--json", "--quantum", "1",
                                                      "--sync-period", "1"] + move),
                      ("SystemC pin-accurate (--sc, sc_clock)", [f"{b}/sc_bench_pin", "--json"] + move)]
        base = None
        for name, cmd in cases:
            clocks, wall, cpu = run(cmd)
            per_cpu = clocks / cpu
            base = base or per_cpu
            rows.append((label, name, clocks, wall, clocks / wall / 1e6, per_cpu / 1e6, per_cpu / base))
            print(f"{label:<11} {name:<40} {clocks:>11} clocks {wall:7.2f} s wall "
                  f"{clocks / wall / 1e6:6.2f} M/s wall {per_cpu / 1e6:6.2f} M/s cpu  x{per_cpu / base:.2f}",
                  flush=True)
    print("\n| move | bench | clocks | wall s | M clocks/s (wall) | M clocks/s (CPU) | ratio to plain (CPU) |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r[0]} | {r[1]} | {r[2]:,} | {r[3]:.1f} | {r[4]:.2f} | {r[5]:.2f} | {r[6]:.2f} |")


if __name__ == "__main__":
    main()
