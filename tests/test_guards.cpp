// Guards against the host (GUARD_VEL, GUARD_ACC, GUARD_JERK) through the
// whole register-level axis (sc_axi_axis), RTL and model in lockstep every
// clock, the pins watched by the pin monitor.
//
// What is checked does not come from the executor's algorithm: which row is
// the first over a limit, where the axis is at that row's boundary and how
// far a controlled stop from there may go come from the plan's rows in the
// host library's closed forms; the pins, PULSE_COUNT and REF_POS agree to
// the pulse; the flags, the interrupt, the emptied FIFO and the recovery are
// read through the documented register map.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "axi_bench.h"
#include "board_regs.h"
#include "planner.h"
#include "random_moves.h"
#include "stop_check.h"

using namespace sc;
using namespace sc::board_test;

namespace {

using stopcheck::kLsb;
using stopcheck::ld;

using scurve::test::log_uniform;

template <class T>
T magnitude(T x) {
  return x < 0 ? -x : x;
}

void write_guards(AxiBench& b, const scurve::GuardLimitCodes& c) {
  for (const RegWrite& w : scurve::encode_guard_codes(c)) ASSERT_EQ(b.write(w.addr, w.data), kOkay) << reg_name(w.addr);
}

// Runs until the axis has been busy and is idle again (or `limit` clocks).
void run_move(AxiBench& b, uint64_t limit) {
  bool moved = false;
  for (uint64_t i = 0; i < limit && !b.failed(); ++i) {
    b.tick();
    moved = moved || b.out().busy;
    if (moved && !b.out().busy) break;
  }
}

// A random plannable move of at most 400,000 clocks (20 ms).
MoveRequest random_request(std::mt19937_64& g) {
  for (;;) {
    const double v = log_uniform(g, 2e4, 1.5e5);
    const int64_t d = int64_t(log_uniform(g, 200, v * 0.012)) * ((g() & 1) ? -1 : 1);
    const MoveRequest req =
        scurve::test::move_request(d, 0, v, 0, log_uniform(g, 2e6, 2e7), log_uniform(g, 2e8, 2e10));
    const PlanResult r = plan_move(req, PulseTiming{});
    if (const Plan* p = std::get_if<Plan>(&r); p && p->total_clocks < 400'000) return req;
  }
}

enum class Kind { Vel, Acc, Jerk };
const char* kind_name(Kind k) { return k == Kind::Vel ? "velocity" : k == Kind::Acc ? "acceleration" : "jerk"; }

// The row values the guard of `kind` looks at.
u128 row_value(const Segment& s, Kind kind) {
  switch (kind) {
    case Kind::Vel: return u128(magnitude(s.vel0));
    case Kind::Acc: return u128(magnitude(i128(s.acc0)));
    case Kind::Jerk: return u128(magnitude(i128(s.jerk)));
  }
  return 0;
}

}  // namespace

// Guards set from the move's own limits (rounded up by the host library)
// never refuse a row of a move planned within them.
TEST(Guard, MovesPlannedWithinTheGuardLimitsRunToTheirExactEnd) {
  std::mt19937_64 g(5);
  for (int i = 0; i < 6 && !::testing::Test::HasFatalFailure(); ++i) {
    const MoveRequest req = random_request(g);
    const Plan p = plan_or_die(req);
    SCOPED_TRACE("distance " + std::to_string(p.distance));
    AxiBench b(true, uint32_t(300 + i));
    b.reset();
    const auto codes = scurve::move_guard_codes(req);
    ASSERT_TRUE(std::holds_alternative<scurve::GuardLimitCodes>(codes));
    write_guards(b, std::get<scurve::GuardLimitCodes>(codes));
    load(b, p, PulseTiming{});
    ASSERT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
    run_move(b, p.total_clocks + 100'000);
    ASSERT_FALSE(b.failed()) << b.error();
    EXPECT_EQ(b.net_steps(), p.distance);
    EXPECT_EQ(b.read(reg_addr("ERR")).first, 0u);
    const uint32_t status = b.read(reg_addr("STATUS")).first;
    EXPECT_TRUE(status & field_mask("STATUS", "DONE"));
    EXPECT_FALSE(status & field_mask("STATUS", "GUARD"));
  }
}

// A guard below what the move's rows carry: the first row over it is not
// executed; the axis stops under control from the previous row's end, as
// far as the closed-form stopping distance allows, with the counts exact;
// ERR.GUARD, STATUS.GUARD and IRQ_STATUS.FAULT are set and the FIFO is
// empty. Then the documented recovery: clear ERR, raise the guard, a move
// from there runs to its exact end.
TEST(Guard, TheFirstRowOverAGuardStopsTheAxisUnderControlAtItsBoundaryAndTheAxisRecovers) {
  std::mt19937_64 g(17);
  int cases = 0;
  for (int i = 0; cases < 9 && i < 200 && !::testing::Test::HasFatalFailure(); ++i) {
    const Kind kind = Kind(cases % 3);
    const MoveRequest req = random_request(g);
    const Plan p = plan_or_die(req);
    // The largest value of that kind over the rows after the first; a limit
    // just below a random one of the rows' values picks the row it stops at.
    std::vector<size_t> candidates;
    for (size_t k = 1; k < p.segments.size(); ++k)
      if (row_value(p.segments[k], kind) > row_value(p.segments[0], kind) + 1) candidates.push_back(k);
    if (candidates.empty()) continue;
    const size_t pick = candidates[g() % candidates.size()];
    const u128 limit = row_value(p.segments[pick], kind) - 1;
    // The first row over it (the executor loads the rows in order).
    size_t first = 0;
    while (row_value(p.segments[first], kind) <= limit) ++first;
    ASSERT_GE(first, 1u);
    ++cases;
    scurve::GuardLimitCodes guard;
    if (kind == Kind::Vel) guard.vel = limit;
    if (kind == Kind::Acc) guard.acc = uint64_t(limit);
    if (kind == Kind::Jerk) guard.jerk = uint64_t(limit);
    SCOPED_TRACE(std::string(kind_name(kind)) + " guard, distance " + std::to_string(p.distance) + ", row " +
                 std::to_string(first) + " of " + std::to_string(p.segments.size()));

    // Where the axis is at the end of row first - 1 and its state there.
    i128 pos = i128(p.pos_frac0);
    i128 v_end = 0;
    int64_t a_end = 0;
    for (size_t k = 0; k < first; ++k) {
      const Segment& s = p.segments[k];
      pos += pos_gain(s.vel0, s.acc0, s.jerk, s.clocks);
      v_end = vel_after(s.vel0, s.acc0, s.jerk, s.clocks);
      a_end = int64_t(acc_after(s.acc0, s.jerk, s.clocks));
    }
    const int dir = p.distance > 0 ? 1 : -1;
    const ld boundary = ld(pos) / kLsb;  // pulses
    const double stop_jerk = req.j_max * log_uniform(g, 1, 3), stop_acc = req.a_max * log_uniform(g, 1, 3);

    AxiBench b(true, uint32_t(400 + i));
    b.reset();
    set_stop_limits(b, stop_jerk, stop_acc);
    write_guards(b, guard);
    ASSERT_EQ(b.write(reg_addr("IRQ_STATUS"), 0xffffffffu), kOkay);
    load(b, p, PulseTiming{});
    ASSERT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
    run_move(b, p.total_clocks + 400'000);
    ASSERT_FALSE(b.failed()) << b.error();

    const int64_t end = b.net_steps();
    const auto stop_codes = std::get<scurve::StopLimitCodes>(scurve::stop_limit_codes(stop_jerk, stop_acc));
    const stopcheck::ClosedForm cf =
        stopcheck::closed_form(ld(v_end), ld(a_end), ld(stop_codes.jerk), ld(stop_codes.acc));
    const ld travel = (ld(end) - boundary) * dir;  // pulses past the boundary
    std::printf("[guard] %s guard, row %zu of %zu: %.1f pulses past the boundary (closed form %.1f)\n",
                kind_name(kind), first, p.segments.size(), double(travel), double(cf.dist / kLsb));
    // The stop starts at that boundary: it covers the closed-form stopping
    // distance from there (a stop a row early or late would not).
    EXPECT_GE(travel, cf.dist / kLsb - 2) << "stopped before the boundary";
    EXPECT_LE(travel, cf.dist / kLsb + 2) << "ran past the stopping distance: a refused row ran";
    EXPECT_NE(end, p.distance) << "the move was not stopped";
    EXPECT_EQ(int32_t(b.read(reg_addr("PULSE_COUNT")).first), end);
    EXPECT_EQ(int32_t(b.read(reg_addr("REF_POS")).first), end);
    EXPECT_EQ(b.read(reg_addr("ERR")).first, field_mask("ERR", "GUARD"));
    const uint32_t status = b.read(reg_addr("STATUS")).first;
    EXPECT_TRUE(status & field_mask("STATUS", "GUARD"));
    EXPECT_TRUE(status & field_mask("STATUS", "ERR"));
    EXPECT_FALSE(status & field_mask("STATUS", "DONE")) << "a refused stream is not done";
    EXPECT_FALSE(status & field_mask("STATUS", "DISCONTINUITY"));
    EXPECT_TRUE(b.read(reg_addr("IRQ_STATUS")).first & field_mask("IRQ_STATUS", "FAULT"));
    EXPECT_EQ(b.read(reg_addr("FIFO_STATUS")).first & field_mask("FIFO_STATUS", "LEVEL"), 0u);

    // Recovery: clear the flag, lift the guard, a move from here runs
    // exactly; the next START clears STATUS.GUARD.
    ASSERT_EQ(b.write(reg_addr("ERR"), 0xffffffffu), kOkay);
    write_guards(b, scurve::GuardLimitCodes{});
    const int64_t back_distance = end != 0 ? -end : 100 * dir;  // back to 0, or on from there
    const Plan back = plan_or_die(scurve::test::move_request(back_distance, 0, 20000, 0, 4e5, 4e7));
    load(b, back, PulseTiming{});
    ASSERT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
    run_move(b, back.total_clocks + 100'000);
    ASSERT_FALSE(b.failed()) << b.error();
    EXPECT_EQ(b.net_steps(), end + back_distance);
    EXPECT_EQ(b.read(reg_addr("ERR")).first, 0u);
    EXPECT_EQ(b.read(reg_addr("STATUS")).first & (field_mask("STATUS", "GUARD") | field_mask("STATUS", "DONE")),
              field_mask("STATUS", "DONE"));
  }
  EXPECT_EQ(cases, 9) << "too few moves with a row to refuse";
}

// A START whose first row is over a guard: nothing moves, the rows queued
// behind it are dropped, ERR.GUARD and IRQ_STATUS.FAULT are set.
TEST(Guard, AStartWhoseFirstRowIsOverAGuardIsRefusedAndNothingMoves) {
  const Plan p = plan_or_die(scurve::test::move_request(3000, 0, 50000, 0, 1e6, 1e8));
  ASSERT_GE(p.segments.size(), 2u);
  AxiBench b(true, 7);
  b.reset();
  // The first row of a move from rest carries only the jerk.
  scurve::GuardLimitCodes guard;
  guard.jerk = uint64_t(magnitude(p.segments[0].jerk)) - 1;
  write_guards(b, guard);
  ASSERT_EQ(b.write(reg_addr("IRQ_STATUS"), 0xffffffffu), kOkay);
  load(b, p, PulseTiming{});
  ASSERT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
  b.idle(2000);
  ASSERT_FALSE(b.failed()) << b.error();
  EXPECT_EQ(b.net_steps(), 0);
  EXPECT_FALSE(b.out().busy);
  EXPECT_EQ(b.read(reg_addr("ERR")).first, field_mask("ERR", "GUARD"));
  const uint32_t status = b.read(reg_addr("STATUS")).first;
  EXPECT_TRUE(status & field_mask("STATUS", "GUARD"));
  EXPECT_FALSE(status & field_mask("STATUS", "FAULT_TABLE")) << "the FIFO was not empty";
  EXPECT_EQ(b.read(reg_addr("FIFO_STATUS")).first & field_mask("FIFO_STATUS", "LEVEL"), 0u);
  EXPECT_TRUE(b.read(reg_addr("IRQ_STATUS")).first & field_mask("IRQ_STATUS", "FAULT"));
  // With the guard at the row's value the same move runs.
  guard.jerk += 1;
  write_guards(b, guard);
  ASSERT_EQ(b.write(reg_addr("ERR"), 0xffffffffu), kOkay);
  load(b, p, PulseTiming{});
  ASSERT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
  run_move(b, p.total_clocks + 100'000);
  ASSERT_FALSE(b.failed()) << b.error();
  EXPECT_EQ(b.net_steps(), 3000);
  EXPECT_EQ(b.read(reg_addr("ERR")).first, 0u);
}

// The guard registers are configuration: a write while the axis moves is
// refused (SLVERR, ERR.REJECT) and changes nothing.
TEST(Guard, TheGuardRegistersAreLockedWhileTheAxisMoves) {
  const Plan p = plan_or_die(scurve::test::move_request(2000, 0, 50000, 0, 1e6, 1e8));
  AxiBench b(true, 9);
  b.reset();
  load(b, p, PulseTiming{});
  ASSERT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
  b.idle(500);
  ASSERT_TRUE(b.out().busy);
  for (const char* name : {"GUARD_VEL", "GUARD_ACC", "GUARD_JERK"}) {
    for (uint32_t word = 0; word < 2; ++word) {
      const uint32_t a = reg_addr(std::string(name) + "_" + std::to_string(word));
      EXPECT_EQ(b.write(a, 1), kSlvErr) << name << " word " << word;
      EXPECT_EQ(b.read(a).first, 0u) << name << " word " << word;
    }
  }
  EXPECT_TRUE(b.read(reg_addr("ERR")).first & field_mask("ERR", "REJECT"));
  ASSERT_EQ(b.write(reg_addr("ERR"), 0xffffffffu), kOkay);
  run_move(b, p.total_clocks + 100'000);
  ASSERT_FALSE(b.failed()) << b.error();
  EXPECT_EQ(b.net_steps(), 2000) << "the refused writes changed the move";
  EXPECT_EQ(b.read(reg_addr("ERR")).first, 0u);
}
