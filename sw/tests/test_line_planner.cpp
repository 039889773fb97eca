// Coordinated lines (scurve::plan_line): every axis's table re-run in closed
// form (run_table: steps, rest at the end, no reversal), the rows' clocks
// equal on every axis, the path limits honoured per axis, and the distance
// from the straight line measured clock by clock by an integration written
// here (the executor's recurrence, not the planner's closed forms).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "scurve/line_planner.h"

using namespace scurve;

namespace {

LinePlan plan_or_fail(const LineRequest& r) {
  const LineResult p = plan_line(Planner{}, r, PulseTiming{});
  if (const Error* e = std::get_if<Error>(&p)) {
    ADD_FAILURE() << e->parameter << ": " << e->message;
    return {};
  }
  return std::get<LinePlan>(p);
}

LineRequest line(std::vector<int64_t> d, double v = 40000, double a = 2e6, double j = 4e8) {
  LineRequest r;
  r.distances = std::move(d);
  r.v_path = v;
  r.a_path = a;
  r.j_path = j;
  return r;
}

// Every clock of every axis (pos += v; v += a; a += j), the axes' offsets
// from the line through half a pulse on each axis along the distances
// (pulses): the largest over the move.
double max_deviation_per_clock(const LinePlan& p) {
  const size_t n = p.axes.size();
  std::vector<long double> share(n);
  const long double lead = std::fabs((long double)p.axes[p.lead].distance);
  for (size_t i = 0; i < n; ++i) share[i] = std::fabs((long double)p.axes[i].distance) / lead;
  std::vector<i128> pos(n), vel(n, 0);
  std::vector<int64_t> acc(n, 0);
  for (size_t i = 0; i < n; ++i) pos[i] = i128(p.axes[i].pos_frac0);
  const long double one = (long double)kOne;
  // Magnitude form: the distance from the start, in the move's direction.
  const auto along = [&](size_t i) {
    const long double x = (long double)pos[i] / one;
    return p.axes[i].distance < 0 ? 1.0L - x : x;
  };
  const auto deviation = [&]() {
    long double sum = 0;
    for (size_t i = 0; i < n; ++i) {
      const long double e = (along(i) - 0.5L) - share[i] * (along(p.lead) - 0.5L);
      sum += e * e;
    }
    return double(std::sqrt(sum));
  };
  double worst = deviation();
  const size_t rows = p.axes[0].segments.size();
  for (size_t k = 0; k < rows; ++k) {
    for (uint64_t t = 0; t < p.axes[0].segments[k].clocks; ++t) {
      for (size_t i = 0; i < n; ++i) {
        pos[i] += vel[i];
        vel[i] += acc[i];
        acc[i] += p.axes[i].segments[k].jerk;
      }
      worst = std::max(worst, deviation());
    }
  }
  return worst;
}

// The checks of one line; `per_clock`: also the deviation clock by clock.
void expect_exact_line(const LineRequest& r, bool per_clock, const std::string& what) {
  const LinePlan p = plan_or_fail(r);
  ASSERT_EQ(p.axes.size(), r.distances.size()) << what;
  const Plan& lead = p.axes[p.lead];
  const double length = p.path_length;
  for (size_t i = 0; i < p.axes.size(); ++i) {
    const Plan& a = p.axes[i];
    ASSERT_EQ(a.segments.size(), lead.segments.size()) << what << " axis " << i;
    for (size_t k = 0; k < a.segments.size(); ++k) {
      ASSERT_EQ(a.segments[k].clocks, lead.segments[k].clocks) << what << " axis " << i << " row " << k;
    }
    const int dir = r.distances[i] < 0 ? -1 : 1;
    const TableReport rep = run_table(a.segments, a.pos_frac0, dir);
    EXPECT_TRUE(rep.ok) << what << " axis " << i << ": " << rep.error;
    EXPECT_EQ(rep.steps, r.distances[i]) << what << " axis " << i;
    EXPECT_GE(rep.min_signed_vel, 0) << what << " axis " << i << ": reverses";
    EXPECT_LT(a.pos_frac0, kOne) << what << " axis " << i;
    // The axis's share of the path limits, one LSB of rounding above it.
    const double share = std::fabs(double(r.distances[i])) / length;
    const Clock c{};
    EXPECT_LE(double(rep.peak_jerk), std::ceil(r.j_path * share * jerk_lsb_per_unit(c)) + 1) << what << " axis " << i;
    EXPECT_LE(double(rep.peak_acc), std::ceil(r.a_path * share * acc_lsb_per_unit(c)) + 1) << what << " axis " << i;
    EXPECT_LE(vel_to_phys(rep.peak_vel, c), r.v_path * share * (1 + 1e-9) + 1e-6) << what << " axis " << i;
  }
  EXPECT_LT(p.max_line_deviation, 0.01) << what;
  if (per_clock) {
    const double measured = max_deviation_per_clock(p);
    EXPECT_LT(measured, 0.01) << what;
    // The sampled report sees the same order of magnitude.
    EXPECT_LE(p.max_line_deviation, measured * (1 + 1e-6) + 1e-12) << what;
  }
}

}  // namespace

TEST(LinePlanner, TwoAxisLinesEndExactlyOnEveryAxisWithSharedRowClocksNearTheLine) {
  expect_exact_line(line({12000, 5000}), true, "12000, 5000");
  expect_exact_line(line({-3000, 7001}), true, "-3000, 7001");
  expect_exact_line(line({2000, -2000}), true, "45 degrees");
  expect_exact_line(line({1, 3}), true, "a pulse and three");
  expect_exact_line(line({0, -4000}), true, "one axis still");
}

TEST(LinePlanner, RandomLinesOnTwoToFourAxesEndExactlyOnEveryAxis) {
  std::mt19937_64 g(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int n = 0; n < 300; ++n) {
    const size_t axes = 2 + n % 3;
    std::vector<int64_t> d(axes);
    for (int64_t& x : d) {
      const double mag = std::pow(10.0, 6 * u(g));  // 1 to 1e6 pulses
      x = int64_t(mag) * ((g() & 1) ? 1 : -1);
    }
    const LineRequest r = line(d, 2000 + 60000 * u(g), 1e4 + 3e6 * u(g), 1e6 + 1e9 * u(g));
    const LinePlan p = plan_or_fail(r);
    if (p.axes.empty()) continue;
    std::string what = "line " + std::to_string(n) + ":";
    for (int64_t x : d) what += " " + std::to_string(x);
    expect_exact_line(r, p.total_clocks < 1'000'000, what);
  }
}

TEST(LinePlanner, AxisLimitsLowerThePathSoNoAxisPassesItsOwn) {
  LineRequest r = line({10000, 10000}, 50000, 2e6, 4e8);
  r.axis_limits = {AxisLimits{}, AxisLimits{20000, 5e5, 1e8}};
  const LinePlan p = plan_or_fail(r);
  ASSERT_EQ(p.axes.size(), 2u);
  const Plan& y = p.axes[1];
  EXPECT_LE(y.peak_velocity, 20000 * (1 + 1e-9));
  EXPECT_LE(y.peak_acceleration, 5e5 * (1 + 1e-6));
  EXPECT_LE(y.peak_jerk, 1e8 * (1 + 1e-6));
  // The other axis is held to the same path: equal shares, equal peaks.
  EXPECT_NEAR(p.axes[0].peak_velocity, y.peak_velocity, 1e-6 * y.peak_velocity);
}

TEST(LinePlanner, BadRequestsNameTheFieldTheValueAndTheBound) {
  const auto error_of = [](const LineRequest& r) {
    const LineResult p = plan_line(Planner{}, r, PulseTiming{});
    const Error* e = std::get_if<Error>(&p);
    return e ? *e : Error{"", ""};
  };
  EXPECT_EQ(error_of(line({})).parameter, "distances");
  EXPECT_EQ(error_of(line({1, 2, 3, 4, 5})).parameter, "distances");
  EXPECT_EQ(error_of(line({0, 0})).parameter, "distances");
  const Error far = error_of(line({int64_t(1) << 40, 1}));
  EXPECT_EQ(far.parameter, "distances");
  EXPECT_NE(far.message.find("distances[0]=1099511627776"), std::string::npos) << far.message;
  EXPECT_EQ(error_of(line({100, 100}, 0)).parameter, "v_path");
  EXPECT_EQ(error_of(line({100, 100}, 1000, NAN)).parameter, "a_path");
  EXPECT_EQ(error_of(line({100, 100}, 1000, 1e6, -1)).parameter, "j_path");
  LineRequest lim = line({100, 100});
  lim.axis_limits = {AxisLimits{}};
  EXPECT_EQ(error_of(lim).parameter, "axis_limits");
  lim.axis_limits = {AxisLimits{}, AxisLimits{-1, 0, 0}};
  const Error neg = error_of(lim);
  EXPECT_EQ(neg.parameter, "axis_limits");
  EXPECT_NE(neg.message.find("axis_limits[1].v_max=-1"), std::string::npos) << neg.message;
  // A path jerk whose lead share is below the planner's range: the lead's
  // error, as a path limit.
  const Error low = error_of(line({1000, 1000}, 1000, 1e4, 11));
  EXPECT_EQ(low.parameter, "j_path");
  EXPECT_NE(low.message.find("lead axis 0"), std::string::npos) << low.message;
}
