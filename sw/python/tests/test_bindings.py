#!/usr/bin/env python3
"""`import scurve` against the CLI: for random move requests (valid ones
and ones the validation layer or the planner refuses) scurve.plan() returns
exactly the JSON `scurve plan --json` prints, and raises scurve.Error with
exactly the one line the CLI prints (exit 2); scurve.regs() matches
`scurve regs --json`, the UART frames included.
  PYTHONPATH=build/python python3 sw/python/tests/test_bindings.py <scurve> [requests]"""
import json
import math
import random
import subprocess
import sys
import unittest

import scurve

SCURVE = sys.argv[1] if len(sys.argv) > 1 else "build/bin/scurve"
REQUESTS = int(sys.argv[2]) if len(sys.argv) > 2 else 1000


def log_uniform(rng, lo, hi):
    return math.exp(rng.uniform(math.log(lo), math.log(hi)))


def random_request(rng):
    """Keyword arguments of a move: mostly plannable, some refused."""
    kw = {
        "distance": rng.choice([1, -1]) * int(log_uniform(rng, 1, 200000)),
        "v_cruise": log_uniform(rng, 10, 150000),
        "a_max": log_uniform(rng, 100, 5e6),
        "j_max": log_uniform(rng, 1e3, 1e9),
    }
    if rng.random() < 0.3:
        kw["v_start"] = rng.uniform(0, kw["v_cruise"])
    if rng.random() < 0.3:
        kw["v_end"] = rng.uniform(0, kw["v_cruise"])
        kw["adjust_end_speed"] = rng.random() < 0.5
    if rng.random() < 0.1:
        kw["profile"] = "trapezoid"
        del kw["j_max"]
    elif rng.random() < 0.1:
        kw["jerks"] = [log_uniform(rng, 1e3, 1e9) for _ in range(4)]
    if rng.random() < 0.1:
        kw["clock_hz"] = rng.choice([10e6, 25e6, 50e6, 100e6])
    if rng.random() < 0.1:
        kw["pulse_high"] = rng.randint(1, 100)
        kw["pulse_low"] = rng.randint(1, 100)
    if rng.random() < 0.1:  # a window: the target inside, on a limit or beyond it
        kw["start_pos"] = rng.randint(-10**6, 10**6)
        target = kw["start_pos"] + kw["distance"]
        kw["soft_max" if rng.random() < 0.5 else "soft_min"] = target + rng.randint(-2, 2)
        if rng.random() < 0.3:
            kw["axis"] = rng.choice(["x", "y2", "spindle"])
    # Refused ones: a bad value in one place.
    r = rng.random()
    if r < 0.04:
        kw[rng.choice(["v_cruise", "a_max", "distance"])] = rng.choice([0, -1, float("nan"), float("inf")])
    elif r < 0.06:
        kw["distance"] = str(rng.choice(["0100", "1e3", "ten", ""]))
    elif r < 0.08:
        kw["v_cruise"] = 1e7
    return kw


def flags(kw):
    args = []
    for k, v in kw.items():
        flag = "--" + k.replace("_", "-")
        if isinstance(v, bool):
            if v:
                args.append(flag)
        elif isinstance(v, list):
            args += [flag] + [repr(x) for x in v]
        else:
            args += [flag, v if isinstance(v, str) else repr(v)]
    return args


def cli(command, kw):
    p = subprocess.run([SCURVE, command, "--json"] + flags(kw), capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


class Bindings(unittest.TestCase):
    def check(self, command, fn, kw):
        rc, out, err = cli(command, kw)
        try:
            got = fn(**kw)
        except scurve.Error as e:
            self.assertEqual(rc, 2, f"{kw}: Python refused ({e}), the CLI did not: {err or out[:200]}")
            self.assertEqual(err, f"error: {e}\n", kw)
            return False
        self.assertEqual(rc, 0, f"{kw}: the CLI refused ({err.strip()}), Python did not")
        self.assertEqual(got, json.loads(out), kw)
        return True

    def test_plan_matches_the_cli_on_random_requests(self):
        rng = random.Random(20261202)
        planned = 0
        for _ in range(REQUESTS):
            planned += self.check("plan", scurve.plan, random_request(rng))
        print(f"plan: {REQUESTS} requests, {planned} planned, {REQUESTS - planned} refused alike")
        self.assertGreater(planned, REQUESTS // 2)
        self.assertGreater(REQUESTS - planned, REQUESTS // 20)

    def test_regs_match_the_cli(self):
        rng = random.Random(7)
        for i in range(40):
            kw = random_request(rng)
            kw["uart"] = i % 2 == 0
            kw["closed_loop"] = i % 3 == 0
            if i % 5 == 0:
                kw["stop_at"] = 0.001
            self.check("regs", scurve.regs, kw)

    def test_errors_name_the_parameter(self):
        with self.assertRaises(scurve.Error) as c:
            scurve.plan(distance=1000, v_cruise=3000, a_max=0, j_max=5e5)
        self.assertEqual(str(c.exception).split("=")[0], "a_max")
        self.assertEqual(c.exception.parameter, "a_max")
        self.assertTrue(issubclass(scurve.Error, ValueError))
        with self.assertRaises(TypeError):
            scurve.plan(distanc=1000)
        with self.assertRaises(scurve.Error):
            scurve.uart_write_frame(3, 0)

    def test_soft_limits_refuse_a_target_beyond_the_window(self):
        move = dict(distance=1000, v_cruise=3000, a_max=500, j_max=2500)
        p = scurve.plan(**move, start_pos=200, soft_max=1200)
        self.assertEqual((p["target_position"], p["soft_limits"]), (1200, {"axis": "x", "min": None, "max": 1200}))
        with self.assertRaises(scurve.Error) as c:
            scurve.plan(**move, start_pos=200, soft_max=1000)
        self.assertEqual(c.exception.parameter, "soft_limits.max_pos")
        self.assertEqual(str(c.exception),
                         "axis x: target position 1200 is beyond soft limit max=1000 pulses (start 200, distance +1000)")
        with self.assertRaises(scurve.Error) as c:
            scurve.plan(**move, soft_min=5, soft_max=1)
        self.assertTrue(str(c.exception).startswith("soft-min=5: must be <= soft-max=1"), str(c.exception))

    def test_uart_frames_match_the_cli(self):
        out = subprocess.run([SCURVE, "regs", "--distance", "1000", "--v-cruise", "20000", "--a-max", "1e6",
                              "--j-max", "1e9", "--uart", "--json"], capture_output=True, text=True, check=True).stdout
        for w in json.loads(out):
            self.assertEqual(scurve.uart_write_frame(w["addr"], w["data"]).hex().upper(), w["frame"])
        self.assertEqual(len(scurve.uart_read_frame(8)), 4)  # sync, command, word address, CRC


    def test_register_map_matches_the_register_writes_and_the_plan(self):
        regs = scurve.register_map()
        writes = scurve.regs(distance=1000, v_cruise=3000, a_max=500, j_max=2500, closed_loop=True)
        for w in writes:
            self.assertEqual(regs[w["reg"]]["addr"], w["addr"], w["reg"])
        self.assertEqual(regs["ID"]["fields"]["MAGIC"]["reset"], 0x5343)
        self.assertEqual(regs["CL_STATUS"]["servo"], True)
        self.assertEqual(regs["STATUS"]["access"], "RO")
        self.assertEqual(len({r["addr"] for r in regs.values()}), len(regs))
        for r in regs.values():
            for f in r["fields"].values():
                self.assertEqual(r["mask"] >> f["lsb"] & 1, 1)
        names = scurve.phase_names()
        for s in scurve.plan(distance=1000, v_cruise=3000, a_max=500, j_max=2500)["segments"]:
            self.assertEqual(names[s["phase_code"]], s["phase"])
        self.assertEqual((names[0], names[8]), ("idle", "done"))


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
