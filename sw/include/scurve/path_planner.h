// Coordinated paths on 1 to 4 axes: a sequence of straight lines, each one
// plan_line() from the previous target, joined by exact stops (every axis
// at rest at every corner, paper 002's "exact stop"), as one row stream.
//
//   scurve::PathRequest r;
//   r.axes = 2;
//   r.moves = {{{1200, 8000}, 6000, 1}, {{7200, 8000}, 6000, 2}};  // absolute pulses, pulses/s, source line
//   r.limits = {10000, 1e5, 1e6};                                  // path speed cap, acceleration, jerk
//   auto p = scurve::plan_path(scurve::Planner{}, r, scurve::PulseTiming{});
//   // std::get<PathPlan>(p).axes[i].rows: axis i's rows of every move back to back
//
// The executor keeps its position fraction from row to row in a stream, so
// each line starts from the fraction the previous one ended with
// (LineRequest::start_fracs): the concatenated rows, run from the path's
// POS_FRAC0, end every line exactly on its integer target.
#pragma once

#include <cstddef>
#include <cstdint>
#include <variant>
#include <vector>

#include "scurve/line_planner.h"
#include "scurve/reg_encode.h"

namespace scurve {

struct PathMove {
  std::vector<int64_t> target_pulses;  // absolute position per axis, pulses
  double feed = 0;                     // requested speed along the path, pulses/s (> 0)
  int source_line = 0;                 // where it came from: a file's line (1-based) or a point index
};

// Limits along the path (Euclidean, in pulses of the axes).
struct PathLimits {
  double v = 0;  // speed cap, pulses/s: a move runs at min(its feed, v)
  double a = 0;  // acceleration, pulses/s^2
  double j = 0;  // jerk, pulses/s^3
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
};

struct SkippedMove {
  size_t move = 0;  // a move to where the axes already are: no rows
  int source_line = 0;
};

struct PathAxisRows {
  std::vector<Segment> rows;     // every planned move's rows back to back
  std::vector<RowFlags> flags;   // per row: MOVE_END on each move's last, STREAM_END on the path's last
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
};
using PathResult = std::variant<PathPlan, Error>;

// Checked before any planning: "axes" (1 to 4), "start" (count, range),
// "moves" (none), "limits.v" / "limits.a" / "limits.j" (finite, > 0),
// "axis_limits" (count; values as plan_line), and per move "target_pulses"
// (count, range) and "feed" (finite, > 0), named by the move's index and
// source: "move 3 (line 7): feed=0: ...". A line plan_line() refuses gives
// its Error with the same prefix.
PathResult plan_path(const Planner& planner, const PathRequest& request, const PulseTiming& timing);

}  // namespace scurve
