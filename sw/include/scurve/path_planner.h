// Coordinated paths on 1 to 4 axes: a sequence of straight lines, each one
// plan_line() from the previous target, as one row stream. At the corners
// (PathRequest::junction) either every axis comes to rest (paper 002's
// "exact stop", the default) or consecutive lines blend: the next line
// starts while the previous one still decelerates, the two superposed, so
// the tool cuts the corner within a tolerance instead of stopping.
//
//   scurve::PathRequest r;
//   r.axes = 2;
//   r.moves = {{{1200, 8000}, 6000, 1}, {{7200, 8000}, 6000, 2}};  // absolute pulses, pulses/s, source line
//   r.limits = {10000, 1e5, 1e6};                                  // path speed cap, acceleration, jerk
//   r.junction = scurve::Junction::kBlend;                         // optional: cut corners ...
//   r.tolerance = 20;                                              // ... within 20 pulses of the corner
//   auto p = scurve::plan_path(scurve::Planner{}, r, scurve::PulseTiming{});
//   // std::get<PathPlan>(p).axes[i].rows: axis i's rows of the whole path
//
// The executor keeps its position fraction from row to row in a stream, so
// each line starts from the fraction the previous one ended with
// (LineRequest::start_fracs): the concatenated rows, run from the path's
// POS_FRAC0, end every line exactly on its integer target.
//
// Blend by superposition: the lines are planned exactly as for exact stops
// (the same plan_line calls and fractions), then line k+1 starts
// PlannedPathMove::blend_clocks before line k ends. The executor's recurrence is linear
// and exact in integers, so rows whose jerk, start velocity and start
// acceleration are the sums of the two lines' (split where either line's
// rows change) run exactly as the sum of the two motions: every axis still
// ends the path exactly where the exact-stop rows end (the corners between
// are cut, not reached). An overlap covers
// only line k's deceleration and line k+1's acceleration; per junction it
// is the largest the search finds (bisection over clocks, every accepted
// overlap checked) with, over every clock of the overlap,
//   * the reference within `tolerance` pulses of the corner point (where
//     the exact-stop rows rest), and
//   * on every axis |v| <= its axis_limits v_max and the step-rate limit,
//     |a| <= limits.a and its a_max, |jerk| <= its j_max (where given),
//     each plus one LSB per line for the lines' own rounding, and the speed
//     along the path <= the larger of the two lines' speed caps (relative
//     1e-6).
// Along the path the acceleration and jerk of a blend are sums of two
// profiles each within limits.a / limits.j: at most twice those (the jerk
// 2 cos(turn / 2) j where both lines are at full jerk), the acceleration
// also at most sqrt(axes) limits.a by the per-axis bound above
// (docs/multiaxis.md, "Blended junctions").
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <variant>
#include <vector>

#include "scurve/line_planner.h"
#include "scurve/reg_encode.h"

namespace scurve {

struct PathMove {
  std::vector<int64_t> target_pulses;  // absolute position per axis, pulses
  double feed = 0;                     // requested speed along the path, pulses/s (> 0)
  int source_line = 0;                 // where it came from: a file's line (1-based) or a point index
  // Paper 002's asymmetric S-shape of this line along the path, pulses/s^3
  // (Ts1, Ts2, Te1, Te2: LineRequest::jerks), each finite, > 0 and <=
  // PathLimits::j. Unset: PathLimits::j throughout (the symmetric shape).
  std::optional<std::array<double, 4>> jerks = std::nullopt;
};

// Limits along the path (Euclidean, in pulses of the axes).
struct PathLimits {
  double v = 0;  // speed cap, pulses/s: a move runs at min(its feed, v)
  double a = 0;  // acceleration, pulses/s^2
  double j = 0;  // jerk, pulses/s^3
};

// How consecutive lines join (PathRequest::junction).
enum class Junction {
  kExactStop,  // every axis at rest at every corner
  kBlend,      // the next line starts while the previous one decelerates, within PathRequest::tolerance
};

// How messages name a move's source_line: "line 7" (a G-code file) or
// "point 7" (the points of a JSON path file).
enum class PathSource { kLine, kPoint };

struct PathRequest {
  size_t axes = 0;                      // 1 to LineRequest::kMaxAxes
  std::vector<int64_t> start;           // pulses per axis; empty: all 0
  std::vector<PathMove> moves;
  PathLimits limits;
  std::vector<AxisLimits> axis_limits;  // empty, or one per axis (pulses units, 0: unbounded)
  PathSource source = PathSource::kLine;
  Junction junction = Junction::kExactStop;
  // kBlend: the largest distance (pulses) of the reference from a corner
  // point while it blends; finite and > 0 (not used with kExactStop).
  double tolerance = 0;
  // Positions (start and targets) within +-kMaxPosition pulses: the range
  // a single move covers, and the executor's 32-bit reference position.
  static constexpr int64_t kMaxPosition = PlannerLimits::kMaxDistance;
};

struct PlannedPathMove {
  size_t move = 0;         // index in PathRequest::moves
  int source_line = 0;
  double v_path = 0;       // the speed cap it was planned with: min(feed, limits.v), pulses/s
  std::vector<int64_t> start, target;  // pulses per axis
  // The line; line.axes[i].pos_frac0 is axis i's position fraction where
  // the move starts (the one the previous move left).
  LinePlan line;
  size_t first_row = 0;     // its first row in PathAxisRows::rows (the same on every axis)
  uint64_t start_clock = 0; // clocks from the path's start
  // Its last row, the one flagged MOVE_END: where its line's rows end (in a
  // blend the next move's first rows share clocks with its last ones).
  size_t end_row = 0;
  uint64_t end_clock = 0;   // start_clock + line.total_clocks: where end_row ends
  // Each axis's exact reference position (LSB, 2^FracBits per pulse; the
  // integer part is what BOUNDARY_POS latches) at end_clock: at rest in its
  // target's pulse with exact stops; in a blend the target's exact-stop
  // position plus what the next move has covered by then.
  std::vector<i128> end_position;
  // The junction at its start: the clocks it overlaps the previous move
  // (0: an exact stop there, and always for the first move) and the
  // largest distance of the reference from that corner point over every
  // clock of the overlap (pulses; an upper bound, within 1e-4 tolerance of
  // the per-clock maximum unless its search hit its evaluation budget; 0
  // without overlap).
  uint64_t blend_clocks = 0;
  double corner_deviation = 0;
};

struct SkippedMove {
  size_t move = 0;  // a move to where the axes already are: no rows
  int source_line = 0;
};

struct PathAxisRows {
  std::vector<Segment> rows;     // every planned move's rows back to back
  std::vector<RowFlags> flags;   // per row: MOVE_END on each move's last (end_row), STREAM_END on the path's last
  u128 pos_frac0 = 0;            // POS_FRAC0 the stream starts from (mid-pulse)
};

struct PathPlan {
  std::vector<PlannedPathMove> moves;  // in order, zero-length moves left out
  std::vector<SkippedMove> skipped;
  std::vector<PathAxisRows> axes;      // one per axis; row k lasts the same clocks on every axis
  uint64_t total_clocks = 0;
  double duration_s = 0;
  double path_length = 0;              // pulses, the lines' lengths summed
  double max_line_deviation = 0;       // pulses, the largest of the lines' (LinePlan::max_line_deviation)
  uint64_t exact_stop_clocks = 0;      // the lines' clocks summed: total_clocks with exact stops
  double max_corner_deviation = 0;     // pulses, the largest of the moves' corner_deviation
};
using PathResult = std::variant<PathPlan, Error>;

// Checked before any planning: "axes" (1 to 4), "start" (count, range),
// "moves" (none), "limits.v" / "limits.a" / "limits.j" (finite, > 0),
// "axis_limits" (count; values as plan_line), "junction" (a known value),
// "tolerance" (kBlend: finite, > 0), and per move "target_pulses"
// (count, range), "feed" (finite, > 0) and "jerks" (each finite, > 0,
// <= limits.j), named by the move's index and source: "move 3 (line 7):
// feed=0: ...". A line plan_line() refuses gives its Error with the same
// prefix.
PathResult plan_path(const Planner& planner, const PathRequest& request, const PulseTiming& timing);

}  // namespace scurve
