// Paper 002's cornering case: two straight lines on an X-Y table joined by
// an exact stop, each with its own asymmetric S-shape, the eight shape
// times searched for the paper's fitness
//   10000 * (0.8 * contour error + 0.2 * corner error)   (errors in m)
// over the paper's admissible set.
//
//   scurve::CornerRequest r;                 // the paper's case by default
//   auto s = scurve::search_corner(r);       // CornerSearchResult or Error
//   // std::get<CornerSearchResult>(s).best.times: Ts1, Ts2, Te1, Te2 per line
//
// A shape is given by times, as in the paper: Ts1 / Ts2 while |a| rises /
// falls when speeding up, Te1 / Te2 when slowing down. Each transition is a
// triangle of acceleration reaching the feed with no constant-acceleration
// part, so its jerks follow from its times (paper eq. 5):
//   Js1 = 2 V / (Ts1 (Ts1 + Ts2)),  Js2 = 2 V / (Ts2 (Ts1 + Ts2))   (Te alike)
// and plan_line() plans the line with those path jerks (LineRequest::jerks)
// and the acceleration limit; the admissible set keeps the triangle's peak
// within it, so the planned rows are the paper's shape.
//
// The errors are measured on a servo model of each axis driven by the
// planned reference (the executor's exact position, not the integer steps),
// because the reference itself is on the path and stops exactly on the
// corner: both errors are 0 by construction there. See docs/multiaxis.md,
// "Paper 002: asymmetric jerks", for the definitions and figures.
#pragma once

#include <array>
#include <cstdint>
#include <variant>
#include <vector>

#include "scurve/line_planner.h"
#include "scurve/planner.h"

namespace scurve {

// An axis's closed position loop as a second-order low-pass
//   y'' = wn^2 (r - y) - 2 zeta wn y'
// (no feed-forward, unit static gain), set by its -3 dB bandwidth.
struct AxisServoModel {
  double bandwidth_hz = 100;                    // paper 002: "about 100 Hz"
  double damping = 0.70710678118654752440;      // zeta; at 1/sqrt(2) wn equals the bandwidth
};

// One line's S-shape, in seconds: {Ts1, Ts2, Te1, Te2}.
using ShapeTimes = std::array<double, 4>;

struct CornerShape {
  ShapeTimes first{}, second{};  // the line to the corner, the line from it
};

struct CornerRequest {
  double line_length = 0.1;          // m, each line
  double first_angle_deg = 45;       // direction of the line to the corner
  double second_angle_deg = 135;     // direction of the line from the corner
  double feed = 0.1;                 // V_M, m/s (6000 mm/min)
  double accel = 1;                  // A_M, m/s^2
  double jerk = 10;                  // J_M, m/s^3
  double pulses_per_metre = 1e5;     // both axes (sw/examples/paths/paper002_corner.json: 100 per mm)
  AxisServoModel servo_x, servo_y;
  double stop_tolerance = 1e-5;      // m per axis: "exact stop fine" changes block once both are within
  double sample_period = 20e-6;      // s, the servo simulation's step (a whole number of clocks)
  uint64_t seed = 1;                 // the search's random numbers
  int budget = 2000;                 // fitness evaluations of the search
};

// Paper 002's admissible set for one line of length `length` (m), in the
// shape times (section 2, constraints 1 to 4):
//   (3) acceleration: Ts1 + Ts2 >= 2 V / A and Te1 + Te2 >= 2 V / A
//   (4) jerk: Ts1 (Ts1 + Ts2) >= 2 V / J, Ts2 (Ts1 + Ts2) >= 2 V / J, Te alike
//   (1) travel: V (Ts1 + 2 Ts2) / 3 + V (2 Te1 + Te2) / 3 <= length
//   (2) the feed is reached: implied, the cruise covers the rest of (1)
struct ShapeLimits {
  double feed = 0, accel = 0, jerk = 0, length = 0;  // V, A, J (SI), the line's length (m)
  bool contains(const ShapeTimes& t) const;
  // Each time's range over the set (the search's gene bounds).
  ShapeTimes lower() const;
  ShapeTimes upper() const;
  // The path jerks of a shape (m/s^3; paper eq. 5), each capped at `jerk`
  // (a shape on the jerk boundary computes it to within rounding).
  std::array<double, 4> jerks(const ShapeTimes& t) const;
};

struct CornerScore {
  double fitness = 0;            // 10000 * (0.8 * contour_error + 0.2 * corner_error)
  double contour_error = 0;      // m, time average of the servo's distance from the path
  double contour_error_max = 0;  // m, its largest value
  double corner_error = 0;       // m, its largest value in the corner's transitions
  double closest_to_corner = 0;  // m, how near the servo passes the corner point
  double duration = 0;           // s, start to the end of the second line's reference, dwell included
  double dwell = 0;              // s, the exact stop's wait at the corner
};

struct CornerCandidate {
  CornerShape times;
  std::array<double, 4> first_jerks{}, second_jerks{};  // path jerks, m/s^3
  CornerScore score;
};

// The two lines as planned: rows of the line to the corner (from the
// origin, each axis's own start fraction) and of the line from it (from
// the fractions the first ended with, as in one row stream).
struct CornerPlan {
  std::array<LinePlan, 2> lines;
  std::array<std::array<int64_t, 2>, 2> distances{};  // pulses per line and axis
  std::array<ShapeLimits, 2> limits;                  // each line's admissible set (its integer length)
};

struct CornerSearchResult {
  std::array<ShapeLimits, 2> limits;
  // The fastest symmetric shape in the set: every transition time
  // max(V / A, sqrt(V / J)) (with the paper's data, the planner's default
  // symmetric profile at j_path = J).
  CornerCandidate symmetric;
  CornerCandidate best;                         // <= symmetric's fitness
  int evaluations = 0;                          // fitness evaluations made
  int generations = 0;                          // of the genetic algorithm
  std::vector<double> best_fitness_by_generation;
};

using CornerPlanResult = std::variant<CornerPlan, Error>;
using CornerEvaluation = std::variant<CornerCandidate, Error>;
using CornerSearchOutcome = std::variant<CornerSearchResult, Error>;

// Errors name the request field ("line_length", "feed", "servo_y.bandwidth_hz",
// "budget", ...) with its value and bound; a shape outside the admissible
// set is refused naming "times" and the constraint.
CornerPlanResult plan_corner(const CornerRequest& request, const CornerShape& shape);
CornerEvaluation evaluate_corner(const CornerRequest& request, const CornerShape& shape);

// The search: the paper's genetic algorithm (8 individuals of 8 genes of 10
// bits over each time's range, the 4 best kept, rank-weighted parents,
// single-point crossover, 5 % bit mutation sparing the best, inadmissible
// offspring thrown out), its first population the symmetric shape and 7
// random admissible ones, for 3/4 of the budget; then a compass search from
// its best point for the rest (the 10-bit genes are coarse), moving one
// time or two of a line's times at equal travel (the best shapes lie on the
// travel bound). Deterministic for a seed.
CornerSearchOutcome search_corner(const CornerRequest& request);

}  // namespace scurve
