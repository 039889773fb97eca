#!/usr/bin/env python3
"""The mutation tool itself (scripts/mutation.py, scripts/mutation_catalogue.py):
the catalogue is generated deterministically from the sources and skips the
FORMAL code and comments, a known mutant applies and restores byte for byte,
a known site pairs with its mirror statement in the model, a register
transfer does not, and bad arguments are refused naming the parameter.

    python3 tests/tools/test_mutation_tool.py [project root]
"""

import shutil
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

ROOT = Path(sys.argv.pop(1)).resolve() if len(sys.argv) > 1 else Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "scripts"))
import mutation_catalogue as mc  # noqa: E402

STEP_GEN = "rtl/sc_step_gen.sv"
# The pulse's minimum low time: a known site with a mirror in cmodel/step_gen.cpp.
KNOWN_RTL = "low_cnt_q >= cfg_low_i"
KNOWN_MODEL = "q_.low_cnt >= in.cfg.low"


def offset_of(text: str, needle: str, sub: str) -> int:
    at = text.index(needle)
    return at + needle.index(sub)


class Catalogue(unittest.TestCase):
    def setUp(self):
        self.text = (ROOT / STEP_GEN).read_text()
        self.mutants = mc.catalogue(ROOT, [STEP_GEN])

    def known(self, operator="relational"):
        start = offset_of(self.text, KNOWN_RTL, ">=")
        hits = [m for m in self.mutants if m.start == start and m.operator == operator]
        self.assertEqual(len(hits), 1, f"one {operator} mutant of '{KNOWN_RTL}'")
        return hits[0]

    def test_generated_deterministically_with_unique_ids(self):
        again = mc.catalogue(ROOT, [STEP_GEN])
        self.assertEqual([m.id for m in self.mutants], [m.id for m in again])
        self.assertEqual(len({m.id for m in self.mutants}), len(self.mutants), "ids are unique")
        self.assertGreater(len(self.mutants), 50)
        ops = {m.operator for m in self.mutants}
        for op in ("arith", "relational", "equality", "logical", "constant", "negate_if", "swap_ternary",
                   "drop_term", "stuck_0", "stuck_1"):
            self.assertIn(op, ops)

    def test_known_mutant_has_a_stable_id(self):
        m = self.known()
        line = self.text.count("\n", 0, m.start) + 1
        col = m.start - (self.text.rfind("\n", 0, m.start) + 1) + 1
        self.assertEqual(m.id, f"sc_step_gen.sv:{line}:{col}:relational:>=->>")
        self.assertEqual(m.area, "step_timing")

    def test_formal_code_and_comments_are_not_mutated(self):
        lines = self.text.splitlines()
        first = next(i for i, s in enumerate(lines, 1) if s.startswith("`ifdef FORMAL"))
        last = next(i for i, s in enumerate(lines, 1) if i > first and s.startswith("`endif"))
        for m in self.mutants:
            self.assertFalse(first <= m.line <= last, f"{m.id} is in the FORMAL code")
            self.assertFalse(lines[m.line - 1].lstrip().startswith("//"), f"{m.id} is in a comment")
            code = lines[m.line - 1].split("//")[0]
            self.assertGreaterEqual(len(code), m.col, f"{m.id} starts in a trailing comment")

    def test_known_mutant_applies_and_restores_byte_for_byte(self):
        m = self.known()
        with tempfile.TemporaryDirectory() as tmp:
            copy = Path(tmp) / "sc_step_gen.sv"
            shutil.copy2(ROOT / STEP_GEN, copy)
            before = copy.read_bytes()
            previous = mc.apply_edit(copy, m.start, m.end, m.original, m.replacement)
            mutated = copy.read_text()
            self.assertIn("low_cnt_q > cfg_low_i", mutated)
            self.assertNotIn(KNOWN_RTL, mutated)
            self.assertEqual(len(mutated), len(previous) - 1)
            copy.write_text(previous)
            self.assertEqual(copy.read_bytes(), before)
            # a second application on the mutated text is refused, not stacked
            mc.apply_edit(copy, m.start, m.end, m.original, m.replacement)
            with self.assertRaises(RuntimeError):
                mc.apply_edit(copy, m.start, m.end, m.original, m.replacement)
        self.assertEqual((ROOT / STEP_GEN).read_text(), self.text, "the source tree is untouched")

    def test_sample_is_deterministic(self):
        def listing(seed):
            r = subprocess.run([sys.executable, str(ROOT / "scripts/mutation.py"), "--root", str(ROOT), "--list",
                                "--file", "sc_step_gen", "--sample", "7", "--seed", str(seed)],
                               capture_output=True, text=True, check=True)
            return r.stdout
        self.assertEqual(listing(3), listing(3))
        self.assertNotEqual(listing(3), listing(4))
        # seven per area
        self.assertIn("14 mutants (step_accounting 7, step_timing 7)", listing(3))


class Pairing(unittest.TestCase):
    def test_known_site_pairs_with_its_mirror_statement(self):
        mutants = mc.catalogue(ROOT, [STEP_GEN])
        text = (ROOT / STEP_GEN).read_text()
        start = offset_of(text, KNOWN_RTL, ">=")
        m = next(x for x in mutants if x.start == start and x.operator == "relational")
        pairs = mc.pair_all(mutants, ROOT)
        p = pairs[m.id]
        self.assertEqual(p.status, "paired", p.reason)
        self.assertEqual(p.model_file, "cmodel/step_gen.cpp")
        model = (ROOT / p.model_file).read_text()
        self.assertEqual(p.start, offset_of(model, KNOWN_MODEL, ">="))
        self.assertEqual((p.original, p.replacement), (">=", ">"))

    def test_register_transfer_is_unpaired_with_a_reason(self):
        mutants = mc.catalogue(ROOT, [STEP_GEN])
        text = (ROOT / STEP_GEN).read_text()
        start = offset_of(text, "step_q       <= step_d;", "step_d")
        m = next(x for x in mutants if x.start == start and x.operator == "stuck_0")
        p = mc.pair_all(mutants, ROOT)[m.id]
        self.assertEqual(p.status, "unpaired")
        self.assertIn("register transfer", p.reason)


class Suites(unittest.TestCase):
    """Which suites a mutant runs: its module's, then, for a survivor of an
    open-loop module, the servo suite (those modules sit in sc_servo_axis),
    then the module's formal property groups."""

    def setUp(self):
        import mutation  # the runner; imported here, the catalogue tests do not need it
        self.mut = mutation
        self.args = mutation.parse_args(["--list"])
        self.by_module = {}
        for m in mc.catalogue(ROOT, ["rtl/sc_axis_core.sv", "rtl/sc_step_nco.sv"]):
            self.by_module.setdefault(m.module, m)

    def result(self, suites):
        m = self.by_module["sc_axis_core"]
        return self.mut.Result(m.id, "rtl_only", m.area, m.operator, m.file, "survived", "", 0, 0, "", "", suites)

    def test_open_loop_modules_get_the_servo_suite_second(self):
        names = [s.name for s in self.mut.suites_for(self.by_module["sc_axis_core"], self.args)]
        self.assertEqual(names, ["open_loop", "servo", "formal_sc_axis_core"])
        names = [s.name for s in self.mut.suites_for(self.by_module["sc_step_nco"], self.args)]
        self.assertEqual(names, ["servo"])

    def test_results_say_how_many_suites_they_cover(self):
        suites = self.mut.suites_for(self.by_module["sc_axis_core"], self.args)
        self.assertEqual(self.mut.suites_run(self.result(""), suites), 1)  # an older result: its module's suite
        self.assertEqual(self.mut.suites_run(self.result("open_loop"), suites), 1)
        self.assertEqual(self.mut.suites_run(self.result("open_loop,servo"), suites), 2)
        self.assertEqual(self.mut.suites_run(self.result("servo"), suites), 0)  # not this mutant's order
        formal_stage = suites[-1].stages[0]
        self.assertEqual(formal_stage.binary, self.mut.FORMAL_STAGE)
        self.assertEqual(formal_stage.gtest_filter.split(","), ["core_done", "core_abort", "core_limits", "core_rate"])


class FormalStage(unittest.TestCase):
    """The formal stage on a mutated copy: the unmutated module passes, the
    queue's full check dropped (a mutant no simulation reaches: both tops
    keep the queue from filling) is caught by a property, with its name."""

    def test_a_counterexample_kills_and_the_design_passes(self):
        # scripts/setup.sh installs them (the formal tests need them too)
        self.assertIsNotNone(shutil.which("yosys-smtbmc"), "yosys-smtbmc not on PATH")
        self.assertTrue((ROOT / ".venv" / "bin" / "yices-smt2").exists(), "no .venv/bin/yices-smt2")
        import mutation
        stage = mutation.FORMAL_SUITE_OF_MODULE["sc_step_gen"].stages[0]
        self.assertIn("step_gen_count", stage.gtest_filter.split(","))
        one = mutation.Stage(mutation.FORMAL_STAGE, "step_gen_count")
        with tempfile.TemporaryDirectory() as d:
            ws = mutation.Workspace(ROOT, Path(d), 1)
            for sub in ("scripts", "rtl"):
                shutil.copytree(ROOT / sub, ws.src / sub, ignore=shutil.ignore_patterns("__pycache__"))
            status, detail, _ = ws.run_formal(one, 120)
            self.assertEqual((status, detail), ("passed", ""))
            path = ws.src / STEP_GEN
            text = path.read_text()
            old = "req_blocked = pend_d == PendMax;"
            self.assertEqual(text.count(old), 1)
            path.write_text(text.replace(old, "req_blocked = '0;"))
            status, detail, _ = ws.run_formal(one, 120)
            self.assertEqual(status, "failed")
            self.assertIn("formal step_gen_count: counterexample at step", detail)
            self.assertIn("p_pend_account", detail)


class Equivalents(unittest.TestCase):
    """The list of equivalent survivors: each entry finds exactly one mutant of
    today's catalogue by its diff, and only a survivor of its campaigns is
    taken out of the kill rate."""

    def setUp(self):
        import mutation
        self.mut = mutation
        self.equivalents = mutation.load_equivalents(ROOT)
        self.active, self.stale = mutation.match_equivalents(self.equivalents, ROOT)

    def test_every_entry_finds_one_mutant_of_the_catalogue_by_its_diff(self):
        self.assertTrue(self.equivalents, "the list has entries")
        self.assertEqual(self.stale, [], "judge these again (the site changed)")
        self.assertEqual(len(self.active), len(self.equivalents))
        for e in self.equivalents.values():
            self.assertGreater(len(e.reason), 40, f"{e.id}: a reason")

    def test_a_line_shift_keeps_the_entry_and_an_edit_makes_it_stale(self):
        e = next(iter(self.equivalents.values()))
        rel = "rtl/" + e.id.split(":", 1)[0]
        with tempfile.TemporaryDirectory() as d:
            (Path(d) / "rtl").mkdir()
            for f in (ROOT / "rtl").glob("*.sv"):
                shutil.copy(f, Path(d) / "rtl" / f.name)
            text = (ROOT / rel).read_text()
            first_nl = text.index("\n") + 1
            (Path(d) / rel).write_text(text[:first_nl] + "// a line more\n" + text[first_nl:])
            active, stale = self.mut.match_equivalents({e.id: e}, Path(d))
            self.assertEqual(stale, [])
            (moved_id,) = active
            self.assertEqual(int(moved_id.split(":")[1]), int(e.id.split(":")[1]) + 1, "found one line lower")
            line = e.diff.splitlines()[0][2:]
            (Path(d) / rel).write_text(text.replace(line, line.replace("=", "= ", 1), 1))
            active, stale = self.mut.match_equivalents({e.id: e}, Path(d))
            self.assertEqual((active, len(stale)), ({}, 1), "an edited site is stale")

    def test_only_a_survivor_of_the_entry_campaigns_becomes_equivalent(self):
        (mid, e), = list(self.active.items())[:1]
        m = next(x for x in mc.catalogue(ROOT, ["rtl/" + mid.split(":", 1)[0]]) if x.id == mid)

        def result(outcome, campaign="rtl_only"):
            return self.mut.Result(m.id, campaign, m.area, m.operator, m.file, outcome, "", 0, 0, e.diff)
        out = self.mut.classify([result("survived"), result("killed")], self.active)
        self.assertEqual([r.outcome for r in out], ["equivalent", "killed"])
        self.assertEqual(self.mut.kill_rate(out), 100.0)
        only_common = {mid: self.mut.Equivalent(e.id, e.diff, ("common_mode",), e.reason)}
        self.assertEqual(self.mut.classify([result("survived")], only_common)[0].outcome, "survived",
                         "an entry applies to its campaigns only")


class Arguments(unittest.TestCase):
    def run_tool(self, *args):
        return subprocess.run([sys.executable, str(ROOT / "scripts/mutation.py"), "--root", str(ROOT), *args],
                              capture_output=True, text=True)

    def test_bad_arguments_name_the_parameter_value_and_bound(self):
        for args, words in ((["--list", "--sample", "0"], ["--sample", "0", "minimum 1"]),
                            (["--list", "--operator", "flip"], ["--operator", "flip", "relational"]),
                            (["--list", "--file", "sc_nothing"], ["--file", "sc_nothing"]),
                            (["--list", "--min-kill-rate", "101"], ["--min-kill-rate", "101", "0..100"])):
            r = self.run_tool(*args)
            self.assertEqual(r.returncode, 2, args)
            for w in words:
                self.assertIn(w, r.stderr, args)


if __name__ == "__main__":
    unittest.main(verbosity=1)
