#!/usr/bin/env python3
"""scurve.Board against `scurve virtual-board` (the Verilated board top
behind a pseudo-terminal): the same reports and the same errors as
`scurve board`, and the example script.
  PYTHONPATH=build/python python3 sw/python/tests/test_board.py <scurve> <source dir>"""
import json
import os
import subprocess
import sys
import tempfile
import time
import unittest

import scurve

SCURVE = sys.argv[1] if len(sys.argv) > 1 else "build/bin/scurve"
SOURCE = sys.argv[2] if len(sys.argv) > 2 else "."


class BoardFromPython(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.port = os.path.join(cls.tmp.name, "pty")
        cls.vb = subprocess.Popen([SCURVE, "virtual-board", "--speed", "0", "--pty-link", cls.port],
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        for _ in range(100):
            if os.path.exists(cls.port):
                break
            time.sleep(0.1)

    @classmethod
    def tearDownClass(cls):
        cls.vb.terminate()
        cls.vb.wait()
        cls.tmp.cleanup()

    def test_a_move_runs_exactly_and_reads_back_as_the_cli_reports_it(self):
        board = scurve.Board(self.port)
        info = board.info()
        self.assertEqual(info["id"] >> 16, 0x5343)
        self.assertEqual(info["axes"], 1)
        start = board.status()["ref_pos"]
        run = board.run(distance=1500, v_cruise=100000, a_max=1e7, j_max=1e10)
        self.assertTrue(run["pass"])
        self.assertEqual(run["status"]["pulse_count"], 1500)
        self.assertEqual(run["status"]["ref_pos"], start + 1500)
        # The CLI's status of the same board (the fields that hold at rest;
        # the encoder pins and ENC_POS follow the settling rotor).
        cli = json.loads(subprocess.run([SCURVE, "board", "--port", self.port, "--json", "status"],
                                        check=True, capture_output=True, text=True).stdout)
        py = board.status()
        for k in ("ref_pos", "pulse_count", "boundary_pos", "move_index", "phase", "busy", "done", "faults"):
            self.assertEqual(cli[k], py[k], k)

    def test_a_stream_file_ends_on_the_sum_of_its_distances(self):
        board = scurve.Board(self.port)
        start = board.status()["ref_pos"]
        r = board.stream(os.path.join(SOURCE, "tests/streams/uart_paced.json"), timeout=600)
        self.assertEqual(r["end_ref"], start + 1100)
        self.assertEqual(r["expected_end"], r["end_ref"])

    def test_refusals_raise_scurve_error_naming_the_place(self):
        with self.assertRaises(scurve.Error) as e:
            scurve.Board(os.path.join(self.tmp.name, "missing"))
        self.assertEqual(e.exception.parameter, "port")
        with self.assertRaises(scurve.Error) as e:
            scurve.Board(self.port, timeout_ms=0)
        self.assertEqual(e.exception.parameter, "timeout")
        board = scurve.Board(self.port)
        with self.assertRaises(scurve.Error) as e:
            board.run(distance=100, v_cruise=1e7, a_max=1e6, j_max=1e9)
        self.assertEqual(e.exception.parameter, "v_cruise")
        with self.assertRaises(TypeError):
            board.run(distanse=100)
        board.estop()
        with self.assertRaises(scurve.Error) as e:
            board.run(distance=100, v_cruise=10000, a_max=1e6, j_max=1e9)
        self.assertEqual(e.exception.parameter, "board")
        self.assertIn("SLVERR", str(e.exception))
        board.clear()
        self.assertTrue(board.run(distance=100, v_cruise=10000, a_max=1e6, j_max=1e9)["pass"])

    def test_the_example_script_drives_the_board(self):
        out = subprocess.run([sys.executable, os.path.join(SOURCE, "sw/python/examples/drive_board.py"), self.port],
                             check=True, capture_output=True, text=True).stdout
        self.assertIn("ran 2000 pulses", out)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
