// Coordinated straight lines on 1 to 4 axes: one S-curve along the path,
// rows of shared durations, each axis's rows the path profile scaled to its
// share, every axis ending exactly on its integer target.
//
//   scurve::LineRequest r;
//   r.distances = {12000, -5000};           // pulses per axis
//   r.v_path = 40000; r.a_path = 2e6; r.j_path = 4e8;
//   auto p = scurve::plan_line(scurve::Planner{}, r, scurve::PulseTiming{});
//   // std::get<LinePlan>(p).axes[i]: axis i's table; the same clocks row by row
//
// Construction: the axis with the longest travel (the lead) is planned by
// Planner::plan() with the path limits scaled to its share. Every other
// axis takes, at each of the lead's row boundaries, the lead's acceleration
// scaled to its share and rounded to the LSB, and reaches it exactly within
// the row by two jerks one LSB apart (the row split where they change, for
// all axes at once). The velocity left at the end (the rounding's, and
// plan()'s own: it ends a move within one clock of peak acceleration of
// rest) a short pulse within the axis's own peaks removes, each axis in
// turn, after the lead's last row; each axis's start fraction places its
// end in the middle of its target's pulse, as the lead's. The rows are rest
// to rest (exact stop at both ends of the line).
//
// From given start fractions (start_fracs: a line continuing another in one
// row stream) the lead is planned by Planner::plan_from() from its fraction,
// aimed mid-pulse, and every axis's share is its travel from its fraction to
// the middle of its target's pulse: the others then end within their
// share of the lead's offset from its aim, so the fractions stay near half a
// pulse from line to line instead of drifting.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <variant>
#include <vector>

#include "scurve/planner.h"

namespace scurve {

// An axis's own limits (pulses/s, /s^2, /s^3); 0 leaves one unbounded.
struct AxisLimits {
  double v_max = 0, a_max = 0, j_max = 0;
};

struct LineRequest {
  std::vector<int64_t> distances;  // pulses per axis, the sign the direction; 1 to kMaxAxes axes
  double v_path = 0;               // path speed (Euclidean, in pulses of the axes), pulses/s
  double a_path = 0;               // path acceleration, pulses/s^2
  double j_path = 0;               // path jerk, pulses/s^3
  // Paper 002's asymmetric S-shape along the path, pulses/s^3: the jerk
  // while |a| rises / falls when speeding up (Ts1, Ts2) and when slowing
  // down (Te1, Te2), each in (0, j_path]. The lead axis is planned with
  // them scaled to its share, as MoveRequest::jerks; an axis limit that
  // lowers the path jerk caps each of them. Unset: j_path throughout.
  std::optional<std::array<double, 4>> jerks;
  std::vector<AxisLimits> axis_limits;  // empty, or one per axis
  // Where each axis's executor position fraction is at the start (rest), in
  // [0, 2^FracBits): a line that continues another in one row stream, where
  // the fraction carries over (plan_path). Empty: a line on its own, each
  // axis's start fraction chosen so that it ends mid-pulse.
  std::vector<u128> start_fracs;
  static constexpr size_t kMaxAxes = 4;
};

struct LinePlan {
  std::vector<Plan> axes;       // one table per axis: the same row clocks
  size_t lead = 0;              // the axis planned by plan()
  uint64_t total_clocks = 0;
  double duration_s = 0;
  double path_length = 0;       // pulses
  // The largest distance of the reference from the straight line through
  // the axes' start and end points, over the row boundaries and 16 points
  // inside every row (pulses; a bound: each axis's offset from where the
  // lead's progress puts it on the line).
  double max_line_deviation = 0;
};
using LineResult = std::variant<LinePlan, Error>;

// Errors name the field and the bound: "distances" (count, range, all 0),
// "v_path" / "a_path" / "j_path", "jerks" (a value), "axis_limits" (count or a value),
// "start_fracs" (count or a value), and the lead's plan() errors with the
// path limits as they scaled.
LineResult plan_line(const Planner& planner, const LineRequest& request, const PulseTiming& timing);

}  // namespace scurve
