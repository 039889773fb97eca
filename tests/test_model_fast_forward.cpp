// The model's closed-form fast paths are bit-exact with its per-clock step():
// on random tables (including reversing velocity, where the fast path must
// fall back), and for the whole core on planned moves.
#include <gtest/gtest.h>

#include <random>

#include "axis_core.h"
#include "planner.h"
#include "sim_run.h"

using namespace sc;

namespace {

std::vector<Segment> random_table(std::mt19937_64& g, int rows) {
  std::vector<Segment> t;
  const i128 vmax = i128(kOne) / 64;  // up to 1/64 pulse per clock
  for (int i = 0; i < rows; ++i) {
    Segment s;
    s.phase = Phase(1 + g() % 7);
    s.clocks = uint32_t(1 + g() % 200000);
    const i128 v = i128(g() % uint64_t(vmax >> 40)) << 40;
    s.vel0 = (g() & 1) ? v : -v;
    // Acceleration/jerk large enough to cross zero velocity now and then.
    const int64_t a = int64_t(g() % (uint64_t(1) << 56));
    s.acc0 = (g() & 1) ? a : -a;
    const int64_t j = int64_t(g() % (uint64_t(1) << 40));
    s.jerk = (g() & 1) ? j : -j;
    t.push_back(s);
  }
  continue_velocities(t);
  return t;
}

}  // namespace

TEST(ExecFastForward, MatchesStepOnRandomTablesIncludingReversals) {
  std::mt19937_64 g(7);
  int reversing_rows = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const auto table = random_table(g, 1 + int(g() % 6));
    const u128 frac0 = (u128(g()) << 16) & (kOne - 1);
    ProfileExec slow, fast;
    load_and_start(slow, table, frac0);
    load_and_start(fast, table, frac0);
    for (const Segment& s : table) {
      const i128 v_end = vel_after(s.vel0, s.acc0, s.jerk, s.clocks - 1);
      if ((v_end < 0) != (s.vel0 < 0)) ++reversing_rows;
    }
    // Advance in random chunks; compare the whole state at every chunk end.
    uint64_t total = 0;
    while (slow.state().run || slow.state().step_req) {
      const uint64_t n = 1 + g() % 300000;
      for (uint64_t i = 0; i < n; ++i) slow.step({});
      fast.fast_forward(n);
      total += n;
      ASSERT_EQ(slow.state(), fast.state()) << "trial " << trial << " after " << total << " clocks";
    }
  }
  EXPECT_GT(reversing_rows, 20) << "the campaign must exercise the fall-back path";
}

TEST(ExecFastForward, AdvanceEqualsStepForEveryPrefix) {
  MoveRequest r;
  r.distance = 700;
  r.v_start = 100;
  r.v_cruise = 40000;
  r.v_end = 0;
  r.a_max = 2e5;
  r.j_max = 4e7;
  const Plan p = std::get<Plan>(plan_move(r, {}));
  ProfileExec slow;
  load_and_start(slow, p.segments, p.pos_frac0);
  std::mt19937_64 g(3);
  // From many points of the move, a closed-form advance of k clocks must
  // land on the same state as k single steps.
  while (slow.state().run) {
    const uint64_t span = slow.closed_form_span();
    if (span > 0) {
      ProfileExec fast = slow;
      const uint64_t k = 1 + g() % span;
      fast.advance(k);
      for (uint64_t i = 0; i < k; ++i) slow.step({});
      ASSERT_EQ(slow.state(), fast.state());
    } else {
      slow.step({});
    }
  }
  EXPECT_EQ(slow.state().pint, 700);
}

TEST(CoreFastForward, MatchesStepClockForClockAtEveryPulse) {
  std::mt19937_64 g(11);
  for (int trial = 0; trial < 20; ++trial) {
    MoveRequest r;
    r.distance = int64_t(1 + g() % 3000) * ((g() & 1) ? 1 : -1);
    r.v_start = double(g() % 2000);
    r.v_cruise = 1000 + double(g() % 100000);
    r.v_end = double(g() % 2000);
    r.a_max = 1e4 + double(g() % 1000000);
    r.j_max = 1e6 + double(g() % 100000000);
    r.adjust_end_speed = true;
    PulseTiming t;
    t.high = uint16_t(1 + g() % 60);
    t.low = uint16_t(1 + g() % 60);
    const PlanResult pr = plan_move(r, t);
    ASSERT_TRUE(std::holds_alternative<Plan>(pr)) << std::get<PlanError>(pr).message;
    const Plan& p = std::get<Plan>(pr);
    AxisCore slow, fast;
    CoreInputs in;
    in.enable = true;
    in.cfg = t;
    for (const CoreInputs& ci : load_sequence(p.segments, p.pos_frac0, in)) {
      slow.step(ci);
      fast.step(ci);
      in = ci;
    }
    in.start = false;
    uint64_t clock = 0;
    int pulses_checked = 0;
    while (!slow.done() || clock < 10) {
      const uint64_t n = 1 + g() % 5000;
      bool last_step = slow.outputs().step;
      for (uint64_t i = 0; i < n; ++i) {
        slow.step(in);
        if (slow.outputs().step && !last_step) ++pulses_checked;
        last_step = slow.outputs().step;
      }
      fast.fast_forward(in, n);
      clock += n;
      ASSERT_EQ(slow.outputs(), fast.outputs()) << "trial " << trial << " clock " << clock;
      ASSERT_EQ(slow.exec().state(), fast.exec().state());
      ASSERT_EQ(slow.step_gen().state(), fast.step_gen().state());
    }
    EXPECT_EQ(slow.outputs().pulse_count, r.distance);
    EXPECT_EQ(pulses_checked, std::abs(r.distance));
  }
}
