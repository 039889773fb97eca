"""cocotb test of sc_axi_axis, the open-loop axis with its AXI4-Lite slave:
an AXI4-Lite master (cocotbext-axi) loads a move planned through the Python
bindings (`import scurve`), starts it and polls STATUS as a host would; the
STEP/DIR monitor checks the pulse count, the pulse timing and the duty-cycle
phases on the pins; PULSE_COUNT and REF_POS must read back the distance.

Copy this file and step_dir_monitor.py into your SoC verification: the
register addresses and fields come from scurve.register_map(), the move from
scurve.regs(), so nothing here repeats the register layout.

Run by tb/cocotb/run.py (Icarus, cocotb's Python runner).
"""
import logging

import cocotb
from cocotb.clock import Clock
from cocotb.triggers import ClockCycles
from cocotbext.axi import AxiLiteBus, AxiLiteMaster
from cocotbext.axi.axil_channels import (AxiLiteARBus, AxiLiteAWBus, AxiLiteBBus, AxiLiteRBus, AxiLiteReadBus,
                                         AxiLiteWBus, AxiLiteWriteBus)

import scurve
from step_dir_monitor import StepDirMonitor, expected_trends

CLOCK_HZ = 20_000_000
PERIOD_NS = 1e9 / CLOCK_HZ
REGS = scurve.register_map()

# A short move with all seven phases: about 3.4 ms, 68,000 clocks.
MOVE = dict(distance=80, v_cruise=40000, a_max=4e7, j_max=1e11)

# The slave's ports carry Ibex-style direction suffixes (s_axi_awaddr_i,
# s_axi_awready_o): map each cocotbext-axi channel onto them.
SLAVE_OUTPUTS = {"awready", "wready", "bresp", "bvalid", "arready", "rdata", "rresp", "rvalid"}


def _suffixed(channel):
    def names(signals):
        return {s: s + ("_o" if s in SLAVE_OUTPUTS else "_i") for s in signals}
    return type(channel.__name__, (channel,), {"_signals": names(channel._signals),
                                              "_optional_signals": names(channel._optional_signals)})


def axil_bus(dut, prefix="s_axi"):
    write = AxiLiteWriteBus(*(_suffixed(c)(dut, prefix) for c in (AxiLiteAWBus, AxiLiteWBus, AxiLiteBBus)))
    read = AxiLiteReadBus(*(_suffixed(c)(dut, prefix) for c in (AxiLiteARBus, AxiLiteRBus)))
    return AxiLiteBus(write, read)


def field(reg, name, word):
    f = REGS[reg]["fields"][name]
    return (word >> f["lsb"]) & ((1 << f["width"]) - 1)


def signed32(word):
    return word - (1 << 32) if word & (1 << 31) else word


class Host:
    """What a driver does over the bus: register writes and reads by name."""

    def __init__(self, dut):
        self.dut = dut
        self.axil = AxiLiteMaster(axil_bus(dut), dut.clk_i, dut.rst_ni, reset_active_level=False)
        for channel in (self.axil.write_if, self.axil.read_if):
            channel.log.setLevel(logging.WARNING)   # not one line per access

    async def read(self, reg):
        return await self.axil.read_dword(REGS[reg]["addr"])

    async def write_checked(self, addr, data, what):
        resp = await self.axil.write(addr, int(data).to_bytes(4, "little"))
        assert int(resp.resp) == 0, f"{what} = 0x{data:08X}: response {resp.resp}, expected OKAY"


async def reset(dut):
    for name in ("s_axi_awvalid_i", "s_axi_wvalid_i", "s_axi_arvalid_i", "estop_i", "enc_index_i"):
        getattr(dut, name).value = 0
    dut.s_axi_bready_i.value = 1
    dut.s_axi_rready_i.value = 1
    dut.enc_ab_i.value = 0
    dut.enc_pos_i.value = 0
    dut.sw_i.value = 0
    dut.rst_ni.value = 0
    await ClockCycles(dut.clk_i, 5)
    dut.rst_ni.value = 1
    await ClockCycles(dut.clk_i, 5)


async def run_move(dut, move):
    plan = scurve.plan(**move)
    writes = scurve.regs(**move)
    timing = {}
    for w in writes:
        if w["reg"] == "PULSE_TIME":
            timing["high"], timing["low"] = field("PULSE_TIME", "HIGH", w["data"]), field("PULSE_TIME", "LOW", w["data"])
        if w["reg"] == "DIR_TIME":
            timing["setup"], timing["hold"] = field("DIR_TIME", "SETUP", w["data"]), field("DIR_TIME", "HOLD", w["data"])
    assert writes[-1]["reg"] == "CMD" and field("CMD", "START", writes[-1]["data"]), "regs() ends with CMD.START"

    host = Host(dut)
    monitor = StepDirMonitor(dut, PERIOD_NS, timing, scurve.phase_names())
    monitor.start()
    ident = await host.read("ID")
    assert field("ID", "MAGIC", ident) == REGS["ID"]["fields"]["MAGIC"]["reset"], f"ID 0x{ident:08X}"
    for w in writes:
        await host.write_checked(w["addr"], w["data"], w["reg"])

    # Poll STATUS as a host would; the plan says how long the move takes.
    deadline = plan["clocks"] + 20000
    waited = 0
    while True:
        status = await host.read("STATUS")
        if field("STATUS", "DONE", status) and not field("STATUS", "BUSY", status):
            break
        assert not field("STATUS", "ERR", status), f"STATUS 0x{status:08X}: ERR set"
        assert waited < deadline, f"not done after {waited} clocks (plan: {plan['clocks']})"
        await ClockCycles(dut.clk_i, 2000)
        waited += 2000
    await ClockCycles(dut.clk_i, 200)   # a STEP edge after DONE would show here
    monitor.stop()

    pulse_count = signed32(await host.read("PULSE_COUNT"))
    ref_pos = signed32(await host.read("REF_POS"))
    dut._log.info(f"move {move}: {monitor.pulses} pulses, net {monitor.net}, PULSE_COUNT {pulse_count}, "
                  f"REF_POS {ref_pos}, STEP high {sorted(monitor.high_clocks)} clocks, "
                  f"duty phases {' '.join(monitor.trends)}")
    assert not monitor.errors, "pin monitor:\n  " + "\n  ".join(monitor.errors)
    assert monitor.net == move["distance"], f"net STEP edges {monitor.net}, distance {move['distance']}"
    assert plan["pulses"] == move["distance"], f"plan: {plan['pulses']} pulses"
    assert monitor.pulses == abs(move["distance"]), f"{monitor.pulses} STEP pulses, distance {move['distance']}"
    assert pulse_count == move["distance"], f"PULSE_COUNT {pulse_count}, distance {move['distance']}"
    assert ref_pos == move["distance"], f"REF_POS {ref_pos}, distance {move['distance']}"
    want = expected_trends(plan["segments"])
    assert monitor.trends == want, f"duty phases {monitor.trends}, planned {want}"


@cocotb.test()
async def forward_move_has_exact_count_and_duty_phases(dut):
    Clock(dut.clk_i, PERIOD_NS, unit="ns").start()
    await reset(dut)
    await run_move(dut, MOVE)


@cocotb.test()
async def reverse_move_counts_down_with_dir_low(dut):
    Clock(dut.clk_i, PERIOD_NS, unit="ns").start()
    await reset(dut)
    await run_move(dut, dict(MOVE, distance=-MOVE["distance"]))


@cocotb.test()
async def refused_writes_answer_slverr(dut):
    """A write to a read-only register and a START while disabled are refused."""
    Clock(dut.clk_i, PERIOD_NS, unit="ns").start()
    await reset(dut)
    host = Host(dut)
    for reg, data in (("ID", 0), ("CMD", 1 << REGS["CMD"]["fields"]["START"]["lsb"])):
        resp = await host.axil.write(REGS[reg]["addr"], int(data).to_bytes(4, "little"))
        assert int(resp.resp) == 2, f"write {reg}: response {resp.resp}, expected SLVERR (2)"
    status = await host.read("STATUS")
    assert field("STATUS", "ERR", status) and not field("STATUS", "BUSY", status), f"STATUS 0x{status:08X}"
