#!/usr/bin/env python3
"""RTL coverage of the default regression: Verilator line, toggle and user
(cover point) coverage of every Verilated top, merged, reported and held to
floors.

  scripts/coverage.py [--build-dir build-cov] [--jobs N] [--skip-build] [--skip-run]
                      [--json FILE] [--html DIR] [--tests REGEX]

1. configures and builds the coverage build (cmake -DSC_COVERAGE=ON) in
   --build-dir;
2. runs the default suite there (ctest -LE 'long|extended', without the four
   full-length paper groups: 1.3 G clocks that reach no line or bit the short
   moves do not) with SC_COVERAGE_DIR set: each test process writes its
   counters (tb/coverage_sink.h);
3. merges them (verilator_coverage --write), writes an lcov tracefile and an
   HTML report (genhtml) and an annotated source tree;
4. prints line / toggle / user coverage per module and in total, after the
   exclusions of scripts/coverage_exclusions.json (each with its reason), and
   checks the floors: 95 % line, 90 % toggle, every cover point hit.
Exit status: 0 when the floors hold, 1 when one does not, 2 on bad usage or a
failed build/run step.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import time
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
FLOORS = {"line": 95.0, "toggle": 90.0, "user": 100.0}
# Full-length paper groups: minutes of coverage-instrumented simulation each.
SLOW_TESTS = r"FullLengthLockstepIsExactAndInPhase"


def fail(msg, code=2):
    print(f"error: {msg}", file=sys.stderr)
    sys.exit(code)


def run(cmd, **kw):
    print("+ " + " ".join(str(c) for c in cmd), flush=True)
    r = subprocess.run([str(c) for c in cmd], **kw)
    return r.returncode


def parse_key(key):
    """A coverage point's key: \\x01name\\x02value pairs."""
    fields = {}
    for part in key.split("\x01"):
        if "\x02" in part:
            k, v = part.split("\x02", 1)
            fields[k] = v
    return fields


def read_points(path):
    points = {}
    with open(path, encoding="utf-8", errors="surrogateescape") as f:
        for line in f:
            if not line.startswith("C '"):
                continue
            end = line.rfind("' ")
            points[line[3:end]] = points.get(line[3:end], 0) + int(line[end + 2:])
    return points


def load_exclusions(path):
    try:
        rules = json.loads(Path(path).read_text(encoding="utf-8"))["exclusions"]
    except (OSError, ValueError, KeyError) as e:
        fail(f"--exclusions {path}: {e}")
    for i, r in enumerate(rules):
        for k in ("type", "module", "point", "reason"):
            if k not in r:
                fail(f"--exclusions {path}: exclusion {i} has no '{k}'")
        if r["type"] not in FLOORS:
            fail(f"--exclusions {path}: exclusion {i}: type={r['type']!r}, must be one of {', '.join(FLOORS)}")
        r["module_re"] = re.compile(r["module"])
        r["point_re"] = re.compile(r["point"])
        r["matched"] = 0
    return rules


def instance_free(points):
    """One point per place in the source: the same line, bit or cover point
    of a module counts once however many tops instantiate it (hit if any
    instance hit it). A cover point inside a generate loop keeps its
    generate path (g_x__BRA__3__KET__.c_y) to stay apart from its siblings."""
    merged = {}
    for key, count in points.items():
        f = parse_key(key)
        hier = f.pop("h", "")
        if f.get("page", "").startswith("v_user/"):
            tail = []
            for part in reversed(hier.split(".")):
                tail.insert(0, part)
                if "__BRA__" not in part and part != f.get("o"):
                    tail.pop(0)
                    break
            f["gen"] = ".".join(tail)
        ident = tuple(sorted(f.items()))
        merged[ident] = merged.get(ident, 0) + count
    return merged


def summarize(points, rules):
    """{type: {module: [hit, total]}} after exclusions; the misses by type."""
    table = defaultdict(lambda: defaultdict(lambda: [0, 0]))
    misses = defaultdict(list)
    for ident, count in instance_free(points).items():
        f = dict(ident)
        page = f.get("page", "")
        kind = page.split("/")[0].removeprefix("v_")
        if kind not in FLOORS:
            continue   # branch points count as lines in Verilator 5.006 ('v_branch'): reported with lines
        module = page.split("/", 1)[1] if "/" in page else "?"
        what = f.get("gen") or f.get("o", "")
        where = f"{f.get('f', '?')}:{f.get('l', '?')}"
        rule = next((r for r in rules if r["type"] == kind and r["module_re"].fullmatch(module)
                     and r["point_re"].search(what)), None)
        if rule:
            rule["matched"] += 1
            continue
        cell = table[kind][module]
        cell[1] += 1
        if count > 0:
            cell[0] += 1
        else:
            misses[kind].append(f"{module} {where} {what}")
    return table, misses


def pct(hit, total):
    return 100.0 * hit / total if total else 100.0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build-dir", type=Path, default=ROOT / "build-cov")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    ap.add_argument("--skip-build", action="store_true", help="use the build as it is")
    ap.add_argument("--skip-run", action="store_true", help="report on the counters already collected")
    ap.add_argument("--tests", help="ctest -R REGEX: a subset (the floors then only inform)")
    ap.add_argument("--exclusions", type=Path, default=ROOT / "scripts" / "coverage_exclusions.json")
    ap.add_argument("--json", type=Path, help="write the summary as JSON")
    ap.add_argument("--html", type=Path, help="HTML report directory (default BUILD/coverage/html)")
    args = ap.parse_args()
    if args.jobs < 1 or args.jobs > 256:
        fail(f"--jobs={args.jobs}: must be from 1 to 256")
    rules = load_exclusions(args.exclusions)
    build = args.build_dir.resolve()
    cov = build / "coverage"
    raw = cov / "raw"
    html = (args.html or cov / "html").resolve()
    t0 = time.monotonic()

    if not args.skip_build:
        if run(["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release", "-DSC_COVERAGE=ON"],
               stdout=subprocess.DEVNULL):
            fail("cmake configure failed")
        if run(["cmake", "--build", build, "-j", args.jobs]):
            fail("coverage build failed")
    if not args.skip_run:
        raw.mkdir(parents=True, exist_ok=True)
        for old in raw.glob("*.dat"):
            old.unlink()
        sel = ["-R", args.tests] if args.tests else ["-LE", "^(long|extended)$", "-E", SLOW_TESTS]
        env = dict(os.environ, SC_COVERAGE_DIR=str(raw))
        rc = run(["ctest", "--test-dir", build, "-j", args.jobs, "--output-on-failure", *sel], env=env)
        if rc:
            fail(f"the regression failed under coverage (ctest exit {rc}): fix that first")
    parts = sorted(raw.glob("*.dat"))
    if not parts:
        fail(f"no coverage counters in {raw}: is {build} a coverage build (-DSC_COVERAGE=ON)?")
    merged = cov / "merged.dat"
    if run(["verilator_coverage", "--write", merged, *parts], stdout=subprocess.DEVNULL):
        fail("verilator_coverage --write failed")
    info = cov / "merged.info"
    run(["verilator_coverage", "--write-info", info, merged], stdout=subprocess.DEVNULL)
    run(["verilator_coverage", "--annotate", cov / "annotated", "--annotate-min", "1", merged],
        stdout=subprocess.DEVNULL)
    if run(["genhtml", "--quiet", "--output-directory", html, "--title", "scurve RTL coverage", info],
           stdout=subprocess.DEVNULL):
        print("warning: genhtml failed (package lcov): no HTML report", file=sys.stderr)

    table, misses = summarize(read_points(merged), rules)
    modules = sorted({m for k in table for m in table[k]})
    print(f"\nRTL coverage over {len(parts)} test processes ({time.monotonic() - t0:.0f} s)")
    print(f"{'module':<22} {'line':>14} {'toggle':>16} {'user':>10}")
    for m in modules:
        cells = []
        for kind, w in (("line", 14), ("toggle", 16), ("user", 10)):
            hit, total = table[kind].get(m, [0, 0])
            cells.append(f"{pct(hit, total):5.1f}% {hit:>4}/{total:<4}".rjust(w) if total else "-".rjust(w))
        print(f"{m:<22} {cells[0]} {cells[1]} {cells[2]}")
    totals = {k: [sum(c[0] for c in table[k].values()), sum(c[1] for c in table[k].values())] for k in FLOORS}
    print(f"{'total':<22} " + " ".join(f"{pct(*totals[k]):5.1f}% {totals[k][0]}/{totals[k][1]}" for k in FLOORS))
    excluded = [r for r in rules if r["matched"]]
    print(f"excluded: {sum(r['matched'] for r in rules)} points by {len(excluded)} of {len(rules)} rules "
          f"({args.exclusions.relative_to(ROOT) if args.exclusions.is_relative_to(ROOT) else args.exclusions})")
    verdict = {}
    for kind, floor in FLOORS.items():
        value = pct(*totals[kind])
        verdict[kind] = value >= floor
        if not verdict[kind]:
            print(f"FLOOR: {kind} coverage {value:.2f} % < {floor} %; first misses:")
            for m in misses[kind][:15]:
                print(f"  {m}")
    unused = [r["point"] for r in rules if not r["matched"]]
    if unused:
        print(f"note: {len(unused)} exclusion rules matched nothing: {unused}")
    print(f"report: {html}/index.html, annotated sources {cov / 'annotated'}, merged {merged}")
    if args.json:
        args.json.write_text(json.dumps({
            "processes": len(parts),
            "totals": {k: {"hit": v[0], "total": v[1], "percent": round(pct(*v), 2), "floor": FLOORS[k]}
                       for k, v in totals.items()},
            "modules": {m: {k: dict(zip(("hit", "total"), table[k].get(m, [0, 0]))) for k in FLOORS}
                        for m in modules},
            "misses": {k: v for k, v in misses.items()},
            "exclusions": [{"type": r["type"], "module": r["module"], "point": r["point"], "reason": r["reason"],
                            "matched": r["matched"]} for r in rules],
            "pass": all(verdict.values()),
        }, indent=2) + "\n", encoding="utf-8")
    if args.tests:
        return 0
    return 0 if all(verdict.values()) else 1


if __name__ == "__main__":
    sys.exit(main())
