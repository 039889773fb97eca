// Red-team regression tests (adversarial review of planner, model, RTL).
// Passing tests record what held; the F* tests reproduce the findings (all fixed)
// (see tests/redteam/FINDINGS.md).
#include <gtest/gtest.h>

#include <random>

#include "paper_moves.h"
#include "ref_time.h"
#include "rt_util.h"
#include "sim_run.h"

using namespace sc;
using scurve::test::log_uniform;
using scurve::test::move_request;

namespace {

SimResult sim(const MoveRequest& r, const PulseTiming& t) {
  const PlanResult pr = plan_move(r, t);
  EXPECT_TRUE(std::holds_alternative<Plan>(pr)) << std::get<PlanError>(pr).message;
  const Plan& p = std::get<Plan>(pr);
  Limits4Check l;
  l.v_max = std::max({r.v_cruise, r.v_start, p.v_end_used});
  l.a_max = r.a_max;
  if (r.kind == ProfileKind::SCurve) {
    l.j_max = scurve::test::jerk_cap(r);
  }
  return run_move(p, t, l, SimOptions{});
}

}  // namespace

// ---- what held ----------------------------------------------------------

// Jerk/acceleration ratios of a real drive (a/j between 10 us and 10 s),
// speeds up to the step-rate limit, pulse timing 1..65535, distances up to
// 2^31-2: exact step count, mid-pulse end, no reversal, limits (per clock
// on the model for short moves), one-line errors naming a parameter, never
// "internal", planning < 100 ms.
TEST(RedTeam, RealisticRandomRequestsAreExactAndFast) {
  std::mt19937_64 g(4242);
  int accepted = 0;
  for (int i = 0; i < 3000; ++i) {
    PulseTiming t;
    t.high = uint16_t(1 + g() % (i % 3 ? 200 : 65535));
    t.low = uint16_t(1 + g() % (i % 3 ? 200 : 65535));
    const double vl = step_rate_limit(t);
    auto speed = [&](bool z) { const int c = int(g() % 10); return z && c < 3 ? 0.0 : c < 5 ? vl : log_uniform(g, std::min(1.0, vl), vl); };
    MoveRequest r = move_request(std::llround(log_uniform(g, 1, 2147483646.0)) * (g() % 2 ? -1 : 1), speed(true), speed(false), 0, 0, 0);
    r.v_end = g() % 5 == 0 ? r.v_start : speed(true);
    r.a_max = log_uniform(g, 0.01, 1e8);
    r.j_max = std::clamp(r.a_max * log_uniform(g, 0.1, 1e5), 10.0, 1e11);
    if (g() % 6 == 0) r.kind = ProfileKind::Trapezoid;
    r.adjust_end_speed = g() % 6 == 0;
    const rt::Outcome o = rt::run(r, t, 200'000);
    EXPECT_TRUE(o.problems.empty()) << rt::describe(r, t) << ": " << o.problems;
    EXPECT_LT(o.plan_ms, 100.0) << rt::describe(r, t);
    accepted += o.accepted;
  }
  EXPECT_GT(accepted, 800);
}

// RTL and model in lockstep with DIR setup 0: no mismatch, no pin error,
// exact count, for timing 1..65535 and both directions.
TEST(RedTeam, LockstepRandomMovesWithUnusualPulseTimingAndNoSetup) {
  std::mt19937_64 g(77);
  int runs = 0;
  while (runs < 25) {
    PulseTiming t;
    const int tc = int(g() % 3);
    t.high = uint16_t(1 + g() % (tc == 0 ? 8 : tc == 1 ? 300 : 65535));
    t.low = uint16_t(1 + g() % (tc == 0 ? 8 : tc == 1 ? 300 : 65535));
    t.setup = 0;
    t.hold = uint16_t(g() % 65536);
    const double vl = step_rate_limit(t);
    MoveRequest r = move_request(std::llround(log_uniform(g, 1, 20000)) * (g() % 2 ? -1 : 1), g() % 3 ? 0.0 : vl, vl, 0, 0, 0);
    r.v_end = g() % 3 ? 0.0 : log_uniform(g, 1.0, vl);
    r.a_max = std::min(1e8, vl * log_uniform(g, 1, 1e4));
    r.j_max = std::min(1e11, r.a_max * log_uniform(g, 1, 1e4));
    r.adjust_end_speed = true;
    const PlanResult pr = plan_move(r, t);
    if (!std::holds_alternative<Plan>(pr) || std::get<Plan>(pr).total_clocks > 1'000'000) continue;
    const SimResult s = sim(r, t);
    EXPECT_TRUE(s.pass()) << rt::describe(r, t) << "\n" << s.failure_lines();
    ++runs;
  }
}

TEST(RedTeam, CornerRequestsHold) {
  const PulseTiming d{};
  for (const MoveRequest& r : {move_request(1, 0, 200000, 0, 1e8, 1e11), move_request(-1, 0, 200000, 0, 1e8, 1e11),
                               move_request(1, 200000, 200000, 200000, 1e8, 1e11), move_request(1, 0, 1, 0, 0.01, 10)}) {
    const rt::Outcome o = rt::run(r, d);
    EXPECT_TRUE(o.accepted) << rt::describe(r, d);
    EXPECT_TRUE(o.problems.empty()) << rt::describe(r, d) << ": " << o.problems;
  }
  const PulseTiming fast{1, 1, 0, 0};
  const rt::Outcome o = rt::run(move_request(-123456, 0, 1e7, 0, 1e8, 1e11), fast);
  EXPECT_TRUE(o.accepted && o.problems.empty()) << o.problems;
}

// ---- the findings, fixed: each proves the behaviour the review found broken ----

// F1: a_max / j_max < 1 clock (j_max > 2e7 * a_max, or one asymmetric jerk
// that large): make_transition floors the jerk-up length to 0 clocks and the
// transition vanishes. The plan is accepted but never slows down: it ends at
// 1000 pulses/s and the executor drops to 0 in one clock (2e10 pulses/s^2
// against a_max = 100). run_table does not check the end speed or the final
// stop, so plan_move's self-check and the lockstep sim both pass it.
// (Fixed: ramps take >= 1 clock.) Slowing from 1000 to 0 at a = 100 takes
// 10 s and 5000 pulses, so 1000 pulses is infeasible and must say so; with
// room to brake, the plan must reach the end speed.
TEST(RedTeam, F1_EndSpeedReachedWhenJerkRampIsUnderOneClock) {
  const rt::Outcome short_move = rt::run(move_request(1000, 1000, 1000, 0, 100, 1e10), PulseTiming{});
  ASSERT_FALSE(short_move.accepted);
  EXPECT_EQ(short_move.err.parameter, "v_end");
  EXPECT_NE(short_move.err.message.find(">= 5000 pulses"), std::string::npos) << short_move.err.message;
  const rt::Outcome o = rt::run(move_request(6000, 1000, 1000, 0, 100, 1e10), PulseTiming{});
  ASSERT_TRUE(o.accepted) << o.err.message;
  EXPECT_LE(o.plan.v_end_actual, 100 / 20e6 * 1.01) << "ends at " << o.plan.v_end_actual << " pulses/s";
}
TEST(RedTeam, F1_AsymmetricHugeDecelJerkStillDecelerates) {
  MoveRequest r = move_request(50000, 0, 5000, 0, 1e4, 1e5);
  r.jerks = std::array<double, 4>{10, 1e11, 1e11, 10};
  const rt::Outcome o = rt::run(r, PulseTiming{});
  ASSERT_TRUE(o.accepted) << o.err.message;
  EXPECT_LE(o.plan.v_end_actual, 1e4 / 20e6 * 1.01) << "ends at " << o.plan.v_end_actual << " pulses/s";
}
TEST(RedTeam, F1_RestToRestWithHugeJerkIsPlannedNotBlamedOnDistance) {
  const rt::Outcome o = rt::run(move_request(1000, 0, 1000, 0, 100, 1e10), PulseTiming{});
  EXPECT_TRUE(o.accepted) << "[" << o.err.parameter << "] " << o.err.message;
}

// F2: backward moves (DIR must flip) whose first steps come sooner than the
// DIR setup time: the executor runs on, requests pile up in the 4-bit step
// queue (+-7), overflow drops steps. RTL and model agree (0 mismatches), the
// pins emit fewer than |distance| steps. Now every step is on the pins and
// the whole run passes (pin timing, duty phases, limits, lockstep).
TEST(RedTeam, F2_BackwardMoveWithLongDirSetupEmitsEveryStep) {
  const SimResult s = sim(move_request(-20000, 0, 200000, 0, 1e8, 1e11), PulseTiming{50, 50, 65535, 100});
  EXPECT_EQ(s.pulses, -20000) << s.failure_lines();
  EXPECT_TRUE(s.pass()) << s.failure_lines();
}
TEST(RedTeam, F2_BackwardAtRateLimitWithModestSetupEmitsEveryStep) {
  const SimResult s = sim(move_request(-19, 2857142.8571428573, 2857142.8571428573, 2857142.8571428573, 59299052.318841696, 1e11),
                          PulseTiming{4, 3, 135, 44216});
  EXPECT_EQ(s.pulses, -19) << s.failure_lines();
  EXPECT_TRUE(s.pass()) << s.failure_lines();
}
// Same cause, no loss: the queued steps leave back to back at 2x the planned
// step rate, the sim fails its steady-cruise check.
TEST(RedTeam, F2_BackwardCruiseStaysSteadyWithDirSetup) {
  const SimResult s = sim(move_request(-3000, 100000, 100000, 0, 1e7, 1e10), PulseTiming{50, 50, 800, 100});
  EXPECT_TRUE(s.pass()) << s.failure_lines();
}

// F3: pin monitor false positive: the second pulse interval of a phase still
// straddles the velocity peak; the monitor calls a correct forward move a
// duty-trend violation (scurve sim exits 1).
TEST(RedTeam, F3_PinMonitorAcceptsPeakStraddlingIntervals) {
  MoveRequest r = move_request(63, 187.01773354147682, 2222222.222222222, 0, 21341866.432203829, 1e11);
  r.jerks = std::array<double, 4>{154725430.95915189, 1e11, 9300259659.4784851, 1e11};
  const SimResult s = sim(r, PulseTiming{7, 2, 1, 59509});
  EXPECT_TRUE(s.pass()) << s.failure_lines();
}

// F4: distance = INT64_MIN: -distance overflows, the range check passes,
// plan_move returns parameter "internal" instead of "distance".
TEST(RedTeam, F4_Int64MinDistanceIsARangeError) {
  const rt::Outcome o = rt::run(move_request(INT64_MIN, 0, 100, 0, 500, 2500), PulseTiming{});
  EXPECT_EQ(o.err.parameter, "distance") << o.err.message;
}

// F5: time optimality. The jerk-up length is floor(a_max/j) clocks at the
// full jerk, so with a_max/j of a few clocks the peak acceleration is far
// below a_max (1.86 clocks -> 1 clock, 54 % of a_max: 36 % slower); the
// trapezoid rounds a speed change below one clock of a_max to no change at
// all (cruises at v_start, 128x slower).
double ref_ratio(const MoveRequest& r, const PulseTiming& t) {
  const rt::Outcome o = rt::run(r, t, 0);
  EXPECT_TRUE(o.accepted) << o.err.message;
  const double j[4] = {r.j_max, r.j_max, r.j_max, r.j_max};
  // The plan travels |L| + 1/2 pulse by design (the move ends mid-pulse).
  const rt::RefPlan rp = rt::ref_plan(double(std::llabs(r.distance)) + 0.5, r.v_start, r.v_cruise, o.plan.v_end_used,
                                      r.a_max, j, r.kind == ProfileKind::Trapezoid, step_rate_limit(t));
  EXPECT_TRUE(rp.ok);
  return o.plan.duration_s / rp.T;
}
TEST(RedTeam, F5_SCurveWithJerkRampOfAFewClocksIsTimeOptimal) {
  EXPECT_LT(ref_ratio(move_request(10356, 0, 285714.28571428574, 0, 9234.7960435935111, 99588861241.75354),
                      PulseTiming{53, 17, 0, 0}),
            1.01);
}
TEST(RedTeam, F5_TrapezoidSmallSpeedChangeIsTimeOptimal) {
  MoveRequest r = move_request(-5, 0.002748703736096965, 0.3524996624810911, 0, 38498212.527533501, 0);
  r.kind = ProfileKind::Trapezoid;
  EXPECT_LT(ref_ratio(r, PulseTiming{196, 14, 0, 0}), 1.01);
}
