// Paper 002's corner (scurve::search_corner): the searched shape lies in the
// paper's admissible set and beats the symmetric one, the lines planned with
// it end exactly on their integer targets clock by clock (the executor's
// recurrence of line_checks.h), the search repeats itself for a seed, the
// servo model matches its closed form, and bad requests name the field.
// The search runs with a small budget here; the full one is in the docs.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "line_checks.h"
#include "scurve/corner_search.h"
#include "scurve/line_planner.h"

using namespace scurve;

namespace {

constexpr int kTestBudget = 120;
constexpr double kPi = 3.14159265358979323846;

CornerRequest small_search(uint64_t seed = 1) {
  CornerRequest r;
  r.seed = seed;
  r.budget = kTestBudget;
  return r;
}

CornerSearchResult search_or_fail(const CornerRequest& r) {
  CornerSearchOutcome s = search_corner(r);
  if (const Error* e = std::get_if<Error>(&s)) {
    ADD_FAILURE() << e->parameter << ": " << e->message;
    return {};
  }
  return std::get<CornerSearchResult>(std::move(s));
}

// The paper's case searched once for the tests that need a searched shape.
const CornerSearchResult& searched() {
  static const CornerSearchResult result = search_or_fail(small_search());
  return result;
}

// Runs one line's rows clock by clock on both axes from its start fractions
// and checks the steps, rest at the end and the distance from the line;
// returns the end positions (LSB, from the line's integer start).
std::vector<i128> run_line_per_clock(const LinePlan& p, bool carried, const std::string& what) {
  const size_t n = p.axes.size();
  test::StraightLine line;
  line.lead = p.lead;
  std::vector<i128> start(n);
  std::vector<const std::vector<Segment>*> rows(n);
  for (size_t i = 0; i < n; ++i) {
    const Plan& a = p.axes[i];
    start[i] = i128(a.pos_frac0);
    rows[i] = &a.segments;
    const long double f = (long double)start[i] / (long double)kOne;
    line.anchor.push_back(carried ? f : 0.5L);
    line.direction.push_back(carried ? (long double)a.distance + 0.5L - f : (long double)a.distance);
  }
  test::AxesState state(start);
  const double deviation = test::run_rows_per_clock(rows, 0, p.axes[0].segments.size(), state, line);
  EXPECT_LT(deviation, 0.01) << what;
  const i128 one = i128(kOne);
  const auto floor_div = [&](i128 x) { return x >= 0 ? x / one : -((-x + one - 1) / one); };
  for (size_t i = 0; i < n; ++i) {
    const Plan& a = p.axes[i];
    EXPECT_EQ(int64_t(floor_div(state.pos[i]) - floor_div(start[i])), a.distance) << what << " axis " << i;
    EXPECT_EQ(state.vel[i], 0) << what << " axis " << i << ": not at rest";
    EXPECT_EQ(state.acc[i], 0) << what << " axis " << i;
    const TableReport rep = run_table(a.segments, a.pos_frac0, a.distance < 0 ? -1 : 1);
    EXPECT_EQ(rep.steps, a.distance) << what << " axis " << i;
    EXPECT_GE(rep.min_signed_vel, 0) << what << " axis " << i << ": reverses";
  }
  return state.pos;
}

std::optional<Error> error_of(const CornerRequest& r) {
  const CornerEvaluation e = evaluate_corner(r, CornerShape{{0.1, 0.1, 0.1, 0.1}, {0.1, 0.1, 0.1, 0.1}});
  if (const Error* err = std::get_if<Error>(&e)) return *err;
  return std::nullopt;
}

}  // namespace

TEST(CornerSearch, SearchedShapeLiesInTheAdmissibleSetAndBeatsTheSymmetricOne) {
  const CornerSearchResult& s = searched();
  ASSERT_GT(s.generations, 0);
  EXPECT_LE(s.evaluations, kTestBudget);
  const ShapeTimes* times[2] = {&s.best.times.first, &s.best.times.second};
  const std::array<double, 4>* jerks[2] = {&s.best.first_jerks, &s.best.second_jerks};
  for (int line = 0; line < 2; ++line) {
    const ShapeLimits& lim = s.limits[line];
    EXPECT_TRUE(lim.contains(*times[line])) << "line " << line;
    const ShapeTimes lo = lim.lower(), hi = lim.upper();
    const ShapeTimes& t = *times[line];
    for (int k = 0; k < 4; ++k) {
      EXPECT_GE(t[k], lo[k] * (1 - 1e-9)) << "line " << line << " time " << k;
      EXPECT_LE(t[k], hi[k] * (1 + 1e-9)) << "line " << line << " time " << k;
      EXPECT_GT((*jerks[line])[k], 0) << "line " << line << " jerk " << k;
      EXPECT_LE((*jerks[line])[k], lim.jerk) << "line " << line << " jerk " << k;
    }
    // The constraints one by one (paper 002 section 2): peak acceleration
    // 2 V / (T1 + T2) <= A, the jerks <= J, the transitions' travel <= L.
    EXPECT_LE(2 * lim.feed / (t[0] + t[1]), lim.accel * (1 + 1e-9));
    EXPECT_LE(2 * lim.feed / (t[2] + t[3]), lim.accel * (1 + 1e-9));
    EXPECT_LE(lim.feed * (t[0] + 2 * t[1]) / 3 + lim.feed * (2 * t[2] + t[3]) / 3, lim.length * (1 + 1e-9));
  }
  // The symmetric shape is the fastest symmetric one (0.1 s each with the
  // paper's data) and on the set's boundary.
  for (double t : s.symmetric.times.first) EXPECT_NEAR(t, 0.1, 1e-12);
  EXPECT_TRUE(s.limits[0].contains(s.symmetric.times.first));
  EXPECT_LE(s.best.score.fitness, s.symmetric.score.fitness);
  // Not merely equal: the search finds a far better shape even on this budget.
  EXPECT_LT(s.best.score.fitness, 0.1 * s.symmetric.score.fitness);
  EXPECT_GT(s.best.score.duration, s.symmetric.score.duration);
  // The reported fitness is the paper's formula of the reported errors.
  const CornerScore& b = s.best.score;
  EXPECT_DOUBLE_EQ(b.fitness, 10000 * (0.8 * b.contour_error + 0.2 * b.corner_error));
  ASSERT_EQ(s.best_fitness_by_generation.size(), size_t(s.generations));
  for (size_t g = 1; g < s.best_fitness_by_generation.size(); ++g) {
    EXPECT_LE(s.best_fitness_by_generation[g], s.best_fitness_by_generation[g - 1]);
  }
}

TEST(CornerSearch, EveryAxisEndsExactlyOnItsIntegerTargetWithTheSearchedJerks) {
  const CornerRequest r = small_search();
  const CornerPlanResult p = plan_corner(r, searched().best.times);
  ASSERT_TRUE(std::holds_alternative<CornerPlan>(p)) << std::get<Error>(p).message;
  const CornerPlan& plan = std::get<CornerPlan>(p);
  EXPECT_EQ(plan.distances[0], (std::array<int64_t, 2>{7071, 7071}));
  EXPECT_EQ(plan.distances[1], (std::array<int64_t, 2>{-7071, 7071}));
  const std::vector<i128> corner = run_line_per_clock(plan.lines[0], false, "to the corner");
  // The second line continues the row stream from the fractions the first ended with.
  for (size_t i = 0; i < 2; ++i) {
    const i128 one = i128(kOne);
    EXPECT_EQ(i128(plan.lines[1].axes[i].pos_frac0), ((corner[i] % one) + one) % one) << "axis " << i;
  }
  run_line_per_clock(plan.lines[1], true, "from the corner");
  // The asymmetric shape is really in the rows: the lead's peak jerk is the
  // largest of the shape's (its share of it), well below the symmetric J.
  const Plan& lead = plan.lines[0].axes[plan.lines[0].lead];
  double shape_peak = 0;
  for (double j : searched().best.first_jerks) shape_peak = std::max(shape_peak, j);
  EXPECT_NEAR(lead.peak_jerk, shape_peak * r.pulses_per_metre / std::sqrt(2.0), 1e-3 * lead.peak_jerk);
}

TEST(CornerSearch, SymmetricJerksGiveTheDefaultRowsByteForByte) {
  LineRequest r;
  r.distances = {7071, 7071};
  r.v_path = 1e4;
  r.a_path = 1e5;
  r.j_path = 1e6;
  const LineResult plain = plan_line(Planner{}, r, PulseTiming{});
  r.jerks = std::array<double, 4>{1e6, 1e6, 1e6, 1e6};
  const LineResult shaped = plan_line(Planner{}, r, PulseTiming{});
  ASSERT_TRUE(std::holds_alternative<LinePlan>(plain) && std::holds_alternative<LinePlan>(shaped));
  for (size_t i = 0; i < 2; ++i) {
    const Plan& a = std::get<LinePlan>(plain).axes[i];
    const Plan& b = std::get<LinePlan>(shaped).axes[i];
    EXPECT_EQ(a.segments, b.segments) << "axis " << i;
    EXPECT_EQ(a.pos_frac0, b.pos_frac0) << "axis " << i;
  }
}

TEST(CornerSearch, ServoModelMatchesTheClosedFormOvershoot) {
  // An ideal second-order loop at damping 1/sqrt(2) overshoots a stop ended
  // by jerk J by J exp(-pi/4) / wn^3; the two axes are alike, so the servo
  // leaves the path only there (the corner and the end).
  const CornerSearchResult& s = searched();
  const double wn = 2 * kPi * 100;
  const double overshoot = 10 * std::exp(-kPi / 4) / (wn * wn * wn);
  EXPECT_NEAR(s.symmetric.score.corner_error, overshoot, 1e-3 * overshoot);
  EXPECT_NEAR(s.symmetric.score.contour_error_max, overshoot, 1e-3 * overshoot);
  EXPECT_LT(s.symmetric.score.closest_to_corner, 1e-12);
  EXPECT_NEAR(s.symmetric.score.duration, 2.4, 1e-3);
  EXPECT_LT(s.symmetric.score.dwell, 1e-4);
}

TEST(CornerSearch, SearchIsDeterministicForASeed) {
  CornerRequest r = small_search(7);
  r.budget = 40;
  const CornerSearchResult a = search_or_fail(r);
  const CornerSearchResult b = search_or_fail(r);
  EXPECT_EQ(a.best.times.first, b.best.times.first);
  EXPECT_EQ(a.best.times.second, b.best.times.second);
  EXPECT_EQ(a.best.score.fitness, b.best.score.fitness);
  EXPECT_EQ(a.best_fitness_by_generation, b.best_fitness_by_generation);
  r.seed = 8;
  const CornerSearchResult c = search_or_fail(r);
  EXPECT_NE(a.best.times.first, c.best.times.first);
}

TEST(CornerSearch, BadRequestsNameTheFieldTheValueAndTheBound) {
  EXPECT_FALSE(error_of(CornerRequest{}).has_value());
  const auto expect_field = [](const CornerRequest& r, const char* field, const char* text) {
    const std::optional<Error> e = error_of(r);
    ASSERT_TRUE(e.has_value()) << field;
    EXPECT_EQ(e->parameter, field) << e->message;
    EXPECT_NE(e->message.find(text), std::string::npos) << e->message;
  };
  CornerRequest r;
  r.line_length = 0;
  expect_field(r, "line_length", "line_length=0");
  r = {};
  r.line_length = 0.01;  // shorter than the two fastest transitions (0.02 m)
  expect_field(r, "line_length", "admissible set is empty");
  r = {};
  r.feed = NAN;
  expect_field(r, "feed", "feed=nan");
  r = {};
  r.accel = -1;
  expect_field(r, "accel", "accel=-1");
  r = {};
  r.jerk = 0;
  expect_field(r, "jerk", "jerk=0");
  r = {};
  r.pulses_per_metre = 0;
  expect_field(r, "pulses_per_metre", "pulses_per_metre=0");
  r = {};
  r.first_angle_deg = INFINITY;
  expect_field(r, "first_angle_deg", "first_angle_deg=inf");
  r = {};
  r.servo_y.bandwidth_hz = 0;
  expect_field(r, "servo_y.bandwidth_hz", "servo_y.bandwidth_hz=0");
  r = {};
  r.servo_x.damping = -0.5;
  expect_field(r, "servo_x.damping", "servo_x.damping=-0.5");
  r = {};
  r.stop_tolerance = 0;
  expect_field(r, "stop_tolerance", "stop_tolerance=0");
  r = {};
  r.sample_period = 1e-3;  // coarser than 1/20 of the 100 Hz loop's period
  expect_field(r, "sample_period", "sample_period=0.001");
  r = {};
  r.budget = 0;
  const CornerSearchOutcome s = search_corner(r);
  ASSERT_TRUE(std::holds_alternative<Error>(s));
  EXPECT_EQ(std::get<Error>(s).parameter, "budget");

  // A shape outside the admissible set: the paper's printed second line
  // (its acceleration alone would travel 0.127 m of the 0.1 m line).
  const CornerEvaluation paper = evaluate_corner(CornerRequest{}, CornerShape{{0.3191, 0.1397, 0.0228, 1.0217},
                                                                              {2.9328, 0.4348, 0.7037, 0.5424}});
  ASSERT_TRUE(std::holds_alternative<Error>(paper));
  EXPECT_EQ(std::get<Error>(paper).parameter, "times");
  EXPECT_NE(std::get<Error>(paper).message.find("times.second="), std::string::npos) << std::get<Error>(paper).message;
}

TEST(CornerSearch, LineJerksAreCheckedWhereTheLineIsChecked) {
  const auto error_of_jerks = [](std::array<double, 4> jerks) {
    LineRequest r;
    r.distances = {7071, 7071};
    r.v_path = 1e4;
    r.a_path = 1e5;
    r.j_path = 1e6;
    r.jerks = jerks;
    const LineResult p = plan_line(Planner{}, r, PulseTiming{});
    const Error* e = std::get_if<Error>(&p);
    return e ? *e : Error{"", ""};
  };
  const Error above = error_of_jerks({1e6, 1e6, 2e6, 1e6});
  EXPECT_EQ(above.parameter, "jerks");
  EXPECT_NE(above.message.find("jerks[2] (Te1)=2000000"), std::string::npos) << above.message;
  EXPECT_NE(above.message.find("j_path=1000000"), std::string::npos) << above.message;
  EXPECT_EQ(error_of_jerks({1e6, NAN, 1e6, 1e6}).parameter, "jerks");
  EXPECT_EQ(error_of_jerks({1e6, 1e6, 1e6, 0}).parameter, "jerks");
  // Below the planner's jerk range once scaled to the lead's share: the
  // lead's error, named as the path field.
  const Error low = error_of_jerks({1, 1e6, 1e6, 1e6});
  EXPECT_EQ(low.parameter, "jerks");
  EXPECT_NE(low.message.find("lead axis 0"), std::string::npos) << low.message;
  EXPECT_EQ(error_of_jerks({2e5, 5e5, 1e6, 3e4}).parameter, "");
}
