// Soft limits in hardware (SOFT_MIN / SOFT_MAX with SW_CFG.SOFT_EN): the
// window's edges act as limit switches on REF_POS. sc_axi_axis RTL and
// model in lockstep every clock; what is checked does not come from the
// RTL: the stop lies past the edge by at most the latency travel (hard) or
// that plus the closed-form stopping distance (controlled); the pins,
// PULSE_COUNT and REF_POS agree; the flags are set; a START further out is
// refused; a move back into the window runs to its exact end. The same for
// a stream of moves pushed while the axis runs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "axi_bench.h"
#include "board_regs.h"
#include "scurve/stream_planner.h"
#include "planner.h"
#include "random_moves.h"
#include "stop_check.h"

using namespace sc;
using namespace sc::board_test;

namespace {

using stopcheck::kF;
using stopcheck::kLsb;
using stopcheck::ld;

using scurve::test::log_uniform;

template <class Done>
void run_until(AxiBench& b, uint64_t limit, Done done) {
  const uint64_t t0 = b.clock();
  while (b.clock() - t0 < limit && !b.failed() && !done()) b.tick();
}

// The most the axis may run past the window's edge, pulses, from a speed
// of at most v (pulses/s) and an acceleration of at most a (pulses/s^2)
// there: the latency from the reference reaching the edge to the stop's
// first clock (the comparison, the core's input register, the executor),
// one pulse, and for a controlled stop the closed-form stopping distance.
ld overtravel_bound(ld v, ld a, bool hard, double stop_jerk, double stop_acc) {
  const ld latency = 4;
  ld bound = v * latency / kF + 1;
  if (!hard) {
    const stopcheck::ClosedForm cf = stopcheck::closed_form(
        v * kLsb / kF, a * kLsb / (kF * kF), ld(stop_jerk) * kLsb / (kF * kF * kF), ld(stop_acc) * kLsb / (kF * kF));
    bound += cf.dist / kLsb;
  }
  return bound;
}

// Loads and starts a move, runs it to rest.
void run_move(AxiBench& b, const Plan& p, const PulseTiming& t) {
  load(b, p, t);
  ASSERT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
  bool moved = false;
  run_until(b, p.total_clocks + 2'000'000, [&] {
    moved = moved || b.out().busy;
    return moved && !b.out().busy;
  });
  ASSERT_FALSE(b.failed()) << b.error();
  b.idle(10);
}

void run_soft_case(std::mt19937_64& g, int i) {
  const bool hard = (i & 2) != 0;
  const int dir = (i & 1) ? -1 : 1;
  const PulseTiming t{};
  AxiBench b(true, uint32_t(200 + i));
  b.reset();
  b.idle(4);
  ASSERT_EQ(b.write(reg_addr("CTRL"), field_mask("CTRL", "ENABLE")), kOkay);

  // To a random start (the window off): REF_POS carries over between STARTs.
  const int64_t s0 = int64_t(g() % 6001) - 3000;
  if (s0 != 0) run_move(b, plan_or_die(scurve::test::move_request(s0, 0, 50000, 0, 1e6, 1e9), t), t);
  ASSERT_EQ(b.net_steps(), s0);

  MoveRequest req;
  int64_t distance = 0;
  for (;;) {
    const int64_t d = int64_t(2000 + g() % 18000);
    req = scurve::test::move_request(d * dir, 0, log_uniform(g, 5e3, 1.5e5), 0, log_uniform(g, 1e5, 2e6),
                                     log_uniform(g, 1e7, 2e9));
    const PlanResult r = plan_move(req, t);
    if (const Plan* p = std::get_if<Plan>(&r); p && p->total_clocks < 1'500'000) {
      distance = d * dir;
      break;
    }
  }
  const Plan p = plan_or_die(req, t);
  // The window's edge inside the move, far enough from its end for the stop.
  const int64_t edge = s0 + distance / 10 + int64_t(g() % uint64_t(std::abs(distance) / 3)) * dir;
  const int64_t other = s0 - dir * int64_t(100 + g() % 1000);
  const int64_t soft_min = dir > 0 ? other : edge, soft_max = dir > 0 ? edge : other;
  const double stop_jerk = req.j_max * log_uniform(g, 1, 4), stop_acc = req.a_max * log_uniform(g, 1, 4);
  const std::string what = "start " + std::to_string(s0) + ", distance " + std::to_string(distance) + ", window [" +
                           std::to_string(soft_min) + ", " + std::to_string(soft_max) + "], " +
                           (hard ? "hard" : "controlled");
  SCOPED_TRACE(what);

  set_stop_limits(b, stop_jerk, stop_acc);
  ASSERT_EQ(b.write(reg_addr("SOFT_MIN"), uint32_t(int32_t(soft_min))), kOkay);
  ASSERT_EQ(b.write(reg_addr("SOFT_MAX"), uint32_t(int32_t(soft_max))), kOkay);
  const uint32_t sw_cfg = field_mask("SW_CFG", "LIM_EN") | field_mask("SW_CFG", "SOFT_EN") |
                          (hard ? field_mask("SW_CFG", "LIM_HARD") : 0);
  ASSERT_EQ(b.write(reg_addr("SW_CFG"), sw_cfg), kOkay);
  ASSERT_EQ(b.read(reg_addr("ERR")).first, 0u) << "inside the window nothing trips";
  ASSERT_EQ(b.write(reg_addr("IRQ_STATUS"), 0xffffffffu), kOkay);
  run_move(b, p, t);

  const int64_t end = b.net_steps();
  const int64_t overtravel = (end - edge) * dir;
  const ld bound = overtravel_bound(ld(p.peak_velocity), ld(p.peak_acceleration), hard, stop_jerk, stop_acc);
  std::printf("[soft] %s: overtravel %lld pulses (bound %.1f)\n", what.c_str(), (long long)overtravel, double(bound));
  // The look-ahead stops at the boundary before the first row whose reach
  // leaves the window; the reactive check flags the side only if the stop
  // from there still crossed the edge.
  EXPECT_LE(ld(overtravel), bound) << "stopped at " << end;
  EXPECT_LT((end - s0) * dir, std::abs(distance)) << "the window did not stop the move";
  EXPECT_EQ(int32_t(b.read(reg_addr("PULSE_COUNT")).first), end - s0);
  EXPECT_EQ(int32_t(b.read(reg_addr("REF_POS")).first), end);
  const uint32_t side = field_mask("ERR", dir > 0 ? "LIMIT_POS" : "LIMIT_NEG");
  const uint32_t crossed = overtravel >= 1 ? side : 0u;
  EXPECT_EQ(b.read(reg_addr("ERR")).first, crossed | field_mask("ERR", "SOFT_LIMIT"));
  const uint32_t status = b.read(reg_addr("STATUS")).first;
  EXPECT_TRUE(status & field_mask("STATUS", "REACH")) << "the look-ahead refused the row";
  EXPECT_TRUE(status & field_mask("STATUS", "ERR"));
  EXPECT_FALSE(status & field_mask("STATUS", "DONE")) << "a stopped move is not done";
  EXPECT_TRUE(b.read(reg_addr("IRQ_STATUS")).first & field_mask("IRQ_STATUS", "FAULT"));

  // Further out: refused, nothing moves, the flags again.
  ASSERT_EQ(b.write(reg_addr("ERR"), 0xffffffffu), kOkay);
  ASSERT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "FLUSH")), kOkay);
  const int64_t further = std::max<int64_t>(overtravel, 0) - overtravel + 100;  // to 100 past the edge
  load(b, plan_or_die(scurve::test::move_request(further * dir, 0, 5000, 0, 1e5, 1e7), t), t);
  ASSERT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
  run_until(b, 50'000'000, [&] { return !b.out().busy; });
  b.idle(10);
  // It runs up to the boundary before its row that leaves (or is refused at
  // once from beyond the edge), then stops.
  const int64_t end2 = b.net_steps();
  const int64_t over2 = (end2 - edge) * dir;
  EXPECT_LT((end2 - end) * dir, further) << "a move further out of the window ran to its end";
  EXPECT_LE(ld(over2), std::max(ld(overtravel), bound)) << "stopped at " << end2;
  EXPECT_EQ(int32_t(b.read(reg_addr("REF_POS")).first), end2);
  EXPECT_TRUE(b.read(reg_addr("ERR")).first & field_mask("ERR", "SOFT_LIMIT"));

  // Back into the window: runs to its exact end; the window is locked while
  // the axis moves; no flag.
  ASSERT_EQ(b.write(reg_addr("ERR"), 0xffffffffu), kOkay);
  ASSERT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "FLUSH")), kOkay);
  const int64_t back = -(std::max<int64_t>(over2, 0) + 50) * dir;
  const Plan away = plan_or_die(scurve::test::move_request(back, 0, 20000, 0, 4e5, 4e7), t);
  load(b, away, t);
  ASSERT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
  b.idle(200);
  ASSERT_TRUE(b.out().busy);
  EXPECT_EQ(b.write(reg_addr("SOFT_MAX"), 0x7fffffffu), kSlvErr) << "the window is configuration";
  EXPECT_EQ(b.write(reg_addr("ERR"), field_mask("ERR", "REJECT")), kOkay);
  run_until(b, away.total_clocks + 200'000, [&] { return !b.out().busy; });
  b.idle(10);
  EXPECT_FALSE(b.failed()) << b.error();
  EXPECT_EQ(b.net_steps(), end2 + back);
  EXPECT_EQ(int32_t(b.read(reg_addr("REF_POS")).first), end2 + back);
  EXPECT_EQ(int32_t(b.read(reg_addr("SOFT_MAX")).first), soft_max);
  EXPECT_EQ(b.read(reg_addr("ERR")).first, 0u);
  EXPECT_TRUE(b.read(reg_addr("STATUS")).first & field_mask("STATUS", "DONE"));
}

// A stream of moves (nonzero junction speeds) running out of the window:
// the rows are pushed while the axis runs, the window's edge lies inside
// one of the later moves. The axis stops past the edge within the bound of
// the fastest the stream may be (v_max, a_max), the counts agree, every move
// boundary reached is the planner's running sum, the rest of the stream is
// not run; after ERR and FLUSH a move back into the window ends exactly.
// With the edge on the stream's last end nothing trips.
void run_soft_stream(std::mt19937_64& g, int i) {
  const bool hard = (i & 2) != 0, on_edge = i == 4;
  const int dir = (i & 1) ? -1 : 1;
  const PulseTiming t{};
  const scurve::StreamLimits limits(log_uniform(g, 2e5, 2e6), log_uniform(g, 2e7, 2e9), log_uniform(g, 2e4, 1.5e5));
  scurve::StreamPlanner sp(scurve::Clock{}, scurve::PulseTiming{}, limits);
  int64_t total = 0;
  std::vector<int64_t> ends;
  for (int k = 0; k < 12; ++k) {
    const int64_t d = dir * int64_t(200 + g() % 1500);
    ASSERT_FALSE(sp.append({d, limits.v_max * log_uniform(g, 0.2, 1), limits.v_max * log_uniform(g, 0.1, 1)}));
    total += d;
    ends.push_back(total);
  }
  ASSERT_FALSE(sp.flush());
  const std::vector<scurve::StreamedMove> moves = sp.take_ready();
  ASSERT_EQ(moves.size(), ends.size());
  std::vector<scurve::Segment> rows;
  std::vector<scurve::RowFlags> flags;
  for (size_t k = 0; k < moves.size(); ++k) {
    const auto f = scurve::move_row_flags(moves[k].segments, k + 1 == moves.size());
    rows.insert(rows.end(), moves[k].segments.begin(), moves[k].segments.end());
    flags.insert(flags.end(), f.begin(), f.end());
  }
  const int64_t edge = on_edge ? total : (total * 3) / 10 + int64_t(g() % uint64_t(std::abs(total) / 2)) * dir;
  const int64_t other = -dir * 1000;
  const int64_t soft_min = dir > 0 ? other : edge, soft_max = dir > 0 ? edge : other;
  const double stop_jerk = limits.j_max * log_uniform(g, 1, 2), stop_acc = limits.a_max * log_uniform(g, 1, 2);
  const std::string what = "stream of " + std::to_string(moves.size()) + " moves to " + std::to_string(total) +
                           ", window [" + std::to_string(soft_min) + ", " + std::to_string(soft_max) + "], " +
                           (hard ? "hard" : "controlled");
  SCOPED_TRACE(what);

  AxiBench b(true, uint32_t(300 + i));
  b.reset();
  b.idle(4);
  ASSERT_EQ(b.write(reg_addr("CTRL"), field_mask("CTRL", "ENABLE")), kOkay);
  set_stop_limits(b, stop_jerk, stop_acc);
  ASSERT_EQ(b.write(reg_addr("SOFT_MIN"), uint32_t(int32_t(soft_min))), kOkay);
  ASSERT_EQ(b.write(reg_addr("SOFT_MAX"), uint32_t(int32_t(soft_max))), kOkay);
  ASSERT_EQ(b.write(reg_addr("SW_CFG"), field_mask("SW_CFG", "LIM_EN") | field_mask("SW_CFG", "SOFT_EN") |
                                            (hard ? field_mask("SW_CFG", "LIM_HARD") : 0)),
            kOkay);
  ASSERT_EQ(b.write(reg_addr("POS_FRAC0_0"), 0), kOkay);
  ASSERT_EQ(b.write(reg_addr("POS_FRAC0_2"), uint32_t(1u << (FracBits - 65))), kOkay);  // 1/2 pulse, as the planner
  ASSERT_EQ(b.write(reg_addr("IRQ_STATUS"), 0xffffffffu), kOkay);

  // Rows pushed as the FIFO has room: START after the first ones, then on
  // while the axis runs; a refused push (full) is retried after a while.
  const uint32_t push = reg_addr("ROW_PUSH");
  bool started = false, cut = false;
  for (size_t r = 0; r < rows.size() && !cut && !b.failed(); ++r) {
    for (const RegWrite& w : encode_row(rows[r], flags[r])) {
      if (w.addr != push) {
        ASSERT_EQ(b.write(w.addr, w.data), kOkay);
        continue;
      }
      while (b.write(w.addr, w.data) != kOkay) {
        ASSERT_EQ(b.write(reg_addr("ERR"), field_mask("ERR", "FIFO_FULL")), kOkay);
        if (!started) {
          ASSERT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
          started = true;
        }
        b.idle(500);
        if (!b.out().busy) {
          cut = true;  // stopped: the rest of the stream is not pushed
          break;
        }
      }
      if (cut) break;
    }
  }
  if (!started) {
    ASSERT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
  }
  run_until(b, 40'000'000, [&] { return !b.out().busy; });
  b.idle(10);
  ASSERT_FALSE(b.failed()) << b.error();
  ASSERT_FALSE(b.out().busy);

  const int64_t end = b.net_steps();
  const uint32_t move_idx = b.read(reg_addr("MOVE_INDEX")).first;
  if (move_idx > 0) {
    ASSERT_LE(move_idx, ends.size());
    EXPECT_EQ(int32_t(b.read(reg_addr("BOUNDARY_POS")).first), ends[move_idx - 1]) << "move " << move_idx;
  }
  EXPECT_EQ(int32_t(b.read(reg_addr("PULSE_COUNT")).first), end);
  EXPECT_EQ(int32_t(b.read(reg_addr("REF_POS")).first), end);
  if (on_edge) {
    EXPECT_EQ(end, total) << "a stream ending on the edge runs to its end";
    EXPECT_EQ(move_idx, ends.size());
    EXPECT_EQ(b.read(reg_addr("ERR")).first, 0u);
    EXPECT_TRUE(b.read(reg_addr("STATUS")).first & field_mask("STATUS", "DONE"));
    std::printf("[soft stream] %s: ends on the edge, %u moves\n", what.c_str(), move_idx);
    return;
  }
  const int64_t overtravel = (end - edge) * dir;
  const ld bound = overtravel_bound(ld(limits.v_max), ld(limits.a_max), hard, stop_jerk, stop_acc);
  std::printf("[soft stream] %s: %u moves done, overtravel %lld pulses (bound %.1f)\n", what.c_str(), move_idx,
              (long long)overtravel, double(bound));
  EXPECT_LE(ld(overtravel), bound) << "stopped at " << end;
  EXPECT_LT(move_idx, ends.size()) << "the window did not stop the stream";
  const uint32_t side = overtravel >= 1 ? field_mask("ERR", dir > 0 ? "LIMIT_POS" : "LIMIT_NEG") : 0u;
  EXPECT_EQ(b.read(reg_addr("ERR")).first & ~field_mask("ERR", "FIFO_FULL"), side | field_mask("ERR", "SOFT_LIMIT"));
  EXPECT_TRUE(b.read(reg_addr("STATUS")).first & field_mask("STATUS", "REACH")) << "the look-ahead refused a row";
  EXPECT_TRUE(b.read(reg_addr("IRQ_STATUS")).first & field_mask("IRQ_STATUS", "FAULT"));

  // Recovery: clear, flush the rest, back into the window exactly.
  ASSERT_EQ(b.write(reg_addr("ERR"), 0xffffffffu), kOkay);
  ASSERT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "FLUSH")), kOkay);
  const int64_t back = -(std::max<int64_t>(overtravel, 0) + 50) * dir;
  run_move(b, plan_or_die(scurve::test::move_request(back, 0, 20000, 0, 4e5, 4e7), t), t);
  EXPECT_EQ(b.net_steps(), end + back);
  EXPECT_EQ(int32_t(b.read(reg_addr("REF_POS")).first), end + back);
  EXPECT_EQ(b.read(reg_addr("ERR")).first, 0u);
  EXPECT_FALSE(b.failed()) << b.error();
}

}  // namespace

TEST(SoftLimit, StreamsRunningOutOfTheWindowStopPastItsEdgeKeepEveryBoundaryAndMoveBackExactly) {
  std::mt19937_64 g(52);
  for (int i = 0; i < 5 && !::testing::Test::HasFatalFailure(); ++i) run_soft_stream(g, i);
}

TEST(SoftLimit, RandomMovesOutOfTheWindowStopPastItsEdgeWithinTheStopDistanceAndMoveBackExactly) {
  std::mt19937_64 g(51);
  for (int i = 0; i < 8 && !::testing::Test::HasFatalFailure(); ++i) run_soft_case(g, i);
}

TEST(SoftLimit, DisabledTheWindowStopsNothingAndItsRegistersReadBack) {
  const PulseTiming t{};
  AxiBench b(true, 7);
  b.reset();
  b.idle(4);
  ASSERT_EQ(b.write(reg_addr("CTRL"), field_mask("CTRL", "ENABLE")), kOkay);
  ASSERT_EQ(b.write(reg_addr("SOFT_MIN"), uint32_t(-10)), kOkay);
  ASSERT_EQ(b.write(reg_addr("SOFT_MAX"), 10u), kOkay);
  EXPECT_EQ(int32_t(b.read(reg_addr("SOFT_MIN")).first), -10);
  EXPECT_EQ(int32_t(b.read(reg_addr("SOFT_MAX")).first), 10);
  EXPECT_FALSE(b.read(reg_addr("SW_CFG")).first & field_mask("SW_CFG", "SOFT_EN")) << "off after reset";
  run_move(b, plan_or_die(scurve::test::move_request(500, 0, 50000, 0, 1e6, 1e9), t), t);
  EXPECT_EQ(b.net_steps(), 500);
  EXPECT_EQ(b.read(reg_addr("ERR")).first, 0u);
  EXPECT_TRUE(b.read(reg_addr("STATUS")).first & field_mask("STATUS", "DONE"));
}
