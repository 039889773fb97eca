// Coordinated lines (scurve::plan_line): every axis's table re-run in closed
// form (run_table: steps, rest at the end, no reversal), the rows' clocks
// equal on every axis, the path limits honoured per axis, and the distance
// from the straight line measured clock by clock by an integration written
// here (the executor's recurrence, not the planner's closed forms).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "line_checks.h"
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
// from the line (pulses): the largest over the move. A line on its own runs
// through half a pulse on each axis along the distances; from given start
// fractions, from the start point to the middle of the targets' pulses.
double max_deviation_per_clock(const LinePlan& p, bool from_start_fracs) {
  const size_t n = p.axes.size();
  test::StraightLine line;
  line.lead = p.lead;
  std::vector<i128> start(n);
  std::vector<const std::vector<Segment>*> rows(n);
  for (size_t i = 0; i < n; ++i) {
    const Plan& a = p.axes[i];
    start[i] = i128(a.pos_frac0);
    rows[i] = &a.segments;
    if (from_start_fracs) {
      const long double f = (long double)start[i] / (long double)kOne;
      line.anchor.push_back(f);
      line.direction.push_back(a.distance == 0 ? 0.0L : (long double)a.distance + 0.5L - f);
    } else {
      line.anchor.push_back(0.5L);
      line.direction.push_back((long double)a.distance);
    }
  }
  test::AxesState state(start);
  return test::run_rows_per_clock(rows, 0, p.axes[0].segments.size(), state, line);
}

// The checks of one line; `per_clock`: also the deviation clock by clock.
void expect_exact_line(const LineRequest& r, bool per_clock, const std::string& what) {
  const LinePlan p = plan_or_fail(r);
  ASSERT_EQ(p.axes.size(), r.distances.size()) << what;
  const Plan& lead = p.axes[p.lead];
  // Each axis's share of the path: of the distances, or from given start
  // fractions of the travels (from the fraction to the middle of the
  // target's pulse), which the rows' travels measure to a few 1e-6 pulse.
  const bool carried = !r.start_fracs.empty();
  std::vector<double> travel(p.axes.size());
  double travel_length = 0;
  for (size_t i = 0; i < p.axes.size(); ++i) {
    const Plan& a = p.axes[i];
    const TableReport rep = run_table(a.segments, a.pos_frac0, a.distance < 0 ? -1 : 1);
    travel[i] = std::fabs(double(rep.end_pos - i128(a.pos_frac0)) / kTwoPowFrac);
    travel_length += travel[i] * travel[i];
  }
  travel_length = std::sqrt(travel_length);
  const double slack = carried ? 1e-5 : 1e-9;
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
    if (carried) {
      EXPECT_EQ(a.pos_frac0, r.start_fracs[i]) << what << " axis " << i;
    }
    // The axis's share of the path limits, one LSB of rounding above it.
    const double share = carried ? travel[i] / travel_length : std::fabs(double(r.distances[i])) / length;
    const Clock c{};
    EXPECT_LE(double(rep.peak_jerk), std::ceil(r.j_path * share * (1 + slack) * jerk_lsb_per_unit(c)) + 1)
        << what << " axis " << i;
    EXPECT_LE(double(rep.peak_acc), std::ceil(r.a_path * share * (1 + slack) * acc_lsb_per_unit(c)) + 1)
        << what << " axis " << i;
    EXPECT_LE(vel_to_phys(rep.peak_vel, c), r.v_path * share * (1 + slack) + 1e-6) << what << " axis " << i;
  }
  EXPECT_LT(p.max_line_deviation, 0.01) << what;
  if (per_clock) {
    const double measured = max_deviation_per_clock(p, carried);
    EXPECT_LT(measured, 0.01) << what;
    // The sampled report sees the same order of magnitude.
    EXPECT_LE(p.max_line_deviation, measured * (1 + 1e-6) + (carried ? 1e-10 : 1e-12)) << what;
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

// A line that continues another in one row stream starts from the
// fractions the other left (plan_path): any fraction, both directions.
TEST(LinePlanner, LinesFromGivenStartFractionsEndExactlyNearMidPulse) {
  std::mt19937_64 g(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst_end_offset = 0;
  for (int n = 0; n < 200; ++n) {
    const size_t axes = 2 + n % 3;
    std::vector<int64_t> d(axes);
    for (int64_t& x : d) {
      const double mag = n % 4 == 0 ? std::floor(4 * u(g)) : std::pow(10.0, 5 * u(g));  // 0 to 3 pulses, or up to 1e5
      x = int64_t(mag) * ((g() & 1) ? 1 : -1);
    }
    if (std::all_of(d.begin(), d.end(), [](int64_t x) { return x == 0; })) d[0] = 1;
    LineRequest r = line(d, 2000 + 60000 * u(g), 1e4 + 3e6 * u(g), 1e6 + 1e9 * u(g));
    for (size_t i = 0; i < axes; ++i) r.start_fracs.push_back(u128(g()) << 16);  // anywhere in [0, 1) pulse
    const LinePlan p = plan_or_fail(r);
    if (p.axes.empty()) continue;
    std::string what = "line " + std::to_string(n) + ":";
    for (int64_t x : d) what += " " + std::to_string(x);
    expect_exact_line(r, p.total_clocks < 1'000'000, what);
    // A moving axis ends within its share of the lead's offset from mid-pulse.
    for (const Plan& a : p.axes) {
      if (a.distance == 0) continue;
      const double off = std::fabs(double(a.end_state.frac) / kTwoPowFrac - 0.5);
      worst_end_offset = std::max(worst_end_offset, off);
    }
  }
  EXPECT_LT(worst_end_offset, 0.5);
  std::printf("largest end offset from mid-pulse: %.3g pulse\n", worst_end_offset);
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
  LineRequest fr = line({100, 100});
  fr.start_fracs = {kOne / 2};
  EXPECT_EQ(error_of(fr).parameter, "start_fracs");
  fr.start_fracs = {kOne / 2, kOne};
  const Error whole = error_of(fr);
  EXPECT_EQ(whole.parameter, "start_fracs");
  EXPECT_NE(whole.message.find("start_fracs[1]="), std::string::npos) << whole.message;
  // A path jerk whose lead share is below the planner's range: the lead's
  // error, as a path limit.
  const Error low = error_of(line({1000, 1000}, 1000, 1e4, 11));
  EXPECT_EQ(low.parameter, "j_path");
  EXPECT_NE(low.message.find("lead axis 0"), std::string::npos) << low.message;
}
