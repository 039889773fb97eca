#!/usr/bin/env python3
"""RTL coverage of the default regression: Verilator line, toggle and user
(cover point) coverage of every Verilated top, merged, reported and held to
floors.

  scripts/coverage.py [--build-dir build-cov] [--jobs N] [--skip-build] [--skip-run]
                      [--kinds line,user,toggle] [--json FILE] [--html DIR] [--tests REGEX]
                      [--profile full|ci] [--per-test] [--minimize FILE]

Two coverage builds, because toggle points make a simulation about 20 times
slower and line and user points barely:
1. BUILD-line (cmake -DSC_COVERAGE=ON -DSC_COVERAGE_KINDS="line;user"):
   the tests CI runs (ctest -LE long: the default suite and its extended
   tier), without the four full-length paper groups (1.3 G clocks that reach
   no line the short moves do not), with SC_COVERAGE_DIR set: each test
   process writes its counters (tb/coverage_sink.h);
2. BUILD-toggle (SC_COVERAGE_KINDS=toggle): the short runs of TOGGLE_TESTS,
   chosen to drive every module's registers through their values;
3. merges all counters (verilator_coverage --write), writes an lcov
   tracefile and an HTML report (genhtml) and an annotated source tree;
4. prints line / toggle / user coverage per module and in total (Verilator's
   branch points count as lines), after the exclusions of
   scripts/coverage_exclusions.json (each with its reason), and checks the
   floors of the kinds measured: 95 % line, 90 % toggle, every cover point
   hit.

--profile ci instead builds once with the kinds of --kinds (all three by
default; the CI stage asks for line and user, since toggle points make the
build and the runs about three times longer) and runs
only the tests of scripts/coverage_ci.json: a subset of the default
regression. A subset's coverage is a lower bound of the whole regression's,
so floors that hold on it hold on the regression. --per-test runs each
candidate with its own counters (and times it); --minimize FILE then picks,
greedily by new points per second, tests until they hit every cover point
the candidates hit and line and toggle coverage --margin points above the
floors, and writes them to FILE.
"""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time
from collections import defaultdict
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
FLOORS = {"line": 95.0, "toggle": 90.0, "user": 100.0}
# Full-length paper groups: minutes of coverage-instrumented simulation each.
# Also left out: the host driver against the virtual board over a pty, whose
# 200 ms answer timeouts the instrumented board misses on a loaded machine
# (the same UART frames run in board.BoardUart.* and board.RegisterFuzz.*).
SLOW_TESTS = r"FullLengthLockstepIsExactAndInPhase|tools\.board_driver_over_a_pty|tools\.python_board_drives_the"
# Labels outside what CI runs (the default and extended tiers), the Slurm
# cluster run (the same regression as a local one), and those that simulate
# no Verilated RTL (synthesis, lint, formal, the host planner).
NO_RTL_OR_LONG = r"^(long|slurm|coverage|mutation|synth|lint|formal|planner)$"
# The toggle runs: short tests that between them drive each module's
# registers through their range (raw tables with reversals and overruns,
# stops of every kind, streams, the register file and UART, the controller
# alone and in the loop, the decoder, switches and homing).
TOGGLE_TESTS = "|".join([
    r"core\.Lockstep/RawTableSeed\.",
    r"core\.Lockstep\.(DirSetupAndHold|ReversalWithSteps|StepQueuePeaks|FullFifo|RowPastAFullFifo)",
    r"core\.CoreStop\.",
    r"core\.StopGen(Lockstep|Edges)\.",
    r"closed_loop\.NeuronPiLockstep\.",
    r"closed_loop\.QuadDecoderLockstep\.",
    r"closed_loop\.ClosedLoopLockstep\.UnequalLearningRates",
    r"board\.AxiRegs\.",
    r"board\.BoardUart\.",
    r"board\.(AxiServo|Guard|LimitSwitch|SwitchFilter|IndexLatch)\.",
    r"board\.Homing\.RandomHomingsInRtlLockstep",
])
# Phase: (name, build-directory suffix, SC_COVERAGE_KINDS, kinds it measures, ctest selection,
#         targets to build: all for the whole suite, the binaries of the selection otherwise)
PHASES = [
    ("line+user", "line", "line;user", ("line", "user"),
     ["-LE", NO_RTL_OR_LONG, "-E", SLOW_TESTS], []),
    ("toggle", "toggle", "toggle", ("toggle",), ["-R", TOGGLE_TESTS],
     ["core_tests", "stop_tests", "cl_tests", "board_tests"]),
]


# The CI profile: one build with every kind, the selection of CI_SELECTION.
# Its candidates (for --minimize): the toggle runs and the short stops and
# directed tests that reach the executor's stream paths. Not the random
# stream campaigns (core.StreamLockstep, core.StreamRun): over 10 minutes
# each with toggle points.
CI_SELECTION = ROOT / "scripts" / "coverage_ci.json"
# The tops (Verilator PREFIXes) that no candidate runs: the multi-axis cores
# alone (their modules are counted inside sc_axi_multi_axis and the two-axis
# board top). The CI build compiles them without coverage at -O0, to link.
CI_PLAIN_TOPS = ["Vsc_multi_axis_core2", "Vsc_multi_axis_core3", "Vsc_multi_servo_core2"]
CI_CANDIDATES = TOGGLE_TESTS + "|" + "|".join([
    r"core\.MutationGaps\.",
    r"core\.Lockstep\.(StopAtRandomTimes|RandomRawTables)",
    r"closed_loop\.(ClosedLoopStop|ClosedLoopPins|ServoAxisPins)\.",
    r"board\.(HomeLatch|SoftLimit|RegisterFuzz)\.",
])


def ci_phase(per_test):
    """The CI profile's one phase: the committed selection, or with
    --per-test (to choose it) every candidate."""
    if per_test:
        return ("ci", "ci", "line;user;toggle", ("line", "user", "toggle"), ["-R", CI_CANDIDATES],
                ["core_tests", "stop_tests", "cl_tests", "board_tests"])
    try:
        sel = json.loads(CI_SELECTION.read_text(encoding="utf-8"))
        tests, targets = sel["tests"], sel["targets"]
    except (OSError, ValueError, KeyError) as e:
        fail(f"{CI_SELECTION}: {e}")
    if not tests:
        fail(f"{CI_SELECTION}: 'tests' is empty")
    return ("ci", "ci", "line;user;toggle", ("line", "user", "toggle"),
            ["-R", "^(" + "|".join(ctest_escape(t) for t in tests) + ")$"], targets)


def ctest_escape(name):
    """A test name as a literal in ctest's (CMake's) regular expressions."""
    return re.sub(r"([.\[\]()*+?^$|\\])", r"\\\1", name)


def fail(msg, code=2):
    print(f"error: {msg}", file=sys.stderr)
    sys.exit(code)


def run(cmd, **kw):
    shown = [str(c) for c in cmd[:8]] + ([f"... ({len(cmd) - 8} more)"] if len(cmd) > 8 else [])
    print("+ " + " ".join(shown), flush=True)
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


# Verilator's suffix of a parameterised module's name: one part per
# parameter given, joined by "_" (sc_axis_core__Ez1, sc_axis_core__Ez1_Sz2).
VARIANT = re.compile(r"__[A-Z][A-Za-z0-9]*(_[A-Z][A-Za-z0-9]*)*$")


def instance_free(points):
    """One point per place in the source: the same line, bit or cover point
    of a module counts once however many tops instantiate it (hit if any
    instance hit it). A cover point inside a generate loop keeps its
    generate path (g_x__BRA__3__KET__.c_y) to stay apart from its siblings,
    but for a step Verilator's writer already merged (an index written as
    "*": g_x__BRA__*__KET__, or g_x[*__KET__ where it also folded the
    generate blocks below it, as inside a multi-axis core's g_axis loop).
    Parameterised variants (sc_axis_core__Ez1_Sz2, the servo's core) are the same
    source: a point counts once for them too."""
    merged = {}
    for key, count in points.items():
        f = parse_key(key)
        hier = f.pop("h", "")
        f["page"] = VARIANT.sub("", f.get("page", ""))
        if f.get("page", "").startswith("v_user/"):
            tail = []
            for part in reversed(hier.split(".")):
                tail.insert(0, part)
                if "__BRA__" not in part and part != f.get("o"):
                    tail.pop(0)
                    break
            f["gen"] = ".".join(t for t in tail if "*" not in t)
        ident = tuple(sorted(f.items()))
        merged[ident] = merged.get(ident, 0) + count
    return merged


def classify(ident, rules):
    """(kind, module, what, where, rule) of an instance-free point; kind None
    for a point that is no line, toggle or user point."""
    f = dict(ident)
    page = f.get("page", "")
    kind = page.split("/")[0].removeprefix("v_")
    if kind == "branch":
        kind = "line"   # Verilator 5.006 writes an if's arms as 'v_branch' points: they are lines
    if kind not in FLOORS:
        return None, None, None, None, None
    module = page.split("/", 1)[1] if "/" in page else "?"
    what = f.get("gen") or f.get("o", "")
    where = f"{f.get('f', '?')}:{f.get('l', '?')}"
    rule = next((r for r in rules if r["type"] == kind and r["module_re"].fullmatch(module)
                 and r["point_re"].search(what)), None)
    return kind, module, what, where, rule


def summarize(points, rules):
    """{type: {module: [hit, total]}} after exclusions; the misses by type."""
    table = defaultdict(lambda: defaultdict(lambda: [0, 0]))
    misses = defaultdict(list)
    for ident, count in instance_free(points).items():
        kind, module, what, where, rule = classify(ident, rules)
        if kind is None:
            continue
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


def read_all(dat_files):
    """The counters of these files added up."""
    points = {}
    for path in dat_files:
        for key, count in read_points(path).items():
            points[key] = points.get(key, 0) + count
    return points


def hit_points(points, rules):
    """The counted (not excluded) points that these counters hit."""
    hits = set()
    for ident, count in instance_free(points).items():
        if count > 0:
            kind, _, _, _, rule = classify(ident, rules)
            if kind is not None and rule is None:
                hits.add(ident)
    return hits


def list_tests(build, selection):
    """{name: binary} of the tests ctest selects (ctest --show-only=json-v1;
    a test whose binary is not built has no command: binary '')."""
    r = subprocess.run(["ctest", "--test-dir", str(build), "--show-only=json-v1", *selection],
                       capture_output=True, text=True)
    if r.returncode:
        fail(f"ctest --show-only in {build} failed: {r.stderr.strip()}")
    return {t["name"]: Path((t.get("command") or [""])[0]).name for t in json.loads(r.stdout)["tests"]}


def run_per_test(build, raw, selection, jobs):
    """Each selected test alone, with its own counter directory; their times."""
    tests = list_tests(build, selection)
    if not tests:
        fail(f"the selection {selection} names no test in {build}")
    times = {}
    failed = []

    def one(item):
        i, name = item
        out = raw / f"t{i:04d}"
        out.mkdir(parents=True, exist_ok=True)
        t = time.monotonic()
        r = subprocess.run(["ctest", "--test-dir", str(build), "--output-on-failure", "-R", f"^{ctest_escape(name)}$"],
                           env=dict(os.environ, SC_COVERAGE_DIR=str(out)), capture_output=True, text=True)
        return name, out.name, time.monotonic() - t, r

    with ThreadPoolExecutor(max_workers=jobs) as pool:
        for n, (name, sub, seconds, r) in enumerate(pool.map(one, enumerate(sorted(tests))), 1):
            ok = r.returncode == 0 and "No tests were found" not in r.stdout
            print(f"[{n}/{len(tests)}] {'ok  ' if ok else 'FAIL'} {seconds:7.1f} s  {name}", flush=True)
            if not ok:
                failed.append(name)
                print(r.stdout[-3000:], flush=True)
            times[name] = {"dir": sub, "seconds": round(seconds, 2), "binary": tests[name]}
    (raw / "tests.json").write_text(json.dumps(times, indent=1) + "\n", encoding="utf-8")
    if failed:
        fail(f"{len(failed)} tests failed under coverage: {', '.join(failed[:5])}: fix that first")


def minimize(raw, rules, out, margin):
    """Greedy selection: while a target is unmet, the test with the most
    new points toward the unmet targets per second. The targets: every
    cover point the candidates hit, and line and toggle coverage `margin`
    percentage points above their floors (or all the candidates hit, if
    less). A pick the later ones make redundant is dropped again. Writes the
    selection to `out`."""
    try:
        times = json.loads((raw / "tests.json").read_text(encoding="utf-8"))
    except (OSError, ValueError) as e:
        fail(f"--minimize needs the --per-test counters of {raw}: {e}")
    points, hits = {}, {}
    for name, t in times.items():
        own = read_all(sorted((raw / t["dir"]).glob("*.dat")))
        hits[name] = hit_points(own, rules)
        for key, count in own.items():
            points[key] = points.get(key, 0) + count
    table, _ = summarize(points, rules)
    totals = {k: sum(c[1] for c in table[k].values()) for k in FLOORS}
    kind_of = {}
    for ident in set().union(*hits.values()):
        kind_of[ident] = classify(ident, rules)[0]
    reach = {k: sum(1 for i in kind_of if kind_of[i] == k) for k in FLOORS}
    need = {k: min(reach[k], math.ceil(totals[k] * min(FLOORS[k] + margin, 100.0) / 100.0)) for k in FLOORS}
    need["user"] = reach["user"]

    def count(covered):
        c = defaultdict(int)
        for i in covered:
            c[kind_of[i]] += 1
        return c

    def met(covered):
        c = count(covered)
        return all(c[k] >= need[k] for k in FLOORS)

    chosen, covered = [], set()
    while not met(covered):
        have = count(covered)
        open_kinds = {k for k in FLOORS if have[k] < need[k]}
        name = max((n for n in hits if n not in chosen),
                   key=lambda n: (sum(1 for i in hits[n] - covered if kind_of[i] in open_kinds)
                                  / max(times[n]["seconds"], 0.5), n))
        chosen.append(name)
        covered |= hits[name]
    for name in sorted(chosen, key=lambda n: -times[n]["seconds"]):
        rest = set().union(*(hits[n] for n in chosen if n != name))
        if met(rest):
            chosen.remove(name)
    got = count(set().union(*(hits[n] for n in chosen)))
    selection = {
        "about": "The CI coverage selection (scripts/coverage.py --profile ci): tests of the default regression "
                 "chosen by scripts/coverage.py --profile ci --per-test --minimize FILE. Regenerate it when the "
                 "RTL or the tests change and the CI floors fail.",
        "tests": sorted(chosen),
        "targets": sorted({times[n]["binary"] for n in chosen}),
        "margin_points": margin,
        "percent": {k: round(pct(got[k], totals[k]), 2) for k in FLOORS},
        "candidates_percent": {k: round(pct(reach[k], totals[k]), 2) for k in FLOORS},
        "candidates": len(times),
        "seconds_candidates": round(sum(t["seconds"] for t in times.values()), 1),
        "seconds_selected": round(sum(times[n]["seconds"] for n in chosen), 1),
    }
    out.write_text(json.dumps(selection, indent=2) + "\n", encoding="utf-8")
    print(f"minimize: {len(chosen)} of {len(times)} tests, {selection['seconds_selected']} s of "
          f"{selection['seconds_candidates']} s: " +
          ", ".join(f"{k} {selection['percent'][k]} % (candidates {selection['candidates_percent'][k]} %)"
                    for k in FLOORS) + f": {out}")


def pct(hit, total):
    return 100.0 * hit / total if total else 100.0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build-dir", type=Path, default=ROOT / "build-cov",
                    help="prefix of the coverage builds: BUILD-line and BUILD-toggle (default build-cov)")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    ap.add_argument("--kinds", default="line,user,toggle",
                    help="the kinds to measure, comma-separated (line and user come from one build)")
    ap.add_argument("--skip-build", action="store_true", help="use the builds as they are")
    ap.add_argument("--skip-run", action="store_true", help="report on the counters already collected")
    ap.add_argument("--tests", help="ctest -R REGEX instead of each phase's selection (the floors then only inform)")
    ap.add_argument("--exclusions", type=Path, default=ROOT / "scripts" / "coverage_exclusions.json")
    ap.add_argument("--json", type=Path, help="write the summary as JSON")
    ap.add_argument("--html", type=Path, help="HTML report directory (default BUILD/html)")
    ap.add_argument("--profile", choices=("full", "ci"), default="full",
                    help="full: the two builds over the default regression; ci: one build, the tests of "
                         "scripts/coverage_ci.json")
    ap.add_argument("--per-test", action="store_true",
                    help="run each test alone with its own counters and time it (to --minimize)")
    ap.add_argument("--minimize", type=Path, metavar="FILE",
                    help="after a --per-test run, write a quick selection that holds the floors with --margin")
    ap.add_argument("--margin", type=float, default=1.0,
                    help="percentage points above the line and toggle floors the selection keeps (default 1)")
    args = ap.parse_args()
    if args.jobs < 1 or args.jobs > 256:
        fail(f"--jobs={args.jobs}: must be from 1 to 256")
    kinds = [k.strip() for k in args.kinds.split(",") if k.strip()]
    for k in kinds:
        if k not in FLOORS:
            fail(f"--kinds={args.kinds}: '{k}' is not one of {', '.join(FLOORS)}")
    if not kinds:
        fail(f"--kinds={args.kinds!r}: names no kind")
    if args.minimize and not args.per_test:
        fail(f"--minimize={args.minimize}: needs --per-test (the counters of each test)")
    if args.minimize and set(kinds) != set(FLOORS):
        fail(f"--minimize={args.minimize}: chooses the selection on every kind: not with --kinds={args.kinds}")
    if args.minimize and args.profile != "ci":
        fail(f"--minimize={args.minimize}: chooses the CI selection: needs --profile ci")
    if not 0.0 <= args.margin <= 10.0:
        fail(f"--margin={args.margin}: must be from 0 to 10 percentage points")
    if args.per_test and args.tests:
        fail(f"--tests={args.tests}: not with --per-test, whose candidates are the phase's selection")
    rules = load_exclusions(args.exclusions)
    prefix = args.build_dir.resolve()
    report = prefix.parent / (prefix.name + "-report")
    html = (args.html or report / "html").resolve()
    t0 = time.monotonic()

    parts = []
    phases = [ci_phase(args.per_test)] if args.profile == "ci" else PHASES
    for name, suffix, cmake_kinds, measures, selection, targets in phases:
        if not set(measures) & set(kinds):
            continue
        if name == "ci":
            # one build with the kinds asked for (CI: line and user; toggle
            # points make the build and the runs several times longer)
            measures = tuple(k for k in measures if k in kinds)
            cmake_kinds = ";".join(measures)
        build = prefix.parent / f"{prefix.name}-{suffix}"
        raw = build / "coverage" / "raw"
        if not args.skip_build:
            print(f"== {name}: build {build}", flush=True)
            plain = ";".join(CI_PLAIN_TOPS) if name == "ci" else ""
            # Without toggle points the CI selection's runs take about two
            # minutes and its build several: the Verilated code at -O1
            # builds faster than it then runs slower.
            # The host C++ (model, benches, tests) likewise at -O1: it is
            # most of the build, and the instrumented RTL most of the runs.
            quick = name == "ci" and "toggle" not in measures
            opt = "-O1" if quick else ""
            host_flags = [f"-DCMAKE_CXX_FLAGS_RELEASE={'-O1' if quick else '-O3'} -DNDEBUG"]
            if run(["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release", "-DSC_COVERAGE=ON",
                    f"-DSC_COVERAGE_KINDS={cmake_kinds}", f"-DSC_COVERAGE_PLAIN_TOPS={plain}",
                    f"-DSC_VERILATE_OPT={opt}", *host_flags],
                   stdout=subprocess.DEVNULL):
                fail(f"cmake configure of {build} failed")
            if run(["cmake", "--build", build, "-j", args.jobs] + (["--target", *targets] if targets else [])):
                fail(f"coverage build {build} failed")
        if not args.skip_run:
            print(f"== {name}: run", flush=True)
            if raw.exists():
                shutil.rmtree(raw)
            raw.mkdir(parents=True)
            sel = ["-R", args.tests] if args.tests else selection
            if args.per_test:
                run_per_test(build, raw, sel, args.jobs)
            else:
                if not list_tests(build, sel):
                    fail(f"the selection {sel} names no test in {build}")
                env = dict(os.environ, SC_COVERAGE_DIR=str(raw))
                rc = run(["ctest", "--test-dir", build, "-j", args.jobs, "--output-on-failure", *sel], env=env)
                if rc:
                    fail(f"the regression failed under {name} coverage (ctest exit {rc}): fix that first")
        if args.minimize:
            minimize(raw, rules, args.minimize, args.margin)
        found = sorted(raw.rglob("*.dat"))
        if not found:
            fail(f"no coverage counters in {raw}: run without --skip-run first")
        parts += found
    report.mkdir(parents=True, exist_ok=True)
    merged = report / "merged.dat"
    if run(["verilator_coverage", "--write", merged, *parts], stdout=subprocess.DEVNULL):
        fail("verilator_coverage --write failed")
    info = report / "merged.info"
    run(["verilator_coverage", "--write-info", info, merged], stdout=subprocess.DEVNULL)
    run(["verilator_coverage", "--annotate", report / "annotated", "--annotate-min", "1", merged],
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
    totals = {k: [sum(c[0] for c in table[k].values()), sum(c[1] for c in table[k].values())] for k in kinds}
    print(f"{'total':<22} " + " ".join(f"{k} {pct(*v):5.1f}% {v[0]}/{v[1]}" for k, v in totals.items()))
    excluded = [r for r in rules if r["matched"]]
    print(f"excluded: {sum(r['matched'] for r in rules)} points by {len(excluded)} of {len(rules)} rules "
          f"({args.exclusions.relative_to(ROOT) if args.exclusions.is_relative_to(ROOT) else args.exclusions})")
    (report / "misses.txt").write_text("".join(f"{k} {m}\n" for k in kinds for m in misses[k]), encoding="utf-8")
    verdict = {}
    for kind in kinds:
        floor = FLOORS[kind]
        value = pct(*totals[kind])
        verdict[kind] = value >= floor
        if not verdict[kind]:
            print(f"FLOOR: {kind} coverage {value:.2f} % < {floor} %; first misses (all in {report / 'misses.txt'}):")
            for m in misses[kind][:15]:
                print(f"  {m}")
    unused = [r["point"] for r in rules if not r["matched"] and r["type"] in kinds]
    if unused:
        print(f"note: {len(unused)} exclusion rules matched nothing: {unused}")
    print(f"report: {html}/index.html, annotated sources {report / 'annotated'}, merged {merged}")
    if args.json:
        args.json.write_text(json.dumps({
            "processes": len(parts),
            "totals": {k: {"hit": v[0], "total": v[1], "percent": round(pct(*v), 2), "floor": FLOORS[k]}
                       for k, v in totals.items()},
            "modules": {m: {k: dict(zip(("hit", "total"), table[k].get(m, [0, 0]))) for k in kinds}
                        for m in modules},
            "misses": {k: misses[k] for k in kinds},
            "exclusions": [{"type": r["type"], "module": r["module"], "point": r["point"], "reason": r["reason"],
                            "matched": r["matched"]} for r in rules],
            "pass": all(verdict.values()),
        }, indent=2) + "\n", encoding="utf-8")
    if args.tests:
        return 0
    return 0 if all(verdict.values()) else 1


if __name__ == "__main__":
    sys.exit(main())
