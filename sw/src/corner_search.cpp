#include "scurve/corner_search.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace scurve {

namespace {

constexpr double kPi = 3.14159265358979323846;
// Boundary points (the symmetric shape sits on the acceleration and jerk
// bounds) are inside: the constraints hold to this relative rounding.
constexpr double kBoundarySlack = 1e-12;
// The paper's fitness weights and multiplier.
constexpr double kFitnessScale = 10000, kContourWeight = 0.8, kCornerWeight = 0.2;
// The search: the paper's genetic algorithm.
constexpr int kGenes = 8, kGeneBits = 10, kChromosomeBits = kGenes * kGeneBits;
constexpr int kPopulation = 8, kKept = 4;
constexpr double kMutationRate = 0.05;
constexpr uint32_t kGeneMax = (1u << kGeneBits) - 1;
// Tries for an admissible random individual, crossover or mutation before
// giving up on it (a thin admissible set).
constexpr int kInitTries = 200000, kOffspringTries = 20;

// One transition's geometry in its two times (x weighs 1 and y 2 in its
// travel, V (x + 2 y) / 3): x is Ts1 or Te2, y is Ts2 or Te1.
struct PairGeometry {
  double t_acc = 0;   // x + y >= t_acc (acceleration)
  double k_jerk = 0;  // x (x + y) >= k_jerk and y (x + y) >= k_jerk (jerk)
  double t_min = 0;   // the shortest transition
  double w_min = 0;   // the least weighted travel x + 2 y
  double budget = 0;  // the weighted travel this transition may use, the other at its least
};

PairGeometry pair_geometry(const ShapeLimits& s) {
  PairGeometry g;
  g.t_acc = 2 * s.feed / s.accel;
  g.k_jerk = 2 * s.feed / s.jerk;
  // x, y >= k / T need T >= sqrt(2 k); w = T + y >= T + k / T grows for such T.
  g.t_min = std::max(g.t_acc, std::sqrt(2 * g.k_jerk));
  g.w_min = g.t_min + g.k_jerk / g.t_min;
  g.budget = 3 * s.length / s.feed - g.w_min;
  return g;
}

// Ranges of x and y over {x + y = T in [t_min, t_max], x, y >= k / T, x + 2 y <= budget}.
struct PairRanges {
  double x_lo = 0, x_hi = 0, y_lo = 0, y_hi = 0;
};

PairRanges pair_ranges(const PairGeometry& g) {
  const double b = g.budget, k = g.k_jerk;
  PairRanges r;
  if (b < g.w_min) return r;
  const double t_max = (b + std::sqrt(std::max(0.0, b * b - 4 * k))) / 2;  // T + k / T = budget
  const double t_cross = (b + std::sqrt(b * b + 8 * k)) / 4;               // k / T = 2 T - budget
  const double t_star = std::clamp(t_cross, g.t_min, t_max);
  r.x_lo = std::max(k / t_star, 2 * t_star - b);
  r.x_hi = t_max - k / t_max;
  r.y_lo = k / t_max;
  r.y_hi = std::min(t_star - k / t_star, b - t_star);
  return r;
}

bool at_least(double value, double bound) { return value >= bound * (1 - kBoundarySlack); }

std::optional<Error> check_finite_positive(const std::string& name, double v, const char* unit) {
  if (std::isfinite(v) && v > 0) return std::nullopt;
  return Error{name, fmt::format("{}={}: needs a finite number > 0 {}", name, v, unit)};
}

// ---- the servo model ---------------------------------------------------------------

using Mat4 = std::array<std::array<double, 4>, 4>;

Mat4 mat_mul(const Mat4& a, const Mat4& b) {
  Mat4 c{};
  for (int i = 0; i < 4; ++i) {
    for (int k = 0; k < 4; ++k) {
      for (int j = 0; j < 4; ++j) c[i][j] += a[i][k] * b[k][j];
    }
  }
  return c;
}

// exp(m) by scaling and squaring with a Taylor series (small, well-scaled m).
Mat4 mat_exp(Mat4 m) {
  double norm = 0;
  for (const auto& row : m) {
    double s = 0;
    for (double v : row) s += std::fabs(v);
    norm = std::max(norm, s);
  }
  int squarings = 0;
  while (norm > 0.5) {
    norm /= 2;
    ++squarings;
  }
  for (auto& row : m) {
    for (double& v : row) v = std::ldexp(v, -squarings);
  }
  Mat4 sum{}, term{};
  for (int i = 0; i < 4; ++i) sum[i][i] = term[i][i] = 1;
  for (int n = 1; n <= 24; ++n) {
    term = mat_mul(term, m);
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) {
        term[i][j] /= n;
        sum[i][j] += term[i][j];
      }
    }
  }
  for (int s = 0; s < squarings; ++s) sum = mat_mul(sum, sum);
  return sum;
}

// One axis's loop discretised exactly for a reference that is linear
// between samples (first-order hold). State: the offset of the position from
// the last reference sample, and the velocity; the offset form keeps the
// tiny errors apart from the position's magnitude.
class ServoAxis {
 public:
  ServoAxis(const AxisServoModel& m, double h) : h_(h) {
    // -3 dB bandwidth of wn^2 / (s^2 + 2 zeta wn s + wn^2) in units of wn.
    const double z2 = m.damping * m.damping;
    const double ratio = std::sqrt(1 - 2 * z2 + std::sqrt(4 * z2 * z2 - 4 * z2 + 2));
    wn_ = 2 * kPi * m.bandwidth_hz / ratio;
    decay_rate_ = m.damping * wn_;
    // States (y, y', r, r'), r' constant over a step.
    Mat4 a{};
    a[0][1] = 1;
    a[1][0] = -wn_ * wn_;
    a[1][1] = -2 * m.damping * wn_;
    a[1][2] = wn_ * wn_;
    a[2][3] = 1;
    for (auto& row : a) {
      for (double& v : row) v *= h;
    }
    const Mat4 e = mat_exp(a);
    phi_ = {e[0][0], e[0][1], e[1][0], e[1][1]};
    ramp_ = {e[0][3], e[1][3]};
  }

  void reset(double ref) {
    ref_ = ref;
    offset_ = 0;
    vel_ = 0;
  }

  // Advances one step to the reference sample `ref`; returns the position.
  double step(double ref) {
    const double slope = (ref - ref_) / h_;
    // Unit static gain: phi00 + gamma0 = 1 and phi10 + gamma1 = 0.
    const double offset = phi_[0] * offset_ + phi_[1] * vel_ + ramp_[0] * slope - (ref - ref_);
    vel_ = phi_[2] * offset_ + phi_[3] * vel_ + ramp_[1] * slope;
    offset_ = offset;
    ref_ = ref;
    return ref + offset_;
  }

  double error() const { return -offset_; }  // reference - position
  double position() const { return ref_ + offset_; }
  double decay_rate() const { return decay_rate_; }

 private:
  double h_ = 0, wn_ = 0, decay_rate_ = 0;
  std::array<double, 4> phi_{};
  std::array<double, 2> ramp_{};
  double ref_ = 0, offset_ = 0, vel_ = 0;
};

// One axis's reference over one line, in pulses at any clock: the rows'
// closed form (the executor's position at that clock, with its fraction).
class AxisReference {
 public:
  AxisReference(const Plan& p, i128 start_lsb) {
    i128 pos = start_lsb;
    uint64_t clock = 0;
    for (const Segment& s : p.segments) {
      rows_.push_back(Row{clock, s.clocks, double(pos) / kTwoPowFrac, double(s.vel0) / kTwoPowFrac,
                          double(s.acc0) / kTwoPowFrac, double(s.jerk) / kTwoPowFrac});
      pos += pos_gain(s.vel0, s.acc0, s.jerk, s.clocks);
      clock += s.clocks;
    }
    end_lsb_ = pos;
    end_ = double(pos) / kTwoPowFrac;
    clocks_ = clock;
  }

  // Position (pulses) at `clock` from the line's start; calls with
  // non-decreasing clocks walk the rows once.
  double at(uint64_t clock) {
    if (clock >= clocks_) return end_;
    while (clock >= rows_[cursor_].start + rows_[cursor_].clocks) ++cursor_;
    const Row& r = rows_[cursor_];
    const double c = double(clock - r.start);
    return r.p0 + c * r.v0 + c * (c - 1) / 2 * r.a0 + c * (c - 1) * (c - 2) / 6 * r.j;
  }
  i128 end_lsb() const { return end_lsb_; }
  double end() const { return end_; }

 private:
  struct Row {
    uint64_t start = 0, clocks = 0;
    double p0 = 0, v0 = 0, a0 = 0, j = 0;
  };
  std::vector<Row> rows_;
  size_t cursor_ = 0;
  uint64_t clocks_ = 0;
  i128 end_lsb_ = 0;
  double end_ = 0;
};

struct Point {
  double x = 0, y = 0;
};

double distance_to_segment(Point p, Point a, Point b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

std::optional<Error> check_request(const CornerRequest& r) {
  if (auto e = check_finite_positive("line_length", r.line_length, "m")) return e;
  if (!std::isfinite(r.first_angle_deg)) {
    return Error{"first_angle_deg", fmt::format("first_angle_deg={}: needs a finite angle", r.first_angle_deg)};
  }
  if (!std::isfinite(r.second_angle_deg)) {
    return Error{"second_angle_deg", fmt::format("second_angle_deg={}: needs a finite angle", r.second_angle_deg)};
  }
  if (auto e = check_finite_positive("feed", r.feed, "m/s")) return e;
  if (auto e = check_finite_positive("accel", r.accel, "m/s^2")) return e;
  if (auto e = check_finite_positive("jerk", r.jerk, "m/s^3")) return e;
  if (auto e = check_finite_positive("pulses_per_metre", r.pulses_per_metre, "pulses/m")) return e;
  for (const auto& [name, servo] : {std::pair{"servo_x", r.servo_x}, std::pair{"servo_y", r.servo_y}}) {
    if (auto e = check_finite_positive(std::string(name) + ".bandwidth_hz", servo.bandwidth_hz, "Hz")) return e;
    if (!(std::isfinite(servo.damping) && servo.damping > 0 && servo.damping <= 10)) {
      const std::string field = std::string(name) + ".damping";
      return Error{field, fmt::format("{}={}: needs a damping ratio > 0 and <= 10", field, servo.damping)};
    }
  }
  if (auto e = check_finite_positive("stop_tolerance", r.stop_tolerance, "m")) return e;
  // At least one clock, and at least 20 samples per period of the faster loop.
  const double clock_s = 1 / Clock::kDefaultHz;
  const double max_period = 1 / (20 * std::max(r.servo_x.bandwidth_hz, r.servo_y.bandwidth_hz));
  if (!(std::isfinite(r.sample_period) && r.sample_period >= clock_s && r.sample_period <= max_period)) {
    return Error{"sample_period", fmt::format("sample_period={} s: needs {} s (one clock) to {} s (1/20 of the "
                                              "fastest servo's period)", r.sample_period, clock_s, max_period)};
  }
  if (r.budget < 1 || r.budget > 1000000) {
    return Error{"budget", fmt::format("budget={}: needs 1 to 1000000 fitness evaluations", r.budget)};
  }
  return std::nullopt;
}

// A line's distances in pulses (rounded) and its integer length in metres.
struct LineGeometry {
  std::array<int64_t, 2> distances{};
  double length = 0;
};

std::variant<LineGeometry, Error> line_geometry(const CornerRequest& r, double angle_deg, const char* field) {
  const double a = angle_deg * kPi / 180;
  const double pulses = r.line_length * r.pulses_per_metre;
  const double max_pulses = double(PlannerLimits::kMaxDistance);
  if (pulses > max_pulses) {
    return Error{"line_length", fmt::format("line_length={} m: {} pulses at {} pulses/m, needs <= {}",
                                            r.line_length, pulses, r.pulses_per_metre, max_pulses)};
  }
  LineGeometry g;
  g.distances = {int64_t(std::llround(pulses * std::cos(a))), int64_t(std::llround(pulses * std::sin(a)))};
  if (g.distances[0] == 0 && g.distances[1] == 0) {
    return Error{"line_length", fmt::format("line_length={} m: less than a pulse along {}={} at {} pulses/m",
                                            r.line_length, field, angle_deg, r.pulses_per_metre)};
  }
  g.length = std::hypot(double(g.distances[0]), double(g.distances[1])) / r.pulses_per_metre;
  return g;
}

std::variant<std::array<LineGeometry, 2>, Error> corner_geometry(const CornerRequest& r) {
  if (auto e = check_request(r)) return *e;
  std::array<LineGeometry, 2> lines;
  const double angles[2] = {r.first_angle_deg, r.second_angle_deg};
  const char* fields[2] = {"first_angle_deg", "second_angle_deg"};
  for (int i = 0; i < 2; ++i) {
    auto g = line_geometry(r, angles[i], fields[i]);
    if (const Error* e = std::get_if<Error>(&g)) return *e;
    lines[i] = std::get<LineGeometry>(g);
    // Paper eq. 14: the set is empty unless the line holds the two fastest
    // transitions.
    const ShapeLimits s{r.feed, r.accel, r.jerk, lines[i].length};
    const PairGeometry pg = pair_geometry(s);
    const double shortest = 2 * r.feed * pg.w_min / 3;
    if (lines[i].length < shortest) {
      return Error{"line_length", fmt::format("line_length={} m ({} m in whole pulses): paper 002's admissible set "
                                              "is empty, needs >= {} m for feed {} m/s, accel {} m/s^2, jerk {} "
                                              "m/s^3", r.line_length, lines[i].length, shortest, r.feed, r.accel,
                                              r.jerk)};
    }
  }
  return lines;
}

std::optional<Error> check_shape(const ShapeLimits& s, const ShapeTimes& t, const char* line) {
  for (size_t k = 0; k < 4; ++k) {
    if (!(std::isfinite(t[k]) && t[k] > 0)) {
      return Error{"times", fmt::format("times.{}[{}]={} s: needs a finite time > 0", line, k, t[k])};
    }
  }
  if (!s.contains(t)) {
    return Error{"times", fmt::format("times.{}=({}, {}, {}, {}) s: outside paper 002's admissible set (feed {} "
                                      "m/s, accel {} m/s^2, jerk {} m/s^3, length {} m)", line, t[0], t[1], t[2],
                                      t[3], s.feed, s.accel, s.jerk, s.length)};
  }
  return std::nullopt;
}

LineRequest line_request(const CornerRequest& r, const LineGeometry& g, const ShapeLimits& s,
                         const ShapeTimes& t) {
  LineRequest lr;
  lr.distances = {g.distances[0], g.distances[1]};
  lr.v_path = r.feed * r.pulses_per_metre;
  lr.a_path = r.accel * r.pulses_per_metre;
  lr.j_path = r.jerk * r.pulses_per_metre;
  std::array<double, 4> j = s.jerks(t);
  for (double& v : j) v = std::min(v * r.pulses_per_metre, lr.j_path);
  lr.jerks = j;
  return lr;
}

CornerPlanResult plan_checked(const CornerRequest& r, const std::array<LineGeometry, 2>& geo,
                              const CornerShape& shape) {
  CornerPlan out;
  const ShapeTimes* times[2] = {&shape.first, &shape.second};
  const char* names[2] = {"first", "second"};
  const Planner planner;
  for (int i = 0; i < 2; ++i) {
    out.distances[i] = geo[i].distances;
    out.limits[i] = ShapeLimits{r.feed, r.accel, r.jerk, geo[i].length};
    if (auto e = check_shape(out.limits[i], *times[i], names[i])) return *e;
    LineRequest lr = line_request(r, geo[i], out.limits[i], *times[i]);
    if (i == 1) {
      // Continues the first line's row stream: its end fractions.
      for (const Plan& a : out.lines[0].axes) lr.start_fracs.push_back(a.end_state.frac);
    }
    LineResult p = plan_line(planner, lr, PulseTiming{});
    if (const Error* e = std::get_if<Error>(&p)) {
      return Error{e->parameter, fmt::format("{} line: {}", names[i], e->message)};
    }
    out.lines[i] = std::get<LinePlan>(std::move(p));
  }
  return out;
}

// The servo run over both lines with the exact stop at the corner.
CornerScore simulate(const CornerRequest& r, const CornerPlan& plan, const CornerShape& shape) {
  const double hz = plan.lines[0].axes[0].clock.hz;
  const uint64_t step_clocks = std::max<uint64_t>(1, uint64_t(std::llround(r.sample_period * hz)));
  const double h = double(step_clocks) / hz;
  const double to_m = 1 / r.pulses_per_metre;
  std::array<ServoAxis, 2> servo{ServoAxis(r.servo_x, h), ServoAxis(r.servo_y, h)};
  // A second line starts from where the first ended (whole pulses + fraction).
  std::vector<AxisReference> first, second;
  for (int a = 0; a < 2; ++a) first.emplace_back(plan.lines[0].axes[a], i128(plan.lines[0].axes[a].pos_frac0));
  for (int a = 0; a < 2; ++a) {
    const i128 end = first[a].end_lsb();
    const i128 one = i128(kOne);
    const i128 whole = (end >= 0 ? end / one : -((-end + one - 1) / one)) * one;
    second.emplace_back(plan.lines[1].axes[a], whole + i128(plan.lines[1].axes[a].pos_frac0));
  }
  // The path: the reference's own start, corner and end (the corner is the
  // first line's end, mid-pulse on each axis), relative to the start.
  const double x0 = first[0].at(0), y0 = first[1].at(0);
  const Point start{0, 0};
  const Point corner{(first[0].end() - x0) * to_m, (first[1].end() - y0) * to_m};
  const Point end{(second[0].end() - x0) * to_m, (second[1].end() - y0) * to_m};
  servo[0].reset(0);
  servo[1].reset(0);

  const uint64_t line1_clocks = plan.lines[0].total_clocks, line2_clocks = plan.lines[1].total_clocks;
  // After the last reference the run goes on until the slower loop's
  // transients have decayed to e^-10, to see the overshoot at the end.
  const double settle = 10 / std::min(servo[0].decay_rate(), servo[1].decay_rate());
  const uint64_t settle_clocks = uint64_t(std::ceil(settle * hz));
  // The corner's transitions: the first line's deceleration and the
  // second's acceleration (the shape's times), around the stop.
  const double decel1 = shape.first[2] + shape.first[3], accel2 = shape.second[0] + shape.second[1];
  const uint64_t zone_begin = line1_clocks - std::min<uint64_t>(line1_clocks, uint64_t(decel1 * hz));

  CornerScore score;
  score.closest_to_corner = std::hypot(corner.x, corner.y);
  double contour_sum = 0;
  uint64_t samples = 0;
  Point prev = start;
  enum class Stage { kFirst, kCornerStop, kSecond, kEndStop, kSettle } stage = Stage::kFirst;
  uint64_t second_start = 0, zone_end = 0, settle_end = 0;
  const auto within_tolerance = [&] {
    return std::fabs(servo[0].error()) < r.stop_tolerance && std::fabs(servo[1].error()) < r.stop_tolerance;
  };
  for (uint64_t clock = step_clocks;; clock += step_clocks) {
    double ref[2];
    if (stage == Stage::kFirst || stage == Stage::kCornerStop) {
      for (int a = 0; a < 2; ++a) ref[a] = (first[a].at(clock) - (a == 0 ? x0 : y0)) * to_m;
    } else {
      for (int a = 0; a < 2; ++a) ref[a] = (second[a].at(clock - second_start) - (a == 0 ? x0 : y0)) * to_m;
    }
    const Point p{servo[0].step(ref[0]), servo[1].step(ref[1])};
    const double contour = std::min(distance_to_segment(p, start, corner), distance_to_segment(p, corner, end));
    contour_sum += contour;
    ++samples;
    score.contour_error_max = std::max(score.contour_error_max, contour);
    if (clock >= zone_begin && (stage <= Stage::kCornerStop || clock <= zone_end)) {
      score.corner_error = std::max(score.corner_error, contour);
    }
    score.closest_to_corner = std::min(score.closest_to_corner, distance_to_segment(corner, prev, p));
    prev = p;
    // Block change: the first line's reference is done and both axes are
    // within the tolerance ("exact stop fine"); the second starts next sample.
    if (stage == Stage::kFirst && clock >= line1_clocks) {
      stage = Stage::kCornerStop;
    }
    if (stage == Stage::kCornerStop && within_tolerance()) {
      stage = Stage::kSecond;
      second_start = clock;
      score.dwell = double(clock - line1_clocks) / hz;
      zone_end = clock + uint64_t(std::ceil((accel2 + settle) * hz));
      continue;
    }
    if (stage == Stage::kSecond && clock >= second_start + line2_clocks) stage = Stage::kEndStop;
    if (stage == Stage::kEndStop && within_tolerance()) {
      stage = Stage::kSettle;
      score.duration = double(clock) / hz;
      settle_end = clock + settle_clocks;
    }
    if (stage == Stage::kSettle && clock >= settle_end) break;
  }
  score.contour_error = contour_sum / double(samples);
  score.fitness = kFitnessScale * (kContourWeight * score.contour_error + kCornerWeight * score.corner_error);
  return score;
}

CornerEvaluation evaluate_checked(const CornerRequest& r, const std::array<LineGeometry, 2>& geo,
                                  const CornerShape& shape) {
  CornerPlanResult p = plan_checked(r, geo, shape);
  if (const Error* e = std::get_if<Error>(&p)) return *e;
  const CornerPlan& plan = std::get<CornerPlan>(p);
  CornerCandidate c;
  c.times = shape;
  c.first_jerks = plan.limits[0].jerks(shape.first);
  c.second_jerks = plan.limits[1].jerks(shape.second);
  c.score = simulate(r, plan, shape);
  return c;
}

// ---- the search ---------------------------------------------------------------------

using Genes = std::array<double, kGenes>;

CornerShape shape_of(const Genes& g) {
  CornerShape s;
  for (int k = 0; k < 4; ++k) {
    s.first[k] = g[k];
    s.second[k] = g[k + 4];
  }
  return s;
}

Genes genes_of(const CornerShape& s) {
  Genes g{};
  for (int k = 0; k < 4; ++k) {
    g[k] = s.first[k];
    g[k + 4] = s.second[k];
  }
  return g;
}

struct Individual {
  std::array<uint32_t, kGenes> code{};
  Genes value{};
  double fitness = std::numeric_limits<double>::infinity();
  bool evaluated = false;
};

// The search's state: gene ranges, random numbers (the engine's raw output
// only, so the sequence is the same with every standard library), the
// evaluation count and the best point so far.
class Search {
 public:
  Search(const CornerRequest& r, const std::array<LineGeometry, 2>& geo, const std::array<ShapeLimits, 2>& limits)
      : request_(r), geo_(geo), limits_(limits), random_(r.seed) {
    for (int line = 0; line < 2; ++line) {
      const ShapeTimes lo = limits[line].lower(), hi = limits[line].upper();
      for (int k = 0; k < 4; ++k) {
        lo_[line * 4 + k] = lo[k];
        hi_[line * 4 + k] = hi[k];
      }
    }
  }

  bool admissible(const Genes& g) const {
    const CornerShape s = shape_of(g);
    return limits_[0].contains(s.first) && limits_[1].contains(s.second);
  }

  // The fitness of a point (+inf if its lines cannot be planned).
  double evaluate(const Genes& g) {
    ++evaluations_;
    const CornerEvaluation e = evaluate_checked(request_, geo_, shape_of(g));
    if (const CornerCandidate* c = std::get_if<CornerCandidate>(&e)) {
      if (c->score.fitness < best_.score.fitness || !have_best_) {
        best_ = *c;
        have_best_ = true;
      }
      return c->score.fitness;
    }
    return std::numeric_limits<double>::infinity();
  }

  void evaluate(Individual& ind) {
    if (ind.evaluated) return;
    ind.fitness = evaluate(ind.value);
    ind.evaluated = true;
  }

  double decode(int gene, uint32_t code) const {
    return lo_[gene] + (hi_[gene] - lo_[gene]) * double(code) / double(kGeneMax);
  }

  uint32_t nearest_code(int gene, double v) const {
    const double span = hi_[gene] - lo_[gene];
    const double c = span > 0 ? std::round((v - lo_[gene]) / span * kGeneMax) : 0;
    return uint32_t(std::clamp(c, 0.0, double(kGeneMax)));
  }

  void decode(Individual& ind) const {
    for (int g = 0; g < kGenes; ++g) ind.value[g] = decode(g, ind.code[g]);
    ind.evaluated = false;
  }

  bool bit(const Individual& ind, int b) const { return (ind.code[b / kGeneBits] >> (b % kGeneBits)) & 1u; }
  void flip(Individual& ind, int b) const { ind.code[b / kGeneBits] ^= 1u << (b % kGeneBits); }

  double uniform01() { return double(random_() >> 11) * 0x1.0p-53; }
  int below(int n) { return int(random_() % uint64_t(n)); }

  // The paper's genetic algorithm, then a compass search.
  std::optional<Error> run(const Genes& symmetric, CornerSearchResult& out) {
    const int ga_budget = std::max(1, request_.budget * 3 / 4);
    std::vector<Individual> pop;
    Individual sym;
    for (int g = 0; g < kGenes; ++g) sym.code[g] = nearest_code(g, symmetric[g]);
    sym.value = symmetric;  // exact, kept while it is the best
    sym.fitness = best_.score.fitness;  // evaluated before the search
    sym.evaluated = true;
    pop.push_back(sym);
    for (int tries = 0; int(pop.size()) < kPopulation; ++tries) {
      if (tries == kInitTries) {
        return Error{"line_length", fmt::format("no admissible random shape in {} tries: the admissible set is too "
                                                "thin for a population", kInitTries)};
      }
      Individual ind;
      for (int g = 0; g < kGenes; ++g) ind.code[g] = uint32_t(below(int(kGeneMax) + 1));
      decode(ind);
      if (admissible(ind.value)) pop.push_back(ind);
    }
    for (Individual& ind : pop) {
      if (evaluations_ < request_.budget) evaluate(ind);
    }
    const auto by_fitness = [](const Individual& a, const Individual& b) { return a.fitness < b.fitness; };
    std::stable_sort(pop.begin(), pop.end(), by_fitness);
    // Rank weights (N_keep - n + 1) / sum: 4, 3, 2, 1 tenths.
    std::array<double, kKept> cumulative{};
    double total = 0;
    for (int n = 0; n < kKept; ++n) total += kKept - n;
    for (int n = 0, acc = 0; n < kKept; ++n) {
      acc += kKept - n;
      cumulative[n] = acc / total;
    }
    const auto pick = [&] {
      const double u = uniform01();
      for (int n = 0; n < kKept; ++n) {
        if (u < cumulative[n]) return n;
      }
      return kKept - 1;
    };
    // A generation evaluates at most its changed individuals: all but the best.
    while (evaluations_ + kPopulation - 1 <= ga_budget) {
      // Selection: the best half survives; two pairs of parents make four children.
      pop.resize(kKept);
      for (int pair = 0; pair < 2; ++pair) {
        const int a = pick();
        int b = pick();
        for (int t = 0; t < 8 && b == a; ++t) b = pick();
        Individual child_a = pop[a], child_b = pop[b];
        for (int t = 0; t < kOffspringTries; ++t) {
          const int cut = 1 + below(kChromosomeBits - 1);
          Individual ca = pop[a], cb = pop[b];
          for (int bit_index = cut; bit_index < kChromosomeBits; ++bit_index) {
            if (bit(ca, bit_index) != bit(cb, bit_index)) {
              flip(ca, bit_index);
              flip(cb, bit_index);
            }
          }
          decode(ca);
          decode(cb);
          if (admissible(ca.value) && admissible(cb.value)) {
            child_a = ca;
            child_b = cb;
            break;
          }
        }
        pop.push_back(child_a);
        pop.push_back(child_b);
      }
      // Mutation: rate * (N_pop - 1) * N_bits flips, never on the best; a
      // flip that leaves the admissible set is thrown out.
      const int flips = int(std::lround(kMutationRate * (kPopulation - 1) * kChromosomeBits));
      for (int m = 0; m < flips; ++m) {
        Individual& ind = pop[1 + below(kPopulation - 1)];
        const int b = below(kChromosomeBits);
        Individual mutated = ind;
        flip(mutated, b);
        decode(mutated);
        if (admissible(mutated.value)) ind = mutated;
      }
      for (Individual& ind : pop) evaluate(ind);
      std::stable_sort(pop.begin(), pop.end(), by_fitness);
      ++out.generations;
      out.best_fitness_by_generation.push_back(best_.score.fitness);
    }
    compass(genes_of(best_.times));
    return std::nullopt;
  }

  // Compass search from `x`: each time +-step, and each pair of a line's
  // times moved against each other at equal travel (one up, the other down
  // by the same V (w_i t_i) / 3), since the best shapes sit on the travel
  // bound (constraint 1), which single-time moves cannot follow; the first
  // improvement is taken, the steps halve after a sweep without one. Points
  // outside the admissible set are not evaluated.
  void compass(Genes x) {
    double fx = best_.score.fitness;
    Genes step{};
    for (int g = 0; g < kGenes; ++g) step[g] = (hi_[g] - lo_[g]) / 32;
    constexpr double kFinestStep = 1e-7;  // s: two clocks, below what the rows resolve
    constexpr std::array<double, 4> kTravelWeight{1, 2, 2, 1};  // of Ts1, Ts2, Te1, Te2
    std::vector<Genes> directions;  // unit moves of the primary time
    for (int g = 0; g < kGenes; ++g) {
      Genes d{};
      d[g] = 1;
      directions.push_back(d);
      const int line = g / 4;
      for (int other = line * 4; other < line * 4 + 4; ++other) {
        if (other == g) continue;
        Genes slide{};
        slide[g] = 1;
        slide[other] = -kTravelWeight[g % 4] / kTravelWeight[other % 4];
        directions.push_back(slide);
      }
    }
    while (evaluations_ < request_.budget) {
      bool improved = false, any_step = false;
      for (const Genes& d : directions) {
        if (evaluations_ >= request_.budget) break;
        int primary = 0;
        while (d[primary] != 1) ++primary;
        if (step[primary] < kFinestStep) continue;
        any_step = true;
        for (const double sign : {1.0, -1.0}) {
          Genes y = x;
          for (int g = 0; g < kGenes; ++g) y[g] += sign * step[primary] * d[g];
          if (!admissible(y) || evaluations_ >= request_.budget) continue;
          const double fy = evaluate(y);
          if (fy < fx) {
            x = y;
            fx = fy;
            improved = true;
            break;
          }
        }
      }
      if (!any_step) break;
      if (!improved) {
        for (double& s : step) s /= 2;
      }
    }
  }

  int evaluations() const { return evaluations_; }
  const CornerCandidate& best() const { return best_; }
  void set_best(const CornerCandidate& c) {
    best_ = c;
    have_best_ = true;
    evaluations_ = std::max(evaluations_, 1);
  }

 private:
  const CornerRequest& request_;
  const std::array<LineGeometry, 2>& geo_;
  std::array<ShapeLimits, 2> limits_;
  std::mt19937_64 random_;
  Genes lo_{}, hi_{};
  int evaluations_ = 0;
  CornerCandidate best_;
  bool have_best_ = false;
};

}  // namespace

bool ShapeLimits::contains(const ShapeTimes& t) const {
  for (double v : t) {
    if (!(std::isfinite(v) && v > 0)) return false;
  }
  const PairGeometry g = pair_geometry(*this);
  const auto transition_ok = [&](double x, double y) {
    const double total = x + y;
    return at_least(total, g.t_acc) && at_least(x * total, g.k_jerk) && at_least(y * total, g.k_jerk);
  };
  const double travel = feed * (t[0] + 2 * t[1]) / 3 + feed * (2 * t[2] + t[3]) / 3;
  return transition_ok(t[0], t[1]) && transition_ok(t[3], t[2]) && travel <= length * (1 + kBoundarySlack);
}

ShapeTimes ShapeLimits::lower() const {
  const PairRanges r = pair_ranges(pair_geometry(*this));
  return {r.x_lo, r.y_lo, r.y_lo, r.x_lo};
}

ShapeTimes ShapeLimits::upper() const {
  const PairRanges r = pair_ranges(pair_geometry(*this));
  return {r.x_hi, r.y_hi, r.y_hi, r.x_hi};
}

std::array<double, 4> ShapeLimits::jerks(const ShapeTimes& t) const {
  const double acc = t[0] + t[1], dec = t[2] + t[3];
  return {std::min(jerk, 2 * feed / (t[0] * acc)), std::min(jerk, 2 * feed / (t[1] * acc)),
          std::min(jerk, 2 * feed / (t[2] * dec)), std::min(jerk, 2 * feed / (t[3] * dec))};
}

CornerPlanResult plan_corner(const CornerRequest& request, const CornerShape& shape) {
  auto geo = corner_geometry(request);
  if (const Error* e = std::get_if<Error>(&geo)) return *e;
  return plan_checked(request, std::get<std::array<LineGeometry, 2>>(geo), shape);
}

CornerEvaluation evaluate_corner(const CornerRequest& request, const CornerShape& shape) {
  auto geo = corner_geometry(request);
  if (const Error* e = std::get_if<Error>(&geo)) return *e;
  return evaluate_checked(request, std::get<std::array<LineGeometry, 2>>(geo), shape);
}

CornerSearchOutcome search_corner(const CornerRequest& request) {
  auto geo_or = corner_geometry(request);
  if (const Error* e = std::get_if<Error>(&geo_or)) return *e;
  const auto& geo = std::get<std::array<LineGeometry, 2>>(geo_or);
  CornerSearchResult out;
  for (int i = 0; i < 2; ++i) out.limits[i] = ShapeLimits{request.feed, request.accel, request.jerk, geo[i].length};
  // The fastest symmetric shape: each time at the larger of the acceleration
  // and jerk bounds.
  const double tau = std::max(request.feed / request.accel, std::sqrt(request.feed / request.jerk));
  const CornerShape symmetric{{tau, tau, tau, tau}, {tau, tau, tau, tau}};
  CornerEvaluation sym = evaluate_checked(request, geo, symmetric);
  if (const Error* e = std::get_if<Error>(&sym)) return *e;
  out.symmetric = std::get<CornerCandidate>(sym);

  Search search(request, geo, out.limits);
  search.set_best(out.symmetric);  // one evaluation of the budget
  if (auto e = search.run(genes_of(symmetric), out)) return *e;
  out.best = search.best();
  out.evaluations = search.evaluations();
  return out;
}

}  // namespace scurve
