// Register-level tests of the host interface:
//   AxiRegs.*   AXI4-Lite master on sc_axi_axis, RTL and model in lockstep
//   BoardUart.* UART host on the Verilated board top (sc_board_top)
//   BoardLong.* a paper group (30,000 pulses, ~14 s of motion) over AXI
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "axi_bench.h"
#include "board_regs.h"
#include "planner.h"
#include "reg_encode.h"
#include "sc_regmap.h"
#include "scenarios.h"
#include "scurve/stream_planner.h"

using namespace sc;
using namespace sc::board_test;

namespace {

// 30,000 pulses in about a quarter of a second.
MoveRequest short_move(int64_t distance = 30000) {
  return scurve::test::move_request(distance, 0, 150000, 0, 2e6, 2e8);
}

// Start, poll STATUS until DONE; returns clocks from START to DONE seen.
uint64_t run_to_done(AxiBench& b, uint64_t limit, int poll = 2000) {
  EXPECT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
  const uint64_t t0 = b.clock();
  while (b.clock() - t0 < limit && !b.failed()) {
    const auto [st, resp] = b.read(reg_addr("STATUS"));
    EXPECT_EQ(resp, kOkay);
    if (st & field_mask("STATUS", "DONE")) return b.clock() - t0;
    b.idle(poll);
  }
  ADD_FAILURE() << "no DONE within " << limit << " clocks";
  return 0;
}

}  // namespace

// ---------------------------------------------------------------------------------
TEST(AxiRegs, ResetValuesReservedBitsAndAccessTypes) {
  AxiBench b(true, 11);
  b.set_jitter(true);
  for (const regmap::Reg& r : regmap::kRegs) {
    if (r.servo) continue;  // sc_axi_servo only (tests/test_board_servo.cpp)
    expect_reset_read(b, r);
  }
  for (const regmap::Reg& r : regmap::kRegs) {
    if (r.servo) continue;
    const std::string n = r.name;
    if (r.access == regmap::Access::RW) {
      // LATCH_CFG.SRC = 3 names no input and is refused (below): its largest legal value
      const uint32_t ones = n == "LATCH_CFG" ? 0xffffffffu & ~(uint32_t(3 & ~LatchSrcIndex) << LatchSrcLsb)
                                             : 0xffffffffu;
      EXPECT_EQ(b.write(r.addr, ones), kOkay) << n;
      EXPECT_EQ(b.read(r.addr).first, r.mask & ones) << n << ": all-ones must read back as the implemented bits";
      // PULSE_TIME HIGH = 0 or LOW = 0 is refused (below): its smallest legal value
      const uint32_t low = n == "PULSE_TIME" ? (1u << PulseHighLsb) | (1u << PulseLowLsb) : 0u;
      EXPECT_EQ(b.write(r.addr, low), kOkay) << n;
      EXPECT_EQ(b.read(r.addr).first, low) << n;
    } else if (r.access == regmap::Access::RO) {
      const uint32_t before = b.read(r.addr).first;
      EXPECT_EQ(b.write(r.addr, ~before), kSlvErr) << n << ": write to a read-only register";
      if (n == "ID") {
        EXPECT_EQ(b.read(r.addr).first, before);
      }
      EXPECT_TRUE(b.read(reg_addr("ERR")).first & field_mask("ERR", "BAD_ACCESS"));
      EXPECT_EQ(b.write(reg_addr("ERR"), field_mask("ERR", "BAD_ACCESS")), kOkay);
      EXPECT_EQ(b.read(reg_addr("ERR")).first, 0u) << "ERR is write-1-to-clear";
    } else if (r.access == regmap::Access::WO) {
      EXPECT_EQ(b.read(r.addr).first, 0u) << n << " reads 0";
    }
  }
  // a value that names nothing is refused and changes nothing
  EXPECT_EQ(b.write(reg_addr("LATCH_CFG"), field_mask("LATCH_CFG", "RISE")), kOkay);
  EXPECT_EQ(b.write(reg_addr("LATCH_CFG"), field_mask("LATCH_CFG", "SRC")), kSlvErr) << "LATCH_CFG.SRC = 3";
  EXPECT_EQ(b.read(reg_addr("LATCH_CFG")).first, field_mask("LATCH_CFG", "RISE"));
  EXPECT_TRUE(b.read(reg_addr("ERR")).first & field_mask("ERR", "REJECT"));
  EXPECT_EQ(b.write(reg_addr("ERR"), field_mask("ERR", "REJECT")), kOkay);
  // a pulse time of 0 clocks is refused and changes nothing, also when the
  // byte strobes leave the other half as it is
  const uint32_t pulse = (7u << PulseHighLsb) | (9u << PulseLowLsb);
  EXPECT_EQ(b.write(reg_addr("PULSE_TIME"), pulse), kOkay);
  for (const auto& [data, strobes] : {std::pair{0u, 0xfu}, std::pair{9u << PulseLowLsb, 0xfu},
                                      std::pair{7u << PulseHighLsb, 0xfu}, std::pair{0u, 0x3u},
                                      std::pair{0u, 0xcu}}) {
    const std::string what = fmt::format("PULSE_TIME = {:#010x}, WSTRB {:#x}", data, strobes);
    EXPECT_EQ(b.write(reg_addr("PULSE_TIME"), data, strobes), kSlvErr) << what;
    EXPECT_EQ(b.read(reg_addr("PULSE_TIME")).first, pulse) << what;
    EXPECT_TRUE(b.read(reg_addr("ERR")).first & field_mask("ERR", "REJECT")) << what;
    EXPECT_EQ(b.write(reg_addr("ERR"), field_mask("ERR", "REJECT")), kOkay);
  }
  EXPECT_EQ(b.write(reg_addr("PULSE_TIME"), 5u << PulseLowLsb, 0xcu), kOkay) << "LOW alone to 5";
  EXPECT_EQ(b.read(reg_addr("PULSE_TIME")).first, (7u << PulseHighLsb) | (5u << PulseLowLsb));
  // byte strobes: only the selected bytes change
  EXPECT_EQ(b.write(reg_addr("SEG_CLOCKS"), 0x11223344u), kOkay);
  EXPECT_EQ(b.write(reg_addr("SEG_CLOCKS"), 0xaabbccddu, 0x5), kOkay);
  EXPECT_EQ(b.read(reg_addr("SEG_CLOCKS")).first, 0x11bb33ddu);
  EXPECT_FALSE(b.failed()) << b.error();
  EXPECT_GT(b.matched(), 500u);
}

TEST(AxiRegs, IllegalAddressesAnswerDecErrAndChangeNothing) {
  AxiBench b(true, 12);
  b.set_jitter(true);
  std::vector<uint32_t> snapshot;
  for (const regmap::Reg& r : regmap::kRegs)
    if (!r.servo) snapshot.push_back(b.read(r.addr).first);
  // the whole 1 KiB window: the 2.x map sits at 0x000..0x0FC and nothing
  // above it aliases it (0x100 + a must not reach register a)
  int illegal = 0;
  for (uint32_t a = 0; a < (1u << RegAddrW); ++a) {
    bool mapped = false;
    for (const regmap::Reg& r : regmap::kRegs) mapped = mapped || (r.addr == a && !r.servo);
    if (mapped) continue;
    ++illegal;
    const auto [v, rresp] = b.read(a);
    EXPECT_EQ(rresp, kDecErr) << "read 0x" << std::hex << a;
    EXPECT_EQ(v, 0u) << "read 0x" << std::hex << a;
    EXPECT_EQ(b.write(a, 0xffffffffu), kDecErr) << "write 0x" << std::hex << a;
  }
  EXPECT_GT(illegal, 950);  // unaligned, unmapped and every word above 0x0FC
  EXPECT_EQ(RegAddrW, 10);
  EXPECT_EQ(b.read(reg_addr("ERR")).first, field_mask("ERR", "BAD_ACCESS"));
  EXPECT_EQ(b.write(reg_addr("ERR"), 0xffffffffu), kOkay);
  size_t i = 0;
  for (const regmap::Reg& r : regmap::kRegs) {
    if (r.servo) continue;
    EXPECT_EQ(b.read(r.addr).first, snapshot[i++]) << r.name << " changed by an illegal access";
  }
  EXPECT_FALSE(b.failed()) << b.error();
}

TEST(AxiRegs, ShortMoveLoadedByRegistersEmitsExactPulses) {
  const PulseTiming t{};
  const Plan p = plan_or_die(short_move(30000), t);
  AxiBench b(true, 13);
  b.set_jitter(true);
  load(b, p, t);
  // the rows wait in the FIFO
  EXPECT_EQ(b.read(reg_addr("FIFO_STATUS")).first & field_mask("FIFO_STATUS", "LEVEL"), uint32_t(p.segments.size()));
  const uint64_t clocks = run_to_done(b, p.total_clocks + 100000);
  b.idle(2000);
  EXPECT_FALSE(b.failed()) << b.error();
  EXPECT_EQ(int32_t(b.read(reg_addr("PULSE_COUNT")).first), 30000);
  EXPECT_EQ(b.net_steps(), 30000);
  EXPECT_EQ(int32_t(b.read(reg_addr("REF_POS")).first), 30000);
  EXPECT_EQ(b.read(reg_addr("STATUS")).first & field_mask("STATUS", "PHASE"), uint32_t(Phase::PhDone));
  EXPECT_EQ(b.read(reg_addr("ERR")).first, 0u);
  EXPECT_GE(clocks, p.total_clocks);
  EXPECT_GT(b.matched(), p.total_clocks);
}

TEST(AxiRegs, WritesWhileBusyAreRejectedFlaggedAndTheMoveIsUnharmed) {
  const PulseTiming t{};
  const Plan p = plan_or_die(short_move(6000), t);
  // undisturbed reference: clocks from START to the last pulse
  AxiBench ref(false);
  load(ref, p, t);
  const uint64_t ref_clocks = run_to_done(ref, p.total_clocks + 100000, 1);

  AxiBench b(true, 14);
  b.set_jitter(true);
  load(b, p, t);
  EXPECT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
  const uint64_t t0 = b.clock() - 0;
  b.idle(50000);
  ASSERT_TRUE(b.out().busy);
  const std::vector<std::pair<std::string, uint32_t>> attempts = {
      {"PULSE_TIME", 0x00010001}, {"DIR_TIME", 0}, {"POS_FRAC0_0", 0},
      {"POS_FRAC0_2", 0xffff}, {"CMD", field_mask("CMD", "START")}, {"CMD", field_mask("CMD", "FLUSH")}};
  for (const auto& [name, value] : attempts) {
    const uint32_t before = b.read(reg_addr(name)).first;
    EXPECT_EQ(b.write(reg_addr(name), value), kSlvErr) << name << " written while busy";
    EXPECT_EQ(b.read(reg_addr(name)).first, before) << name << " changed while busy";
    EXPECT_TRUE(b.read(reg_addr("ERR")).first & field_mask("ERR", "REJECT")) << name;
    EXPECT_TRUE(b.read(reg_addr("STATUS")).first & field_mask("STATUS", "ERR"));
    EXPECT_EQ(b.write(reg_addr("ERR"), field_mask("ERR", "REJECT")), kOkay);
  }
  // CTRL and the table rows outside the lock stay writable? CTRL yes (EN pin).
  while (!b.out().done && b.clock() - t0 < p.total_clocks + 100000 && !b.failed()) b.idle(1000);
  b.idle(1000);
  EXPECT_FALSE(b.failed()) << b.error();
  EXPECT_EQ(b.net_steps(), 6000);
  EXPECT_EQ(int32_t(b.read(reg_addr("PULSE_COUNT")).first), 6000);
  // unharmed: every STEP edge at the same clock (after START) as undisturbed
  ASSERT_EQ(b.rise_times().size(), 6000u);
  EXPECT_TRUE(b.rise_times() == ref.rise_times()) << "the refused writes moved a STEP edge";
  EXPECT_NEAR(double(b.clock() - t0), double(ref_clocks), 3000.0);
}

namespace {

uint32_t fifo_level(AxiBench& b) { return b.read(reg_addr("FIFO_STATUS")).first & field_mask("FIFO_STATUS", "LEVEL"); }

// Two streamed moves joined at a nonzero junction speed (rows of each move
// flagged by move_row_flags, the stream ending at rest).
std::vector<scurve::StreamedMove> two_streamed_moves(int64_t d1, int64_t d2, int64_t d3 = 0) {
  scurve::StreamPlanner sp(scurve::Clock{}, scurve::PulseTiming{}, {2e6, 2e8, 150000});
  EXPECT_FALSE(sp.append({d1, 100000, 100000}));
  EXPECT_FALSE(sp.append({d2, 100000, 100000}));
  if (d3 != 0) {
    EXPECT_FALSE(sp.append({d3, 100000, 100000}));
  }
  EXPECT_FALSE(sp.flush());
  return sp.take_ready();
}

}  // namespace

TEST(AxiRegs, RowPushToAFullFifoIsRefusedFlaggedAndKeepsTheStagedRow) {
  AxiBench b(true, 21);
  const Plan p = plan_or_die(short_move(3000), PulseTiming{});
  const std::vector<RegWrite> row = encode_row(p.segments[0]);
  for (int i = 0; i < RowFifoDepth; ++i) {
    for (const RegWrite& w : row) ASSERT_EQ(b.write(w.addr, w.data), kOkay) << reg_name(w.addr);
  }
  EXPECT_EQ(fifo_level(b), uint32_t(RowFifoDepth));
  EXPECT_TRUE(b.read(reg_addr("FIFO_STATUS")).first & field_mask("FIFO_STATUS", "FULL"));
  const uint32_t staged_clocks = b.read(reg_addr("SEG_CLOCKS")).first;
  EXPECT_EQ(b.write(reg_addr("ROW_PUSH"), 0), kSlvErr);
  EXPECT_EQ(b.read(reg_addr("ERR")).first, field_mask("ERR", "FIFO_FULL"));
  EXPECT_EQ(fifo_level(b), uint32_t(RowFifoDepth));
  EXPECT_EQ(b.read(reg_addr("SEG_CLOCKS")).first, staged_clocks) << "the staged row is kept for a retry";
  EXPECT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "FLUSH")), kOkay);
  b.idle(4);
  EXPECT_EQ(fifo_level(b), 0u);
  EXPECT_EQ(b.write(reg_addr("ROW_PUSH"), 0), kOkay) << "the retry after room was made";
  b.idle(4);
  EXPECT_EQ(fifo_level(b), 1u);
  EXPECT_EQ(b.write(reg_addr("ERR"), field_mask("ERR", "FIFO_FULL")), kOkay);
  EXPECT_EQ(b.read(reg_addr("ERR")).first, 0u);
  EXPECT_FALSE(b.failed()) << b.error();
}

TEST(AxiRegs, RowNotContinuingTheMotionIsNotRunTheAxisStopsAndFlagsDiscontinuity) {
  AxiBench b(true, 22);
  const PulseTiming t{};
  const Plan p = plan_or_die(short_move(6000), t);
  ASSERT_GE(p.segments.size(), 3u);
  EXPECT_EQ(b.write(reg_addr("CTRL"), 1), kOkay);
  EXPECT_EQ(b.write(reg_addr("IRQ_ENABLE"), field_mask("IRQ_ENABLE", "MASK")), kOkay);
  set_stop_limits(b, 2e8, 2e6);
  std::vector<Segment> rows = p.segments;
  rows[2].vel0 += 1;  // one LSB off: a lost or corrupted write
  const std::vector<scurve::RowFlags> flags = scurve::move_row_flags(to_host(p).segments);
  for (size_t i = 0; i < rows.size(); ++i) {
    for (const RegWrite& w : encode_row(rows[i], flags[i])) ASSERT_EQ(b.write(w.addr, w.data), kOkay);
  }
  EXPECT_EQ(b.write(reg_addr("IRQ_STATUS"), 0xff), kOkay);  // low-water of the empty FIFO at reset
  const uint32_t start_row2 = [&] {
    uint64_t c = 0;
    for (size_t i = 0; i < 2; ++i) c += rows[i].clocks;
    return uint32_t(c);
  }();
  EXPECT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
  b.idle(start_row2 + 2000);
  while (b.out().busy && !b.failed()) b.idle(100);
  const uint32_t st = b.read(reg_addr("STATUS")).first;
  EXPECT_TRUE(st & field_mask("STATUS", "DISCONTINUITY"));
  EXPECT_FALSE(st & field_mask("STATUS", "UNDERRUN"));
  EXPECT_EQ(st & field_mask("STATUS", "PHASE"), uint32_t(Phase::PhStop)) << "a controlled stop";
  EXPECT_EQ(b.read(reg_addr("ERR")).first, field_mask("ERR", "DISCONTINUITY"));
  EXPECT_EQ(fifo_level(b), 0u) << "the rest of the stream is not run";
  const uint32_t irq = b.read(reg_addr("IRQ_STATUS")).first;
  EXPECT_TRUE(irq & field_mask("IRQ_STATUS", "FAULT"));
  EXPECT_TRUE(irq & field_mask("IRQ_STATUS", "IDLE"));
  EXPECT_TRUE(b.out().irq);
  // With the move's own limits the stop ends no later than the plan would.
  EXPECT_LE(b.net_steps(), 6000) << "the rest of the stream is not run";
  EXPECT_EQ(b.net_steps(), int32_t(b.read(reg_addr("REF_POS")).first)) << "no position lost";
  EXPECT_EQ(b.write(reg_addr("IRQ_STATUS"), 0xff), kOkay);
  b.idle(4);
  EXPECT_FALSE(b.out().irq);
  EXPECT_FALSE(b.failed()) << b.error();
}

TEST(AxiRegs, StreamedMovesCountMovesLatchBoundariesAndRaiseInterrupts) {
  AxiBench b(true, 23);
  const auto moves = two_streamed_moves(2500, 4000);
  ASSERT_EQ(moves.size(), 2u);
  ASSERT_GT(moves[0].v_out, 0.0) << "the junction is not a stop";
  EXPECT_EQ(b.write(reg_addr("CTRL"), 1), kOkay);
  EXPECT_EQ(b.write(reg_addr("POS_FRAC0_0"), 0), kOkay);
  EXPECT_EQ(b.write(reg_addr("POS_FRAC0_2"), uint32_t(1u << (FracBits - 65))), kOkay);  // 1/2 pulse
  ASSERT_LE(moves[0].segments.size(), size_t(RowFifoDepth));
  push_rows(b, moves[0].segments, scurve::move_row_flags(moves[0].segments, false));
  EXPECT_EQ(b.write(reg_addr("IRQ_STATUS"), 0xff), kOkay);
  EXPECT_EQ(b.write(reg_addr("IRQ_ENABLE"), field_mask("IRQ_STATUS", "MOVE_DONE")), kOkay);
  EXPECT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
  push_rows(b, moves[1].segments, scurve::move_row_flags(moves[1].segments, false));  // while it runs
  const uint64_t limit = b.clock() + moves[1].end_clock + 200000;
  while (b.clock() < limit && !(b.read(reg_addr("STATUS")).first & field_mask("STATUS", "DONE"))) b.idle(2000);
  EXPECT_EQ(b.read(reg_addr("STATUS")).first & ~field_mask("STATUS", "SEG_IDX"),
            field_mask("STATUS", "DONE") | field_mask("STATUS", "EN") | uint32_t(Phase::PhDone));
  EXPECT_EQ(b.read(reg_addr("MOVE_INDEX")).first, 2u);
  EXPECT_EQ(int32_t(b.read(reg_addr("BOUNDARY_POS")).first), 6500);
  EXPECT_EQ(b.net_steps(), 6500);
  const uint32_t irq = b.read(reg_addr("IRQ_STATUS")).first;
  EXPECT_TRUE(irq & field_mask("IRQ_STATUS", "MOVE_DONE"));
  EXPECT_TRUE(irq & field_mask("IRQ_STATUS", "IDLE"));
  EXPECT_TRUE(irq & field_mask("IRQ_STATUS", "LOW_WATER"));
  EXPECT_FALSE(irq & field_mask("IRQ_STATUS", "UNDERRUN"));
  EXPECT_FALSE(irq & field_mask("IRQ_STATUS", "FAULT"));
  EXPECT_TRUE(b.out().irq);
  EXPECT_EQ(b.read(reg_addr("ERR")).first, 0u);
  EXPECT_FALSE(b.failed()) << b.error();
}

// Velocity mode through the registers: ROW_PUSH.HOLD keeps the target
// velocity while the host takes its time; the next command (pushed row by
// row over the bus) starts only once it is whole; CMD.STOP ends it under
// control. The speeds are checked on the pins against the planner's target.
TEST(AxiRegs, VelocityModeHoldsEachTargetUntilTheWholeNextCommandIsQueuedAndStopsUnderControl) {
  AxiBench b(true, 25);
  const scurve::Planner planner{model_clock()};
  const scurve::PulseTiming t{};
  const auto plan = [&](i128 from, double v) {
    auto r = planner.plan_velocity(from, {v, 2e6, 4e8}, t);
    EXPECT_TRUE(std::holds_alternative<scurve::VelocityPlan>(r));
    return std::get<scurve::VelocityPlan>(r);
  };
  EXPECT_EQ(b.write(reg_addr("CTRL"), 1), kOkay);
  EXPECT_EQ(b.write(reg_addr("POS_FRAC0_2"), uint32_t(1u << (FracBits - 65))), kOkay);
  set_stop_limits(b, 4e8, 2e6);
  const scurve::VelocityPlan up = plan(0, 40000);
  push_rows(b, up.segments, scurve::velocity_row_flags(up));
  EXPECT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
  b.idle(up.ramp_clocks + 1000);
  // Held: 40,000 pulses/s on the pins over 0.05 s, for as long as nothing is queued.
  for (int k = 0; k < 2; ++k) {
    const int32_t p0 = b.net_steps();
    b.idle(1'000'000);
    EXPECT_NEAR(b.net_steps() - p0, 2000, 1);
  }
  EXPECT_TRUE(b.out().busy);
  EXPECT_EQ(b.read(reg_addr("ERR")).first, 0u);
  // The next command, -25,000 pulses/s, pushed one register write at a time.
  const scurve::VelocityPlan down = plan(up.v_end, -25000);
  push_rows(b, down.segments, scurve::velocity_row_flags(down));
  b.idle(down.ramp_clocks + 1000);
  const int32_t p1 = b.net_steps();
  b.idle(1'000'000);
  EXPECT_NEAR(b.net_steps() - p1, -1250, 1);
  EXPECT_EQ(b.read(reg_addr("MOVE_INDEX")).first, 1u) << "the first command's move ended with its hold";
  EXPECT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "STOP")), kOkay);
  while (b.out().busy && !b.failed()) b.idle(100);
  const uint32_t st = b.read(reg_addr("STATUS")).first;
  EXPECT_EQ(st & field_mask("STATUS", "PHASE"), uint32_t(Phase::PhStop));
  EXPECT_FALSE(st & field_mask("STATUS", "UNDERRUN"));
  EXPECT_EQ(b.read(reg_addr("ERR")).first, 0u);
  EXPECT_EQ(b.net_steps(), int32_t(b.read(reg_addr("REF_POS")).first)) << "no position lost";
  EXPECT_FALSE(b.failed()) << b.error();
}

// Retarget through the registers: RETARGET_ROW and ROW_PUSH.REPLACE
// redirect a running move at a future row boundary (planned from the exact
// state there, as the host library knows it); once that row is loaded the
// replace is refused with ERR.RETARGET and the old move runs on untouched.
TEST(AxiRegs, RetargetRedirectsARunningMoveAtAFutureBoundaryAndIsRefusedOnceItsRowIsLoaded) {
  const scurve::Planner planner{model_clock()};
  const scurve::PulseTiming t{};
  scurve::MoveRequest req;
  req.distance = 3000;
  req.v_cruise = 40000;
  req.a_max = 2e6;
  req.j_max = 4e8;
  const scurve::Plan p = std::get<scurve::Plan>(planner.plan(req, t));
  size_t k = 1;  // the cruise row: a = 0 at its boundary
  while (k < p.segments.size() && p.segments[k].acc0 != 0) ++k;
  ASSERT_LT(k + 1, p.segments.size());
  i128 pos = i128(p.pos_frac0);
  for (size_t i = 0; i < k; ++i) {
    const scurve::Segment& s = p.segments[i];
    pos += scurve::pos_gain(s.vel0, s.acc0, s.jerk, s.clocks);
  }
  const i128 here = pos / i128(kOne);
  scurve::MoveRequest more = req;
  more.distance = 2500 - int64_t(here);
  const scurve::Plan fresh = std::get<scurve::Plan>(
      planner.plan_from({p.segments[k].vel0, u128(pos - here * i128(kOne))}, more, t));
  const std::vector<RegWrite> retarget =
      scurve::encode_retarget(uint32_t(k), fresh.segments, scurve::move_row_flags(fresh.segments, true));

  for (const bool late : {false, true}) {
    AxiBench b(true, late ? 27 : 26);
    EXPECT_EQ(b.write(reg_addr("CTRL"), 1), kOkay);
    load(b, to_model(p), PulseTiming{});
    EXPECT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
    // Row 0 loads once START has armed the axis; a replace before that is
    // refused (no stream runs yet).
    while (b.read(reg_addr("ROW_COUNT")).first == 0 && !b.failed()) b.idle(10);
    if (late) {
      while (b.read(reg_addr("ROW_COUNT")).first <= k && !b.failed()) b.idle(100);
    } else {
      EXPECT_LT(b.read(reg_addr("ROW_COUNT")).first, k);
    }
    size_t w = 0;
    for (; w < retarget.size(); ++w) {
      EXPECT_EQ(b.write(retarget[w].addr, retarget[w].data), kOkay) << reg_name(retarget[w].addr);
      if (retarget[w].addr == uint32_t(reg_addr("ROW_PUSH"))) break;  // the replace: check it took
    }
    b.idle(4);  // the executor's verdict reaches ERR within 4 clocks of the write's response
    const uint32_t err = b.read(reg_addr("ERR")).first;
    EXPECT_EQ(err, late ? field_mask("ERR", "RETARGET") : 0u);
    if (!late) {
      for (++w; w < retarget.size(); ++w) EXPECT_EQ(b.write(retarget[w].addr, retarget[w].data), kOkay);
    }
    while (b.out().busy && !b.failed()) b.idle(1000);
    EXPECT_EQ(int32_t(b.read(reg_addr("REF_POS")).first), late ? 3000 : 2500);
    EXPECT_EQ(b.net_steps(), late ? 3000 : 2500);
    EXPECT_TRUE(b.read(reg_addr("STATUS")).first & field_mask("STATUS", "DONE"));
    EXPECT_EQ(b.write(reg_addr("ERR"), field_mask("ERR", "RETARGET")), kOkay);
    EXPECT_EQ(b.read(reg_addr("ERR")).first, 0u);
    EXPECT_FALSE(b.failed()) << b.error();
  }
}

TEST(AxiRegs, FifoRunningDryWhileMovingIsAnUnderrunWithTheBoundaryKept) {
  AxiBench b(true, 24);
  const auto moves = two_streamed_moves(2500, 4000, 3000);
  ASSERT_EQ(moves.size(), 3u);
  EXPECT_EQ(b.write(reg_addr("CTRL"), 1), kOkay);
  EXPECT_EQ(b.write(reg_addr("POS_FRAC0_2"), uint32_t(1u << (FracBits - 65))), kOkay);
  set_stop_limits(b, 2e8, 2e6);
  push_rows(b, moves[0].segments, scurve::move_row_flags(moves[0].segments, false));  // the host falls behind
  EXPECT_EQ(b.write(reg_addr("IRQ_STATUS"), 0xff), kOkay);
  EXPECT_EQ(b.write(reg_addr("IRQ_ENABLE"), field_mask("IRQ_STATUS", "UNDERRUN")), kOkay);
  EXPECT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
  b.idle(moves[0].end_clock + 1000);
  while (b.out().busy && !b.failed()) b.idle(100);
  EXPECT_TRUE(b.read(reg_addr("STATUS")).first & field_mask("STATUS", "UNDERRUN"));
  EXPECT_EQ(b.read(reg_addr("ERR")).first, field_mask("ERR", "UNDERRUN"));
  EXPECT_EQ(b.read(reg_addr("MOVE_INDEX")).first, 1u);
  EXPECT_EQ(int32_t(b.read(reg_addr("BOUNDARY_POS")).first), 2500);
  // The controlled stop runs on from the boundary's junction speed.
  EXPECT_GT(b.net_steps(), 2500);
  EXPECT_EQ(b.net_steps(), int32_t(b.read(reg_addr("REF_POS")).first)) << "no position lost";
  EXPECT_EQ(b.read(reg_addr("STATUS")).first & field_mask("STATUS", "PHASE"), uint32_t(Phase::PhStop));
  const int32_t stopped_at = b.net_steps();
  EXPECT_TRUE(b.read(reg_addr("IRQ_STATUS")).first & field_mask("IRQ_STATUS", "UNDERRUN"));
  EXPECT_TRUE(b.out().irq);
  // STOP while idle changes nothing.
  const uint32_t st = b.read(reg_addr("STATUS")).first;
  EXPECT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "STOP")), kOkay);
  b.idle(100);
  EXPECT_EQ(b.read(reg_addr("STATUS")).first, st);
  EXPECT_EQ(b.net_steps(), stopped_at);
  // Recovery: clear the flag, plan the rest from rest where the axis
  // stopped, START: it runs to its exact end, with no new flag.
  EXPECT_EQ(b.write(reg_addr("ERR"), 0xffffffffu), kOkay);
  EXPECT_EQ(b.write(reg_addr("IRQ_STATUS"), 0xffffffffu), kOkay);
  const int64_t rest = 2500 + 4000 - stopped_at;
  const Plan p = plan_or_die(short_move(rest), PulseTiming{});
  load(b, p, PulseTiming{});
  EXPECT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
  b.idle(p.total_clocks + 1000);
  while (b.out().busy && !b.failed()) b.idle(100);
  EXPECT_EQ(b.net_steps(), 2500 + 4000);
  EXPECT_EQ(int32_t(b.read(reg_addr("REF_POS")).first), 2500 + 4000);
  EXPECT_TRUE(b.read(reg_addr("STATUS")).first & field_mask("STATUS", "DONE"));
  EXPECT_EQ(b.read(reg_addr("ERR")).first, 0u);
  EXPECT_FALSE(b.failed()) << b.error();
}

TEST(AxiRegs, StartRefusedWhenDisabledOrEstoppedStopAndEstopAbort) {
  const PulseTiming t{};
  const Plan p = plan_or_die(short_move(6000), t);
  AxiBench b(true, 15);
  load(b, p, t);
  const uint32_t start = field_mask("CMD", "START");
  // disabled: refused
  EXPECT_EQ(b.write(reg_addr("CTRL"), 0), kOkay);
  EXPECT_EQ(b.write(reg_addr("CMD"), start), kSlvErr);
  EXPECT_TRUE(b.read(reg_addr("ERR")).first & field_mask("ERR", "REJECT"));
  EXPECT_EQ(b.write(reg_addr("ERR"), 0xff), kOkay);
  // enabled: runs; STOP stops under control (the move's own limits)
  EXPECT_EQ(b.write(reg_addr("CTRL"), 1), kOkay);
  set_stop_limits(b, 2e8, 2e6);
  EXPECT_EQ(b.write(reg_addr("CMD"), start), kOkay);
  b.idle(200000);
  EXPECT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "STOP")), kOkay);
  b.idle(10);
  uint32_t st = b.read(reg_addr("STATUS")).first;
  EXPECT_TRUE(st & field_mask("STATUS", "STOPPING"));
  EXPECT_EQ(st & field_mask("STATUS", "PHASE"), uint32_t(Phase::PhStop));
  EXPECT_EQ(b.write(reg_addr("STOP_JERK_0"), 1), kSlvErr) << "stop limits are locked while busy";
  EXPECT_EQ(b.write(reg_addr("ERR"), field_mask("ERR", "REJECT")), kOkay);
  while ((b.read(reg_addr("STATUS")).first & field_mask("STATUS", "BUSY")) && !b.failed()) b.idle(1000);
  st = b.read(reg_addr("STATUS")).first;
  EXPECT_EQ(st & field_mask("STATUS", "PHASE"), uint32_t(Phase::PhStop));
  EXPECT_FALSE(st & (field_mask("STATUS", "STOPPING") | field_mask("STATUS", "OVERSHOOT") | field_mask("STATUS", "DONE")));
  EXPECT_EQ(b.read(reg_addr("ERR")).first, 0u) << "a controlled stop is no error";
  const int64_t after_stop = b.net_steps();
  EXPECT_GT(after_stop, 0);
  EXPECT_LT(after_stop, 6000);
  b.idle(20000);
  EXPECT_EQ(b.net_steps(), after_stop) << "pulses after STOP";
  // restart, then the e-stop input: abort, EN off, latched, START refused
  EXPECT_EQ(b.write(reg_addr("CMD"), start), kOkay);
  b.idle(100000);
  b.side().estop = true;
  b.idle(3);
  b.side().estop = false;
  b.idle(1000);
  st = b.read(reg_addr("STATUS")).first;
  EXPECT_TRUE(st & field_mask("STATUS", "ESTOP"));
  EXPECT_FALSE(st & field_mask("STATUS", "EN"));
  EXPECT_FALSE(b.out().en);
  EXPECT_TRUE(b.read(reg_addr("IRQ_STATUS")).first & field_mask("IRQ_STATUS", "FAULT"));
  EXPECT_EQ(b.net_steps(), int32_t(b.read(reg_addr("REF_POS")).first)) << "the e-stop lost a position";
  const int64_t at_estop = b.net_steps();
  b.idle(20000);
  EXPECT_EQ(b.net_steps(), at_estop) << "pulses after the e-stop";
  EXPECT_EQ(b.read(reg_addr("CTRL")).first, 0u);
  EXPECT_EQ(b.write(reg_addr("CTRL"), 1), kOkay);
  EXPECT_EQ(b.write(reg_addr("CMD"), start), kSlvErr) << "START while e-stop latched";
  EXPECT_EQ(b.write(reg_addr("ERR"), field_mask("ERR", "ESTOP") | field_mask("ERR", "REJECT")), kOkay);
  EXPECT_EQ(b.write(reg_addr("CMD"), start), kOkay);
  // CMD.ESTOP does the same from the bus
  b.idle(1000);
  EXPECT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "ESTOP")), kOkay);
  b.idle(100);
  EXPECT_TRUE(b.read(reg_addr("ERR")).first & field_mask("ERR", "ESTOP"));
  EXPECT_EQ(b.read(reg_addr("CTRL")).first, 0u);
  // encoder position and following error
  b.side().enc_pos = -5;
  b.side().enc_ab = 2;
  b.idle(2);
  const int32_t ref_pos = int32_t(b.read(reg_addr("REF_POS")).first);
  EXPECT_EQ(int32_t(b.read(reg_addr("ENC_POS")).first), -5);
  EXPECT_EQ(int32_t(b.read(reg_addr("FOLLOW_ERR")).first), ref_pos + 5);
  EXPECT_EQ((b.read(reg_addr("STATUS")).first & field_mask("STATUS", "ENC_AB")) >> 12, 2u);
  EXPECT_FALSE(b.failed()) << b.error();
}

TEST(AxiRegs, CheckerCatchesAnInjectedDifference) {
  AxiBench b(true, 16);
  EXPECT_EQ(b.read(reg_addr("FOLLOW_ERR")).first, 0u);
  EXPECT_FALSE(b.failed());
  b.inject_model_enc_offset(1);
  b.read(reg_addr("FOLLOW_ERR"));
  ASSERT_TRUE(b.failed());
  EXPECT_NE(b.error().find("rdata"), std::string::npos) << b.error();
}

// ---------------------------------------------------------------------------------
namespace {

// A frame the encoder must accept (the test's addresses are registers).
std::vector<uint8_t> frame(const FrameResult& f) {
  if (const auto* e = std::get_if<scurve::Error>(&f)) throw std::runtime_error(e->message);
  return std::get<std::vector<uint8_t>>(f);
}

struct Board {
  RtlBoard rtl;
  UartHost host{rtl, UartClksPerBit};
  Board() { host.idle(200); }  // MMCM stand-in lock + reset synchroniser
};

}  // namespace

TEST(BoardUart, LoadMoveStartPollAndCountPulses) {
  Board bd;
  UartResponse r = bd.host.read(reg_addr("ID"));
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.status, kOkay);
  EXPECT_EQ(r.data, reg("ID").reset);
  const PulseTiming t{};
  MoveRequest req = short_move(2000);
  req.a_max = 1e7;
  req.j_max = 1e10;
  const Plan p = plan_or_die(req, t);
  for (const RegWrite& w : encode_move(p, t, true)) {
    r = bd.host.write(w.addr, w.data);
    ASSERT_TRUE(r.ok) << reg_name(w.addr) << ": " << r.error;
    ASSERT_EQ(r.status, kOkay) << reg_name(w.addr);
  }
  bool done = false;
  for (int i = 0; i < 200 && !done; ++i) {
    r = bd.host.read(reg_addr("STATUS"));
    ASSERT_TRUE(r.ok) << r.error;
    done = r.data & field_mask("STATUS", "DONE");
  }
  ASSERT_TRUE(done);
  r = bd.host.read(reg_addr("PULSE_COUNT"));
  EXPECT_EQ(int32_t(r.data), 2000);
  EXPECT_EQ(bd.host.net_steps(), 2000);
  EXPECT_EQ(bd.host.pulses(), 2000u);
  EXPECT_TRUE(bd.host.pins().errors().empty()) << bd.host.pins().errors().front();
}

TEST(BoardUart, IllegalAddressReservedBitsAndWriteWhileBusy) {
  Board bd;
  // The frame carries a word address: an unaligned or out-of-window byte
  // address cannot be sent, the encoder refuses it naming the address.
  UartResponse r = bd.host.read(0xce);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("addr=0xCE"), std::string::npos) << r.error;
  r = bd.host.write(0x400, 1);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("0x3FC"), std::string::npos) << r.error;
  // Words above the 2.x map (address bytes 0x40..0xFF) reach the bus as
  // byte addresses 0x100..0x3FC: STOP_JERK / STOP_ACC at 0x100..0x10C and
  // SW_CFG .. LATCH_ENC at 0x110..0x11C (their reset values, not ID or
  // CTRL), the rest unmapped, DECERR, no alias of 0x000..0x0FC.
  r = bd.host.read(0x100);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.status, kOkay);
  EXPECT_EQ(r.data, uint32_t(StopJerkReset)) << "STOP_JERK_0 at its reset value";
  r = bd.host.read(0x10C);
  EXPECT_EQ(r.data, uint32_t(StopAccReset >> 32)) << "STOP_ACC_1 at its reset value";
  r = bd.host.read(reg_addr("SW_CFG"));
  EXPECT_EQ(r.data, reg("SW_CFG").reset) << "SW_CFG at its reset value";
  EXPECT_EQ(bd.host.read(reg_addr("LATCH_CFG")).data, 0u);
  for (const uint32_t a : {0x150u, 0x154u, 0x180u, 0x1F8u, 0x200u, 0x2CCu, 0x3FCu}) {
    r = bd.host.read(a);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.status, kDecErr) << std::hex << a;
    EXPECT_EQ(r.data, 0u) << std::hex << a;
  }
  r = bd.host.write(0x154, field_mask("CTRL", "ENABLE"));
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.status, kDecErr);
  EXPECT_EQ(bd.host.read(reg_addr("CTRL")).data, 0u) << "0x154 wrote CTRL";
  r = bd.host.write(reg_addr("ID"), 0);
  EXPECT_EQ(r.status, kSlvErr);
  r = bd.host.write(reg_addr("SEG_PHASE"), 0xffffffffu);
  EXPECT_EQ(r.status, kOkay);
  EXPECT_EQ(bd.host.read(reg_addr("SEG_PHASE")).data, reg("SEG_PHASE").mask);
  EXPECT_EQ(bd.host.read(reg_addr("ERR")).data, field_mask("ERR", "BAD_ACCESS"));
  EXPECT_EQ(bd.host.write(reg_addr("ERR"), 0xff).status, kOkay);
  // a move, then writes while it runs
  const PulseTiming t{};
  const Plan p = plan_or_die(short_move(3000), t);
  for (const RegWrite& w : encode_move(p, t, true)) ASSERT_EQ(bd.host.write(w.addr, w.data).status, kOkay);
  r = bd.host.write(reg_addr("PULSE_TIME"), 0x00010001);
  EXPECT_EQ(r.status, kSlvErr);
  EXPECT_EQ(bd.host.read(reg_addr("PULSE_TIME")).data, (uint32_t(t.low) << 16) | t.high);
  EXPECT_TRUE(bd.host.read(reg_addr("ERR")).data & field_mask("ERR", "REJECT"));
  bool done = false;
  for (int i = 0; i < 400 && !done; ++i) done = bd.host.read(reg_addr("STATUS")).data & field_mask("STATUS", "DONE");
  ASSERT_TRUE(done);
  EXPECT_EQ(bd.host.net_steps(), 3000);
  EXPECT_TRUE(bd.host.pins().errors().empty()) << bd.host.pins().errors().front();
}

TEST(BoardUart, CorruptedFramesAreRejectedWithNothingWritten) {
  Board bd;
  const uint32_t a = reg_addr("SEG_CLOCKS");
  ASSERT_EQ(bd.host.write(a, 0x12345678u).status, kOkay);
  // one data bit flipped after the CRC was computed
  std::vector<uint8_t> f = frame(uart_write_frame(a, 0xdeadbeefu));
  f[4] ^= 0x10;
  std::vector<uint8_t> rsp = bd.host.transact(f, 3);
  UartResponse r = parse_uart_response(rsp, false);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.status, uint8_t(UartStCrcErr));
  EXPECT_EQ(bd.host.read(a).data, 0x12345678u) << "corrupted frame wrote";
  // wrong CRC byte on a write to CMD (would start / stop): ignored
  f = frame(uart_write_frame(reg_addr("CTRL"), 1));
  f.back() ^= 0xff;
  r = parse_uart_response(bd.host.transact(f, 3), false);
  EXPECT_EQ(r.status, uint8_t(UartStCrcErr));
  EXPECT_EQ(bd.host.read(reg_addr("CTRL")).data, 0u);
  // address byte corrupted: nothing written anywhere
  f = frame(uart_write_frame(a, 1));
  ASSERT_EQ(f[2], a / 4);  // the word address
  f[2] ^= 0x01;            // would be SEG_PHASE
  r = parse_uart_response(bd.host.transact(f, 3), false);
  EXPECT_EQ(r.status, uint8_t(UartStCrcErr));
  EXPECT_EQ(bd.host.read(a).data, 0x12345678u);
  EXPECT_EQ(bd.host.read(a - 4).data, 0u);  // SEG_PHASE
  // unknown command byte
  std::vector<uint8_t> bad = {0xA5, 0x07};
  r = parse_uart_response(bd.host.transact(bad, 3), false);
  EXPECT_EQ(r.status, uint8_t(UartStBadCmd));
  // a truncated frame is dropped after the gap; the next frame works
  f = frame(uart_write_frame(a, 0xcafef00du));
  f.resize(5);
  EXPECT_TRUE(bd.host.transact(f, 1, 2 * UartTimeoutBits).empty());
  EXPECT_EQ(bd.host.read(a).data, 0x12345678u);
  ASSERT_EQ(bd.host.write(a, 0x0badf00du).status, kOkay);
  EXPECT_EQ(bd.host.read(a).data, 0x0badf00du);
  // garbage between frames is skipped
  std::vector<uint8_t> g = {0x00, 0x5A, 0xFF};
  const std::vector<uint8_t> rd = frame(uart_read_frame(a));
  g.insert(g.end(), rd.begin(), rd.end());
  r = parse_uart_response(bd.host.transact(g, 7), true);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.data, 0x0badf00du);
}

// Faults on the line itself, below the frame: a low pulse too short for a
// start bit is ignored, and a byte with a low stop bit (a framing error)
// inside a frame drops the frame unanswered, whatever its CRC; either way
// nothing is written and the next clean frame is answered.
TEST(BoardUart, LineGlitchesAndFramingErrorsWriteNothingAndTheNextFrameWorks) {
  Board bd;
  const uint32_t a = reg_addr("SEG_CLOCKS");
  ASSERT_EQ(bd.host.write(a, 0x12345678u).status, kOkay);
  const int bit = bd.host.pin_clocks_per_bit();
  // glitches of a quarter and a third of a bit before a clean write frame
  bd.host.line().send_glitch(bit / 4);
  bd.host.line().send_glitch(bit / 3);
  UartResponse r = parse_uart_response(bd.host.transact(frame(uart_write_frame(a, 0x0badf00du)), 3), false);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.status, kOkay);
  EXPECT_EQ(bd.host.read(a).data, 0x0badf00du);
  // a framing error on each byte after the sync byte of a write frame
  const std::vector<uint8_t> f = frame(uart_write_frame(a, 0x11223344u));
  for (size_t bad = 1; bad < f.size(); ++bad) {
    for (size_t i = bad + 1; i < f.size(); ++i) ASSERT_NE(f[i], 0xA5) << "a later byte would open a frame";
    for (size_t i = 0; i < f.size(); ++i) {
      if (i == bad) {
        bd.host.line().send_with_low_stop_bit(f[i]);
      } else {
        bd.host.line().send(f[i]);
      }
    }
    EXPECT_TRUE(bd.host.transact({}, 1, 2 * UartTimeoutBits).empty()) << "byte " << bad << ": answered";
    EXPECT_EQ(bd.host.read(a).data, 0x0badf00du) << "byte " << bad << ": the broken frame wrote";
  }
  // a framing error on the sync byte: no frame opens, the next one works
  bd.host.line().send_with_low_stop_bit(0xA5);
  EXPECT_TRUE(bd.host.transact({}, 1, 2 * UartTimeoutBits).empty());
  ASSERT_EQ(bd.host.write(a, 0x5eed5eedu).status, kOkay);
  EXPECT_EQ(bd.host.read(a).data, 0x5eed5eedu);
}

// The encoder pins reach the closed-loop axis's quadrature decoder: a Gray
// sequence on Pmod JB counts up and down, read back over the UART; the
// index pin latches the count it came with.
TEST(BoardUart, EncoderPinsCountThroughTheQuadratureDecoderAndTheIndexLatchesItsCount) {
  Board bd;
  static constexpr uint8_t kGray[4] = {0, 1, 3, 2};  // A leads B: forward
  for (int i = 1; i <= 10; ++i) {
    bd.host.enc_ab = kGray[i & 3];
    bd.host.idle(500);
  }
  UartResponse r = bd.host.read(reg_addr("ENC_POS"));
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(int32_t(r.data), 10);
  EXPECT_EQ((bd.host.read(reg_addr("STATUS")).data & field_mask("STATUS", "ENC_AB")) >> 12, uint32_t(kGray[10 & 3]));
  for (int i = 9; i >= 7; --i) {
    bd.host.enc_ab = kGray[i & 3];
    bd.host.idle(500);
  }
  EXPECT_EQ(int32_t(bd.host.read(reg_addr("ENC_POS")).data), 7);
  EXPECT_EQ(int32_t(bd.host.read(reg_addr("FOLLOW_ERR")).data), -7);
  EXPECT_EQ(bd.host.read(reg_addr("CL_STATUS")).data & field_mask("CL_STATUS", "ENC_ILLEGAL"), 0u);
  // The index pin (Pmod JB9) is a latch source: Z rising with the step to
  // count 6 captures 6.
  const uint32_t index_rise = field_mask("LATCH_CFG", "RISE") | (uint32_t(LatchSrcIndex) << LatchSrcLsb);
  ASSERT_EQ(bd.host.write(reg_addr("LATCH_CFG"), index_rise).status, kOkay);
  EXPECT_EQ(bd.host.read(reg_addr("STATUS")).data & field_mask("STATUS", "LATCHED"), 0u);
  bd.host.enc_ab = kGray[6 & 3];
  bd.host.enc_z = true;
  bd.host.idle(500);
  bd.host.enc_ab = kGray[5 & 3];
  bd.host.enc_z = false;
  bd.host.idle(500);
  EXPECT_NE(bd.host.read(reg_addr("STATUS")).data & field_mask("STATUS", "LATCHED"), 0u);
  EXPECT_EQ(int32_t(bd.host.read(reg_addr("LATCH_ENC")).data), 6);
  EXPECT_EQ(int32_t(bd.host.read(reg_addr("ENC_POS")).data), 5);
  // SRC = 3 names no input: refused, nothing changes
  EXPECT_EQ(bd.host.write(reg_addr("LATCH_CFG"), field_mask("LATCH_CFG", "SRC")).status, kSlvErr);
  EXPECT_EQ(bd.host.read(reg_addr("LATCH_CFG")).data, index_rise);
  EXPECT_NE(bd.host.read(reg_addr("STATUS")).data & field_mask("STATUS", "LATCHED"), 0u);
  EXPECT_NE(bd.host.read(reg_addr("ERR")).data & field_mask("ERR", "REJECT"), 0u);
}

// ---------------------------------------------------------------------------------
TEST(BoardLong, PaperGroup1OverAxiExactly30000Pulses) {
  const PulseTiming t{};
  const Plan p = plan_or_die(paper_group(1), t);
  AxiBench b(true, 21);
  b.set_jitter(true);
  load(b, p, t);
  run_to_done(b, p.total_clocks + 1000000, 200000);
  b.idle(2000);
  EXPECT_FALSE(b.failed()) << b.error();
  EXPECT_EQ(int32_t(b.read(reg_addr("PULSE_COUNT")).first), 30000);
  EXPECT_EQ(b.net_steps(), 30000);
  EXPECT_GT(b.matched(), p.total_clocks);
}
