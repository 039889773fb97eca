// Planner: every case of paper 000 section 2.1, vs > vc, ve > vc, short
// moves, trapezoid, asymmetric jerks, and the errors for bad requests.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <set>

#include "paper_moves.h"
#include "random_moves.h"
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

// ---- soft limits (the travel window) -------------------------------------

namespace {

MoveRequest windowed(int64_t start, int64_t distance, std::optional<int64_t> min_pos, std::optional<int64_t> max_pos,
                     const std::string& axis = "x") {
  MoveRequest r = move(distance, 0, 3000, 0);
  r.start_position = start;
  r.soft_limits = SoftLimits{axis, min_pos, max_pos};
  return r;
}

// The table never reverses, so the target is the move's extreme position:
// executed, it moves exactly `distance` steps with a speed >= 0 in the move
// direction on every clock.
void expect_monotone_to_target(const Plan& p, const MoveRequest& r) {
  const TableReport rep = run_table(p.segments, p.pos_frac0, r.distance < 0 ? -1 : 1);
  ASSERT_TRUE(rep.ok) << rep.error;
  EXPECT_EQ(rep.steps, r.distance);
  EXPECT_GE(rep.min_signed_vel, 0) << "the move reverses: its target is not its extreme position";
}

}  // namespace

TEST(SoftLimits, TargetBeyondMaxIsRefusedNamingAxisTargetAndLimit) {
  const PlanError e = plan_err(windowed(200, 1000, 0, 1000));
  EXPECT_EQ(e.parameter, "soft_limits.max_pos");
  EXPECT_EQ(e.message, "axis x: target position 1200 is beyond soft limit max=1000 pulses (start 200, distance +1000)");
}

TEST(SoftLimits, TargetBeyondMinIsRefusedNamingAxisTargetAndLimit) {
  const PlanError e = plan_err(windowed(200, -250, -49, 1000, "z"));
  EXPECT_EQ(e.parameter, "soft_limits.min_pos");
  EXPECT_EQ(e.message, "axis z: target position -50 is beyond soft limit min=-49 pulses (start 200, distance -250)");
}

TEST(SoftLimits, TargetExactlyOnEitherLimitIsAcceptedAndTheTableIsUnchanged) {
  for (const MoveRequest& r : {windowed(200, 800, 0, 1000), windowed(200, -200, 0, 1000), windowed(0, 1, 0, 1),
                               windowed(-5, -1, -6, -6)}) {
    const Plan p = plan_ok(r);
    expect_monotone_to_target(p, r);
    MoveRequest plain = r;
    plain.soft_limits.reset();
    EXPECT_EQ(p.segments, plan_ok(plain).segments) << "the window only accepts or refuses";
  }
  // One pulse further is refused on either side.
  EXPECT_EQ(plan_err(windowed(200, 801, 0, 1000)).parameter, "soft_limits.max_pos");
  EXPECT_EQ(plan_err(windowed(200, -201, 0, 1000)).parameter, "soft_limits.min_pos");
}

TEST(SoftLimits, EitherSideAloneLeavesTheOtherUnbounded) {
  plan_ok(windowed(0, -2000000, std::nullopt, 10));
  plan_ok(windowed(0, 2000000, -10, std::nullopt));
  EXPECT_EQ(plan_err(windowed(0, 11, std::nullopt, 10)).parameter, "soft_limits.max_pos");
  EXPECT_EQ(plan_err(windowed(0, -11, -10, std::nullopt)).parameter, "soft_limits.min_pos");
  plan_ok(windowed(0, 5000, std::nullopt, std::nullopt));  // a window without bounds
}

TEST(SoftLimits, FromBeyondALimitOnlyMovesBackTowardTheWindowAreAccepted) {
  // Start 1100 beyond max=1000: back toward the window (still beyond, or
  // into it) is accepted; further out is refused naming the start.
  plan_ok(windowed(1100, -50, 0, 1000));
  plan_ok(windowed(1100, -600, 0, 1000));
  PlanError e = plan_err(windowed(1100, 100, 0, 1000));
  EXPECT_EQ(e.parameter, "start_position");
  EXPECT_EQ(e.message,
            "axis x: start position 1100 is already beyond soft limit max=1000 pulses and target position 1200 is "
            "further out (distance +100): from there only moves back toward the window are accepted");
  // Back across the whole window and out the other side: the target is refused.
  e = plan_err(windowed(1100, -1200, 0, 1000));
  EXPECT_EQ(e.parameter, "soft_limits.min_pos");
  EXPECT_NE(e.message.find("target position -100 is beyond soft limit min=0"), std::string::npos) << e.message;
  // The same below min.
  plan_ok(windowed(-30, 20, 0, 1000));
  e = plan_err(windowed(-30, -1, 0, 1000));
  EXPECT_EQ(e.parameter, "start_position");
  EXPECT_NE(e.message.find("start position -30 is already beyond soft limit min=0"), std::string::npos) << e.message;
}

TEST(SoftLimits, PlanFromAppliesTheSameWindow) {
  const Planner planner;
  JunctionState start;
  start.velocity = i128(std::floor(100 * vel_lsb_per_unit(Clock{})));
  start.frac = kOne / 2;
  MoveRequest r = windowed(200, 1000, 0, 1000);
  PlanResult res = planner.plan_from(start, r, PulseTiming{});
  ASSERT_TRUE(std::holds_alternative<Error>(res));
  EXPECT_EQ(std::get<Error>(res).parameter, "soft_limits.max_pos");
  r.distance = 800;
  res = planner.plan_from(start, r, PulseTiming{});
  ASSERT_TRUE(std::holds_alternative<Plan>(res)) << std::get<Error>(res).message;
  const Plan& p = std::get<Plan>(res);
  const TableReport rep = run_table(p.segments, start.frac, 1);
  EXPECT_EQ(rep.steps, 800);
  EXPECT_GE(rep.min_signed_vel, 0);
}

TEST(SoftLimits, BadWindowFieldsAreNamedBeforeSolving) {
  struct Case {
    MoveRequest r;
    const char* param;
    const char* text;
  };
  const int64_t too_far = PlannerLimits::kMaxPosition + 1;
  MoveRequest far_start = move(100, 0, 3000, 0);
  far_start.start_position = -too_far;  // checked without a window too
  const Case cases[] = {
      {windowed(0, 100, 5, 1), "soft_limits.min_pos",
       "axis x: soft limit min=5 is above max=1 pulses: needs min <= max"},
      {windowed(0, 100, std::nullopt, too_far), "soft_limits.max_pos",
       "soft_limits.max_pos=4611686018427387905: exceeds the limit +-4611686018427387904 pulses"},
      {windowed(0, 100, -too_far, 10), "soft_limits.min_pos", "exceeds the limit"},
      {far_start, "start_position", "start_position=-4611686018427387905: exceeds the limit"},
      {windowed(0, 100, 0, 10, ""), "soft_limits.axis", "soft_limits.axis='': must be 1 to 32 characters"},
      {windowed(0, 100, 0, 10, "x y"), "soft_limits.axis", "soft_limits.axis='x y'"},
      {windowed(0, 100, 0, 10, "a\nb"), "soft_limits.axis", "soft_limits.axis='a\\x0ab'"},
      {windowed(0, 100, 0, 10, std::string(33, 'a')), "soft_limits.axis", "must be 1 to 32"},
  };
  for (const Case& c : cases) {
    const PlanError e = plan_err(c.r);
    EXPECT_EQ(e.parameter, c.param) << e.message;
    EXPECT_NE(e.message.find(c.text), std::string::npos) << e.message;
    EXPECT_EQ(e.message.find('\n'), std::string::npos) << "one line";
  }
  plan_ok(windowed(0, 100, 0, 1000, "spindle_2.A-1"));
  plan_ok(windowed(PlannerLimits::kMaxPosition - 100, 100, std::nullopt, PlannerLimits::kMaxPosition));
}

// The independent rule: a move is accepted iff its target is inside the
// window, or it starts beyond a limit and ends closer to it without crossing
// the other - whenever it is plannable without the window; the window never
// changes an accepted table.
TEST(SoftLimits, RandomMovesAreAcceptedIffTheTargetRuleHolds) {
  std::mt19937_64 g(20261203);
  const Clock clock{};
  const Planner planner(clock);
  std::uniform_int_distribution<int> coin(0, 99);
  std::uniform_int_distribution<int64_t> start_pos(-1000000000, 1000000000);
  std::uniform_int_distribution<int64_t> near(-2, 2);
  const int kMoves = 3000;
  int plannable = 0, accepted = 0, refused_target = 0, refused_start = 0, from_outside = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < kMoves; ++i) {
    test::RandomRequest rr = test::random_request(g, clock);
    MoveRequest r = rr.req;
    r.start_position = start_pos(g);
    const int64_t target = r.start_position + r.distance;
    const int64_t span = std::max<int64_t>(4, 2 * (r.distance < 0 ? -r.distance : r.distance));
    // A bound near the target (on it, a pulse or two off) or anywhere
    // within twice the distance of it (the start can end up outside).
    const auto bound = [&]() -> std::optional<int64_t> {
      const int c = coin(g);
      if (c < 15) return std::nullopt;
      if (c < 45) return target + near(g);
      return target + std::uniform_int_distribution<int64_t>(-span, span)(g);
    };
    SoftLimits w{"x", bound(), bound()};
    if (w.min_pos && w.max_pos && *w.min_pos > *w.max_pos) std::swap(w.min_pos, w.max_pos);
    r.soft_limits = w;

    const auto inside = [&](int64_t p) { return (!w.min_pos || p >= *w.min_pos) && (!w.max_pos || p <= *w.max_pos); };
    const bool back_from_above = w.max_pos && r.start_position > *w.max_pos && target < r.start_position &&
                                 (!w.min_pos || target >= *w.min_pos);
    const bool back_from_below = w.min_pos && r.start_position < *w.min_pos && target > r.start_position &&
                                 (!w.max_pos || target <= *w.max_pos);
    const bool rule = inside(target) || back_from_above || back_from_below;
    from_outside += !inside(r.start_position);

    MoveRequest plain = r;
    plain.soft_limits.reset();
    const PlanResult base = planner.plan(plain, rr.timing);
    const PlanResult res = planner.plan(r, rr.timing);
    if (!std::holds_alternative<Plan>(base)) {
      EXPECT_TRUE(std::holds_alternative<Error>(res)) << "move " << i << ": accepted only with a window";
      continue;
    }
    ++plannable;
    const Plan& b = std::get<Plan>(base);
    const TableReport rep = run_table(b.segments, b.pos_frac0, r.distance < 0 ? -1 : 1);
    ASSERT_TRUE(rep.ok) << rep.error;
    ASSERT_EQ(rep.steps, r.distance) << "move " << i;
    ASSERT_GE(rep.min_signed_vel, 0) << "move " << i << " reverses: the target is not its extreme position";
    if (rule) {
      ASSERT_TRUE(std::holds_alternative<Plan>(res)) << "move " << i << ": " << std::get<Error>(res).message;
      EXPECT_EQ(std::get<Plan>(res).segments, b.segments) << "move " << i;
      ++accepted;
      continue;
    }
    ASSERT_TRUE(std::holds_alternative<Error>(res)) << "move " << i << ": target " << target << " accepted";
    const Error& e = std::get<Error>(res);
    const bool by_start = e.parameter == "start_position";
    (by_start ? refused_start : refused_target)++;
    const bool above = w.max_pos && target > *w.max_pos;
    const int64_t limit = above ? *w.max_pos : *w.min_pos;
    if (!by_start) {
      EXPECT_EQ(e.parameter, above ? "soft_limits.max_pos" : "soft_limits.min_pos") << e.message;
    }
    EXPECT_EQ(e.message.rfind("axis x: ", 0), 0u) << e.message;
    EXPECT_NE(e.message.find("target position " + std::to_string(target) + " "), std::string::npos) << e.message;
    EXPECT_NE(e.message.find(std::string(above ? "max=" : "min=") + std::to_string(limit) + " pulses"),
              std::string::npos)
        << e.message;
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("[soft limits] %d random moves in %.1f s: %d plannable, %d accepted, %d refused by the target, %d by "
              "the start (%d started outside the window)\n",
              kMoves, secs, plannable, accepted, refused_target, refused_start, from_outside);
  EXPECT_GT(accepted, plannable / 5);
  EXPECT_GT(refused_target, plannable / 10);
  EXPECT_GT(refused_start, 10);
}

// ---- Planner::plan_from_state: a move from an exact state with acceleration

namespace {

// The request's limits in LSB, floored as the planner floors them.
struct LsbLimits {
  i128 v_rate = 0;
  int64_t a_max = 0, j_max = 0;
};
LsbLimits lsb_limits(const MoveRequest& r, const PulseTiming& t, Clock c = Clock{}) {
  LsbLimits l;
  l.v_rate = i128(kOne) / (i128(t.high) + t.low);
  l.a_max = int64_t(std::floor(r.a_max * acc_lsb_per_unit(c)));
  l.j_max = int64_t(std::floor(scurve::test::jerk_cap(r) * jerk_lsb_per_unit(c)));
  return l;
}

// The request's end speed in LSB (floored, capped at the step-rate limit).
i128 end_speed_lsb(double v, const LsbLimits& l, Clock c = Clock{}) {
  return std::min(i128(std::floor(v * vel_lsb_per_unit(c))), l.v_rate);
}

// A random start state within the request's limits: both signs of the
// acceleration, speeds from 0 to the step-rate limit in the move's direction.
ExactState random_state(std::mt19937_64& g, const MoveRequest& r, const PulseTiming& t) {
  const LsbLimits l = lsb_limits(r, t);
  std::uniform_real_distribution<double> u(0, 1);
  ExactState s;
  const int dir = r.distance < 0 ? -1 : 1;
  const double pick = u(g);
  const double v_frac = pick < 0.1 ? 0.0 : pick < 0.2 ? 1.0 - u(g) * 1e-3 : u(g) * u(g);
  // Mostly up to the request's own speeds (a running move's), some up to the step-rate limit.
  const double v_request = std::max(r.v_start, r.v_cruise) * vel_lsb_per_unit(Clock{});
  const double v_top = u(g) < 0.25 ? double(l.v_rate) : std::min(double(l.v_rate), v_request);
  s.velocity = dir * i128(v_top * v_frac);
  const double a_frac = u(g) < 0.1 ? 1.0 : u(g);
  // Half of them small enough to end (at the jerk limit) within the speed range, as a running move's.
  const double a_top = u(g) < 0.5 ? double(l.a_max)
                                  : std::min(double(l.a_max), std::sqrt(2.0 * double(std::max<int64_t>(l.j_max, 1)) *
                                                                        v_top * std::max(v_frac, 0.5)));
  s.acceleration = int64_t(a_top * a_frac) * (u(g) < 0.5 ? 1 : -1);
  if (s.acceleration == 0) s.acceleration = 1;
  s.frac = u128(i128(u(g) * double(kOne))) & (kOne - 1);
  return s;
}

// Executes the table independently (run_table and the closed forms) and
// checks every promise of plan_from_state.
void expect_exact_from_state(const Plan& p, const ExactState& s, const MoveRequest& r, const PulseTiming& t) {
  const int dir = r.distance < 0 ? -1 : 1;
  const LsbLimits l = lsb_limits(r, t);
  ASSERT_FALSE(p.segments.empty());
  EXPECT_EQ(p.pos_frac0, s.frac);
  EXPECT_TRUE(p.segments.front().vel0 == s.velocity) << to_string_i128(p.segments.front().vel0);
  if (r.kind == ProfileKind::SCurve) EXPECT_EQ(p.segments.front().acc0, s.acceleration);
  i128 v = 0;
  int64_t a = 0;
  for (size_t k = 0; k < p.segments.size(); ++k) {
    const Segment& g = p.segments[k];
    if (k > 0) {
      EXPECT_TRUE(g.vel0 == v) << "row " << k << " does not continue the velocity";
      if (r.kind == ProfileKind::SCurve) EXPECT_EQ(g.acc0, a) << "row " << k << " does not continue the acceleration";
    }
    v = vel_after(g.vel0, g.acc0, g.jerk, g.clocks);
    a = int64_t(acc_after(g.acc0, g.jerk, g.clocks));
  }
  if (r.kind == ProfileKind::SCurve) EXPECT_EQ(a, 0);
  const TableReport rep = run_table(p.segments, p.pos_frac0, dir);
  ASSERT_TRUE(rep.ok) << rep.error;
  EXPECT_EQ(rep.steps, r.distance);
  const i128 window_lo = i128(r.distance) * i128(kOne);
  EXPECT_TRUE(rep.end_pos >= window_lo && rep.end_pos < window_lo + i128(kOne)) << "end outside the window";
  EXPECT_TRUE(p.end_state.frac == u128(rep.end_pos - window_lo));
  EXPECT_GE(rep.min_signed_vel, 0) << "velocity reverses";
  EXPECT_LE(rep.peak_vel, l.v_rate);
  EXPECT_LE(rep.peak_acc, l.a_max);
  if (r.kind == ProfileKind::SCurve) EXPECT_LE(rep.peak_jerk, l.j_max);
  EXPECT_EQ(rep.clocks, p.total_clocks);
  const i128 ve = end_speed_lsb(p.end_speed_adjusted ? p.v_end_used : r.v_end, l);
  if (!p.end_speed_adjusted) EXPECT_TRUE(v == dir * ve) << to_string_i128(v) << " vs " << to_string_i128(ve);
  EXPECT_TRUE(p.end_state.velocity == v);
}

// The shortest distance an error names ("needs distance >= N pulses").
int64_t needed_distance_in(const std::string& msg) {
  const auto at = msg.find("needs distance >= ");
  if (at == std::string::npos) return -1;
  return std::atoll(msg.c_str() + at + 18);
}

}  // namespace

TEST(PlanFromState, ZeroAccelerationReturnsExactlyWhatPlanFromReturns) {
  std::mt19937_64 g(11);
  const Planner planner;
  for (int i = 0; i < 500; ++i) {
    const auto rr = scurve::test::random_request(g, Clock{});
    ExactState s = random_state(g, rr.req, rr.timing);
    s.acceleration = 0;
    const PlanResult a = planner.plan_from_state(s, rr.req, rr.timing);
    const PlanResult b = planner.plan_from(JunctionState{s.velocity, s.frac}, rr.req, rr.timing);
    ASSERT_EQ(a.index(), b.index());
    if (const auto* pa = std::get_if<Plan>(&a)) {
      const Plan& pb = std::get<Plan>(b);
      EXPECT_EQ(pa->segments, pb.segments);
      EXPECT_TRUE(pa->pos_frac0 == pb.pos_frac0 && pa->end_state.frac == pb.end_state.frac);
      EXPECT_TRUE(pa->end_state.velocity == pb.end_state.velocity);
      EXPECT_EQ(pa->total_clocks, pb.total_clocks);
    } else {
      EXPECT_EQ(std::get<Error>(a).message, std::get<Error>(b).message);
    }
  }
}

TEST(PlanFromState, EndsExactlyOnTheTargetFromRandomStatesWithinTheLimits) {
  std::mt19937_64 g(12);
  const Planner planner;
  int planned = 0, too_short = 0, refused = 0, checked_needs = 0;
  for (int i = 0; i < 8000; ++i) {
    auto rr = scurve::test::random_request(g, Clock{});
    if (i % 4 == 0) rr.req.v_end = 0;
    const ExactState s = random_state(g, rr.req, rr.timing);
    const PlanResult res = planner.plan_from_state(s, rr.req, rr.timing);
    if (const auto* p = std::get_if<Plan>(&res)) {
      ++planned;
      SCOPED_TRACE(i);
      expect_exact_from_state(*p, s, rr.req, rr.timing);
      if (HasFailure()) return;
      continue;
    }
    const Error& e = std::get<Error>(res);
    if (e.parameter == "start_acceleration") {
      ++refused;
      continue;
    }
    ASSERT_TRUE(e.parameter == "distance" || e.parameter == "v_end") << e.parameter << ": " << e.message;
    ++too_short;
    if (rr.req.kind == ProfileKind::Trapezoid) continue;  // plan_from's errors (the acceleration steps anyway)
    // The shortest distance named is enough (a few of them, re-planned).
    const int64_t need = needed_distance_in(e.message);
    ASSERT_GT(need, 0) << e.message;
    if (need <= PlannerLimits::kMaxDistance && checked_needs < 300) {
      ++checked_needs;
      MoveRequest r2 = rr.req;
      r2.distance = (rr.req.distance < 0 ? -1 : 1) * need;
      const PlanResult again = planner.plan_from_state(s, r2, rr.timing);
      ASSERT_TRUE(std::holds_alternative<Plan>(again))
          << "named " << need << ": " << e.message << " / " << std::get<Error>(again).message;
      expect_exact_from_state(std::get<Plan>(again), s, r2, rr.timing);
    }
  }
  std::printf("plan_from_state: %d planned, %d too short (%d re-planned at the named distance), %d refused\n",
              planned, too_short, checked_needs, refused);
  EXPECT_GT(planned, 2500);
}

namespace {

// Continuous-time reference (pulses, seconds): the time-optimal move from
// (v0, a0) to (ve, 0) over a travel d at speeds <= vc is an opening to a
// plateau V at acceleration 0, a cruise, and a transition to ve, with the
// highest V whose transitions fit in d. Jerk per direction: |a| rises at
// the "in" jerk and falls at the "out" jerk of the acceleration's sign.
struct RefLimits {
  double a = 0, acc_in = 0, acc_out = 0, dec_in = 0, dec_out = 0;
};
struct RefState {
  double t = 0, s = 0, v = 0, a = 0;
};
// Constant jerk j for a time t, integrated exactly.
void ref_phase(RefState& x, double j, double t) {
  x.s += x.v * t + x.a * t * t / 2 + j * t * t * t / 6;
  x.v += x.a * t + j * t * t / 2;
  x.a += j * t;
  x.t += t;
}
// On to speed V at acceleration 0, fastest: either |a| falls to 0 first
// (V on the near side of where that ends), or it rises on to a peak, holds
// and falls.
void ref_ramp(RefState& x, double V, const RefLimits& l) {
  if (x.a != 0) {
    const double s0 = x.a > 0 ? 1.0 : -1.0;
    const double j_fall = s0 > 0 ? l.acc_out : l.dec_out;
    const double v_settle = x.v + x.a * std::fabs(x.a) / (2 * j_fall);
    if (s0 * (V - v_settle) <= 0) {
      ref_phase(x, -s0 * j_fall, std::fabs(x.a) / j_fall);
      x.a = 0;
    }
  }
  if (x.a == 0 && V == x.v) return;
  const double s = x.a != 0 ? (x.a > 0 ? 1.0 : -1.0) : (V > x.v ? 1.0 : -1.0);
  const double j_in = s > 0 ? l.acc_in : l.dec_in, j_out = s > 0 ? l.acc_out : l.dec_out;
  const double a0 = std::fabs(x.a), dv = std::fabs(V - x.v);
  double peak = std::sqrt((dv + a0 * a0 / (2 * j_in)) / (0.5 / j_in + 0.5 / j_out)), hold = 0;
  if (peak > l.a) {
    peak = l.a;
    hold = (dv - (peak * peak - a0 * a0) / (2 * j_in) - peak * peak / (2 * j_out)) / peak;
  }
  ref_phase(x, s * j_in, (peak - a0) / j_in);
  ref_phase(x, 0, hold);
  ref_phase(x, -s * j_out, peak / j_out);
  x.a = 0;
}
std::string fmt_case(int i, double v0, double a0, double ve, double vc, double d, double a, double j, double t,
                     double t_ref) {
  char buf[400];
  std::snprintf(buf, sizeof buf, "#%d v0=%g a0=%g ve=%g vc=%g d=%g a_max=%g j=%g: %.6g s vs %.6g s", i, v0, a0, ve, vc,
                d, a, j, t, t_ref);
  return buf;
}

// The shortest duration, or -1 if nothing fits.
double ref_duration(double v0, double a0, double ve, double vc, double d, const RefLimits& l) {
  const auto profile = [&](double V) {
    RefState x{0, 0, v0, a0};
    ref_ramp(x, V, l);
    const RefState opening = x;
    ref_ramp(x, ve, l);
    return std::pair{opening, x};
  };
  if (profile(ve).second.s > d) return -1;
  double lo = ve, hi = vc;
  if (profile(hi).second.s <= d) {
    lo = hi;
  } else {
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (profile(mid).second.s <= d ? lo : hi) = mid;
    }
  }
  const RefState all = profile(lo).second;
  return all.t + (lo > 0 ? std::max(0.0, d - all.s) / lo : 0.0);
}

}  // namespace

TEST(PlanFromState, DurationIsNearTheContinuousTimeOptimum) {
  std::mt19937_64 g(13);
  const Planner planner;
  const Clock c{};
  double worst = -1, worst_carry = -1, worst_settle = -1, worst_base = -1, worst_above = -1, worst_asym = -1;
  double worst_base_asym = -1;
  int compared = 0, compared_above = 0, compared_asym = 0, asym_over_1 = 0;
  std::string worst_case;
  for (int i = 0; i < 12000; ++i) {
    auto rr = scurve::test::random_request(g, c);
    MoveRequest& r = rr.req;
    r.kind = ProfileKind::SCurve;
    r.adjust_end_speed = false;
    if (i % 3 == 0) r.v_end = 0;
    const ExactState s = random_state(g, r, rr.timing);
    const PlanResult res = planner.plan_from_state(s, r, rr.timing);
    const Plan* p = std::get_if<Plan>(&res);
    if (!p || p->total_clocks < 2000) continue;  // (a few clocks: the integer clock dominates)
    const int dir = r.distance < 0 ? -1 : 1;
    const LsbLimits l = lsb_limits(r, rr.timing);
    const double a = acc_to_phys(l.a_max, c), j = jerk_to_phys(l.j_max, c);
    const auto floored = [&](double jerk) { return jerk_to_phys(int64_t(std::floor(jerk * jerk_lsb_per_unit(c))), c); };
    const std::array<double, 4> jerks = r.jerks.value_or(std::array<double, 4>{r.j_max, r.j_max, r.j_max, r.j_max});
    const RefLimits ref{a, floored(jerks[0]), floored(jerks[1]), floored(jerks[2]), floored(jerks[3])};
    const double v0 = vel_to_phys(dir * s.velocity, c), a0 = acc_to_phys(dir * s.acceleration, c);
    const double vc = vel_to_phys(end_speed_lsb(r.v_cruise, l), c), ve = vel_to_phys(end_speed_lsb(r.v_end, l), c);
    const double v_settle = v0 + a0 * std::fabs(a0) / (2 * (a0 > 0 ? ref.acc_out : ref.dec_out));
    if (ve > vc) continue;
    // A start above the cruise speed (or one that must pass it) comes down to
    // it if that fits, else cruises above it (faster than this reference).
    const bool above_cruise = v0 > vc || v_settle > vc;
    const TableReport rep = run_table(p->segments, p->pos_frac0, dir);
    const double d = pos_to_phys(dir * (rep.end_pos - i128(s.frac)));
    const double t_ref = ref_duration(v0, a0, ve, vc, d, ref);
    if (t_ref <= 0) continue;
    const double excess = p->duration_s / t_ref - 1;
    // The same request from the same speed at acceleration 0 (plan_from): the solver's own loss.
    ExactState at_rest_acc = s;
    at_rest_acc.acceleration = 0;
    const PlanResult base = planner.plan_from_state(at_rest_acc, r, rr.timing);
    if (const Plan* q = std::get_if<Plan>(&base); q && q->total_clocks >= 2000 && !above_cruise) {
      const TableReport qr = run_table(q->segments, q->pos_frac0, dir);
      const double t_base = ref_duration(v0, 0, ve, vc, pos_to_phys(dir * (qr.end_pos - i128(s.frac))), ref);
      double& w = r.jerks ? worst_base_asym : worst_base;
      if (t_base > 0) w = std::max(w, q->duration_s / t_base - 1);
    }
    if (!above_cruise && !r.jerks) ++compared;
    if (above_cruise) {
      worst_above = std::max(worst_above, excess);
      ++compared_above;
      continue;
    }
    if (r.jerks) {  // asymmetric jerks: apart (the ramps' rounding differs per direction)
      worst_asym = std::max(worst_asym, excess);
      ++compared_asym;
      asym_over_1 += excess > 0.01;
      continue;
    }
    const int64_t first_jerk = dir * p->segments.front().jerk;
    const bool carried = first_jerk != 0 && (a0 > 0) == (first_jerk > 0);
    (carried ? worst_carry : worst_settle) = std::max(carried ? worst_carry : worst_settle, excess);
    if (excess > worst) {
      worst = excess;
      worst_case = fmt_case(i, v0, a0, ve, vc, d, a, j, p->duration_s, t_ref);
    }
  }
  std::printf("plan_from_state vs continuous optimum: %d compared, worst excess %.4f %% (carried ramps %.4f %%, "
              "settled first %.4f %%; plan_from from the same speeds: %.4f %%)\n  worst: %s\n",
              compared, 100 * worst, 100 * worst_carry, 100 * worst_settle, 100 * worst_base, worst_case.c_str());
  std::printf("  starts above the cruise speed: %d compared, at most %.4f %% longer\n", compared_above,
              100 * worst_above);
  std::printf("  asymmetric jerks: %d compared, at most %.4f %% longer, %d of them over 1 %% (plan_from: %.4f %%)\n",
              compared_asym, 100 * worst_asym, asym_over_1, 100 * worst_base_asym);
  EXPECT_GT(compared, 1000);
  EXPECT_LT(worst, 0.001);
  EXPECT_LT(worst_above, 0.001);
  EXPECT_LT(worst_asym, 0.01);
}

namespace {

MoveRequest retarget_move(int64_t distance, double v_end = 0) {
  MoveRequest r = move(distance, 0, 20000, v_end, 50000, 1e6);
  return r;
}

PlanError from_state_err(const ExactState& s, const MoveRequest& r) {
  const PlanResult res = Planner().plan_from_state(s, r, PulseTiming{});
  if (std::holds_alternative<Plan>(res)) {
    ADD_FAILURE() << "expected an error";
    return {};
  }
  return std::get<PlanError>(res);
}

}  // namespace

TEST(PlanFromState, RefusesStartStatesBeyondTheLimitsNamingParameterValueAndBound) {
  const MoveRequest r = retarget_move(100000);
  const LsbLimits l = lsb_limits(r, PulseTiming{});
  const i128 v = end_speed_lsb(5000, l);

  PlanError e = from_state_err(ExactState{v, l.a_max + 1, 0}, r);
  EXPECT_EQ(e.parameter, "start_acceleration");
  EXPECT_NE(e.message.find(std::to_string(l.a_max + 1)), std::string::npos) << e.message;
  EXPECT_NE(e.message.find(std::to_string(l.a_max) + " LSB"), std::string::npos) << e.message;
  e = from_state_err(ExactState{v, -l.a_max - 1, 0}, r);
  EXPECT_EQ(e.parameter, "start_acceleration");

  e = from_state_err(ExactState{l.v_rate + 1, 1000, 0}, r);
  EXPECT_EQ(e.parameter, "start_velocity");
  EXPECT_NE(e.message.find(to_string_i128(l.v_rate + 1)), std::string::npos) << e.message;
  EXPECT_NE(e.message.find(to_string_i128(l.v_rate)), std::string::npos) << e.message;

  // Against the move: as plan_from.
  e = from_state_err(ExactState{-v, 1000, 0}, r);
  EXPECT_EQ(e.parameter, "start_velocity");
  EXPECT_NE(e.message.find("direction change"), std::string::npos) << e.message;

  // From rest with the acceleration against the move: a reversal needs rest first.
  e = from_state_err(ExactState{0, -1000, 0}, r);
  EXPECT_EQ(e.parameter, "start_acceleration");
  EXPECT_NE(e.message.find("reversal needs rest first"), std::string::npos) << e.message;
  e = from_state_err(ExactState{0, 1000, 0}, retarget_move(-100000));
  EXPECT_EQ(e.parameter, "start_acceleration");
  // Moving slowly while braking hard: ending the braking reverses the velocity.
  e = from_state_err(ExactState{10, -l.a_max, 0}, r);
  EXPECT_EQ(e.parameter, "start_acceleration");
  EXPECT_NE(e.message.find("reverses the velocity"), std::string::npos) << e.message;
  // Near the step-rate limit while speeding up hard: ending it passes the limit.
  e = from_state_err(ExactState{l.v_rate - 10, l.a_max, 0}, r);
  EXPECT_EQ(e.parameter, "start_acceleration");
  EXPECT_NE(e.message.find("step-rate limit " + to_string_i128(l.v_rate)), std::string::npos) << e.message;

  // The request is checked as plan_from checks it; and start_frac too.
  MoveRequest bad = r;
  bad.a_max = -1;
  EXPECT_EQ(from_state_err(ExactState{v, 1000, 0}, bad).parameter, "a_max");
  EXPECT_EQ(from_state_err(ExactState{v, 1000, kOne}, r).parameter, "start_frac");
}

TEST(PlanFromState, TooCloseToStopNamesTheShortestDistanceThatWorks) {
  const MoveRequest r = retarget_move(10);
  const LsbLimits l = lsb_limits(r, PulseTiming{});
  const ExactState s{end_speed_lsb(15000, l), l.a_max / 2, kOne / 3};
  const PlanError e = from_state_err(s, r);
  ASSERT_EQ(e.parameter, "distance");
  EXPECT_NE(e.message.find("too short to stop"), std::string::npos) << e.message;
  const int64_t need = needed_distance_in(e.message);
  ASSERT_GT(need, 10) << e.message;
  MoveRequest r2 = r;
  r2.distance = need;
  const PlanResult ok = Planner().plan_from_state(s, r2, PulseTiming{});
  ASSERT_TRUE(std::holds_alternative<Plan>(ok)) << std::get<Error>(ok).message;
  expect_exact_from_state(std::get<Plan>(ok), s, r2, PulseTiming{});
  r2.distance = need - 1;
  EXPECT_EQ(from_state_err(s, r2).parameter, "distance");
  // A nonzero end speed out of reach names v_end; adjust_end_speed plans the nearest one instead.
  MoveRequest r3 = retarget_move(3, 100);
  EXPECT_EQ(from_state_err(s, r3).parameter, "v_end");
  r3.adjust_end_speed = true;
  r3.distance = need;
  const ExactState fast{end_speed_lsb(15000, l), l.a_max / 2, 0};
  const PlanResult adj = Planner().plan_from_state(fast, r3, PulseTiming{});
  ASSERT_TRUE(std::holds_alternative<Plan>(adj)) << std::get<Error>(adj).message;
  EXPECT_TRUE(std::get<Plan>(adj).end_speed_adjusted);
  EXPECT_GT(std::get<Plan>(adj).v_end_used, 100);
  expect_exact_from_state(std::get<Plan>(adj), fast, r3, PulseTiming{});
}

TEST(PlanFromState, SpeedingUpTowardCruiseCarriesTheAccelerationOnInsteadOfSettlingFirst) {
  const MoveRequest r = retarget_move(200000);
  const LsbLimits l = lsb_limits(r, PulseTiming{});
  const ExactState s{end_speed_lsb(2000, l), l.a_max / 2, 0};
  const PlanResult res = Planner().plan_from_state(s, r, PulseTiming{});
  ASSERT_TRUE(std::holds_alternative<Plan>(res));
  const Plan& p = std::get<Plan>(res);
  expect_exact_from_state(p, s, r, PulseTiming{});
  EXPECT_GT(p.segments.front().jerk, 0);  // on up to a_max, not down to 0 first
  EXPECT_EQ(p.segments.front().phase, Phase::PhAccJerkUp);
  EXPECT_NEAR(p.v_plateau, 20000, 1e-6);
  // Braking ahead of a stop carries the braking on, the same way.
  const ExactState braking{end_speed_lsb(19000, l), -l.a_max / 2, 0};
  const MoveRequest near = retarget_move(4000);
  const PlanResult b = Planner().plan_from_state(braking, near, PulseTiming{});
  ASSERT_TRUE(std::holds_alternative<Plan>(b)) << std::get<Error>(b).message;
  expect_exact_from_state(std::get<Plan>(b), braking, near, PulseTiming{});
  EXPECT_LT(std::get<Plan>(b).segments.front().jerk, 0);
}

TEST(PlanFromState, ExtremeAndRandomInputsNeverCrashOrHang) {
  std::mt19937_64 g(14);
  const Planner planner;
  const auto t0 = std::chrono::steady_clock::now();
  int planned = 0;
  const int calls = 3000;
  for (int i = 0; i < calls; ++i) {
    auto rr = scurve::test::random_request(g, Clock{});
    const LsbLimits l = lsb_limits(rr.req, rr.timing);
    ExactState s;
    const uint64_t pick = g() % 6;
    const i128 raw_v = (i128(int64_t(g())) << 20) ^ i128(g() & 0xfffff);
    s.velocity = pick == 0 ? raw_v : pick == 1 ? l.v_rate : pick == 2 ? -l.v_rate : i128(g() % 1000) - 500;
    const int64_t extremes[] = {INT64_MIN, INT64_MAX, l.a_max, -l.a_max, 1, -1};
    s.acceleration = pick < 3 ? extremes[g() % 6] : int64_t(g());
    s.frac = g() % 4 == 0 ? (u128(g()) << 64 | g()) : u128(g()) & (kOne - 1);
    if (g() % 8 == 0) rr.req.distance = (g() % 2 ? 1 : -1) * PlannerLimits::kMaxDistance;
    const PlanResult res = planner.plan_from_state(s, rr.req, rr.timing);
    if (const auto* p = std::get_if<Plan>(&res)) {
      ++planned;
      expect_exact_from_state(*p, s, rr.req, rr.timing);
      if (HasFailure()) return;
    } else {
      EXPECT_FALSE(std::get<Error>(res).message.empty());
      EXPECT_NE(std::get<Error>(res).parameter, "internal") << std::get<Error>(res).message;
    }
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("plan_from_state fuzz: %d calls, %d planned, %.1f s\n", calls, planned, secs);
}

TEST(PlanFromState, OneCallTakesWellUnder100Microseconds) {
  std::mt19937_64 g(15);
  std::vector<std::pair<scurve::test::RandomRequest, ExactState>> set;
  for (int i = 0; i < 2000; ++i) {
    auto rr = scurve::test::random_request(g, Clock{});
    const ExactState s = random_state(g, rr.req, rr.timing);
    set.push_back({rr, s});
  }
  const Planner planner;
  std::vector<double> us;
  for (const auto& [rr, s] : set) {
    const auto t0 = std::chrono::steady_clock::now();
    const PlanResult res = planner.plan_from_state(s, rr.req, rr.timing);
    us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
    (void)res;
  }
  std::sort(us.begin(), us.end());
  std::printf("plan_from_state: median %.1f us, 90%% %.1f us, 99%% %.1f us, max %.1f us\n", us[us.size() / 2],
              us[us.size() * 9 / 10], us[us.size() * 99 / 100], us.back());
  EXPECT_LT(us[us.size() / 2], 100.0);
}
