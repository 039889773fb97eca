#!/usr/bin/env python3
"""scripts/slurm/compare_results.py: equal reports (machine-dependent fields
apart) compare equal; a changed result, a missing test or a failed test do
not."""
import copy
import json
import os
import subprocess
import sys
import tempfile
import unittest

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts", "slurm", "compare_results.py")

REPORT = {"pass": True, "passed": 2, "shard": "1/1", "tests": 2, "results": [
    {"name": "a", "pass": True, "exit_code": 0, "wall_s": 1.5, "log": "/x/a.log", "command": "/x/sc_bench",
     "result": {"clocks": 1000, "final_error": 0, "clocks_per_s": 2e6, "runs": [{"pulses": 5, "real_time_ratio": 0.1}]}},
    {"name": "b", "pass": True, "exit_code": 0, "wall_s": 2.5, "result": {"clocks": 2000, "final_error": 0}}]}


def compare(a, b):
    with tempfile.TemporaryDirectory() as d:
        pa, pb = os.path.join(d, "a.json"), os.path.join(d, "b.json")
        for path, report in ((pa, a), (pb, b)):
            with open(path, "w", encoding="utf-8") as f:
                json.dump(report, f)
        p = subprocess.run([sys.executable, SCRIPT, pa, pb], capture_output=True, text=True)
        return p.returncode, p.stdout


class CompareResults(unittest.TestCase):
    def test_machine_dependent_fields_are_ignored(self):
        b = copy.deepcopy(REPORT)
        b["results"][0].update(wall_s=9.0, log="/y/a.log", command="/y/sc_bench")
        b["results"][0]["result"]["clocks_per_s"] = 1e6
        b["results"][0]["result"]["runs"][0]["real_time_ratio"] = 0.5
        rc, out = compare(REPORT, b)
        self.assertEqual(rc, 0, out)
        self.assertIn("equal", out)

    def test_a_changed_result_is_a_difference(self):
        b = copy.deepcopy(REPORT)
        b["results"][0]["result"]["runs"][0]["pulses"] = 6
        rc, out = compare(REPORT, b)
        self.assertEqual(rc, 1)
        self.assertIn("a: result.runs.0.pulses: 5 != 6", out)

    def test_a_missing_test_is_a_difference(self):
        b = copy.deepcopy(REPORT)
        del b["results"][1]
        rc, out = compare(REPORT, b)
        self.assertEqual(rc, 1)
        self.assertIn("b: only in", out)

    def test_a_failed_test_fails_even_when_equal(self):
        a = copy.deepcopy(REPORT)
        a["results"][1].update({"pass": False, "failure": "final_error 1"})
        rc, out = compare(a, a)
        self.assertEqual(rc, 1)
        self.assertIn("b: failed (final_error 1)", out)

    def test_unreadable_input_exits_2(self):
        p = subprocess.run([sys.executable, SCRIPT, "/nonexistent.json", "/nonexistent.json"], capture_output=True,
                           text=True)
        self.assertEqual(p.returncode, 2)
        self.assertIn("/nonexistent.json: not a regress report", p.stderr)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
