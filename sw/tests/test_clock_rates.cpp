// The clock rate is a run-time parameter: plans at 20, 25 and 50 MHz end on
// exactly the requested pulse and keep v, a, j within the limits in physical
// units at that clock; the same move takes the same time at every clock.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "paper_moves.h"
#include "random_moves.h"
#include "scurve/planner.h"

using namespace scurve;
using scurve::test::paper_group;

namespace {

constexpr double kClocks[] = {20e6, 25e6, 50e6};

// Re-executes the table in closed form and checks endpoint and limits.
void expect_exact_within_limits(const Plan& p, const MoveRequest& r, const PulseTiming& t, Clock c,
                                const std::string& what) {
  const int dir = r.distance < 0 ? -1 : 1;
  const TableReport rep = run_table(p.segments, p.pos_frac0, dir);
  ASSERT_TRUE(rep.ok) << what << ": " << rep.error;
  EXPECT_EQ(rep.steps, r.distance) << what;
  EXPECT_GE(rep.min_signed_vel, 0) << what << ": velocity reverses";
  const double tol = 1 + 1e-12;
  const double v_cap = std::min(std::max({r.v_cruise, r.v_start, p.v_end_used}), step_rate_limit(t, c));
  EXPECT_LE(vel_to_phys(rep.peak_vel, c), v_cap * tol) << what;
  EXPECT_LE(acc_to_phys(rep.peak_acc, c), r.a_max * tol) << what;
  if (r.kind == ProfileKind::SCurve) EXPECT_LE(jerk_to_phys(rep.peak_jerk, c), test::jerk_cap(r) * tol) << what;
  EXPECT_EQ(p.total_clocks, rep.clocks) << what;
  EXPECT_DOUBLE_EQ(p.duration_s, double(rep.clocks) / c.hz) << what;
  EXPECT_EQ(p.clock, c) << what;
}

}  // namespace

TEST(ClockRate, PaperGroupsExactAndWithinLimitsAtEachClock) {
  for (double hz : kClocks) {
    for (int g = 1; g <= 4; ++g) {
      const Clock c{hz};
      const MoveRequest r = paper_group(g);
      const PlanResult res = Planner(c).plan(r, PulseTiming{});
      ASSERT_TRUE(std::holds_alternative<Plan>(res)) << hz << " Hz group " << g << ": "
                                                     << std::get<Error>(res).message;
      expect_exact_within_limits(std::get<Plan>(res), r, PulseTiming{}, c,
                                 "group " + std::to_string(g) + " at " + std::to_string(hz) + " Hz");
    }
  }
}

TEST(ClockRate, SameMoveTakesTheSameTimeAndScaledClocks) {
  for (int g = 1; g <= 4; ++g) {
    const Plan p20 = std::get<Plan>(Planner(Clock{20e6}).plan(paper_group(g), PulseTiming{}));
    for (double hz : {25e6, 50e6}) {
      const Plan p = std::get<Plan>(Planner(Clock{hz}).plan(paper_group(g), PulseTiming{}));
      EXPECT_NEAR(p.duration_s, p20.duration_s, 2e-3) << "group " << g << " at " << hz;
      EXPECT_NEAR(double(p.total_clocks) / double(p20.total_clocks), hz / 20e6, 1e-4) << "group " << g;
      EXPECT_NEAR(p.peak_velocity, p20.peak_velocity, 1e-3 * p20.peak_velocity);
      EXPECT_NEAR(p.peak_acceleration, 500, 1.0);
    }
  }
}

TEST(ClockRate, TablesDifferBetweenClocks) {
  const Plan a = std::get<Plan>(Planner(Clock{20e6}).plan(paper_group(1), PulseTiming{}));
  const Plan b = std::get<Plan>(Planner(Clock{25e6}).plan(paper_group(1), PulseTiming{}));
  ASSERT_EQ(a.segments.size(), b.segments.size());
  EXPECT_NE(a.segments[0].clocks, b.segments[0].clocks);
  EXPECT_NE(a.segments[0].jerk, b.segments[0].jerk);
}

TEST(ClockRate, StepRateLimitScalesWithTheClock) {
  const PulseTiming t{};
  EXPECT_DOUBLE_EQ(step_rate_limit(t, Clock{20e6}), 200000.0);
  EXPECT_DOUBLE_EQ(step_rate_limit(t, Clock{25e6}), 250000.0);
  EXPECT_DOUBLE_EQ(step_rate_limit(t, Clock{50e6}), 500000.0);
  // 240000 pulses/s: above the limit at 20 MHz, accepted at 25 MHz.
  MoveRequest r = paper_group(1);
  r.distance = 1000000;
  r.v_cruise = 240000;
  r.a_max = 1e6;
  r.j_max = 1e9;
  const PlanResult at20 = Planner(Clock{20e6}).plan(r, t);
  ASSERT_TRUE(std::holds_alternative<Error>(at20));
  EXPECT_EQ(std::get<Error>(at20).parameter, "v_cruise");
  EXPECT_NE(std::get<Error>(at20).message.find("20 MHz"), std::string::npos) << std::get<Error>(at20).message;
  EXPECT_TRUE(std::holds_alternative<Plan>(Planner(Clock{25e6}).plan(r, t)));
}

TEST(ClockRate, RandomMovesExactAndWithinLimitsAtEachClock) {
  for (double hz : kClocks) {
    const Clock c{hz};
    std::mt19937_64 g(uint64_t(hz) ^ 0x5c0fe);
    int planned = 0;
    for (int i = 0; i < 400; ++i) {
      const test::RandomRequest rr = test::random_request(g, c);
      const PlanResult res = Planner(c).plan(rr.req, rr.timing);
      const std::string what = "seed " + std::to_string(uint64_t(hz) ^ 0x5c0fe) + " case " + std::to_string(i);
      if (const Error* e = std::get_if<Error>(&res)) {
        EXPECT_NE(e->parameter, "internal") << what << ": " << e->message;
        continue;
      }
      ++planned;
      expect_exact_within_limits(std::get<Plan>(res), rr.req, rr.timing, c, what);
    }
    EXPECT_GT(planned, 200) << hz;
  }
}

TEST(ClockRate, BadClockIsRejectedNamingTheParameterAndBound) {
  const double bad[] = {0, -20e6, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                        999e3, 2e9};
  for (double hz : bad) {
    const PlanResult r = Planner(Clock{hz}).plan(paper_group(1), PulseTiming{});
    ASSERT_TRUE(std::holds_alternative<Error>(r)) << hz;
    const Error& e = std::get<Error>(r);
    EXPECT_EQ(e.parameter, "clock_hz");
    EXPECT_EQ(e.message.rfind("clock_hz=", 0), 0u) << e.message;
    EXPECT_NE(e.message.find("1000000..1000000000 Hz"), std::string::npos) << e.message;
  }
  EXPECT_EQ(check_clock(Clock{25e6}), "");
}

TEST(ClockRate, AccelerationAndJerkBoundsFollowTheRegisterWidths) {
  // At 20 MHz the documented bounds hold unchanged.
  EXPECT_EQ(accel_range(Clock{20e6}).lo, PlannerLimits::kMinAccel);
  EXPECT_EQ(accel_range(Clock{20e6}).hi, PlannerLimits::kMaxAccel);
  EXPECT_EQ(jerk_range(Clock{20e6}).lo, PlannerLimits::kMinJerk);
  EXPECT_EQ(jerk_range(Clock{20e6}).hi, PlannerLimits::kMaxJerk);
  // At 1 MHz a jerk of 1e11 pulses/s^3 does not fit JerkW: refused by name.
  MoveRequest r = paper_group(1);
  r.j_max = 1e11;
  const PlanResult res = Planner(Clock{1e6}).plan(r, PulseTiming{});
  ASSERT_TRUE(std::holds_alternative<Error>(res));
  EXPECT_EQ(std::get<Error>(res).parameter, "j_max");
  EXPECT_NE(std::get<Error>(res).message.find("exceeds the limit"), std::string::npos);
}
