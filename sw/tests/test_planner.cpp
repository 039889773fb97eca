// Planner: every case of paper 000 section 2.1, vs > vc, ve > vc, short
// moves, trapezoid, asymmetric jerks, and the errors for bad requests.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "paper_moves.h"
#include "scurve/planner.h"

using namespace scurve;
using scurve::test::paper_group;

namespace {

MoveRequest move(int64_t l, double vs, double vc, double ve, double a = 500, double j = 2500) {
  return scurve::test::move_request(l, vs, vc, ve, a, j);
}

Plan plan_ok(const MoveRequest& r, const PulseTiming& t = {}) {
  PlanResult res = Planner().plan(r, t);
  if (auto* e = std::get_if<PlanError>(&res)) {
    ADD_FAILURE() << "unexpected error: " << e->message;
    return {};
  }
  return std::get<Plan>(res);
}

PlanError plan_err(const MoveRequest& r, const PulseTiming& t = {}) {
  PlanResult res = Planner().plan(r, t);
  if (std::holds_alternative<Plan>(res)) {
    ADD_FAILURE() << "expected an error";
    return {};
  }
  return std::get<PlanError>(res);
}

std::vector<Phase> phases(const Plan& p) {
  std::vector<Phase> v;
  for (const Segment& s : p.segments) {
    if (v.empty() || v.back() != s.phase) v.push_back(s.phase);
  }
  return v;
}

bool has_phase(const Plan& p, Phase ph) {
  for (const Segment& s : p.segments) {
    if (s.phase == ph) return true;
  }
  return false;
}

// Independent re-execution of the table: exact endpoint and limits.
void expect_exact_and_within(const Plan& p, const MoveRequest& r, const PulseTiming& t = {}) {
  const int dir = r.distance < 0 ? -1 : 1;
  const TableReport rep = run_table(p.segments, p.pos_frac0, dir);
  ASSERT_TRUE(rep.ok) << rep.error;
  EXPECT_EQ(rep.steps, r.distance);
  // Ends exactly mid-pulse: fraction 1/2 past step `distance` (forward) or
  // 1/2 short of the next step back (backward) - the same fraction either way.
  EXPECT_EQ(rep.end_pos, i128(r.distance) * i128(kOne) + (i128(kOne) >> 1));
  EXPECT_GE(rep.min_signed_vel, 0) << "velocity reverses";
  const double v_cap = std::max({r.v_cruise, r.v_start, p.v_end_used});
  EXPECT_LE(vel_to_phys(rep.peak_vel, Clock{}), v_cap * (1 + 1e-12));
  EXPECT_LE(vel_to_phys(rep.peak_vel, Clock{}), step_rate_limit(t) * (1 + 1e-12));
  EXPECT_LE(acc_to_phys(rep.peak_acc, Clock{}), r.a_max * (1 + 1e-12));
  if (r.kind == ProfileKind::SCurve) {
    double j = r.j_max;
    if (r.jerks) j = std::max({(*r.jerks)[0], (*r.jerks)[1], (*r.jerks)[2], (*r.jerks)[3]});
    EXPECT_LE(jerk_to_phys(rep.peak_jerk, Clock{}), j * (1 + 1e-12));
  }
  EXPECT_EQ(rep.clocks, p.total_clocks);
}

}  // namespace

TEST(Planner, PaperGroupsReachCruiseAndAreExact) {
  for (int g = 1; g <= 4; ++g) {
    const MoveRequest r = paper_group(g);
    const Plan p = plan_ok(r);
    EXPECT_TRUE(has_phase(p, Phase::PhCruise)) << "group " << g;
    EXPECT_NEAR(p.v_plateau, r.v_cruise, 1e-3) << "group " << g;
    EXPECT_NEAR(p.peak_acceleration, 500.0, 1e-3);
    EXPECT_LE(p.peak_acceleration, 500.0);
    expect_exact_and_within(p, r);
  }
}

TEST(Planner, CruiseReachedHasSevenPhasesInOrder) {
  const Plan p = plan_ok(paper_group(1));
  const std::vector<Phase> want = {Phase::PhAccJerkUp, Phase::PhAccConst,  Phase::PhAccJerkDown,
                                   Phase::PhCruise,    Phase::PhDecJerkUp, Phase::PhDecConst,
                                   Phase::PhDecJerkDown};
  EXPECT_EQ(phases(p), want);
  // 1500 -> 3000 at a = 500 with 0.2 s jerk phases: 3.2 s; 3000 -> 0: 6.2 s.
  EXPECT_NEAR(p.duration_s, 3.2 + 6.2 + (30000.0 - 7200 - 9300) / 3000.0, 1e-3);
}

TEST(Planner, StartAboveCruiseDeceleratesFirst) {
  const Plan p = plan_ok(paper_group(2));
  ASSERT_FALSE(p.segments.empty());
  EXPECT_EQ(p.segments.front().phase, Phase::PhDecJerkUp);
  EXPECT_FALSE(has_phase(p, Phase::PhAccConst));
}

TEST(Planner, EndAboveCruiseAcceleratesLast) {
  const Plan p = plan_ok(paper_group(3));
  EXPECT_EQ(p.segments.back().phase, Phase::PhAccJerkDown);
  EXPECT_FALSE(has_phase(p, Phase::PhDecConst));
  EXPECT_NEAR(p.v_end_actual, 3000.0, 1e-3);
}

TEST(Planner, OnlyAccelerationWhenTheDistanceJustFits) {
  // 0 -> 1000 pulses/s at a = 500, j = 2500 covers 1100 pulses.
  const MoveRequest r = move(1150, 0, 1000, 1000);
  const Plan p = plan_ok(r);
  for (const Segment& s : p.segments) {
    EXPECT_TRUE(s.phase == Phase::PhAccJerkUp || s.phase == Phase::PhAccConst ||
                s.phase == Phase::PhAccJerkDown || s.phase == Phase::PhCruise);
  }
  expect_exact_and_within(p, r);
}

TEST(Planner, OnlyDecelerationWhenTheDistanceJustFits) {
  const MoveRequest r = move(1150, 1000, 1000, 0);
  const Plan p = plan_ok(r);
  EXPECT_FALSE(has_phase(p, Phase::PhAccConst));
  EXPECT_FALSE(has_phase(p, Phase::PhAccJerkUp));
  EXPECT_TRUE(has_phase(p, Phase::PhDecConst));
  expect_exact_and_within(p, r);
}

TEST(Planner, NoCruiseWhenTooShortForTheCruiseSpeed) {
  const MoveRequest r = move(2000, 0, 3000, 0);
  const Plan p = plan_ok(r);
  EXPECT_LT(p.peak_velocity, 3000.0);
  EXPECT_GT(p.peak_velocity, 900.0);  // v^2/a + v*a/j = 2000 -> v ~ 952
  // At most a sliver of plateau is left to trim the endpoint.
  uint64_t cruise = 0;
  for (const Segment& s : p.segments) {
    if (s.phase == Phase::PhCruise) cruise += s.clocks;
  }
  EXPECT_LT(double(cruise) / Clock::kDefaultHz, 0.01);
  expect_exact_and_within(p, r);
}

TEST(Planner, ShortMoveNeverReachesTheAccelerationLimit) {
  const MoveRequest r = move(10, 0, 3000, 0);
  const Plan p = plan_ok(r);
  EXPECT_LT(p.peak_acceleration, 500.0 * 0.99);
  // At most a few clocks at the (lower) peak acceleration fill the speed
  // change the jerk ramps leave; the move is essentially jerk phases.
  uint64_t ramps = 0, flat = 0;
  for (const Segment& s : p.segments) {
    if (s.phase == Phase::PhAccJerkUp || s.phase == Phase::PhAccJerkDown) ramps += s.clocks;
    if (s.phase == Phase::PhAccConst) flat += s.clocks;
  }
  EXPECT_LT(double(flat), 0.02 * double(ramps));
  expect_exact_and_within(p, r);
}

TEST(Planner, SinglePulseMoveIsExact) {
  for (int64_t l : {1, -1, 2, 3}) {
    const MoveRequest r = move(l, 0, 3000, 0);
    expect_exact_and_within(plan_ok(r), r);
  }
}

TEST(Planner, BackwardMoveMirrorsTheForwardOne) {
  const MoveRequest f = move(5000, 100, 2000, 50);
  MoveRequest b = f;
  b.distance = -5000;
  const Plan pf = plan_ok(f), pb = plan_ok(b);
  ASSERT_EQ(pf.segments.size(), pb.segments.size());
  for (size_t i = 0; i < pf.segments.size(); ++i) {
    EXPECT_EQ(pf.segments[i].clocks, pb.segments[i].clocks);
    EXPECT_EQ(pf.segments[i].vel0, -pb.segments[i].vel0);
    EXPECT_EQ(pf.segments[i].jerk, -pb.segments[i].jerk);
  }
  expect_exact_and_within(pb, b);
}

TEST(Planner, TrapezoidUsesConstantAccelerationOnly) {
  MoveRequest r = paper_group(1);
  r.kind = ProfileKind::Trapezoid;
  const Plan p = plan_ok(r);
  const std::vector<Phase> want = {Phase::PhAccConst, Phase::PhCruise, Phase::PhDecConst};
  EXPECT_EQ(phases(p), want);
  for (const Segment& s : p.segments) EXPECT_EQ(s.jerk, 0);
  // Paper 000 eq. for t1: (vc - vs)/a = 3 s; shorter than the S-curve's 3.2 s.
  EXPECT_NEAR(double(p.segments[0].clocks) / Clock::kDefaultHz, 3.0, 1e-3);
  expect_exact_and_within(p, r);
}

TEST(Planner, AsymmetricJerksEndEachTransitionAtExactlyZeroAcceleration) {
  MoveRequest r = move(30000, 0, 3000, 0);
  r.jerks = std::array<double, 4>{1000, 4000, 3000, 700};
  const Plan p = plan_ok(r);
  const TableReport rep = run_table(p.segments, p.pos_frac0, 1);
  ASSERT_TRUE(rep.ok);
  double j_up = 0, j_down = 0;
  for (size_t i = 0; i < p.segments.size(); ++i) {
    const Segment& s = p.segments[i];
    if (s.phase == Phase::PhAccJerkUp) j_up = jerk_to_phys(s.jerk, Clock{});
    if (s.phase == Phase::PhAccJerkDown) j_down = std::min(j_down, jerk_to_phys(s.jerk, Clock{}));
    if (s.phase == Phase::PhCruise) {
      EXPECT_EQ(s.acc0, 0);
      // The row before the cruise ends at exactly zero acceleration.
      const Segment& prev = p.segments[i - 1];
      EXPECT_EQ(acc_after(prev.acc0, prev.jerk, prev.clocks), 0);
    }
  }
  EXPECT_NEAR(j_up, 1000, 0.01);
  EXPECT_NEAR(j_down, -4000, 0.01);
  expect_exact_and_within(p, r);
}

TEST(Planner, SpeedAtTheStepRateLimitIsAccepted) {
  PulseTiming t;  // 50 + 50 clocks: 200 kHz
  const MoveRequest r = move(100000, 0, 200000, 0, 1e6, 1e8);
  const Plan p = plan_ok(r, t);
  EXPECT_LE(p.peak_velocity, 200000.0);
  expect_exact_and_within(p, r, t);
}

// ---- errors -------------------------------------------------------------

TEST(PlannerErrors, EachBadParameterIsNamed) {
  struct Case {
    MoveRequest r;
    PulseTiming t;
    const char* param;
  };
  PulseTiming bad_high;
  bad_high.high = 0;
  MoveRequest jerks_bad = move(1000, 0, 100, 0);
  jerks_bad.jerks = std::array<double, 4>{100, 100, -5, 100};
  const Case cases[] = {
      {move(0, 0, 100, 0), {}, "distance"},
      {move(int64_t(1) << 40, 0, 100, 0), {}, "distance"},
      {move(1000, -1, 100, 0), {}, "v_start"},
      {move(1000, 0, 0, 0), {}, "v_cruise"},
      {move(1000, 0, 250000, 0), {}, "v_cruise"},
      {move(1000, 0, 100, NAN), {}, "v_end"},
      {move(1000, 0, 100, 0, 0), {}, "a_max"},
      {move(1000, 0, 100, 0, 1e9), {}, "a_max"},
      {move(1000, 0, 100, 0, 500, 1), {}, "j_max"},
      {move(1000, 0, 100, 0, 500, INFINITY), {}, "j_max"},
      {jerks_bad, {}, "jerk_te1"},
      {move(1000, 0, 100, 0), bad_high, "pulse_high"},
  };
  for (const Case& c : cases) {
    const PlanError e = plan_err(c.r, c.t);
    EXPECT_EQ(e.parameter, c.param) << e.message;
    EXPECT_NE(e.message.find(c.param), std::string::npos) << e.message;
    EXPECT_EQ(e.message.find('\n'), std::string::npos) << "one line";
  }
}

TEST(PlannerErrors, StepRateLimitIsStatedInTheMessage) {
  const PlanError e = plan_err(move(1000, 0, 250000, 0));
  EXPECT_NE(e.message.find("200000"), std::string::npos) << e.message;
  EXPECT_NE(e.message.find("step-rate"), std::string::npos) << e.message;
}

TEST(PlannerErrors, UnreachableEndSpeedNamesTheNeededDistance) {
  // 0 -> 3000 pulses/s at a = 500, j = 2500: 6.2 s averaging 1500 = 9300 pulses.
  const PlanError e = plan_err(move(5000, 0, 3000, 3000));
  EXPECT_EQ(e.parameter, "v_end");
  EXPECT_NE(e.message.find("v_end=3000 unreachable"), std::string::npos) << e.message;
  EXPECT_NE(e.message.find("got 5000"), std::string::npos) << e.message;
  const size_t at = e.message.find(">= ");
  ASSERT_NE(at, std::string::npos);
  const long need = std::stol(e.message.substr(at + 3));
  EXPECT_NEAR(double(need), 9300.0, 2.0) << e.message;
  // ...and that distance is indeed enough.
  EXPECT_TRUE(std::holds_alternative<Plan>(Planner().plan(move(need, 0, 3000, 3000), {})));
  EXPECT_FALSE(std::holds_alternative<Plan>(Planner().plan(move(need - 1, 0, 3000, 3000), {})));
}

TEST(PlannerErrors, TooShortToStopIsAnError) {
  const PlanError e = plan_err(move(1000, 3000, 3000, 0));
  EXPECT_EQ(e.parameter, "v_end");
  EXPECT_NE(e.message.find("slowing from v_start=3000"), std::string::npos) << e.message;
}

TEST(PlannerErrors, LoweringTheEndSpeedIsExplicitOnly) {
  MoveRequest r = move(5000, 0, 3000, 3000);
  r.adjust_end_speed = true;
  const Plan p = plan_ok(r);
  EXPECT_TRUE(p.end_speed_adjusted);
  EXPECT_LT(p.v_end_used, 3000.0);
  EXPECT_GT(p.v_end_used, 2000.0);  // sqrt-ish: about 2.2 kHz fits 5000 pulses
  expect_exact_and_within(p, r);
  // A reachable end speed is never changed.
  MoveRequest ok = paper_group(3);
  ok.adjust_end_speed = true;
  EXPECT_FALSE(plan_ok(ok).end_speed_adjusted);
}

TEST(PlannerErrors, RaisingTheEndSpeedWhenBrakingIsTooShortIsExplicitOnly) {
  MoveRequest r = move(1000, 3000, 3000, 0);
  r.adjust_end_speed = true;
  const Plan p = plan_ok(r);
  EXPECT_TRUE(p.end_speed_adjusted);
  EXPECT_GT(p.v_end_used, 0.0);
  expect_exact_and_within(p, r);
}
