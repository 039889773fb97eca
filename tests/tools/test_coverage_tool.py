#!/usr/bin/env python3
"""The coverage tool itself (scripts/coverage.py): a test name escaped for
ctest matches only itself, the greedy selection hits every point its
candidates hit and drops what the others make redundant, exclusions are not
points to hit, bad arguments are refused naming the parameter, and the
committed CI selection names only tests of the default suite of this build.

    python3 tests/tools/test_coverage_tool.py PROJECT_ROOT [BUILD_DIR]
"""

import json
import re
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

ROOT = Path(sys.argv.pop(1)).resolve() if len(sys.argv) > 1 else Path(__file__).resolve().parents[2]
BUILD = Path(sys.argv.pop(1)).resolve() if len(sys.argv) > 1 else None
sys.path.insert(0, str(ROOT / "scripts"))
import coverage as cov  # noqa: E402


def point(page, line, obj=""):
    """A counter key in verilator_coverage's format (\\x01name\\x02value)."""
    fields = {"page": page, "f": "rtl/x.sv", "l": str(line), "o": obj, "h": "TOP.x"}
    return "".join(f"\x01{k}\x02{v}" for k, v in fields.items())


def write_dat(path, hits, lines=6):
    """A counter file over `lines` line points and one toggle point; `hits`
    are the indices of the points hit (`lines`: the toggle point)."""
    keys = [point("v_line/sc_x", i) for i in range(lines)] + [point("v_toggle/sc_x", 999, "cnt_q[31]")]
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("# SystemC::Coverage-3\n" + "".join(f"C '{k}' {1 if i in hits else 0}\n"
                                                       for i, k in enumerate(keys)), encoding="utf-8")


class Escape(unittest.TestCase):
    def test_a_name_with_regex_characters_matches_only_itself(self):
        name = "core.Lockstep/RawTableSeed.MatchesAndEndsExact/3"
        pattern = f"^{cov.ctest_escape(name)}$"
        self.assertRegex(name, pattern)
        self.assertIsNone(re.match(pattern, "core.LockstepXRawTableSeed.MatchesAndEndsExact/3"))
        odd = "a.b[1](x)*+?^$|\\c"
        self.assertRegex(odd, f"^{cov.ctest_escape(odd)}$")


class Minimize(unittest.TestCase):
    def run_minimize(self, per_test, seconds, exclusions=None, lines=6, margin=1.0):
        tmp = Path(tempfile.mkdtemp())
        raw = tmp / "raw"
        times = {}
        for i, (name, hits) in enumerate(per_test.items()):
            write_dat(raw / f"t{i}" / "p.dat", hits, lines)
            times[name] = {"dir": f"t{i}", "seconds": seconds[name], "binary": f"{name.split('.')[0]}_tests"}
        (raw / "tests.json").write_text(json.dumps(times), encoding="utf-8")
        rules_file = tmp / "excl.json"
        rules_file.write_text(json.dumps({"exclusions": exclusions or []}), encoding="utf-8")
        out = tmp / "sel.json"
        cov.minimize(raw, cov.load_exclusions(rules_file), out, margin)
        return json.loads(out.read_text(encoding="utf-8"))

    def test_with_few_points_every_point_the_candidates_hit_is_hit(self):
        per_test = {"a.slow_all": {0, 1, 2, 3, 4}, "b.quick_low": {0, 1, 2}, "c.quick_high": {3, 4, 6},
                    "d.nothing_new": {1}}
        sel = self.run_minimize(per_test, {"a.slow_all": 100, "b.quick_low": 1, "c.quick_high": 1,
                                           "d.nothing_new": 0.1})
        self.assertEqual(sel["tests"], ["b.quick_low", "c.quick_high"])
        self.assertEqual(sel["targets"], ["b_tests", "c_tests"])
        self.assertEqual(sel["percent"], {"line": 83.33, "toggle": 100.0, "user": 100.0})
        self.assertEqual(sel["candidates_percent"], sel["percent"])

    def test_a_pick_made_redundant_by_later_picks_is_dropped(self):
        # Greedy first takes the cheap middle test, which the two others then cover.
        per_test = {"a.left": {0, 1, 2}, "b.right": {3, 4, 5}, "c.middle": {1, 2, 3, 4}}
        sel = self.run_minimize(per_test, {"a.left": 1, "b.right": 1, "c.middle": 0.5})
        self.assertEqual(sel["tests"], ["a.left", "b.right"])

    def test_an_excluded_point_is_not_a_point_to_hit(self):
        per_test = {"a.lines": {0, 1, 2, 3, 4, 5}, "b.toggle_only": {6}}
        excl = [{"type": "toggle", "module": ".*", "point": r"cnt_q\[31\]", "reason": "test"}]
        sel = self.run_minimize(per_test, {"a.lines": 1, "b.toggle_only": 1}, excl)
        self.assertEqual(sel["tests"], ["a.lines"])


    def test_the_margin_above_the_floor_decides_whether_a_slow_last_point_is_taken(self):
        # 40 lines: 39 (97.5 %) in one second, the 40th only in a slow test.
        per_test = {"a.most": set(range(39)), "b.last_line": {39}}
        seconds = {"a.most": 1, "b.last_line": 100}
        sel = self.run_minimize(per_test, seconds, lines=40, margin=1.0)   # needs 96 %: 39 lines
        self.assertEqual(sel["tests"], ["a.most"])
        self.assertEqual(sel["percent"]["line"], 97.5)
        sel = self.run_minimize(per_test, seconds, lines=40, margin=5.0)   # needs 100 %
        self.assertEqual(sel["tests"], ["a.most", "b.last_line"])


class Arguments(unittest.TestCase):
    def refused(self, *args):
        r = subprocess.run([sys.executable, str(ROOT / "scripts" / "coverage.py"), *args],
                           capture_output=True, text=True)
        self.assertEqual(r.returncode, 2, r.stderr)
        return r.stderr

    def test_minimize_without_per_test_is_refused(self):
        self.assertIn("--minimize=x.json: needs --per-test", self.refused("--minimize", "x.json"))

    def test_minimize_outside_the_ci_profile_and_a_bad_margin_are_refused(self):
        self.assertIn("needs --profile ci", self.refused("--per-test", "--minimize", "x.json"))
        self.assertIn("--margin=11.0: must be from 0 to 10", self.refused("--margin", "11"))
        self.assertIn("--margin=nan: must be from 0 to 10", self.refused("--margin", "nan"))

    def test_bad_jobs_and_kinds_are_refused_naming_the_value(self):
        self.assertIn("--jobs=0: must be from 1 to 256", self.refused("--jobs", "0"))
        self.assertIn("'branch' is not one of", self.refused("--kinds", "line,branch"))


class CiSelection(unittest.TestCase):
    def test_the_ci_selection_names_tests_of_the_default_suite(self):
        sel = json.loads((ROOT / "scripts" / "coverage_ci.json").read_text(encoding="utf-8"))
        self.assertTrue(sel["tests"])
        self.assertEqual(len(sel["tests"]), len(set(sel["tests"])))
        if BUILD is None:
            self.skipTest("no build directory given: the names are not checked against ctest")
        default = cov.list_tests(BUILD, ["-LE", "^(long|extended)$"])
        missing = [t for t in sel["tests"] if t not in default]
        self.assertEqual(missing, [], "scripts/coverage_ci.json names tests that the default suite does not have "
                                      "(renamed? regenerate it with --profile ci --per-test --minimize)")
        self.assertTrue(set(sel["targets"]) >= {default[t] for t in sel["tests"]})


if __name__ == "__main__":
    unittest.main(verbosity=2)
