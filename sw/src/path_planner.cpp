#include "scurve/path_planner.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
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
  }
  return std::nullopt;
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
    for (size_t i = 0; i < n; ++i) {
      const Plan& p = pm.line.axes[i];
      PathAxisRows& a = out.axes[i];
      const std::vector<RowFlags> flags = move_row_flags(p.segments, /*stream_end=*/false);
      a.rows.insert(a.rows.end(), p.segments.begin(), p.segments.end());
      a.flags.insert(a.flags.end(), flags.begin(), flags.end());
      frac[i] = p.end_state.frac;
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
  out.duration_s = double(out.total_clocks) / planner.clock().hz;
  return out;
}

}  // namespace scurve
