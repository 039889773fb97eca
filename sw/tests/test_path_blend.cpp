// Blended junctions of scurve::plan_path: the same lines as with exact
// stops, superposed where one decelerates and the next accelerates. The
// merged rows are run as the executor runs one stream: every row continues
// the previous one's end state (the continuity guard), the library's row
// simulation (run_table) and the closed form end every axis exactly where
// the exact-stop rows end, each axis within its limits, and over every
// clock of every overlap, integrated here, the reference stays within the
// tolerance of the corner point.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "line_checks.h"
#include "path_checks.h"
#include "scurve/cli/path_file.h"
#include "scurve/path_planner.h"

using namespace scurve;

namespace {

const std::string kExamples = SCURVE_PATH_EXAMPLES_DIR;

using test::floor_pulses;
using test::plan_or_fail;

// What one blended path measured.
struct BlendFigures {
  size_t junctions = 0, blended = 0;
  double worst_ratio = 0;         // largest per-clock corner distance / tolerance
  double worst_report_gap = 0;    // largest planner figure - per-clock maximum (pulses)
  double path_acc_ratio = 0;      // largest |a| along the path / limits.a (row ends)
  double path_jerk_ratio = 0;     // largest |jerk| along the path / limits.j
  uint64_t blend_clocks = 0, exact_clocks = 0;
  uint64_t clocks_run = 0;        // clocks integrated one by one
};

// The checks of a blended plan `p` against the exact-stop plan `exact` of
// the same request; `per_clock`: integrate every overlap clock by clock.
BlendFigures expect_blended_path(const PathRequest& r, const PathPlan& p, const PathPlan& exact, bool per_clock,
                                 const std::string& what) {
  BlendFigures f;
  const size_t n = r.axes;
  const i128 one = i128(kOne);
  const Clock c{};
  EXPECT_EQ(p.axes.size(), n) << what;
  if (p.axes.size() != n || p.moves.empty()) return f;
  const size_t rows = p.axes[0].rows.size();
  for (size_t i = 0; i < n; ++i) {
    EXPECT_EQ(p.axes[i].rows.size(), rows) << what << " axis " << i;
    EXPECT_EQ(p.axes[i].flags.size(), rows) << what << " axis " << i;
    if (p.axes[i].rows.size() != rows || p.axes[i].flags.size() != rows) return f;
    for (size_t k = 0; k < rows; ++k) {
      EXPECT_EQ(p.axes[i].rows[k].clocks, p.axes[0].rows[k].clocks) << what << " axis " << i << " row " << k;
      EXPECT_GT(p.axes[i].rows[k].clocks, 0u) << what << " axis " << i << " row " << k;
    }
  }
  // The same lines as with exact stops (the same plan_line calls).
  EXPECT_EQ(p.moves.size(), exact.moves.size()) << what;
  if (p.moves.size() != exact.moves.size()) return f;
  for (size_t k = 0; k < p.moves.size(); ++k) {
    for (size_t i = 0; i < n; ++i) {
      EXPECT_TRUE(p.moves[k].line.axes[i].segments == exact.moves[k].line.axes[i].segments) << what << " move " << k;
    }
  }

  // Clocks: each move starts its overlap before the previous one ends, the
  // path is shorter by the overlaps.
  std::vector<uint64_t> row_start(rows + 1, 0);
  for (size_t k = 0; k < rows; ++k) row_start[k + 1] = row_start[k] + p.axes[0].rows[k].clocks;
  uint64_t overlaps = 0;
  for (size_t k = 0; k < p.moves.size(); ++k) {
    const PlannedPathMove& m = p.moves[k];
    const uint64_t expected_start = k == 0 ? 0 : p.moves[k - 1].end_clock - m.blend_clocks;
    EXPECT_EQ(m.start_clock, expected_start) << what << " move " << k;
    EXPECT_EQ(m.end_clock, m.start_clock + m.line.total_clocks) << what << " move " << k;
    if (k > 0) {
      EXPECT_LE(m.blend_clocks, std::min(m.line.total_clocks, p.moves[k - 1].line.total_clocks)) << what;
      ++f.junctions;
      f.blended += m.blend_clocks > 0;
    } else {
      EXPECT_EQ(m.blend_clocks, 0u) << what;
    }
    EXPECT_EQ(m.corner_deviation == 0, m.blend_clocks == 0) << what << " move " << k;
    EXPECT_LE(m.corner_deviation, r.tolerance) << what << " move " << k;
    overlaps += m.blend_clocks;
    EXPECT_LT(m.first_row, rows) << what;
    EXPECT_LT(m.end_row, rows) << what;
    if (m.first_row >= rows || m.end_row >= rows) return f;
    EXPECT_EQ(row_start[m.first_row], m.start_clock) << what << " move " << k;
    EXPECT_EQ(row_start[m.end_row + 1], m.end_clock) << what << " move " << k;
  }
  EXPECT_EQ(p.total_clocks, p.moves.back().end_clock) << what;
  EXPECT_EQ(p.total_clocks, row_start[rows]) << what;
  EXPECT_EQ(p.exact_stop_clocks, exact.total_clocks) << what;
  EXPECT_EQ(p.total_clocks + overlaps, exact.total_clocks) << what;
  EXPECT_LE(p.duration_s, exact.duration_s) << what;
  f.blend_clocks = p.total_clocks;
  f.exact_clocks = exact.total_clocks;
  for (size_t i = 0; i < n; ++i) {
    size_t next_end = 0;
    for (size_t q = 0; q < rows; ++q) {
      const bool end = next_end < p.moves.size() && p.moves[next_end].end_row == q;
      EXPECT_EQ(p.axes[i].flags[q].move_end, end) << what << " axis " << i << " row " << q;
      EXPECT_EQ(p.axes[i].flags[q].stream_end, q + 1 == rows) << what << " axis " << i << " row " << q;
      next_end += end;
    }
    EXPECT_EQ(next_end, p.moves.size()) << what << " axis " << i;
  }

  // Each axis as one stream in closed form: every row continues the
  // previous one's end state exactly (ACC_STEP rows: the velocity), the
  // stream ends at rest exactly where the exact-stop rows end, and the
  // library's row simulation ends there too.
  std::vector<std::vector<i128>> pos_at(n, std::vector<i128>(rows + 1)), vel_at = pos_at;
  std::vector<std::vector<int64_t>> acc_at(n, std::vector<int64_t>(rows + 1));
  std::vector<std::vector<i128>> corner(n);  // the exact-stop rest position at each move's end
  for (size_t i = 0; i < n; ++i) {
    const std::string where = what + " axis " + std::to_string(i);
    const i128 start = i128(r.start.empty() ? 0 : r.start[i]) * one + i128(p.axes[i].pos_frac0);
    EXPECT_EQ(p.axes[i].pos_frac0, exact.axes[i].pos_frac0) << where;
    i128 pos = start, v = 0;
    int64_t a = 0;
    for (size_t q = 0; q < rows; ++q) {
      const Segment& s = p.axes[i].rows[q];
      EXPECT_EQ(s.vel0, v) << where << " row " << q;
      EXPECT_EQ(p.axes[i].flags[q].acc_step, s.acc0 != a) << where << " row " << q;
      if (!p.axes[i].flags[q].acc_step) EXPECT_EQ(s.acc0, a) << where << " row " << q;
      pos_at[i][q] = pos;
      vel_at[i][q] = v;
      acc_at[i][q] = s.acc0;
      pos += pos_gain(s.vel0, s.acc0, s.jerk, s.clocks);
      v = vel_after(s.vel0, s.acc0, s.jerk, s.clocks);
      a = int64_t(acc_after(s.acc0, s.jerk, s.clocks));
    }
    pos_at[i][rows] = pos;
    EXPECT_EQ(v, 0) << where;
    EXPECT_EQ(a, 0) << where;
    EXPECT_EQ(int64_t(floor_pulses(pos)), r.moves.back().target_pulses[i]) << where;
    i128 exact_pos = start;
    for (size_t k = 0; k < exact.moves.size(); ++k) {
      for (const Segment& s : exact.moves[k].line.axes[i].segments) {
        exact_pos += pos_gain(s.vel0, s.acc0, s.jerk, s.clocks);
      }
      corner[i].push_back(exact_pos);
    }
    EXPECT_EQ(pos, exact_pos) << where << ": not where the exact-stop rows end";
    const int dir = r.moves.back().target_pulses[i] >= (r.start.empty() ? 0 : r.start[i]) ? 1 : -1;
    const TableReport rep = run_table(p.axes[i].rows, p.axes[i].pos_frac0, dir);
    EXPECT_TRUE(rep.ok) << where << ": " << rep.error;
    EXPECT_EQ(rep.end_pos + i128(r.start.empty() ? 0 : r.start[i]) * one, pos) << where;
    for (const PlannedPathMove& m : p.moves) {
      EXPECT_EQ(m.end_position.size(), n) << where;
      if (m.end_position.size() != n) continue;
      EXPECT_EQ(m.end_position[i], pos_at[i][m.end_row + 1]) << where << " move " << m.move;
    }

    // Limits: speed within the step rate and v_max, acceleration within
    // limits.a and a_max, jerk within j_max (where given) and twice the
    // path jerk, one LSB per line of rounding.
    const AxisLimits l = r.axis_limits.empty() ? AxisLimits{} : r.axis_limits[i];
    const double v_bound = std::min(step_rate_limit(PulseTiming{}, c), l.v_max > 0 ? l.v_max : 1e300);
    const double a_bound = std::min(r.limits.a, l.a_max > 0 ? l.a_max : 1e300);
    const double j_bound = std::min(2 * r.limits.j, l.j_max > 0 ? l.j_max : 1e300);
    EXPECT_LE(double(rep.peak_vel), v_bound * vel_lsb_per_unit(c) * (1 + 1e-9) + 2) << where;
    EXPECT_LE(double(rep.peak_acc), a_bound * acc_lsb_per_unit(c) * (1 + 1e-9) + 2) << where;
    EXPECT_LE(double(rep.peak_jerk), j_bound * jerk_lsb_per_unit(c) * (1 + 1e-9) + 2) << where;
  }
  // Acceleration (at the row ends: it is linear within a row) and jerk along the path.
  for (size_t q = 0; q < rows; ++q) {
    double a0 = 0, a1 = 0, j = 0;
    for (size_t i = 0; i < n; ++i) {
      const Segment& s = p.axes[i].rows[q];
      const double x0 = acc_to_phys(s.acc0, c), x1 = acc_to_phys(acc_after(s.acc0, s.jerk, s.clocks - 1), c);
      const double y = jerk_to_phys(s.jerk, c);
      a0 += x0 * x0;
      a1 += x1 * x1;
      j += y * y;
    }
    f.path_acc_ratio = std::max(f.path_acc_ratio, std::sqrt(std::max(a0, a1)) / r.limits.a);
    f.path_jerk_ratio = std::max(f.path_jerk_ratio, std::sqrt(j) / r.limits.j);
  }
  if (!per_clock) return f;

  // Every overlap clock by clock from its first row: the distance from the
  // corner point (where the exact-stop rows rest) and the speed along the path.
  std::vector<const std::vector<Segment>*> row_tables(n);
  for (size_t i = 0; i < n; ++i) row_tables[i] = &p.axes[i].rows;
  for (size_t k = 1; k < p.moves.size(); ++k) {
    const PlannedPathMove& m = p.moves[k];
    if (m.blend_clocks == 0) continue;
    const std::string where = what + " junction before move " + std::to_string(m.move);
    std::vector<i128> start(n);
    for (size_t i = 0; i < n; ++i) start[i] = pos_at[i][m.first_row];
    test::AxesState state(start);
    for (size_t i = 0; i < n; ++i) {
      state.vel[i] = vel_at[i][m.first_row];
      state.acc[i] = acc_at[i][m.first_row];
    }
    const double cap = std::max(p.moves[k - 1].v_path, m.v_path) * (1 + 1e-6) * vel_lsb_per_unit(c);
    long double worst2 = 0, fastest2 = 0;
    uint64_t clocks = 0;
    test::run_rows_each_clock(row_tables, m.first_row, p.moves[k - 1].end_row + 1, state,
                              [&](const test::AxesState& s) {
                                long double d2 = 0, v2 = 0;
                                for (size_t i = 0; i < n; ++i) {
                                  const long double e = (long double)(s.pos[i] - corner[i][k - 1]) / (long double)one;
                                  d2 += e * e;
                                  v2 += (long double)s.vel[i] * (long double)s.vel[i];
                                }
                                worst2 = std::max(worst2, d2);
                                fastest2 = std::max(fastest2, v2);
                                ++clocks;
                              });
    EXPECT_EQ(clocks, m.blend_clocks + 1) << where;
    f.clocks_run += clocks;
    const double worst = double(std::sqrt(worst2));
    EXPECT_LE(worst, r.tolerance) << where;
    EXPECT_LE(worst, m.corner_deviation + 1e-9) << where << ": the planner's figure is below the per-clock one";
    EXPECT_LE(m.corner_deviation, worst + 1e-4 * r.tolerance + 1e-9) << where;
    EXPECT_LE(double(std::sqrt(fastest2)), cap) << where;
    f.worst_ratio = std::max(f.worst_ratio, worst / r.tolerance);
    f.worst_report_gap = std::max(f.worst_report_gap, m.corner_deviation - worst);
  }
  return f;
}

PathRequest blended(PathRequest r, double tolerance) {
  r.junction = Junction::kBlend;
  r.tolerance = tolerance;
  return r;
}

// Random paths of 2 to 5 lines in pulses: every axis moves both ways, some
// axes stay still, feeds below and above the speed cap, random tolerances
// from 0.05 to 300 pulses, every fourth path with axis limits; short enough
// ramps to integrate every overlap clock by clock. `jerks`: three lines in
// four with their own asymmetric jerks, down to 1/50 of limits.j (drawn
// from a generator of their own: the paths are the same as without).
void random_blends(size_t axes, int count, uint64_t seed, bool jerks = false) {
  std::mt19937_64 g(seed);
  std::mt19937_64 g_jerks(seed + 1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto log_u = [&](double lo, double hi) {
    return std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * u(g));
  };
  BlendFigures all;
  double plan_seconds = 0, saved_most = 0;
  size_t lines = 0;
  for (int n = 0; n < count; ++n) {
    PathRequest r;
    r.axes = axes;
    r.limits = {log_u(5e3, 4e4), log_u(1e6, 8e6), log_u(2e8, 4e9)};
    r.start.resize(axes);
    for (size_t i = 0; i < axes; ++i) r.start[i] = int64_t(g() % 20001) - 10000;
    std::vector<int64_t> at = r.start;
    const int moves = 2 + int(g() % 4);
    for (int k = 0; k < moves; ++k) {
      PathMove m;
      m.target_pulses = at;
      do {
        for (size_t i = 0; i < axes; ++i) {
          if (g() % 6 == 0) continue;  // this axis still
          const double reach = log_u(20, 6000);
          m.target_pulses[i] = at[i] + int64_t(std::llround((2 * u(g) - 1) * reach));
        }
      } while (m.target_pulses == at);
      m.feed = r.limits.v * log_u(0.3, 1.5);
      m.source_line = k + 1;
      if (jerks && g_jerks() % 4 != 0) {
        m.jerks.emplace();
        for (double& j : *m.jerks) j = r.limits.j * std::exp(std::log(0.02) * u(g_jerks));
      }
      at = m.target_pulses;
      r.moves.push_back(m);
    }
    if (n % 4 == 3) {
      for (size_t i = 0; i < axes; ++i) {
        AxisLimits l;
        if (g() % 2) l.v_max = r.limits.v * log_u(0.4, 1);
        if (g() % 2) l.a_max = r.limits.a * log_u(0.4, 1);
        if (g() % 2) l.j_max = r.limits.j * log_u(0.5, 1.5);
        r.axis_limits.push_back(l);
      }
    }
    const PathRequest b = blended(r, log_u(0.05, 300));
    const std::string what = std::to_string(axes) + "-axis path " + std::to_string(n) + " (tolerance " +
                             std::to_string(b.tolerance) + ")";
    const PathPlan exact = plan_or_fail(r);
    const auto t0 = std::chrono::steady_clock::now();
    const PathPlan p = plan_or_fail(b);
    plan_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (p.moves.empty()) {
      ADD_FAILURE() << what << ": not planned";
      continue;
    }
    lines += p.moves.size();
    const BlendFigures f = expect_blended_path(b, p, exact, true, what);
    all.junctions += f.junctions;
    all.blended += f.blended;
    all.worst_ratio = std::max(all.worst_ratio, f.worst_ratio);
    all.worst_report_gap = std::max(all.worst_report_gap, f.worst_report_gap);
    all.path_acc_ratio = std::max(all.path_acc_ratio, f.path_acc_ratio);
    all.path_jerk_ratio = std::max(all.path_jerk_ratio, f.path_jerk_ratio);
    all.blend_clocks += f.blend_clocks;
    all.exact_clocks += f.exact_clocks;
    all.clocks_run += f.clocks_run;
    saved_most = std::max(saved_most, 1 - double(f.blend_clocks) / double(f.exact_clocks));
  }
  std::printf("%d random %zu-axis blended paths%s, %zu junctions (%zu overlapped, %.3g M clocks integrated): corner "
              "distance <= %.4f tolerance, planner's figure <= %.2g pulse above it; along the path |a| <= %.3f "
              "limits.a, |jerk| <= %.3f limits.j; %.1f %% of the exact-stop time (at best %.1f %% shorter), "
              "blend planning %.0f us per line\n",
              count, axes, jerks ? " with asymmetric jerks" : "", all.junctions, all.blended,
              double(all.clocks_run) / 1e6, all.worst_ratio, all.worst_report_gap, all.path_acc_ratio,
              all.path_jerk_ratio,
              100.0 * double(all.blend_clocks) / double(all.exact_clocks), 100 * saved_most,
              1e6 * plan_seconds / double(std::max<size_t>(1, lines)));
}

PathRequest two_lines(std::vector<int64_t> corner, std::vector<int64_t> end) {
  PathRequest r;
  r.axes = corner.size();
  r.limits = {20000, 2e6, 1e9};
  r.moves = {{corner, 20000, 1}, {end, 20000, 2}};
  return r;
}

}  // namespace

TEST(PathBlend, BadToleranceIsRefusedNamingTheParameterAndTheBound) {
  PathRequest r = two_lines({1000, 0}, {1000, 1000});
  r.junction = Junction::kBlend;
  for (double bad : {0.0, -1.0, std::nan(""), HUGE_VAL}) {
    r.tolerance = bad;
    const PathResult p = plan_path(Planner{}, r, PulseTiming{});
    const Error* e = std::get_if<Error>(&p);
    ASSERT_NE(e, nullptr) << bad;
    EXPECT_EQ(e->parameter, "tolerance");
    EXPECT_EQ(e->message.rfind("tolerance=", 0), 0u) << e->message;
    EXPECT_NE(e->message.find("> 0 pulses"), std::string::npos) << e->message;
  }
  r.junction = Junction::kExactStop;  // not used with exact stops
  r.tolerance = -1;
  EXPECT_TRUE(std::holds_alternative<PathPlan>(plan_path(Planner{}, r, PulseTiming{})));
  r.junction = Junction(7);
  const PathResult p = plan_path(Planner{}, r, PulseTiming{});
  ASSERT_TRUE(std::holds_alternative<Error>(p));
  EXPECT_EQ(std::get<Error>(p).parameter, "junction");
}

TEST(PathBlend, RightAngleCutsTheCornerWithinTheTolerance) {
  const PathRequest r = two_lines({3000, 0}, {3000, 3000});
  const PathPlan exact = plan_or_fail(r);
  double last_clocks = double(exact.total_clocks);
  for (double tol : {0.5, 5.0, 50.0}) {
    const PathRequest b = blended(r, tol);
    const PathPlan p = plan_or_fail(b);
    expect_blended_path(b, p, exact, true, "right angle, tolerance " + std::to_string(tol));
    ASSERT_EQ(p.moves.size(), 2u);
    EXPECT_GT(p.moves[1].blend_clocks, 0u);
    EXPECT_LT(double(p.total_clocks), last_clocks) << "a looser tolerance gives a shorter path";
    last_clocks = double(p.total_clocks);
    std::printf("right angle, tolerance %g: overlap %llu clocks, corner distance %.4g pulse, %.4f s (exact stop "
                "%.4f s)\n",
                tol, (unsigned long long)p.moves[1].blend_clocks, p.moves[1].corner_deviation, p.duration_s,
                exact.duration_s);
  }
}

TEST(PathBlend, CollinearLinesMergeTheirRampsAsFarAsTheToleranceAllows) {
  // Two lines one after the other on the same line at the same feed. The
  // tolerance is a distance from the junction point, so a small one keeps
  // the overlap to the last bit of the first line's deceleration; one
  // larger than the ramps' travel lets the whole ramps overlap: the second
  // line's acceleration cancels the first's deceleration and the speed stays
  // at the feed through the junction.
  const PathRequest r = two_lines({4000, 2000}, {8000, 4000});
  const PathPlan exact = plan_or_fail(r);
  const auto ramp = [](const LinePlan& line, bool tail) {  // clocks to / from its top speed
    const std::vector<Segment>& lead = line.axes[line.lead].segments;
    i128 top = 0;
    for (const Segment& s : lead) top = std::max(top, s.vel0 < 0 ? -s.vel0 : s.vel0);
    uint64_t t = 0, first = 0, last = 0;
    bool seen = false;
    for (const Segment& s : lead) {
      if ((s.vel0 < 0 ? -s.vel0 : s.vel0) == top) {
        if (!seen) first = t;
        last = t;
        seen = true;
      }
      t += s.clocks;
    }
    return tail ? line.total_clocks - last : first;
  };
  const uint64_t whole = std::min(ramp(exact.moves[0].line, true), ramp(exact.moves[1].line, false));
  for (double tol : {1.0, 1e4}) {
    const PathRequest b = blended(r, tol);
    const PathPlan p = plan_or_fail(b);
    const std::string what = "collinear, tolerance " + std::to_string(tol);
    const BlendFigures f = expect_blended_path(b, p, exact, true, what);
    ASSERT_EQ(p.moves.size(), 2u);
    const PlannedPathMove& m = p.moves[1];
    EXPECT_GT(m.blend_clocks, 0u) << what;
    EXPECT_LE(f.path_acc_ratio, 1 + 1e-6) << what;
    if (tol > 1) {
      EXPECT_EQ(m.blend_clocks, whole) << what;
      // The speed along the path over the overlap: the feed, to rounding.
      std::vector<const std::vector<Segment>*> rows{&p.axes[0].rows, &p.axes[1].rows};
      test::AxesState state({0, 0});
      for (size_t i = 0; i < 2; ++i) {
        state.vel[i] = p.axes[i].rows[m.first_row].vel0;
        state.acc[i] = p.axes[i].rows[m.first_row].acc0;
      }
      double slowest = 1e300, fastest = 0;
      test::run_rows_each_clock(rows, m.first_row, p.moves[0].end_row + 1, state, [&](const test::AxesState& s) {
        const double v = std::hypot(vel_to_phys(s.vel[0], Clock{}), vel_to_phys(s.vel[1], Clock{}));
        slowest = std::min(slowest, v);
        fastest = std::max(fastest, v);
      });
      EXPECT_NEAR(slowest, 20000, 1) << what;
      EXPECT_NEAR(fastest, 20000, 1) << what;
      std::printf("collinear, tolerance %g: speed %.4f to %.4f pulses/s through the junction\n", tol, slowest, fastest);
    } else {
      EXPECT_LT(m.blend_clocks, whole) << what;
    }
    std::printf("collinear, tolerance %g: overlap %llu of %llu clocks, corner distance %.4g pulse, %.4f s (exact "
                "stop %.4f s)\n",
                tol, (unsigned long long)m.blend_clocks, (unsigned long long)whole, m.corner_deviation, p.duration_s,
                exact.duration_s);
  }
}

TEST(PathBlend, ReversalTurnsBackOnTheLineWithinTheToleranceAndTheAcceleration) {
  // Out and straight back: the two lines' accelerations point the same way
  // (their jerks cancel), so each axis's acceleration bound limits the
  // overlap; the reference stays on the line and turns back within the
  // tolerance of the corner.
  const PathRequest r = two_lines({5000, 3000}, {0, 0});
  const PathPlan exact = plan_or_fail(r);
  for (double tol : {2.0, 1000.0}) {
    const PathRequest b = blended(r, tol);
    const PathPlan p = plan_or_fail(b);
    const BlendFigures f = expect_blended_path(b, p, exact, true, "reversal, tolerance " + std::to_string(tol));
    ASSERT_EQ(p.moves.size(), 2u);
    EXPECT_GT(p.moves[1].blend_clocks, 0u);
    // Per axis within limits.a (checked above); along this diagonal the
    // sum is at most sqrt(2) limits.a.
    EXPECT_LE(f.path_acc_ratio, std::sqrt(2.0) * (1 + 1e-6));
    // The reference stays on the line: the two axes keep their ratio.
    const i128 one = i128(kOne);
    const long double x = (long double)(p.moves[0].end_position[0] - exact.moves[0].end_position[0]) / one;
    const long double y = (long double)(p.moves[0].end_position[1] - exact.moves[0].end_position[1]) / one;
    EXPECT_NEAR(double(x * 3000 - y * 5000), 0, 5000 * 0.01);
    std::printf("reversal, tolerance %g: overlap %llu clocks, corner distance %.4g pulse, |a| along the path %.3f "
                "limits.a, %.4f s (exact stop %.4f s)\n",
                tol, (unsigned long long)p.moves[1].blend_clocks, p.moves[1].corner_deviation, f.path_acc_ratio,
                p.duration_s, exact.duration_s);
  }
}

TEST(PathBlend, JunctionWithoutOverlapKeepsTheExactStopRows) {
  // A tolerance far below a clock's travel: no overlap holds, and the rows
  // are the exact-stop rows, flags and all.
  PathRequest r = two_lines({3000, 0}, {3000, 3000});
  r.moves.push_back({{0, 0}, 15000, 3});
  const PathPlan exact = plan_or_fail(r);
  const PathRequest b = blended(r, 1e-30);
  const PathPlan p = plan_or_fail(b);
  expect_blended_path(b, p, exact, true, "no overlap");
  for (const PlannedPathMove& m : p.moves) EXPECT_EQ(m.blend_clocks, 0u);
  for (size_t i = 0; i < r.axes; ++i) {
    EXPECT_TRUE(p.axes[i].rows == exact.axes[i].rows) << "axis " << i;
    ASSERT_EQ(p.axes[i].flags.size(), exact.axes[i].flags.size());
    for (size_t q = 0; q < p.axes[i].flags.size(); ++q) {
      EXPECT_EQ(p.axes[i].flags[q].word(), exact.axes[i].flags[q].word()) << "axis " << i << " row " << q;
    }
  }
  for (size_t k = 0; k < p.moves.size(); ++k) {
    EXPECT_EQ(p.moves[k].first_row, exact.moves[k].first_row);
    EXPECT_EQ(p.moves[k].end_row, exact.moves[k].end_row);
    EXPECT_EQ(p.moves[k].end_position, exact.moves[k].end_position);
  }
}

TEST(PathBlend, ManyShortLinesChainTheirOverlaps) {
  // 500 relative moves of 0.001 mm (50 lines of one pulse, 450 skipped)
  // and a zig-zag of 40 lines of 1 to 40 pulses: every line overlaps its
  // neighbours on both sides, never three at once.
  std::string text = "G91 G1 F600\n";
  for (int k = 0; k < 500; ++k) text += "X0.001\n";
  for (int k = 0; k < 40; ++k) text += "X" + std::to_string(0.01 * (1 + k % 40)) + " Y" + (k % 2 ? "-" : "") + "0.2\n";
  const PathRequest r = cli::to_path_request(cli::parse_path_gcode(text));
  const PathPlan exact = plan_or_fail(r);
  const PathRequest b = blended(r, 0.5);
  const auto t0 = std::chrono::steady_clock::now();
  const PathPlan p = plan_or_fail(b);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_EQ(p.moves.size(), 90u);
  const BlendFigures f = expect_blended_path(b, p, exact, true, "short lines");
  EXPECT_EQ(f.blended, f.junctions);
  std::printf("90 short lines, tolerance 0.5: %.3f s (exact stop %.3f s), corner distance <= %.4f tolerance, "
              "planned in %.1f ms\n",
              p.duration_s, exact.duration_s, f.worst_ratio, 1e3 * seconds);
}

TEST(PathBlend, Paper003SquareBlendsEveryCornerWithinTheTolerance) {
  cli::PathFileOptions o;
  o.feed_limit = 0.6;
  o.accel = 0.009;
  o.jerk = 1.01e5;
  const auto loaded = cli::load_path_file(kExamples + "/paper003_square.gcode", o);
  ASSERT_TRUE(std::holds_alternative<cli::PathProgram>(loaded)) << std::get<std::string>(loaded);
  const PathRequest r = cli::to_path_request(std::get<cli::PathProgram>(loaded));
  const PathPlan exact = plan_or_fail(r);
  for (double tol : {1.0, 10.0, 100.0, 1000.0}) {
    const PathRequest b = blended(r, tol);
    const PathPlan p = plan_or_fail(b);
    const BlendFigures f = expect_blended_path(b, p, exact, false, "paper 003 square");  // 1.4e10 clocks
    ASSERT_EQ(p.moves.size(), 4u);
    EXPECT_LT(p.total_clocks, exact.total_clocks);
    std::printf("paper 003 square, tolerance %g pulses: %.1f s (exact stop %.1f s), max corner distance %.4g "
                "pulse, |a| along the path <= %.3f limits.a\n",
                tol, p.duration_s, exact.duration_s, p.max_corner_deviation, f.path_acc_ratio);
  }
}

TEST(PathBlend, Paper002CornerBlendsWithinTheTolerance) {
  const auto loaded = cli::load_path_file(kExamples + "/paper002_corner.json");
  ASSERT_TRUE(std::holds_alternative<cli::PathProgram>(loaded)) << std::get<std::string>(loaded);
  const PathRequest r = cli::to_path_request(std::get<cli::PathProgram>(loaded));
  const PathPlan exact = plan_or_fail(r);
  for (double tol : {1.0, 10.0, 100.0}) {
    const PathRequest b = blended(r, tol);
    const PathPlan p = plan_or_fail(b);
    const BlendFigures f = expect_blended_path(b, p, exact, true, "paper 002 corner");
    ASSERT_EQ(p.moves.size(), 2u);
    EXPECT_LT(p.total_clocks, exact.total_clocks);
    std::printf("paper 002 corner, tolerance %g pulses: %.4f s (exact stop %.4f s), overlap %llu clocks, corner "
                "distance %.4g pulse (clock by clock %.4g tolerance), |a| along the path <= %.3f limits.a, |jerk| <= "
                "%.3f limits.j\n",
                tol, p.duration_s, exact.duration_s, (unsigned long long)p.moves[1].blend_clocks,
                p.max_corner_deviation, f.worst_ratio, f.path_acc_ratio, f.path_jerk_ratio);
  }
}

TEST(PathBlend, Paper002AsymmetricCornerBlendsWithinTheTolerance) {
  // Each line with its own jerks: the blend superposes the same lines.
  const auto loaded = cli::load_path_file(kExamples + "/paper002_asymmetric.json");
  ASSERT_TRUE(std::holds_alternative<cli::PathProgram>(loaded)) << std::get<std::string>(loaded);
  const PathRequest r = cli::to_path_request(std::get<cli::PathProgram>(loaded));
  const PathPlan exact = plan_or_fail(r);
  for (double tol : {1.0, 10.0}) {
    const PathRequest b = blended(r, tol);
    const PathPlan p = plan_or_fail(b);
    const BlendFigures f = expect_blended_path(b, p, exact, true, "paper 002 asymmetric corner");
    ASSERT_EQ(p.moves.size(), 2u);
    EXPECT_GT(p.moves[1].blend_clocks, 0u);
    EXPECT_LT(p.total_clocks, exact.total_clocks);
    std::printf("paper 002 asymmetric corner, tolerance %g pulses: %.4f s (exact stop %.4f s), overlap %llu clocks, "
                "corner distance %.4g pulse (clock by clock %.4g tolerance)\n",
                tol, p.duration_s, exact.duration_s, (unsigned long long)p.moves[1].blend_clocks,
                p.max_corner_deviation, f.worst_ratio);
  }
}

TEST(PathBlend, RandomTwoAxisPathsBlendWithinToleranceAndEndExactly) { random_blends(2, 100, 21); }

TEST(PathBlend, RandomThreeAxisPathsBlendWithinToleranceAndEndExactly) { random_blends(3, 30, 23); }

TEST(PathBlend, RandomPathsWithAsymmetricJerksBlendWithinToleranceAndEndExactly) {
  random_blends(2, 40, 25, /*jerks=*/true);
  random_blends(3, 15, 27, /*jerks=*/true);
}
