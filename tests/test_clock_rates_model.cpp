// Plans for boards clocked at 20, 25 and 50 MHz, run on the bit-exact
// executor model (step() every clock for short moves, the closed-form
// fast_forward() for long ones): exactly |distance| steps, the fraction
// ends mid-pulse, and v, a, j stay within the request's limits in physical
// units at that clock rate.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "planner.h"
#include "profile_exec.h"
#include "random_moves.h"
#include "scenarios.h"

using namespace sc;

namespace {

constexpr double kClocks[] = {20e6, 25e6, 50e6};

struct Peaks {
  int32_t steps = 0;
  u128 frac = 0;
  bool finished = false;
  double v = 0, a = 0, j = 0;  // physical, at the plan's clock
};

ProfileExec load(const Plan& p) {
  ProfileExec ex;
  load_and_start(ex, p.segments, p.pos_frac0);
  return ex;
}

// per_clock: step() every clock; else fast_forward() through every row,
// sampling at least every `sample` clocks and at each row's last clocks.
Peaks run_on_model(const Plan& p, bool per_clock, uint64_t sample = 1000) {
  ProfileExec ex = load(p);
  const scurve::Clock c = p.clock;
  Peaks r;
  const int32_t p0 = ex.state().pint;
  auto observe = [&]() {
    const ProfileExec::State& s = ex.state();
    if (!s.run) return;
    r.v = std::max(r.v, std::fabs(scurve::vel_to_phys(s.vel, c)));
    r.a = std::max(r.a, std::fabs(scurve::acc_to_phys(s.acc, c)));
    r.j = std::max(r.j, std::fabs(scurve::jerk_to_phys(s.jerk, c)));
  };
  observe();
  if (per_clock) {
    for (uint64_t k = 0; k <= p.total_clocks + 1; ++k) {
      ex.step(ProfileExec::Inputs{});
      observe();
    }
  } else {
    uint64_t done = 0;
    while (ex.state().run && done <= p.total_clocks + 1) {
      const uint64_t left = ex.state().left;
      const uint64_t n = left > 2 ? std::min<uint64_t>(left - 1, sample) : 1;
      ex.fast_forward(n);
      done += n;
      observe();
    }
    ex.fast_forward(4);
  }
  r.steps = ex.state().pint - p0;
  r.frac = ex.state().frac;
  r.finished = ex.state().finished && !ex.state().run;
  return r;
}

void expect_exact_within_limits(const Plan& p, const MoveRequest& r, const PulseTiming& t, const Peaks& m,
                                const std::string& what) {
  EXPECT_TRUE(m.finished) << what;
  EXPECT_EQ(m.steps, r.distance) << what;
  EXPECT_EQ(m.frac, kOne >> 1) << "ends mid-pulse; " << what;
  const double tol = 1 + 1e-12;
  const double v_rate = scurve::step_rate_limit(to_host(t), p.clock);
  EXPECT_LE(m.v, std::min(std::max({r.v_cruise, r.v_start, p.v_end_used}), v_rate) * tol) << what;
  EXPECT_LE(m.a, r.a_max * tol) << what;
  if (r.kind == ProfileKind::SCurve) EXPECT_LE(m.j, scurve::test::jerk_cap(r) * tol) << what;
}

}  // namespace

TEST(ModelClockRate, PaperGroupsExactOnTheModelAt20And25And50MHz) {
  for (double hz : kClocks) {
    for (int g = 1; g <= 4; ++g) {
      const MoveRequest r = paper_group(g);
      const PlanResult res = plan_move(r, PulseTiming{}, scurve::Clock{hz});
      ASSERT_TRUE(std::holds_alternative<Plan>(res)) << std::get<PlanError>(res).message;
      const Plan& p = std::get<Plan>(res);
      const std::string what = "group " + std::to_string(g) + " at " + std::to_string(hz) + " Hz";
      const Peaks m = run_on_model(p, false);
      expect_exact_within_limits(p, r, PulseTiming{}, m, what);
      // the limits are reached, in physical units at this clock
      EXPECT_GT(m.v, 0.999 * r.v_cruise) << what;
      EXPECT_GT(m.a, 0.99 * r.a_max) << what;
      EXPECT_GT(m.j, 0.99 * r.j_max) << what;
      EXPECT_NEAR(double(p.total_clocks) / hz, p.duration_s, 1e-12) << what;
    }
  }
}

TEST(ModelClockRate, RandomMovesExactOnTheModelEveryClockAt20And25And50MHz) {
  for (double hz : kClocks) {
    const scurve::Clock c{hz};
    const uint64_t seed = 7000 + uint64_t(hz / 1e6);
    std::mt19937_64 g(seed);
    auto lu = [&](double lo, double hi) {
      return std::exp(std::uniform_real_distribution<double>(std::log(lo), std::log(hi))(g));
    };
    int stepped = 0, fast = 0;
    for (int i = 0; i < 120; ++i) {
      PulseTiming t;
      t.high = uint16_t(1 + g() % 100);
      t.low = uint16_t(1 + g() % 100);
      const double v_lim = scurve::step_rate_limit(to_host(t), c);
      MoveRequest r;
      r.distance = int64_t(std::llround(lu(1, 50000))) * (g() % 2 ? 1 : -1);
      r.v_cruise = lu(10, v_lim);
      r.v_start = g() % 3 ? 0.0 : lu(1, v_lim);
      r.v_end = g() % 3 ? 0.0 : lu(1, v_lim);
      r.a_max = lu(1e3, 1e8);
      r.j_max = lu(1e5, 1e11);
      r.kind = g() % 6 ? ProfileKind::SCurve : ProfileKind::Trapezoid;
      r.adjust_end_speed = true;
      const PlanResult res = plan_move(r, t, c);
      const std::string what = "seed " + std::to_string(seed) + " move " + std::to_string(i);
      if (const auto* e = std::get_if<PlanError>(&res)) {
        ASSERT_NE(e->parameter, "internal") << what << ": " << e->message;
        continue;
      }
      const Plan& p = std::get<Plan>(res);
      const bool per_clock = p.total_clocks <= 4000000;
      (per_clock ? stepped : fast)++;
      expect_exact_within_limits(p, r, t, run_on_model(p, per_clock), what);
    }
    EXPECT_GT(stepped, 30) << hz;
  }
}
