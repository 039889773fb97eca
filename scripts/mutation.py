#!/usr/bin/env python3
"""Mutation testing of the RTL (docs/mutation.md).

The catalogue of mutants is generated from rtl/*.sv (scripts/mutation_catalogue.py):
operator swaps, constants off by one, negated conditions, swapped ternaries,
dropped terms and stuck right-hand sides, outside comments and the FORMAL /
SC_COVER code. Two campaigns run a sample of it:

  rtl_only     the RTL is mutated, the C++ model is not: lockstep should kill it;
  common_mode  the same change is made in the model's mirror statement: only the
               independent checks (pin monitor, planner closed form, properties,
               the model's closed-form fast path) can kill it.

Each mutant is applied to a copy of the committed tree (never to rtl/ or cmodel/
of the project), only the Verilated tops its tests run are rebuilt, and the
area's fast tests run with a time limit; a survivor of an open-loop module
then runs the servo suite, and a survivor of the simulations the module's
formal properties (formal.py --check-as-is). Survivors listed in
scripts/mutation_equivalent.json are reported as equivalent.

  scripts/mutation.py --list --area step_timing
  scripts/mutation.py --list --campaign common_mode --file sc_step_gen
  scripts/mutation.py --campaign rtl_only --area endpoint --sample 20 --seed 1 --json out.json
"""

from __future__ import annotations

import argparse
import dataclasses
import fnmatch
import hashlib
import json
import os
import random
import re
import shutil
import subprocess
import sys
import time
import xml.etree.ElementTree as ET
from collections import Counter
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import formal  # noqa: E402  (the property groups per module)
import mutation_catalogue as mc  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
CAMPAIGNS = ("rtl_only", "common_mode")
OUTCOMES = ("killed", "timeout", "build_error", "survived", "equivalent")
# Survivors shown equivalent (they change nothing the design promises), each
# with its reason: reported apart and left out of the kill rate.
EQUIVALENT_FILE = Path("scripts/mutation_equivalent.json")
BUILD_INPUTS = ("CMakeLists.txt", "cmake", "rtl", "cmodel", "sw", "tb", "tests")


@dataclasses.dataclass(frozen=True)
class Stage:
    binary: str
    gtest_filter: str


@dataclasses.dataclass(frozen=True)
class Suite:
    name: str
    live_tops: tuple[str, ...]
    stages: tuple[Stage, ...]


# The fast tests per RTL area, quickest killers first (a mutant stops at its
# first failing test). The full paper groups (11 minutes each) are left out.
OPEN_LOOP = Suite("open_loop", ("sc_axis_core",), (
    Stage("redteam_tests", "RedTeam.Lockstep*:RedTeam.F2_*:RedTeam.F3_*"),
    Stage("core_tests", "Lockstep/RawTableSeed.*:Lockstep.DirSetupAndHold*:Lockstep.ReversalWithSteps*:"
                        "Lockstep.StepQueuePeaks*:Lockstep.FullFifo*:Lockstep.RowPastAFullFifo*:StepQueue.*:"
                        "ExecFastForward.*:CoreFastForward.*"),
    Stage("stop_tests", "CoreStop.*:MutationGaps.*"),
    Stage("stream_tests", "StreamLockstep.*:StreamRun.*:StreamModel.*"),
    Stage("core_tests", "Lockstep.SixtyRandom*:Lockstep.StopAtRandomTimes*"),
))
SERVO = Suite("servo", ("sc_servo_axis",), (
    Stage("cl_tests", "ServoAxisPins.*:ClosedLoopLockstep.LongDirSetup*:ClosedLoopPins.*:ClosedLoopStop.*"),
))
SUITE_OF_MODULE = {
    "sc_step_gen": OPEN_LOOP, "sc_axis_core": OPEN_LOOP, "sc_profile_exec": OPEN_LOOP, "sc_row_fifo": OPEN_LOOP,
    "sc_stop_gen": OPEN_LOOP, "sc_step_nco": SERVO,
}
# The open-loop modules sit inside sc_servo_axis as well, where some of their
# logic only acts there (sc_axis_core's external step source, ExtStep = 1):
# a mutant that survives the open-loop suite runs the servo suite before it
# counts as a survivor.
SECOND_SUITE_OF_MODULE = {m: SERVO for m, s in SUITE_OF_MODULE.items() if s is OPEN_LOOP}
# Last, a survivor of the simulations meets the module's formal properties:
# scripts/formal.py --check-as-is, a bounded check of every group of the
# module from reset on the mutated RTL (a counterexample kills; a solver
# timeout or error proves nothing and does not).
FORMAL_STAGE = "formal.py"
FORMAL_SUITE_OF_MODULE = {
    m: Suite(f"formal_{m}", (), (Stage(FORMAL_STAGE, ",".join(g.name for g in formal.GROUPS if g.module == m)),))
    for m in sorted({g.module for g in formal.GROUPS})}


# ---- arguments -----------------------------------------------------------------------------------------------------

def parse_args(argv: list[str]) -> argparse.Namespace:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    p.add_argument("--root", type=Path, default=ROOT, help="project root (default: this script's tree)")
    p.add_argument("--list", action="store_true", help="print the (filtered) catalogue and exit")
    p.add_argument("--campaign", choices=CAMPAIGNS, default="rtl_only")
    p.add_argument("--file", action="append", default=[],
                   help="rtl file name or glob (sc_step_gen, sc_step_gen.sv, rtl/sc_*.sv); repeatable")
    p.add_argument("--module", action="append", default=[], help="module name; repeatable")
    p.add_argument("--operator", action="append", default=[], help=f"one of {', '.join(mc.OPERATORS)}; repeatable")
    p.add_argument("--area", action="append", default=[], help=f"one of {', '.join(mc.AREAS)}; repeatable")
    p.add_argument("--id", action="append", default=[], help="a mutant id (or glob); repeatable")
    p.add_argument("--sample", type=int, help="run (or list) N mutants per area, drawn with --seed")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--work-dir", type=Path, help="copy of the tree and its build (default: <root>/build-mutation)")
    p.add_argument("--jobs", type=int, default=2, help="build jobs (default 2)")
    p.add_argument("--timeout-factor", type=float, default=4.0,
                   help="a test stage times out after this many times its unmutated run (default 4)")
    p.add_argument("--min-test-timeout", type=float, default=60.0, help="seconds (default 60)")
    p.add_argument("--build-timeout", type=float, default=1200.0, help="seconds per build (default 1200)")
    p.add_argument("--stage", action="append", default=[], metavar="BINARY:FILTER",
                   help="test stage instead of the area's suite (with --live-tops); repeatable")
    p.add_argument("--live-tops", help="comma-separated Verilated tops to rebuild per mutant (with --stage)")
    p.add_argument("--resume", action="store_true", help="skip mutants already in the work dir's results")
    p.add_argument("--report", action="store_true",
                   help="no run: the report of the selected mutants already in the work dir's results")
    p.add_argument("--json", type=Path, help="write the catalogue (--list) or the results as JSON")
    p.add_argument("--junit", type=Path, help="write the results as JUnit XML")
    p.add_argument("--min-kill-rate", type=float, default=0.0,
                   help="exit 1 when the kill rate (percent, build errors excluded) is below this")
    a = p.parse_args(argv)
    if a.sample is not None and a.sample < 1:
        p.error(f"--sample: {a.sample} is below the minimum 1")
    if a.jobs < 1:
        p.error(f"--jobs: {a.jobs} is below the minimum 1")
    if a.timeout_factor <= 1.0:
        p.error(f"--timeout-factor: {a.timeout_factor} must be above 1")
    if a.min_test_timeout <= 0 or a.build_timeout <= 0:
        p.error("--min-test-timeout / --build-timeout: must be above 0 seconds")
    if not 0.0 <= a.min_kill_rate <= 100.0:
        p.error(f"--min-kill-rate: {a.min_kill_rate} is outside 0..100")
    for op in a.operator:
        if op not in mc.OPERATORS:
            p.error(f"--operator: '{op}' is not one of {', '.join(mc.OPERATORS)}")
    for area in a.area:
        if area not in mc.AREAS:
            p.error(f"--area: '{area}' is not one of {', '.join(mc.AREAS)}")
    for s in a.stage:
        if ":" not in s or not s.split(":", 1)[0] or not s.split(":", 1)[1]:
            p.error(f"--stage: '{s}' is not BINARY:FILTER")
    if a.stage and not a.live_tops:
        p.error("--stage: needs --live-tops (the tops its tests run)")
    if not (a.root / "rtl").is_dir():
        p.error(f"--root: {a.root} has no rtl/ directory")
    rtl_files = sorted((a.root / "rtl").glob("*.sv"))
    a.files = []
    for f in a.file:
        pat = Path(f).name
        pat = pat if pat.endswith(".sv") or "*" in pat else pat + ".sv"
        hits = [x for x in rtl_files if fnmatch.fnmatch(x.name, pat)]
        if not hits:
            p.error(f"--file: '{f}' matches no file in {a.root / 'rtl'}")
        a.files += [str(x.relative_to(a.root)) for x in hits if str(x.relative_to(a.root)) not in a.files]
    for m in a.module:
        if not (a.root / "rtl" / f"{m}.sv").exists():
            p.error(f"--module: '{m}' has no file rtl/{m}.sv")
        rel = f"rtl/{m}.sv"
        if rel not in a.files:
            a.files.append(rel)
    a.work_dir = (a.work_dir or a.root / "build-mutation").resolve()
    return a


# ---- selection -----------------------------------------------------------------------------------------------------

def select(mutants: list[mc.Mutant], a: argparse.Namespace, sample: bool = True) -> list[mc.Mutant]:
    """The filters, then (sample=True) --sample N mutants per area drawn with --seed."""
    out = [m for m in mutants if (not a.operator or m.operator in a.operator) and (not a.area or m.area in a.area)
           and (not a.id or any(fnmatch.fnmatchcase(m.id, pat) for pat in a.id))]
    if not sample or a.sample is None:
        return out
    picked: list[mc.Mutant] = []
    for area in sorted({m.area for m in out}):
        # sorted by id first: the sample depends on the catalogue, not on its order
        pool = sorted((m for m in out if m.area == area), key=lambda m: m.id)
        picked += pool if len(pool) <= a.sample else random.Random(f"{a.seed}:{area}").sample(pool, a.sample)
    return sorted(picked, key=lambda m: (m.file, m.start, m.id))


def default_files(root: Path) -> list[str]:
    return [f"rtl/{n}.sv" for n in ("sc_step_gen", "sc_step_nco", "sc_axis_core", "sc_profile_exec", "sc_row_fifo")
            if (root / "rtl" / f"{n}.sv").exists()]


# ---- the copy of the tree and its build ----------------------------------------------------------------------------

class Workspace:
    """<work>/src: the committed tree (git archive HEAD); <work>/rtl-frozen and
    <work>/cmodel-pristine: its unmodified rtl/ and cmodel/ (the frozen tops are
    Verilated from there, and every file is restored from there); <work>/build."""

    def __init__(self, root: Path, work: Path, jobs: int):
        self.root, self.work, self.jobs = root, work, jobs
        self.src = work / "src"
        self.frozen = work / "rtl-frozen"
        self.pristine_model = work / "cmodel-pristine"
        self.build = work / "build"
        # rtl/ and cmodel/ as committed, whatever a running campaign has applied to src/:
        # the catalogue and the pairing are read from here
        self.pristine = work / "pristine"
        self.live_tops: tuple[str, ...] | None = None

    def prepare(self) -> None:
        """Brings the copy to the committed tree (HEAD), copying only the files
        whose text changed, so an up-to-date build stays up to date."""
        self.src.mkdir(parents=True, exist_ok=True)
        log(f"syncing {self.src} with the committed tree (HEAD)")
        head = subprocess.run(["git", "-C", str(self.root), "rev-parse", "HEAD"], check=True,
                              capture_output=True, text=True).stdout.strip()
        # what the build and the tests are made of (a docs-only commit keeps the baseline)
        trees = subprocess.run(["git", "-C", str(self.root), "rev-parse"] + [f"{head}:{p}" for p in BUILD_INPUTS],
                               check=True, capture_output=True, text=True).stdout
        self.commit = hashlib.sha1(trees.encode()).hexdigest()
        archive = subprocess.run(["git", "-C", str(self.root), "archive", head], check=True,
                                 capture_output=True).stdout
        fresh = self.work / "head.tmp"
        shutil.rmtree(fresh, ignore_errors=True)
        fresh.mkdir(parents=True)
        subprocess.run(["tar", "-x", "-C", str(fresh)], input=archive, check=True)
        sync_tree(fresh, self.src)
        sync_tree(fresh / "rtl", self.frozen)
        sync_tree(fresh / "cmodel", self.pristine_model)
        shutil.rmtree(fresh)
        self.pristine.mkdir(exist_ok=True)
        for name, target in (("rtl", self.frozen), ("cmodel", self.pristine_model)):
            link = self.pristine / name
            if not link.is_symlink():
                link.symlink_to(target)
        self.restore_all()

    def restore_all(self) -> None:
        """Any file left mutated (an interrupted run) back to its committed text."""
        for pristine_dir, live_dir in ((self.frozen, self.src / "rtl"), (self.pristine_model, self.src / "cmodel")):
            for p in pristine_dir.rglob("*"):
                if p.is_file():
                    live = live_dir / p.relative_to(pristine_dir)
                    if not live.exists() or live.read_bytes() != p.read_bytes():
                        shutil.copy2(p, live)

    def configure(self, live_tops: tuple[str, ...]) -> None:
        if self.live_tops == live_tops and (self.build / "build.ninja").exists():
            return
        cache = self.build / "CMakeCache.txt"
        want = ";".join(live_tops)
        if cache.exists() and f"SC_RTL_LIVE_TOPS:STRING={want}\n" in cache.read_text() and \
                "SC_VERILATE_WARN_NOT_FATAL:BOOL=ON\n" in cache.read_text() and (self.build / "build.ninja").exists():
            self.live_tops = live_tops
            return
        log(f"configuring {self.build} (tops rebuilt per mutant: {', '.join(live_tops)})")
        cmd = ["cmake", "-G", "Ninja", "-S", str(self.src), "-B", str(self.build),
               # no LTO and -O1 Verilated code: a mutant's build is mostly its top's compile
               "-DCMAKE_BUILD_TYPE=RelWithDebInfo", "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2",
               "-DSCURVE_PYTHON=OFF", f"-DSC_RTL_FROZEN_DIR={self.frozen}", f"-DSC_RTL_LIVE_TOPS={want}",
               # a mutant that leaves a signal unread is a mutant, not a lint error
               "-DSC_VERILATE_OPT=-O1", "-DSC_VERILATE_WARN_NOT_FATAL=ON"]
        if shutil.which("ccache"):
            cmd.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode:
            raise RuntimeError(f"configure failed:\n{r.stdout[-3000:]}{r.stderr[-3000:]}")
        self.live_tops = live_tops

    def build_target(self, target: str, timeout: float) -> tuple[bool, str, float]:
        t0 = time.monotonic()
        try:
            r = subprocess.run(["ninja", "-C", str(self.build), f"-j{self.jobs}", target], capture_output=True,
                               text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return False, f"build timed out after {timeout:.0f} s", time.monotonic() - t0
        if r.returncode:
            return False, first_error(r.stdout + r.stderr), time.monotonic() - t0
        return True, "", time.monotonic() - t0

    def run_formal(self, stage: Stage, timeout: float) -> tuple[str, str, float]:
        """The module's property groups on the mutated copy: failed on a
        counterexample; inconclusive on a solver timeout or error."""
        out = self.work / "formal.json"
        out.unlink(missing_ok=True)
        cmd = [sys.executable, str(self.src / "scripts" / "formal.py"), "--check-as-is", "--build-dir",
               str(self.work / "formal"), "--json", str(out), "--timeout", str(max(1, int(timeout)))]
        for g in stage.gtest_filter.split(","):
            cmd += ["--group", g]
        # the solvers of scripts/setup.sh's .venv/ (src/ is a copy without one)
        env = dict(os.environ, PATH=str(self.root / ".venv" / "bin") + os.pathsep + os.environ.get("PATH", ""))
        t0 = time.monotonic()
        try:
            subprocess.run(cmd, capture_output=True, text=True, timeout=timeout + 60, env=env)
        except subprocess.TimeoutExpired:
            return "inconclusive", "formal: timed out", time.monotonic() - t0
        dt = time.monotonic() - t0
        try:
            rows = json.loads(out.read_text())["groups"]
        except (OSError, ValueError, KeyError):
            return "inconclusive", "formal: no results", dt
        failed = [r for r in rows if r.get("result") == "FAIL"]
        if failed:
            r = failed[0]
            return "failed", f"formal {r['group']}: {r.get('detail', '')[:200]}", dt
        unsure = [r["group"] for r in rows if r.get("result") != "PASSED"]
        if unsure:
            return "inconclusive", f"formal: no verdict for {', '.join(unsure)}", dt
        return "passed", "", dt

    def run_stage(self, stage: Stage, timeout: float) -> tuple[str, str, float]:
        """(passed | failed | timeout | inconclusive, first failing test or message, seconds)."""
        if stage.binary == FORMAL_STAGE:
            return self.run_formal(stage, timeout)
        exe = self.build / "bin" / stage.binary
        t0 = time.monotonic()
        cmd = [str(exe), f"--gtest_filter={stage.gtest_filter}", "--gtest_fail_fast", "--gtest_brief=1"]
        try:
            r = subprocess.run(cmd, cwd=self.build / "tests", capture_output=True, text=True, timeout=timeout,
                               errors="replace")
        except subprocess.TimeoutExpired as e:
            out = (e.stdout or b"").decode(errors="replace") if isinstance(e.stdout, bytes) else (e.stdout or "")
            running = re.findall(r"\[ RUN      \] (\S+)", out)
            return "timeout", f"{stage.binary} {running[-1] if running else stage.gtest_filter}", \
                time.monotonic() - t0
        dt = time.monotonic() - t0
        if r.returncode == 0:
            return "passed", "", dt
        failed = re.search(r"\[  FAILED  \] (\S+)", r.stdout)
        if failed:
            # the first failure message says which check killed it (lockstep, pins, endpoint...)
            why = re.search(r"(?:Failure|error)\n((?:.*\n){1,4})", r.stdout)
            note = " | ".join(x.strip() for x in why.group(1).splitlines() if x.strip()) if why else ""
            note = f": {note[:240]}" if note else ""
            return "failed", f"{stage.binary} {failed.group(1)}{note}", dt
        running = re.findall(r"\[ RUN      \] (\S+)", r.stdout)
        where = running[-1] if running else stage.gtest_filter
        return "failed", f"{stage.binary} {where} (exit {r.returncode})", dt


def sync_tree(src: Path, dst: Path) -> None:
    """dst becomes a copy of src; unchanged files keep their time stamps."""
    dst.mkdir(parents=True, exist_ok=True)
    for p in src.rglob("*"):
        q = dst / p.relative_to(src)
        if p.is_dir():
            q.mkdir(exist_ok=True)
        elif not q.exists() or q.read_bytes() != p.read_bytes():
            shutil.copy2(p, q)
            os.utime(q)  # newer than the build's outputs
    for q in sorted(dst.rglob("*"), reverse=True):
        if not (src / q.relative_to(dst)).exists():
            shutil.rmtree(q) if q.is_dir() else q.unlink()


def first_error(log_text: str) -> str:
    for line in log_text.splitlines():
        if re.search(r"%Error|%Warning|error:|Error \d", line):
            return line.strip()[:200]
    lines = [x for x in log_text.splitlines() if x.strip()]
    return lines[-1][:200] if lines else "build failed"


def log(msg: str) -> None:
    print(msg, flush=True)


# ---- running -------------------------------------------------------------------------------------------------------

@dataclasses.dataclass
class Result:
    id: str
    campaign: str
    area: str
    operator: str
    file: str
    outcome: str
    detail: str
    build_s: float
    test_s: float
    diff: str
    model_diff: str = ""
    suites: str = ""  # the suites run, in order ("" in results of older runs: the module's own suite)

    def to_json(self) -> dict:
        return dataclasses.asdict(self)


def suites_for(m: mc.Mutant, a: argparse.Namespace) -> list[Suite]:
    """The suites a mutant runs, in order; a later one only for a survivor of the earlier."""
    if a.stage:
        return [Suite("custom", tuple(t.strip() for t in a.live_tops.split(",")),
                      tuple(Stage(*s.split(":", 1)) for s in a.stage))]
    suite = SUITE_OF_MODULE.get(m.module)
    if suite is None:
        raise SystemExit(f"mutation.py: no fast suite for module {m.module}: give --stage BINARY:FILTER "
                         f"and --live-tops")
    more = [x for x in (SECOND_SUITE_OF_MODULE.get(m.module), FORMAL_SUITE_OF_MODULE.get(m.module)) if x]
    return [suite] + more


def suites_run(r: Result, suites: list[Suite]) -> int:
    """How many of the mutant's suites its result covers."""
    names = r.suites.split(",") if r.suites else [suites[0].name]
    n = 0
    while n < len(suites) and n < len(names) and names[n] == suites[n].name:
        n += 1
    return n


def baseline(ws: Workspace, suite: Suite, a: argparse.Namespace) -> dict[Stage, float]:
    """The suite on the unmutated copy: it must pass; its times set the limits.
    Kept per commit and suite in <work>/baseline.json."""
    key = f"{ws.commit}:{suite.name}:{','.join(suite.live_tops)}:" + \
        ";".join(f"{st.binary}:{st.gtest_filter}" for st in suite.stages)
    cache_path = ws.work / "baseline.json"
    cache = json.loads(cache_path.read_text()) if cache_path.exists() else {}
    if key in cache:
        log("  baseline: the unmutated suite passed on this commit (baseline.json)")
        return {st: t for st, t in zip(suite.stages, cache[key])}
    times: dict[Stage, float] = {}
    for st in suite.stages:
        ok, msg, bt = True, "", 0.0
        if st.binary != FORMAL_STAGE:
            ok, msg, bt = ws.build_target(st.binary, a.build_timeout * 3)
        if not ok:
            raise SystemExit(f"mutation.py: the unmutated copy does not build ({st.binary}): {msg}")
        status, detail, tt = ws.run_stage(st, 3600)
        if status != "passed":
            raise SystemExit(f"mutation.py: the unmutated copy fails its suite: {detail}")
        times[st] = tt
        log(f"  baseline {st.binary} [{st.gtest_filter[:60]}]: build {bt:.0f} s, tests {tt:.1f} s")
    cache[key] = [times[st] for st in suite.stages]
    cache_path.write_text(json.dumps(cache, indent=1) + "\n")
    return times


def run_mutant(ws: Workspace, m: mc.Mutant, pairing: mc.Pairing | None, suite: Suite, times: dict[Stage, float],
               a: argparse.Namespace, campaign: str) -> Result:
    rtl_path = ws.src / m.file
    rtl_text = rtl_path.read_text()
    diff = m.diff(rtl_text)
    saved: list[tuple[Path, str]] = []
    model_diff = ""
    build_s = test_s = 0.0
    try:
        saved.append((rtl_path, mc.apply_edit(rtl_path, m.start, m.end, m.original, m.replacement)))
        if pairing is not None:
            mp = ws.src / pairing.model_file
            saved.append((mp, mc.apply_edit(mp, pairing.start, pairing.end, pairing.original, pairing.replacement)))
            model_diff = f"{pairing.model_file}:{pairing.line}: {pairing.original!r} -> {pairing.replacement!r}"
        built: set[str] = set()
        for st in suite.stages:
            if st.binary not in built and st.binary != FORMAL_STAGE:
                ok, msg, bt = ws.build_target(st.binary, a.build_timeout)
                build_s += bt
                if not ok:
                    return Result(m.id, campaign, m.area, m.operator, m.file, "build_error", msg, build_s, test_s,
                                  diff, model_diff)
                built.add(st.binary)
            limit = max(a.min_test_timeout, a.timeout_factor * times[st])
            status, detail, tt = ws.run_stage(st, limit)
            test_s += tt
            if status == "failed":
                return Result(m.id, campaign, m.area, m.operator, m.file, "killed", detail, build_s, test_s, diff,
                              model_diff)
            if status == "timeout":
                return Result(m.id, campaign, m.area, m.operator, m.file, "timeout", detail, build_s, test_s, diff,
                              model_diff)
        return Result(m.id, campaign, m.area, m.operator, m.file, "survived", "", build_s, test_s, diff, model_diff)
    finally:
        for path, text in saved:
            path.write_text(text)


# ---- reporting -----------------------------------------------------------------------------------------------------

@dataclasses.dataclass(frozen=True)
class Equivalent:
    id: str
    diff: str          # the one-line diff as judged: finds the mutant when lines move; an edited site is stale
    campaigns: tuple[str, ...]
    reason: str


def load_equivalents(root: Path) -> dict[str, Equivalent]:
    path = root / EQUIVALENT_FILE
    if not path.exists():
        return {}
    try:
        entries = json.loads(path.read_text())["equivalent"]
        out = {}
        for e in entries:
            out[e["id"]] = Equivalent(e["id"], e["diff"], tuple(e.get("campaigns", CAMPAIGNS)), e["reason"])
            if not out[e["id"]].reason.strip() or not set(out[e["id"]].campaigns) <= set(CAMPAIGNS):
                raise ValueError(f"entry {e['id']}: a reason and campaigns among {', '.join(CAMPAIGNS)}")
        return out
    except (ValueError, KeyError, TypeError) as e:
        raise SystemExit(f"mutation.py: {path}: {e}")


def match_equivalents(equivalents: dict[str, Equivalent], pristine: Path) -> tuple[dict[str, Equivalent], list[str]]:
    """Today's mutant id of each entry: the one mutant of its file and operator
    that makes the entry's diff (ids follow line numbers; the diff does not).
    An entry that matches none or several is stale."""
    active: dict[str, Equivalent] = {}
    stale: list[str] = []
    texts: dict[str, str] = {}
    catalogues: dict[str, list[mc.Mutant]] = {}
    for e in equivalents.values():
        file, _line, _col, operator = e.id.split(":", 4)[:4]
        rel = f"rtl/{file}"
        if rel not in catalogues:
            exists = (pristine / rel).exists()
            catalogues[rel] = mc.catalogue(pristine, [rel]) if exists else []
            texts[rel] = (pristine / rel).read_text() if exists else ""
        hits = [m for m in catalogues[rel] if m.operator == operator and m.diff(texts[rel]) == e.diff]
        if len(hits) == 1:
            active[hits[0].id] = e
        else:
            stale.append(f"{e.id}: {'no' if not hits else len(hits)} mutant(s) of {rel} make this diff "
                         f"({e.diff.splitlines()[0]})")
    return active, stale


def classify(results: list[Result], active: dict[str, Equivalent]) -> list[Result]:
    """Survivors matched by an entry of their campaign become `equivalent`."""
    out = []
    for r in results:
        e = active.get(r.id)
        if r.outcome == "survived" and e is not None and r.campaign in e.campaigns:
            r = dataclasses.replace(r, outcome="equivalent", detail=e.reason)
        out.append(r)
    return out


def rate(c: Counter) -> str:
    scored = c["killed"] + c["timeout"] + c["survived"]
    return f"{100.0 * (c['killed'] + c['timeout']) / scored:5.1f}%" if scored else "    -"


def kill_rate(results: list[Result]) -> float | None:
    c = Counter(r.outcome for r in results)
    scored = c["killed"] + c["timeout"] + c["survived"]
    return 100.0 * (c["killed"] + c["timeout"]) / scored if scored else None


def table(results: list[Result], key: str) -> str:
    groups: dict[str, Counter] = {}
    for r in results:
        groups.setdefault(getattr(r, key), Counter())[r.outcome] += 1
    total = Counter(r.outcome for r in results)
    head = (f"{key:<16} {'mutants':>7} {'killed':>7} {'timeout':>7} {'build':>7} {'equiv':>7} {'survived':>8} "
            f"{'kill rate':>9}")
    lines = [head, "-" * len(head)]
    for name, c in sorted(groups.items()) + [("all", total)]:
        lines.append(f"{name:<16} {sum(c.values()):>7} {c['killed']:>7} {c['timeout']:>7} {c['build_error']:>7} "
                     f"{c['equivalent']:>7} {c['survived']:>8} {rate(c):>9}")
    return "\n".join(lines)


def report(results: list[Result], campaign: str, stale: list[str] | None = None) -> str:
    out = [f"campaign {campaign}: {len(results)} mutants (kill rate = killed and timed out over all but build "
           f"errors and equivalent mutants)", "", table(results, "area"), "", table(results, "operator")]
    if results:
        per = [r.build_s + r.test_s for r in results]
        build = sum(r.build_s for r in results) / len(per)
        tests = sum(r.test_s for r in results) / len(per)
        out += ["", f"per mutant: mean {sum(per) / len(per):.0f} s (build {build:.0f} s, tests {tests:.0f} s), "
                    f"max {max(per):.0f} s"]
    surv = [r for r in results if r.outcome == "survived"]
    if surv:
        out += ["", f"survivors ({len(surv)}):"]
        for r in surv:
            out.append(f"  {r.id}" + (f"  (suites: {r.suites})" if r.suites else ""))
            out += [f"      {line}" for line in r.diff.splitlines()]
            if r.model_diff:
                out.append(f"      model: {r.model_diff}")
    equiv = [r for r in results if r.outcome == "equivalent"]
    if equiv:
        out += ["", f"equivalent ({len(equiv)}, {EQUIVALENT_FILE}; not counted):"]
        for r in equiv:
            out.append(f"  {r.id}")
            out += [f"      {line}" for line in r.diff.splitlines()]
            out.append(f"      why: {r.detail}")
    if stale:
        out += ["", f"stale entries of {EQUIVALENT_FILE} (not applied; judge the mutant again):"]
        out += [f"  {x}" for x in stale]
    builds = [r for r in results if r.outcome == "build_error"]
    if builds:
        out += ["", f"build/lint errors ({len(builds)}, not counted as kills):"]
        out += [f"  {r.id}: {r.detail}" for r in builds]
    return "\n".join(out)


def write_junit(path: Path, results: list[Result], campaign: str) -> None:
    suite = ET.Element("testsuite", name=f"mutation.{campaign}", tests=str(len(results)),
                       failures=str(sum(r.outcome == "survived" for r in results)),
                       skipped=str(sum(r.outcome in ("build_error", "equivalent") for r in results)),
                       time=f"{sum(r.build_s + r.test_s for r in results):.1f}")
    for r in results:
        case = ET.SubElement(suite, "testcase", classname=f"mutation.{campaign}.{r.area}", name=r.id,
                             time=f"{r.build_s + r.test_s:.1f}")
        if r.outcome == "survived":
            ET.SubElement(case, "failure", message="mutant survived").text = r.diff + \
                ("\nmodel: " + r.model_diff if r.model_diff else "")
        elif r.outcome == "build_error":
            ET.SubElement(case, "skipped", message=f"build/lint error: {r.detail}")
        elif r.outcome == "equivalent":
            ET.SubElement(case, "skipped", message=f"equivalent: {r.detail}")
        else:
            ET.SubElement(case, "system-out").text = f"{r.outcome}: {r.detail}"
    root = ET.Element("testsuites")
    root.append(suite)
    ET.ElementTree(root).write(path, encoding="utf-8", xml_declaration=True)


# ---- main ----------------------------------------------------------------------------------------------------------

def list_catalogue(a: argparse.Namespace) -> int:
    files = a.files or default_files(a.root)
    mutants = select(mc.catalogue(a.root, files), a, sample=False)
    pairs = mc.pair_all(mutants, a.root) if a.campaign == "common_mode" else {}
    if pairs and a.sample is not None:
        # as a run draws it: from the paired mutants (without --sample every mutant is listed, with its reason)
        mutants = [m for m in mutants if pairs[m.id].status == "paired"]
    mutants = select(mutants, a)
    rows = []
    for m in mutants:
        row = m.to_json()
        if pairs:
            p = pairs[m.id]
            row["pairing"] = p.to_json()
            extra = f"  -> {p.model_file}:{p.line} {p.original!r} -> {p.replacement!r}" if p.status == "paired" \
                else f"  unpaired: {p.reason}"
        else:
            extra = ""
        print(f"{m.id:<72} {m.area:<16}{extra}")
        rows.append(row)
    c = Counter(m.area for m in mutants)
    summary = f"{len(mutants)} mutants ({', '.join(f'{k} {v}' for k, v in sorted(c.items()))})"
    if pairs:
        summary += f"; paired {sum(p.status == 'paired' for p in pairs.values())}, " \
                   f"unpaired {sum(p.status != 'paired' for p in pairs.values())}"
    print(summary)
    if a.json:
        a.json.write_text(json.dumps({"mutants": rows}, indent=1) + "\n")
    return 0


def main(argv: list[str]) -> int:
    a = parse_args(argv)
    if a.list:
        return list_catalogue(a)
    equivalents = load_equivalents(a.root)  # a bad file fails now, not after the campaign
    os.nice(10)  # the machine is shared with other builds
    ws = Workspace(a.root, a.work_dir, a.jobs)
    if not a.report:
        ws.prepare()
    files = a.files or default_files(ws.pristine)
    mutants = select(mc.catalogue(ws.pristine, files), a, sample=False)
    pairs: dict[str, mc.Pairing] = {}
    if a.campaign == "common_mode":
        # the sample is drawn from the paired mutants; the unpaired are listed by --list
        pairs = mc.pair_all(mutants, ws.pristine)
        unpaired = sum(pairs[m.id].status != "paired" for m in mutants)
        mutants = [m for m in mutants if pairs[m.id].status == "paired"]
        log(f"common-mode: {len(mutants)} mutants paired, {unpaired} unpaired "
            f"(--list --campaign common_mode says why)")
    mutants = select(mutants, a)
    results_path = ws.work / f"results-{a.campaign}.jsonl"
    done: dict[str, Result] = {}
    if (a.resume or a.report) and results_path.exists():
        for line in results_path.read_text().splitlines():
            r = Result(**json.loads(line))
            done[r.id] = r
    if a.report:
        mutants = [m for m in mutants if m.id in done]
    active, stale = match_equivalents(equivalents, ws.pristine)
    suites = {m.id: suites_for(m, a) for m in mutants}
    final: dict[str, Result] = {m.id: done[m.id] for m in mutants if m.id in done}
    n_total = len(mutants)
    log(f"campaign {a.campaign}: {n_total} mutants, work dir {ws.work}")
    # Pass k runs the k-th suite of each mutant that survived the ones before (pass 0: every mutant).
    for level in range(max((len(v) for v in suites.values()), default=0)):
        by_suite: dict[Suite, list[mc.Mutant]] = {}
        for m in mutants:
            r = final.get(m.id)
            if level < len(suites[m.id]) and (r is None if level == 0 else
                                             r.outcome == "survived" and suites_run(r, suites[m.id]) == level
                                             and m.id not in active):  # an equivalent one is judged
                by_suite.setdefault(suites[m.id][level], []).append(m)
        if a.report:
            break
        for suite, todo in by_suite.items():
            if suite.live_tops:  # (a formal suite builds nothing)
                ws.configure(suite.live_tops)
            log(f"suite {suite.name}: unmutated run" + (f" (for the {len(todo)} survivors of the suites before)"
                                                          if level else ""))
            times = baseline(ws, suite, a)
            for k, m in enumerate(todo, 1):
                r = run_mutant(ws, m, pairs.get(m.id), suite, times, a, a.campaign)
                before = final.get(m.id) if level else None
                r.suites = ",".join(st.name for st in suites[m.id][:level + 1])
                if before is not None:
                    r.build_s += before.build_s
                    r.test_s += before.test_s
                final[m.id] = r
                with results_path.open("a") as f:
                    f.write(json.dumps(r.to_json()) + "\n")
                log(f"[{k:>3}/{len(todo)} {suite.name}] {r.outcome:<11} {m.id}  ({r.build_s:.0f}+{r.test_s:.0f} s)"
                    + (f"  {r.detail}" if r.detail else ""))
    results = classify([final[m.id] for m in mutants if m.id in final], active)
    log("")
    log(report(results, a.campaign, stale))
    if a.json:
        kr = kill_rate(results)
        a.json.write_text(json.dumps({
            "campaign": a.campaign, "sample": a.sample, "seed": a.seed, "files": files,
            "kill_rate": kr, "results": [r.to_json() for r in results],
            "by_area": {k2: dict(Counter(r.outcome for r in results if r.area == k2))
                        for k2 in sorted({r.area for r in results})},
            "by_operator": {k2: dict(Counter(r.outcome for r in results if r.operator == k2))
                            for k2 in sorted({r.operator for r in results})},
        }, indent=1) + "\n")
    if a.junit:
        write_junit(a.junit, results, a.campaign)
    kr = kill_rate(results)
    if kr is not None and kr < a.min_kill_rate:
        log(f"kill rate {kr:.1f}% is below --min-kill-rate {a.min_kill_rate:.1f}%")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
