#include "scurve/path_planner.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

namespace scurve {

namespace {

std::string move_place(const PathRequest& r, size_t k) {
  return fmt::format("move {} ({} {})", k, r.source == PathSource::kLine ? "line" : "point",
                     r.moves[k].source_line);
}

std::optional<Error> check_position(const std::string& parameter, const std::string& place, int64_t p) {
  if (p >= -PathRequest::kMaxPosition && p <= PathRequest::kMaxPosition) return std::nullopt;
  return Error{parameter, fmt::format("{}={}: needs |position| <= {} pulses", place, p, PathRequest::kMaxPosition)};
}

std::optional<Error> check_limit(const char* name, double v, const char* unit) {
  if (std::isfinite(v) && v > 0) return std::nullopt;
  return Error{name, fmt::format("{}={}: needs a finite number > 0 {}", name, v, unit)};
}

std::optional<Error> check_request(const PathRequest& r) {
  const size_t n = r.axes;
  if (n == 0 || n > LineRequest::kMaxAxes) {
    return Error{"axes", fmt::format("axes={}: needs 1 to {}", n, LineRequest::kMaxAxes)};
  }
  if (!r.start.empty() && r.start.size() != n) {
    return Error{"start", fmt::format("start: {} values for {} axes", r.start.size(), n)};
  }
  for (size_t i = 0; i < r.start.size(); ++i) {
    if (auto e = check_position("start", fmt::format("start[{}]", i), r.start[i])) return e;
  }
  if (auto e = check_limit("limits.v", r.limits.v, "pulses/s")) return e;
  if (auto e = check_limit("limits.a", r.limits.a, "pulses/s^2")) return e;
  if (auto e = check_limit("limits.j", r.limits.j, "pulses/s^3")) return e;
  if (!r.axis_limits.empty() && r.axis_limits.size() != n) {
    return Error{"axis_limits", fmt::format("axis_limits: {} entries for {} axes, needs none or one per axis",
                                            r.axis_limits.size(), n)};
  }
  if (r.junction != Junction::kExactStop && r.junction != Junction::kBlend) {
    return Error{"junction", fmt::format("junction={}: needs kExactStop or kBlend", int(r.junction))};
  }
  if (r.junction == Junction::kBlend && (!std::isfinite(r.tolerance) || r.tolerance <= 0)) {
    return Error{"tolerance", fmt::format("tolerance={}: needs a finite number > 0 pulses for blended junctions",
                                          r.tolerance)};
  }
  if (r.moves.empty()) return Error{"moves", "moves: none, needs at least one"};
  for (size_t k = 0; k < r.moves.size(); ++k) {
    const PathMove& m = r.moves[k];
    const std::string at = move_place(r, k);
    if (m.target_pulses.size() != n) {
      return Error{"target_pulses",
                   fmt::format("{}: target_pulses: {} values for {} axes", at, m.target_pulses.size(), n)};
    }
    for (size_t i = 0; i < n; ++i) {
      if (auto e = check_position("target_pulses", fmt::format("{}: target_pulses[{}]", at, i), m.target_pulses[i])) {
        return e;
      }
    }
    if (!std::isfinite(m.feed) || m.feed <= 0) {
      return Error{"feed", fmt::format("{}: feed={}: needs a finite number > 0 pulses/s", at, m.feed)};
    }
    // As plan_line checks them, but here also for a move that goes nowhere
    // (skipped, never planned), and before any line is planned.
    if (m.jerks) {
      static const char* const kJerkNames[4] = {"Ts1", "Ts2", "Te1", "Te2"};
      for (size_t q = 0; q < 4; ++q) {
        const double j = (*m.jerks)[q];
        if (!(std::isfinite(j) && j > 0 && j <= r.limits.j)) {
          return Error{"jerks", fmt::format("{}: jerks[{}] ({})={}: needs a finite number > 0 and <= limits.j={} "
                                            "pulses/s^3", at, q, kJerkNames[q], j, r.limits.j)};
        }
      }
    }
  }
  return std::nullopt;
}


// ---- blended junctions -------------------------------------------------------------

// One line's rows on its own clock (0 where it starts): each axis's exact
// position gain, velocity and acceleration at any clock, in closed form.
class LineMotion {
 public:
  explicit LineMotion(const LinePlan& line) : line_(&line), gain_(line.axes.size()) {
    const std::vector<Segment>& lead = line.axes[line.lead].segments;
    starts_.push_back(0);
    for (const Segment& s : lead) starts_.push_back(starts_.back() + s.clocks);
    for (size_t i = 0; i < line.axes.size(); ++i) {
      gain_[i].push_back(0);
      for (const Segment& s : line.axes[i].segments) {
        gain_[i].push_back(gain_[i].back() + pos_gain(s.vel0, s.acc0, s.jerk, s.clocks));
      }
    }
    // Its acceleration ends where the lead first reaches its top speed, its
    // deceleration starts where the lead last has it (row boundaries: the
    // speed peaks where the acceleration is 0, at a row's start).
    i128 top = 0;
    for (const Segment& s : lead) top = std::max(top, s.vel0 < 0 ? -s.vel0 : s.vel0);
    size_t first = lead.size(), last = 0;
    for (size_t k = 0; k < lead.size(); ++k) {
      if ((lead[k].vel0 < 0 ? -lead[k].vel0 : lead[k].vel0) != top) continue;
      first = std::min(first, k);
      last = k;
    }
    if (first == lead.size()) first = last = 0;
    head_ = starts_[first];
    tail_ = clocks() - starts_[last];
  }

  uint64_t clocks() const { return starts_.back(); }
  uint64_t head() const { return head_; }  // clocks of its acceleration
  uint64_t tail() const { return tail_; }  // clocks of its deceleration (and the exact-rest rows after it)
  const std::vector<uint64_t>& row_starts() const { return starts_; }  // and its end
  // The row running at clock t (0 <= t < clocks()).
  size_t row_at(uint64_t t) const {
    return size_t(std::upper_bound(starts_.begin(), starts_.end(), t) - starts_.begin()) - 1;
  }
  const Segment& row(size_t axis, size_t k) const { return line_->axes[axis].segments[k]; }

  struct State {
    i128 gain = 0, vel = 0;
    int64_t acc = 0;
  };
  // Before the line: nothing; after it: at rest, its whole travel done.
  State state(size_t axis, int64_t t) const {
    if (t < 0) return {};
    if (uint64_t(t) >= clocks()) return {gain_[axis].back(), 0, 0};
    const size_t k = row_at(uint64_t(t));
    const Segment& s = row(axis, k);
    const uint64_t in = uint64_t(t) - starts_[k];
    return {gain_[axis][k] + pos_gain(s.vel0, s.acc0, s.jerk, in), vel_after(s.vel0, s.acc0, s.jerk, in),
            int64_t(acc_after(s.acc0, s.jerk, in))};
  }
  i128 gain(size_t axis, int64_t t) const { return state(axis, t).gain; }
  i128 travel(size_t axis) const { return gain_[axis].back(); }

 private:
  const LinePlan* line_;
  std::vector<uint64_t> starts_;
  std::vector<std::vector<i128>> gain_;
  uint64_t head_ = 0, tail_ = 0;
};

// A line started at `start` on the path's clock.
struct PlacedLine {
  const LineMotion* motion = nullptr;
  uint64_t start = 0;
  uint64_t end() const { return start + motion->clocks(); }
};

struct MergedRows {
  std::vector<std::vector<Segment>> axes;  // the same clocks row by row on every axis
  std::vector<uint64_t> starts;            // each row's first clock, and the end
};

// The rows of lines superposed over clocks [from, to): split at every row
// boundary of every line running there, each row's jerk, start velocity and
// start acceleration the sums of those lines' (exact: the executor's
// recurrence is linear), its phase the earliest running line's. `lines`
// in order of start, each ending no earlier than the one before; every
// clock of [from, to) covered by at least one.
MergedRows merge_lines(const std::vector<PlacedLine>& lines, size_t axes, uint64_t from, uint64_t to) {
  std::vector<uint64_t> cuts{from, to};
  for (const PlacedLine& l : lines) {
    if (l.end() <= from || l.start >= to) continue;
    for (uint64_t s : l.motion->row_starts()) {
      if (l.start + s > from && l.start + s < to) cuts.push_back(l.start + s);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  MergedRows out;
  out.axes.resize(axes);
  out.starts = cuts;
  size_t first = 0;  // the earliest line still running
  for (size_t c = 0; c + 1 < cuts.size(); ++c) {
    const uint64_t t = cuts[c];
    while (first < lines.size() && lines[first].end() <= t) ++first;
    for (size_t i = 0; i < axes; ++i) {
      Segment row;
      row.clocks = uint32_t(cuts[c + 1] - t);
      i128 acc = 0;
      bool owner = true;
      for (size_t m = first; m < lines.size() && lines[m].start <= t; ++m) {
        if (lines[m].end() <= t) continue;
        const LineMotion& line = *lines[m].motion;
        const uint64_t local = t - lines[m].start;
        const Segment& s = line.row(i, line.row_at(local));
        const LineMotion::State st = line.state(i, int64_t(local));
        row.jerk += s.jerk;
        row.vel0 += st.vel;
        acc += st.acc;
        if (owner) row.phase = s.phase;
        owner = false;
      }
      row.acc0 = int64_t(acc);
      out.axes[i].push_back(row);
    }
  }
  return out;
}

// What a blend must keep to, in executor LSBs (see path_planner.h).
struct BlendBounds {
  size_t axes = 0;
  std::array<double, LineRequest::kMaxAxes> vel{}, acc{}, jerk{};  // per axis; jerk 0: none
  double tolerance = 0;                                             // pulses
  double deviation_slack = 0;  // pulses: how far above the per-clock maximum the deviation bound may be
};

// Within a bound in LSB (relative rounding of the conversion, one LSB per line).
bool within(i128 peak, double bound) { return double(peak) <= bound * (1 + 1e-9) + 2; }

// Each axis's velocity (LSB per clock) at clock t of a row, t in [0, clocks].
i128 row_vel(const Segment& s, uint64_t t) { return vel_after(s.vel0, s.acc0, s.jerk, t); }

// The largest |v| of a row's velocity register over clocks [t0, t1]: the
// ends, or where the quadratic turns.
double row_max_abs_vel(const Segment& s, uint64_t t0, uint64_t t1) {
  double m = std::max(std::fabs(double(row_vel(s, t0))), std::fabs(double(row_vel(s, t1))));
  if (s.jerk != 0) {
    const double turn = 0.5 - double(s.acc0) / double(s.jerk);
    for (double c : {std::floor(turn), std::ceil(turn)}) {
      if (c > double(t0) && c < double(t1)) m = std::max(m, std::fabs(double(row_vel(s, uint64_t(c)))));
    }
  }
  return m;
}

// Whether the speed along the path stays <= cap (LSB per clock) over
// clocks [t0, t1] of merged row k: bounded per axis, split where the bound
// is not enough, down to single clocks.
bool speed_within(const MergedRows& rows, size_t k, uint64_t t0, uint64_t t1, double cap, int depth = 0) {
  double bound2 = 0, at0 = 0, at1 = 0;
  for (const std::vector<Segment>& axis : rows.axes) {
    const Segment& s = axis[k];
    const double m = row_max_abs_vel(s, t0, t1);
    bound2 += m * m;
    const double v0 = double(row_vel(s, t0)), v1 = double(row_vel(s, t1));
    at0 += v0 * v0;
    at1 += v1 * v1;
  }
  if (bound2 <= cap * cap) return true;
  if (std::max(at0, at1) > cap * cap || t1 - t0 <= 1 || depth > 80) return false;
  const uint64_t mid = t0 + (t1 - t0) / 2;
  return speed_within(rows, k, t0, mid, cap, depth + 1) && speed_within(rows, k, mid, t1, cap, depth + 1);
}

// Every axis within its limits and the path speed within cap over the
// merged rows of an overlap.
bool limits_hold(const MergedRows& rows, const BlendBounds& b, double cap) {
  for (size_t i = 0; i < b.axes; ++i) {
    const TableReport rep = run_table(rows.axes[i], 0, 1);
    if (!rep.ok || !within(rep.peak_vel, b.vel[i]) || !within(rep.peak_acc, b.acc[i])) return false;
    if (b.jerk[i] > 0 && !within(rep.peak_jerk, b.jerk[i])) return false;
  }
  for (size_t k = 0; k + 1 < rows.starts.size(); ++k) {
    if (!speed_within(rows, k, 0, rows.axes[0][k].clocks, cap)) return false;
  }
  return true;
}

// Per axis, where the reference is relative to the corner point during an
// overlap: line A's part (its position minus where it ends, in LSB) and
// line B's (its gain from its start).
struct CornerOffset {
  std::array<i128, LineRequest::kMaxAxes> a{}, b{};
};

struct Deviation {
  double lower = 0;  // the largest distance at the clocks evaluated (pulses)
  double upper = 0;  // a bound of the largest over every clock
};

// The largest distance from the corner point over clocks 0..d of the
// overlap (B's clock) of line B started d clocks before line A ends.
// Branch and bound: each axis of each line moves one way only (plan_line's
// lines never reverse), so over clocks [t0, t1] each part lies between its
// values at t0 and t1, which bounds the distance; pieces whose bound can
// raise the maximum by more than the slack are halved, down to single
// clocks. Stops early once the distance passes `give_up`.
Deviation corner_deviation(const LineMotion& A, const LineMotion& B, uint64_t d, const BlendBounds& b,
                           double give_up) {
  const int64_t shift = int64_t(A.clocks()) - int64_t(d);
  const auto at = [&](uint64_t t) {
    CornerOffset o;
    for (size_t i = 0; i < b.axes; ++i) {
      o.a[i] = A.gain(i, shift + int64_t(t)) - A.travel(i);
      o.b[i] = B.gain(i, int64_t(t));
    }
    return o;
  };
  const auto distance = [&](const CornerOffset& o) {
    double sum = 0;
    for (size_t i = 0; i < b.axes; ++i) {
      const double e = double(o.a[i] + o.b[i]) / kTwoPowFrac;
      sum += e * e;
    }
    return std::sqrt(sum);
  };
  const auto bound = [&](const CornerOffset& p, const CornerOffset& q) {
    double sum = 0;
    for (size_t i = 0; i < b.axes; ++i) {
      const double lo = double(std::min(p.a[i], q.a[i]) + std::min(p.b[i], q.b[i])) / kTwoPowFrac;
      const double hi = double(std::max(p.a[i], q.a[i]) + std::max(p.b[i], q.b[i])) / kTwoPowFrac;
      sum += std::max(lo * lo, hi * hi);
    }
    return std::sqrt(sum);
  };
  struct Piece {
    uint64_t t0, t1;
    CornerOffset o0, o1;
  };
  Deviation out;
  std::vector<Piece> open;
  const uint64_t parts = std::min<uint64_t>(d, 32);
  CornerOffset prev = at(0);
  out.lower = distance(prev);
  for (uint64_t k = 1; k <= parts; ++k) {
    const uint64_t t = d * k / parts;
    CornerOffset next = at(t);
    out.lower = std::max(out.lower, distance(next));
    open.push_back({d * (k - 1) / parts, t, prev, next});
    prev = next;
  }
  size_t budget = 100000;  // evaluations; past it the open pieces' bounds stand
  while (!open.empty()) {
    if (out.lower > give_up) return {out.lower, std::numeric_limits<double>::infinity()};
    Piece p = open.back();
    open.pop_back();
    const double ub = bound(p.o0, p.o1);
    if (ub <= out.lower + b.deviation_slack || p.t1 - p.t0 <= 1 || budget == 0) {
      out.upper = std::max(out.upper, p.t1 - p.t0 <= 1 ? std::max(distance(p.o0), distance(p.o1)) : ub);
      continue;
    }
    --budget;
    const uint64_t mid = p.t0 + (p.t1 - p.t0) / 2;
    const CornerOffset m = at(mid);
    out.lower = std::max(out.lower, distance(m));
    open.push_back({p.t0, mid, p.o0, m});
    open.push_back({mid, p.t1, m, p.o1});
  }
  out.upper = std::max(out.upper, out.lower);
  return out;
}

struct Overlap {
  uint64_t clocks = 0;
  double deviation = 0;
};

// The junction of line A and line B (B after A): the largest overlap the
// search finds within the tolerance and the limits. Overlap 0 (an exact
// stop) always holds. The full overlap min(A's deceleration, B's
// acceleration) is tried first (collinear lines, whose ramps cancel, often
// take it), then bisection keeps an overlap that holds (lo) and one that
// does not (hi) until they are one clock apart.
Overlap choose_overlap(const LineMotion& A, const LineMotion& B, const BlendBounds& b, double speed_cap) {
  const auto holds = [&](uint64_t d, double* deviation) {
    const Deviation dev = corner_deviation(A, B, d, b, b.tolerance);
    if (dev.upper > b.tolerance) return false;
    const uint64_t from = A.clocks() - d;
    const MergedRows rows = merge_lines({{&A, 0}, {&B, from}}, b.axes, from, A.clocks());
    if (!limits_hold(rows, b, speed_cap)) return false;
    *deviation = dev.upper;
    return true;
  };
  Overlap best;
  const uint64_t most = std::min(A.tail(), B.head());
  if (most == 0) return best;
  double deviation = 0;
  if (holds(most, &deviation)) return {most, deviation};
  uint64_t lo = 0, hi = most;
  while (hi - lo > 1) {
    const uint64_t mid = lo + (hi - lo) / 2;
    if (holds(mid, &deviation)) {
      lo = mid;
      best = {mid, deviation};
    } else {
      hi = mid;
    }
  }
  return best;
}

// Replaces the concatenated rows of an exact-stop plan by the blended
// stream: the same lines, each junction overlapped as choose_overlap finds.
void blend_junctions(PathPlan& out, const PathRequest& r, const Planner& planner, const PulseTiming& timing) {
  const size_t n = r.axes;
  const Clock clock = planner.clock();
  BlendBounds b;
  b.axes = n;
  b.tolerance = r.tolerance;
  b.deviation_slack = 1e-4 * r.tolerance;
  const double step_rate = step_rate_limit(timing, clock);
  for (size_t i = 0; i < n; ++i) {
    const AxisLimits l = r.axis_limits.empty() ? AxisLimits{} : r.axis_limits[i];
    b.vel[i] = (l.v_max > 0 ? std::min(step_rate, l.v_max) : step_rate) * vel_lsb_per_unit(clock);
    b.acc[i] = (l.a_max > 0 ? std::min(r.limits.a, l.a_max) : r.limits.a) * acc_lsb_per_unit(clock);
    b.jerk[i] = l.j_max > 0 ? l.j_max * jerk_lsb_per_unit(clock) : 0;
  }
  std::vector<LineMotion> motions;
  motions.reserve(out.moves.size());
  for (const PlannedPathMove& m : out.moves) motions.emplace_back(m.line);

  std::vector<PlacedLine> placed;
  for (size_t k = 0; k < out.moves.size(); ++k) {
    PlannedPathMove& m = out.moves[k];
    uint64_t start = 0;
    if (k > 0) {
      const double cap = std::max(out.moves[k - 1].v_path, m.v_path) * (1 + 1e-6) * vel_lsb_per_unit(clock);
      const Overlap o = choose_overlap(motions[k - 1], motions[k], b, cap);
      m.blend_clocks = o.clocks;
      m.corner_deviation = o.deviation;
      out.max_corner_deviation = std::max(out.max_corner_deviation, o.deviation);
      start = placed.back().end() - o.clocks;
    }
    placed.push_back({&motions[k], start});
  }
  if (placed.empty()) return;
  out.total_clocks = placed.back().end();
  MergedRows rows = merge_lines(placed, n, 0, out.total_clocks);
  const size_t count = rows.starts.size() - 1;
  for (size_t i = 0; i < n; ++i) {
    PathAxisRows& a = out.axes[i];
    a.rows = std::move(rows.axes[i]);
    a.flags.assign(count, RowFlags{});
    for (size_t q = 1; q < count; ++q) {
      const Segment& p = a.rows[q - 1];
      a.flags[q].acc_step = i128(a.rows[q].acc0) != acc_after(p.acc0, p.jerk, p.clocks);
    }
  }
  const auto row_starting = [&](uint64_t t) {
    return size_t(std::lower_bound(rows.starts.begin(), rows.starts.end(), t) - rows.starts.begin());
  };
  for (size_t k = 0; k < out.moves.size(); ++k) {
    PlannedPathMove& m = out.moves[k];
    m.start_clock = placed[k].start;
    m.end_clock = placed[k].end();
    m.first_row = row_starting(m.start_clock);
    m.end_row = row_starting(m.end_clock) - 1;
    for (size_t i = 0; i < n; ++i) {
      out.axes[i].flags[m.end_row].move_end = true;
      // The next line is the only other one that can have moved by then.
      if (k + 1 < out.moves.size()) {
        m.end_position[i] += motions[k + 1].gain(i, int64_t(m.end_clock) - int64_t(placed[k + 1].start));
      }
    }
  }
  for (PathAxisRows& a : out.axes) a.flags.back().stream_end = true;
}

}  // namespace

PathResult plan_path(const Planner& planner, const PathRequest& r, const PulseTiming& timing) {
  if (auto e = check_request(r)) return *e;
  const size_t n = r.axes;
  PathPlan out;
  out.axes.resize(n);
  // A path starts at rest mid-pulse on every axis, as a move from rest ends;
  // from then on each line starts from the fraction the previous one left.
  std::vector<u128> frac(n, kOne / 2);
  for (PathAxisRows& a : out.axes) a.pos_frac0 = kOne / 2;
  std::vector<int64_t> at = r.start.empty() ? std::vector<int64_t>(n, 0) : r.start;

  for (size_t k = 0; k < r.moves.size(); ++k) {
    const PathMove& m = r.moves[k];
    LineRequest lr;
    lr.distances.resize(n);
    for (size_t i = 0; i < n; ++i) lr.distances[i] = m.target_pulses[i] - at[i];  // both within +-2^31
    if (std::all_of(lr.distances.begin(), lr.distances.end(), [](int64_t d) { return d == 0; })) {
      out.skipped.push_back(SkippedMove{k, m.source_line});
      continue;
    }
    lr.v_path = std::min(m.feed, r.limits.v);
    lr.a_path = r.limits.a;
    lr.j_path = r.limits.j;
    lr.jerks = m.jerks;  // unset: the symmetric shape, the same rows as without
    lr.axis_limits = r.axis_limits;
    lr.start_fracs = frac;
    LineResult planned = plan_line(planner, lr, timing);
    if (const Error* e = std::get_if<Error>(&planned)) {
      return Error{e->parameter, fmt::format("{}: {}", move_place(r, k), e->message)};
    }
    PlannedPathMove pm;
    pm.move = k;
    pm.source_line = m.source_line;
    pm.v_path = lr.v_path;
    pm.start = at;
    pm.target = m.target_pulses;
    pm.line = std::move(std::get<LinePlan>(planned));
    pm.first_row = out.axes[0].rows.size();
    pm.start_clock = out.total_clocks;
    pm.end_row = pm.first_row + pm.line.axes[0].segments.size() - 1;
    pm.end_clock = pm.start_clock + pm.line.total_clocks;
    pm.end_position.resize(n);
    for (size_t i = 0; i < n; ++i) {
      const Plan& p = pm.line.axes[i];
      PathAxisRows& a = out.axes[i];
      const std::vector<RowFlags> flags = move_row_flags(p.segments, /*stream_end=*/false);
      a.rows.insert(a.rows.end(), p.segments.begin(), p.segments.end());
      a.flags.insert(a.flags.end(), flags.begin(), flags.end());
      frac[i] = p.end_state.frac;
      pm.end_position[i] = i128(m.target_pulses[i]) * i128(kOne) + i128(frac[i]);
    }
    out.total_clocks += pm.line.total_clocks;
    out.path_length += pm.line.path_length;
    out.max_line_deviation = std::max(out.max_line_deviation, pm.line.max_line_deviation);
    at = m.target_pulses;
    out.moves.push_back(std::move(pm));
  }
  for (PathAxisRows& a : out.axes) {
    if (!a.flags.empty()) a.flags.back().stream_end = true;
  }
  out.exact_stop_clocks = out.total_clocks;
  if (r.junction == Junction::kBlend) blend_junctions(out, r, planner, timing);
  out.duration_s = double(out.total_clocks) / planner.clock().hz;
  return out;
}

}  // namespace scurve
