"""A STEP/DIR pin monitor for cocotb: independent of the RTL and of the C++
model, it watches the pins and the phase output and checks what a stepper
driver needs.

- STEP high exactly HIGH clocks, low at least LOW clocks;
- DIR stable from SETUP clocks before a STEP rising edge until HOLD clocks
  after it;
- the net pulse count (+1 per rising edge with DIR high, -1 with DIR low);
- the duty-cycle phases: within an accelerating phase the pulse intervals do
  not grow, within a decelerating phase they do not shrink, within cruise
  they stay within one clock (each by one clock of rounding), and the phases
  follow each other in the planned order;
- no STEP edge after DONE.

Edge-driven (it wakes only on pin edges), so it costs nothing between
pulses. Copy it with test_sc_axi_axis.py into your own verification.
"""
import cocotb
from cocotb.triggers import Edge, RisingEdge
from cocotb.utils import get_sim_time


def duty_trend(phase_name):
    """The duty trend of a phase as the planner names it (scurve.phase_names())."""
    if phase_name.startswith("acc-"):
        return "rising"
    if phase_name == "cruise":
        return "steady"
    if phase_name.startswith("dec-"):
        return "falling"
    if phase_name == "done":
        return "zero"
    return None


def expected_trends(segments):
    """The trend sequence a plan's segments should show on the pins."""
    seq = []
    for s in segments:
        t = duty_trend(s["phase"])
        if t and (not seq or seq[-1] != t):
            seq.append(t)
    seq.append("zero")
    return seq


class StepDirMonitor:
    def __init__(self, dut, clock_period_ns, timing, phase_names):
        """timing: {'high', 'low', 'setup', 'hold'} in clocks (PULSE_TIME, DIR_TIME)."""
        self.dut = dut
        self.period = clock_period_ns
        self.timing = timing
        self.phase_names = phase_names
        self.errors = []
        self.net = 0
        self.pulses = 0
        self.trends = []
        self._rise = None        # time of the last STEP rising edge
        self._fall = None        # time of the last STEP falling edge
        self._dir_change = None  # time of the last DIR edge
        self._run = None         # the current run of pulses in one phase
        self.high_clocks = set()  # every STEP high time seen
        self._done = False
        self._tasks = []

    def start(self):
        self._tasks = [cocotb.start_soon(self._watch_step()), cocotb.start_soon(self._watch_dir()),
                       cocotb.start_soon(self._watch_done())]

    def stop(self):
        for t in self._tasks:
            t.cancel()

    def _clocks(self, t0, t1):
        return round((t1 - t0) / self.period)

    def _error(self, msg):
        if len(self.errors) < 20:
            self.errors.append(f"{get_sim_time('ns')} ns: {msg}")

    async def _watch_dir(self):
        while True:
            await Edge(self.dut.dir_o)
            now = get_sim_time("ns")
            if self._rise is not None and self._clocks(self._rise, now) < self.timing["hold"]:
                self._error(f"DIR hold {self._clocks(self._rise, now)} < {self.timing['hold']} clocks")
            self._dir_change = now

    async def _watch_done(self):
        await RisingEdge(self.dut.done_o)
        self._done = True
        if not self.trends or self.trends[-1] != "zero":
            self.trends.append("zero")

    async def _watch_step(self):
        while True:
            await Edge(self.dut.step_o)
            now = get_sim_time("ns")
            if int(self.dut.step_o.value):
                self._on_rise(now)
            else:
                high = self._clocks(self._rise, now)
                self.high_clocks.add(high)
                if high != self.timing["high"]:
                    self._error(f"STEP high {high} clocks, configured {self.timing['high']}")
                self._fall = now

    def _on_rise(self, now):
        if self._done:
            self._error("STEP rising edge after DONE")
        if self._fall is not None and self._clocks(self._fall, now) < self.timing["low"]:
            self._error(f"STEP low {self._clocks(self._fall, now)} < {self.timing['low']} clocks")
        if self._dir_change is not None and self._clocks(self._dir_change, now) < self.timing["setup"]:
            self._error(f"DIR setup {self._clocks(self._dir_change, now)} < {self.timing['setup']} clocks")
        self.pulses += 1
        self.net += 1 if int(self.dut.dir_o.value) else -1
        phase = int(self.dut.phase_o.value)
        trend = duty_trend(self.phase_names.get(phase, "?"))
        if trend is None or trend == "zero":
            self._error(f"STEP rising edge in phase {phase} ({self.phase_names.get(phase, '?')})")
        elif not self.trends or self.trends[-1] != trend:
            self.trends.append(trend)
        if self._rise is not None and trend:
            self._judge_interval(phase, trend, self._clocks(self._rise, now))
        self._rise = now

    def _judge_interval(self, phase, trend, interval):
        # The first interval of a run straddles the phase change (its pulse
        # was owed in the previous phase): neither judged nor a reference.
        # One clock of jitter: edges sit on the clock grid.
        if self._run is None or self._run["phase"] != phase:
            self._run = {"phase": phase, "pulses": 0, "last": None, "min": None, "max": None}
        run = self._run
        if run["pulses"] > 0:
            last = run["last"]
            if run["pulses"] > 1:
                if trend == "rising" and interval > last + 1:
                    self._error(f"phase {phase}: interval {interval} after {last} clocks while accelerating")
                if trend == "falling" and interval + 1 < last:
                    self._error(f"phase {phase}: interval {interval} after {last} clocks while decelerating")
            run["min"] = interval if run["min"] is None else min(run["min"], interval)
            run["max"] = interval if run["max"] is None else max(run["max"], interval)
            if trend == "steady" and run["max"] > run["min"] + 1:
                self._error(f"cruise intervals from {run['min']} to {run['max']} clocks")
                run["min"] = run["max"] = interval
        run["last"] = interval
        run["pulses"] += 1
