// Coordinated paths: path files (JSON, the G-code subset) parsed into pulses,
// and scurve::plan_path's rows run as the executor runs one stream (every
// move's rows back to back, the position fraction carried from move to
// move): every axis ends every move exactly on its integer target at rest,
// the rows have the same clocks on every axis, and the axes stay near each
// move's straight line, measured clock by clock by the integration of
// line_checks.h.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <initializer_list>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "line_checks.h"
#include "path_checks.h"
#include "scurve/cli/path_file.h"
#include "scurve/cli/user_input.h"
#include "scurve/path_planner.h"

using namespace scurve;
using cli::PathFileOptions;
using cli::PathProgram;

namespace {

const std::string kExamples = SCURVE_PATH_EXAMPLES_DIR;

// The message of the input::Error `parse` throws; empty if it parses.
std::string parse_error(const std::function<void()>& parse) {
  try {
    parse();
  } catch (const input::Error& e) {
    return e.what();
  }
  return "";
}

void expect_names(const std::string& message, std::initializer_list<const char*> parts) {
  EXPECT_FALSE(message.empty()) << "no error";
  for (const char* p : parts) EXPECT_NE(message.find(p), std::string::npos) << "'" << p << "' not in: " << message;
}

std::string gcode_error(const std::string& text, PathFileOptions o = {}) {
  return parse_error([&] { cli::parse_path_gcode(text, o); });
}
std::string json_error(const std::string& text, PathFileOptions o = {}) {
  return parse_error([&] { cli::parse_path_json(text, o); });
}

std::string mm_text(double v) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3f", v);
  return text;
}

std::vector<std::vector<int64_t>> targets(const PathProgram& p) {
  std::vector<std::vector<int64_t>> t;
  for (const PathMove& m : p.moves) t.push_back(m.target_pulses);
  return t;
}

using test::floor_pulses;
using test::plan_or_fail;

// The checks of one planned path; `per_clock`: also run every clock and
// measure the distance from each move's line (returned, else -1).
double expect_exact_path(const PathRequest& r, const PathPlan& p, bool per_clock, const std::string& what) {
  const size_t n = r.axes;
  const i128 one = i128(kOne);
  EXPECT_EQ(p.axes.size(), n) << what;
  if (p.axes.size() != n) return -1;
  const size_t rows = p.axes[0].rows.size();
  for (size_t i = 0; i < n; ++i) {
    EXPECT_EQ(p.axes[i].rows.size(), rows) << what << " axis " << i;
    EXPECT_EQ(p.axes[i].flags.size(), rows) << what << " axis " << i;
    if (p.axes[i].rows.size() != rows || p.axes[i].flags.size() != rows) return -1;
    for (size_t k = 0; k < rows; ++k) {
      EXPECT_EQ(p.axes[i].rows[k].clocks, p.axes[0].rows[k].clocks) << what << " axis " << i << " row " << k;
    }
  }
  // Every move planned or skipped, in order; skipped exactly where it goes nowhere.
  EXPECT_EQ(p.moves.size() + p.skipped.size(), r.moves.size()) << what;
  std::vector<int64_t> at = r.start.empty() ? std::vector<int64_t>(n, 0) : r.start;
  size_t planned = 0, skipped = 0, next_row = 0;
  uint64_t clock = 0;
  for (size_t k = 0; k < r.moves.size(); ++k) {
    const bool still = r.moves[k].target_pulses == at;
    if (still) {
      EXPECT_TRUE(skipped < p.skipped.size() && p.skipped[skipped].move == k) << what << " move " << k;
      ++skipped;
      continue;
    }
    at = r.moves[k].target_pulses;
    if (planned >= p.moves.size()) {
      ADD_FAILURE() << what << " move " << k << " not planned";
      return -1;
    }
    const PlannedPathMove& m = p.moves[planned++];
    EXPECT_EQ(m.move, k) << what;
    EXPECT_EQ(m.source_line, r.moves[k].source_line) << what;
    EXPECT_EQ(m.target, r.moves[k].target_pulses) << what;
    EXPECT_EQ(m.first_row, next_row) << what << " move " << k;
    EXPECT_EQ(m.start_clock, clock) << what << " move " << k;
    const size_t count = m.line.axes[0].segments.size();
    for (size_t i = 0; i < n; ++i) {
      for (size_t q = next_row; q < next_row + count && q < rows; ++q) {
        EXPECT_EQ(p.axes[i].flags[q].move_end, q + 1 == next_row + count) << what << " axis " << i << " row " << q;
        EXPECT_EQ(p.axes[i].flags[q].stream_end, q + 1 == rows) << what << " axis " << i << " row " << q;
      }
    }
    next_row += count;
    clock += m.line.total_clocks;
  }
  EXPECT_EQ(next_row, rows) << what;
  EXPECT_EQ(p.total_clocks, clock) << what;
  EXPECT_LT(p.max_line_deviation, 0.01) << what;

  // Each axis as one stream, in closed form over each row: every row starts
  // where the previous one ended (the executor stops on a discontinuity),
  // every move starts from the fraction the stream is at and ends at rest
  // in its target's pulse, without reversing.
  const Clock c{};
  for (size_t i = 0; i < n; ++i) {
    i128 pos = i128(r.start.empty() ? 0 : r.start[i]) * one + i128(p.axes[i].pos_frac0);
    i128 v = 0;
    int64_t a = 0;
    for (const PlannedPathMove& m : p.moves) {
      const Plan& axis = m.line.axes[i];
      const std::string where = what + " move " + std::to_string(m.move) + " axis " + std::to_string(i);
      EXPECT_EQ(axis.pos_frac0, u128(pos - floor_pulses(pos) * one)) << where;
      for (size_t q = m.first_row; q < m.first_row + axis.segments.size(); ++q) {
        const Segment& s = p.axes[i].rows[q];
        EXPECT_EQ(s.vel0, v) << where << " row " << q;
        EXPECT_EQ(s.acc0, a) << where << " row " << q;
        pos += pos_gain(v, a, s.jerk, s.clocks);
        v = vel_after(v, a, s.jerk, s.clocks);
        a = int64_t(acc_after(a, s.jerk, s.clocks));
      }
      EXPECT_EQ(v, 0) << where;
      EXPECT_EQ(a, 0) << where;
      EXPECT_EQ(int64_t(floor_pulses(pos)), m.target[i]) << where;
      const int64_t d = m.target[i] - m.start[i];
      const TableReport rep = run_table(axis.segments, axis.pos_frac0, d < 0 ? -1 : 1);
      EXPECT_GE(rep.min_signed_vel, 0) << where << ": reverses";
      // Within its share of the path limits (the share from the travels;
      // one LSB of rounding).
      double travel2 = 0;
      for (const Plan& o : m.line.axes) {
        const double t = double(run_table(o.segments, o.pos_frac0, 1).end_pos - i128(o.pos_frac0)) / kTwoPowFrac;
        travel2 += t * t;
      }
      const double share = std::fabs(double(rep.end_pos - i128(axis.pos_frac0)) / kTwoPowFrac) / std::sqrt(travel2);
      EXPECT_LE(double(rep.peak_jerk), std::ceil(r.limits.j * share * (1 + 1e-5) * jerk_lsb_per_unit(c)) + 1) << where;
      EXPECT_LE(double(rep.peak_acc), std::ceil(r.limits.a * share * (1 + 1e-5) * acc_lsb_per_unit(c)) + 1) << where;
      EXPECT_LE(vel_to_phys(rep.peak_vel, c), m.v_path * share * (1 + 1e-5) + 1e-6) << where;
    }
  }
  if (!per_clock) return -1;

  // Clock by clock from the path's start, each move against its line: from
  // where it starts to the middle of its targets' pulses.
  std::vector<i128> start(n);
  std::vector<const std::vector<Segment>*> row_tables(n);
  for (size_t i = 0; i < n; ++i) {
    start[i] = i128(r.start.empty() ? 0 : r.start[i]) * one + i128(p.axes[i].pos_frac0);
    row_tables[i] = &p.axes[i].rows;
  }
  test::AxesState state(start);
  double worst = 0;
  for (const PlannedPathMove& m : p.moves) {
    test::StraightLine line;
    line.lead = m.line.lead;
    for (size_t i = 0; i < n; ++i) {
      const long double from = (long double)state.pos[i] / (long double)one;
      line.anchor.push_back(from);
      line.direction.push_back(m.target[i] == m.start[i] ? 0.0L : (long double)m.target[i] + 0.5L - from);
    }
    const size_t count = m.line.axes[0].segments.size();
    worst = std::max(worst, test::run_rows_per_clock(row_tables, m.first_row, m.first_row + count, state, line));
    for (size_t i = 0; i < n; ++i) {
      EXPECT_EQ(int64_t(floor_pulses(state.pos[i])), m.target[i]) << what << " move " << m.move << " axis " << i;
      EXPECT_EQ(state.vel[i], 0) << what << " move " << m.move << " axis " << i;
    }
  }
  EXPECT_LT(worst, 0.01) << what;
  return worst;
}

// Each planned line is plan_line's of the same request: the line's
// distances, speed cap, the path limits, its move's jerks and the start
// fractions it starts from (the previous line's end), row for row.
void expect_lines_as_plan_line(const PathRequest& r, const PathPlan& p, const std::string& what) {
  for (const PlannedPathMove& m : p.moves) {
    LineRequest lr;
    for (size_t i = 0; i < r.axes; ++i) {
      lr.distances.push_back(m.target[i] - m.start[i]);
      lr.start_fracs.push_back(m.line.axes[i].pos_frac0);
    }
    lr.v_path = m.v_path;
    lr.a_path = r.limits.a;
    lr.j_path = r.limits.j;
    lr.jerks = r.moves[m.move].jerks;
    lr.axis_limits = r.axis_limits;
    const LineResult line = plan_line(Planner{}, lr, PulseTiming{});
    const std::string where = what + " move " + std::to_string(m.move);
    if (const Error* e = std::get_if<Error>(&line)) {
      ADD_FAILURE() << where << ": plan_line refuses: " << e->message;
      continue;
    }
    const LinePlan& l = std::get<LinePlan>(line);
    EXPECT_EQ(l.lead, m.line.lead) << where;
    ASSERT_EQ(l.axes.size(), m.line.axes.size()) << where;
    for (size_t i = 0; i < l.axes.size(); ++i) {
      EXPECT_TRUE(l.axes[i].segments == m.line.axes[i].segments) << where << " axis " << i;
      EXPECT_EQ(l.axes[i].pos_frac0, m.line.axes[i].pos_frac0) << where << " axis " << i;
    }
  }
}

// The lead axis's jerk magnitude in each phase of its S-curve, pulses/s^3
// (Ts1, Ts2, Te1, Te2 as LineRequest::jerks orders them; 0 where the
// phase has no row), and the clocks of the row it is read from: the first
// row of each phase, since the rows that remove the last velocity at the
// end reuse the deceleration's phases.
struct PhaseJerks {
  std::array<double, 4> jerk{};
  std::array<uint32_t, 4> clocks{};
};
PhaseJerks lead_phase_jerks(const LinePlan& line) {
  const Phase order[4] = {Phase::PhAccJerkUp, Phase::PhAccJerkDown, Phase::PhDecJerkUp, Phase::PhDecJerkDown};
  PhaseJerks j;
  for (const Segment& s : line.axes[line.lead].segments) {
    for (size_t q = 0; q < 4; ++q) {
      if (s.phase != order[q] || j.jerk[q] != 0) continue;
      j.jerk[q] = std::fabs(jerk_to_phys(s.jerk, Clock{}));
      j.clocks[q] = s.clocks;
    }
  }
  return j;
}

// The lead runs each requested jerk scaled to its share of the path: the
// same share in every phase, near its share of the distances. Within
// plan_from's landing: it trims a ramp's jerk by up to about 1/clocks of
// the ramp to land it exactly on its acceleration and speed (and the
// slowing down's jerks by a few 1e-6 to end it mid-pulse).
void expect_lead_runs_the_jerks(const PlannedPathMove& m, const std::array<double, 4>& requested,
                                const std::string& what) {
  const PhaseJerks lead = lead_phase_jerks(m.line);
  double length2 = 0;
  for (size_t i = 0; i < m.target.size(); ++i) length2 += double(m.target[i] - m.start[i]) * (m.target[i] - m.start[i]);
  const size_t l = m.line.lead;
  const double share = std::fabs(double(m.target[l] - m.start[l])) / std::sqrt(length2);
  const auto rounding = [&](size_t q) { return 2.0 / std::max<uint32_t>(1, lead.clocks[q]); };
  for (size_t q = 0; q < 4; ++q) {
    ASSERT_GT(lead.jerk[q], 0) << what << " jerk " << q << ": no row in its phase";
    // The share from the travels (from the start fractions to mid-pulse)
    // differs from the distances' by about a pulse in the line's length.
    const double ran = lead.jerk[q] / requested[q];
    EXPECT_NEAR(ran, share, share * (1e-4 + rounding(q)) + 1 / std::sqrt(length2)) << what << " jerk " << q;
    EXPECT_NEAR(ran, lead.jerk[0] / requested[0], share * (1e-5 + rounding(q) + rounding(0))) << what << " jerk " << q;
  }
}

}  // namespace

// ---- parsing ---------------------------------------------------------------------

TEST(PathFile, AbsoluteAndRelativeGCodeGiveTheSamePulses) {
  const PathProgram abs = cli::parse_path_gcode(
      "%\n"
      "(the same square twice: absolute here)\n"
      "G21 G90\n"
      "N10 G1 X12 Y80 F600 ; 10 mm/s\n"
      "N20 X72.004\n"
      "\n"
      "N30 Y140 (mid-line comment) F1200\n"
      "N40 g0 x12\n"
      "%\n");
  const PathProgram rel = cli::parse_path_gcode(
      "G91 ; relative\n"
      "G1 X12 Y80 F600\n"
      "X60.004\n"
      "Y60 F1200\n"
      "G0 X-60.004\n");
  EXPECT_EQ(targets(abs), targets(rel));
  const std::vector<std::vector<int64_t>> expected{{1200, 8000}, {7200, 8000}, {7200, 14000}, {1200, 14000}};
  EXPECT_EQ(targets(abs), expected);  // 72.004 mm is 7200.4 pulses: 7200
  ASSERT_EQ(abs.moves.size(), 4u);
  EXPECT_EQ(abs.moves[0].source_line, 4);
  EXPECT_EQ(abs.moves[1].source_line, 5);
  EXPECT_EQ(abs.moves[2].source_line, 7);
  EXPECT_EQ(abs.moves[3].source_line, 8);
  // F in mm/min, modal; G0 at the feed limit; 100 pulses/mm by default.
  EXPECT_NEAR(abs.moves[0].feed, 10 * 100, 1e-9);
  EXPECT_NEAR(abs.moves[1].feed, 10 * 100, 1e-9);
  EXPECT_NEAR(abs.moves[2].feed, 20 * 100, 1e-9);
  EXPECT_NEAR(abs.moves[3].feed, PathFileOptions::kDefaultFeedLimit * 100, 1e-9);
  EXPECT_EQ(abs.axes, 2u);
  EXPECT_EQ(abs.source, PathSource::kLine);
  EXPECT_DOUBLE_EQ(abs.limits.v, PathFileOptions::kDefaultFeedLimit * 100);
  EXPECT_DOUBLE_EQ(abs.limits.a, PathFileOptions::kDefaultAccel * 100);
  EXPECT_DOUBLE_EQ(abs.limits.j, PathFileOptions::kDefaultJerk * 100);
}

TEST(PathFile, GCodeThreeAxesPulsesPerMmAndCompactWords) {
  PathFileOptions o;
  o.axes = 3;
  o.pulses_per_mm = {200, 200, 400};
  const PathProgram p = cli::parse_path_gcode("G01X1.5Y-2Z.25F60\nG00 Z0\n", o);
  ASSERT_EQ(p.moves.size(), 2u);
  EXPECT_EQ(p.moves[0].target_pulses, (std::vector<int64_t>{300, -400, 100}));
  EXPECT_EQ(p.moves[1].target_pulses, (std::vector<int64_t>{300, -400, 0}));
  // 1 mm/s along a path whose axes have different pulses per mm: the move's
  // pulses over its mm.
  const double mm = std::sqrt(1.5 * 1.5 + 2.0 * 2.0 + 0.25 * 0.25);
  const double pulses = std::sqrt(300.0 * 300 + 400.0 * 400 + 100.0 * 100);
  EXPECT_NEAR(p.moves[0].feed, pulses / mm, 1e-9);
  EXPECT_DOUBLE_EQ(p.limits.a, PathFileOptions::kDefaultAccel * 200);  // the smallest pulses per mm
}

TEST(PathFile, RelativeMovesRoundEachAbsolutePositionOnceWithoutDrift) {
  // 1,000 moves of 0.001 mm = 0.1 pulse: rounded one by one they would all
  // be 0; rounded as absolute positions they reach 1 mm = 100 pulses.
  std::string text = "G91 G1 F60\n";
  for (int k = 0; k < 1000; ++k) text += "X0.001\n";
  const PathProgram p = cli::parse_path_gcode(text);
  ASSERT_EQ(p.moves.size(), 1000u);
  for (size_t k = 0; k < p.moves.size(); ++k) {
    EXPECT_NEAR(double(p.moves[k].target_pulses[0]), 0.1 * double(k + 1), 0.5 + 1e-9) << "move " << k;
    EXPECT_EQ(p.moves[k].target_pulses[1], 0);
  }
  EXPECT_EQ(p.moves.back().target_pulses[0], 100);
  // And planned: the moves that stay in the same pulse are skipped.
  const PathPlan plan = plan_or_fail(cli::to_path_request(p));
  EXPECT_EQ(plan.moves.size(), 100u);
  EXPECT_EQ(plan.skipped.size(), 900u);
  expect_exact_path(cli::to_path_request(p), plan, false, "1000 x 0.001 mm");
}

TEST(PathFile, JsonPointsFeedsStartAndLimitsInPulses) {
  const PathProgram p = cli::parse_path_json(R"({
    "axes": 2, "pulses_per_mm": [100, 50],
    "limits": {"feed": 20, "accel": 400, "jerk": 8000},
    "axis_limits": [{"v_max": 10}, {"a_max": 100, "j_max": 1000}],
    "start": [1, -2.25],
    "points": [[3.004, 4], {"to": [-5, 4.25], "feed": 5}]
  })");
  EXPECT_EQ(p.axes, 2u);
  EXPECT_EQ(p.source, PathSource::kPoint);
  // Halves round away from 0: -112.5 -> -113, 212.5 -> 213.
  EXPECT_EQ(p.start, (std::vector<int64_t>{100, -113}));
  ASSERT_EQ(p.moves.size(), 2u);
  EXPECT_EQ(p.moves[0].target_pulses, (std::vector<int64_t>{300, 200}));
  EXPECT_EQ(p.moves[1].target_pulses, (std::vector<int64_t>{-500, 213}));
  EXPECT_EQ(p.moves[0].source_line, 0);
  EXPECT_EQ(p.moves[1].source_line, 1);
  // The feed along the path: mm/s times the move's pulses over its mm.
  const double mm0 = std::hypot(200 / 100.0, 313 / 50.0), pulses0 = std::hypot(200.0, 313.0);
  EXPECT_NEAR(p.moves[0].feed, 20 * pulses0 / mm0, 1e-9);
  const double mm1 = std::hypot(800 / 100.0, 13 / 50.0), pulses1 = std::hypot(800.0, 13.0);
  EXPECT_NEAR(p.moves[1].feed, 5 * pulses1 / mm1, 1e-9);
  EXPECT_DOUBLE_EQ(p.limits.v, 20 * 50.0);
  ASSERT_EQ(p.axis_limits.size(), 2u);
  EXPECT_DOUBLE_EQ(p.axis_limits[0].v_max, 1000);
  EXPECT_DOUBLE_EQ(p.axis_limits[0].a_max, 0);  // not given: unbounded
  EXPECT_DOUBLE_EQ(p.axis_limits[1].a_max, 5000);
  EXPECT_DOUBLE_EQ(p.axis_limits[1].j_max, 50000);
}

TEST(PathFile, JsonPointJerksInPulsesAtTheSmallestPulsesPerMm) {
  const PathProgram p = cli::parse_path_json(R"({
    "axes": 2, "pulses_per_mm": [100, 50],
    "limits": {"feed": 20, "accel": 400, "jerk": 8000},
    "points": [[3, 4], {"to": [-5, 4], "jerks": [1000, 8000, 2.5, 7999.5]}, {"to": [0, 0], "feed": 5}]
  })");
  ASSERT_EQ(p.moves.size(), 3u);
  EXPECT_FALSE(p.moves[0].jerks.has_value());  // unset: the symmetric shape at limits.jerk
  ASSERT_TRUE(p.moves[1].jerks.has_value());
  // As the path's jerk limit: mm/s^3 times the smallest pulses_per_mm.
  EXPECT_EQ(*p.moves[1].jerks, (std::array<double, 4>{50000, 400000, 125, 399975}));
  EXPECT_DOUBLE_EQ(p.limits.j, 400000);
  EXPECT_FALSE(p.moves[2].jerks.has_value());
  EXPECT_EQ(cli::to_path_request(p).moves[1].jerks, p.moves[1].jerks);
}

TEST(PathFile, FormatFromTheExtensionElseTheContent) {
  const std::string json = R"({"axes": 2, "limits": {"feed": 10, "accel": 100, "jerk": 1000}, "points": [[1, 2]]})";
  EXPECT_EQ(cli::parse_path_text(json, "p.json").source, PathSource::kPoint);
  EXPECT_EQ(cli::parse_path_text(json, "p.txt").source, PathSource::kPoint);
  EXPECT_EQ(cli::parse_path_text("G0 X1\n", "p.NGC").source, PathSource::kLine);
  EXPECT_EQ(cli::parse_path_text("G0 X1\n", "p").source, PathSource::kLine);
  expect_names(parse_error([&] { cli::parse_path_text(json, "p.gcode"); }), {"line 1 col 1", "text={"});
  const auto missing = cli::load_path_file(kExamples + "/no_such_file.gcode");
  ASSERT_TRUE(std::holds_alternative<std::string>(missing));
  expect_names(std::get<std::string>(missing), {"no_such_file.gcode", "cannot read"});
}

// ---- bad input: the line (and column, word) and the parameter ------------------

TEST(PathFileErrors, JsonSyntaxErrorNamesTheLineAndColumn) {
  const std::string m = json_error("{\n  \"axes\": 2,\n  \"points\": [[1, 2],, [3, 4]]\n}\n");
  expect_names(m, {"line 3 col 21", "not JSON", "unexpected ','"});
}

TEST(PathFileErrors, GCodeSyntaxErrorNamesTheLineAndColumn) {
  expect_names(gcode_error("G1 F60\nG1 X10 #5\n"), {"line 2 col 8", "text=#5", "not G-code"});
  expect_names(gcode_error("G1 F60\n\nG1 X\n"), {"line 3 col 4 X", "needs a number"});
  expect_names(gcode_error("G1 X1.2.3 F60\n"), {"line 1 col 4 X=1.2.3", "needs a number"});
  expect_names(gcode_error("G1 F60 (no end\n"), {"line 1 col 8 comment", "not closed"});
  expect_names(gcode_error("G1 F60\nN5 G1 N6 X1\n"), {"line 2 col 7 N=6", "first word"});
  expect_names(gcode_error("G1 F60 X1 X2\n"), {"line 1 col 11 X=2", "conflicts with X1"});
  expect_names(gcode_error("G0 G1 X1 F60\n"), {"line 1 col 4 G=1", "conflicts with G0"});
  expect_names(gcode_error("X10\n"), {"line 1 col 1 X=10", "no motion mode"});
  expect_names(gcode_error("G90\nG1 X10\n"), {"line 2 col 1 G=1", "needs a feed"});
}

TEST(PathFileErrors, UnsupportedWordNamesTheLineAndTheWord) {
  expect_names(gcode_error("G1 F60\nM3 S1000\n"), {"line 2 col 1 M=3", "unsupported word M3"});
  expect_names(gcode_error("G1 F60 X1\nG2 X10 Y10 I5 J5\n"), {"line 2 col 1 G=2", "unsupported word G2"});
  expect_names(gcode_error("T1\n"), {"line 1 col 1 T=1", "unsupported word T1"});
  expect_names(gcode_error("G1 F60 X1\n\nG1 X2 S200\n"), {"line 3 col 7 S=200", "unsupported word S200"});
  expect_names(gcode_error("G1.5 X1\n"), {"line 1 col 1 G=1.5", "unsupported word G1.5"});
}

TEST(PathFileErrors, InchUnitsAreRefused) {
  expect_names(gcode_error("G20\nG1 X1 F60\n"), {"line 1 col 1 G=20", "inch", "G21"});
}

TEST(PathFileErrors, TargetBeyondThePositionRangeNamesTheBound) {
  // 21474836.47 mm at 100 pulses/mm is 2^31 - 1 pulses: one too many.
  expect_names(gcode_error("G1 F60 X1\nG1 Y21474836.47\n"), {"line 2 col 4 Y=21474836.47", "2147483646"});
  expect_names(gcode_error("G91 G1 F60 X21474836\nX0.46\nX0.01\n"), {"line 3 col 1 X=0.01", "position range"});
  expect_names(json_error(R"({"axes": 2, "limits": {"feed": 1, "accel": 1, "jerk": 1},
                              "points": [[1, 2], [-3e7, 0]]})"),
               {"points[1][0]=-30000000.0", "2147483646"});
  EXPECT_EQ(cli::parse_path_gcode("G1 F60 Y21474836.46\n").moves[0].target_pulses[1], 2147483646);
}

TEST(PathFileErrors, FeedZeroOrNegativeNamesTheLine) {
  expect_names(gcode_error("G1 X1 F0\n"), {"line 1 col 7 F=0", "> 0 mm/min"});
  expect_names(gcode_error("G1 X1 F60\nG1 X2 F-5\n"), {"line 2 col 7 F=-5", "> 0 mm/min"});
  expect_names(json_error(R"({"axes": 2, "limits": {"feed": 1, "accel": 1, "jerk": 1},
                              "points": [{"to": [1, 2], "feed": 0}]})"),
               {"points[0].feed=0", "> 0 mm/s"});
}

TEST(PathFileErrors, NonFiniteNumbersAreRefused) {
  expect_names(json_error("{\"axes\": 2,\n\"limits\": {\"feed\": 1e999, \"accel\": 1, \"jerk\": 1},\n"
                          "\"points\": [[1, 2]]}"),
               {"line 2 col 20", "1e999", "not a finite number"});
  expect_names(json_error(R"({"axes": 2, "limits": {"feed": 1, "accel": 1, "jerk": 1}, "points": [[NaN, 2]]})"),
               {"line 1 col", "not JSON"});
  expect_names(gcode_error("G1 F60\nG1 X1" + std::string(400, '0') + "\n"), {"line 2 col 4 X", "finite"});
}

TEST(PathFileErrors, WrongNumberOfCoordinatesNamesThePointOrTheAxis) {
  expect_names(json_error(R"({"axes": 2, "limits": {"feed": 1, "accel": 1, "jerk": 1},
                              "points": [[1, 2], [1, 2, 3]]})"),
               {"points[1]=[1,2,3]", "needs 2 coordinates"});
  expect_names(json_error(R"({"axes": 3, "limits": {"feed": 1, "accel": 1, "jerk": 1},
                              "start": [0, 0], "points": [[1, 2, 3]]})"),
               {"start=[0,0]", "needs 3 coordinates"});
  expect_names(gcode_error("G1 F60 X1 Y2 Z3\n"), {"line 1 col 14 Z=3", "no Z axis", "--axes 3"});
  PathFileOptions three;
  three.axes = 3;
  EXPECT_EQ(cli::parse_path_gcode("G1 F60 X1 Y2 Z3\n", three).moves[0].target_pulses.size(), 3u);
  PathFileOptions wrong_ppm;
  wrong_ppm.pulses_per_mm = {100, 100, 100};
  expect_names(gcode_error("G1 F60 X1\n", wrong_ppm), {"pulses_per_mm=3 values", "one per axis (2)"});
}

TEST(PathFileErrors, LimitsZeroOrNegativeNameTheLimit) {
  expect_names(json_error(R"({"axes": 2, "limits": {"feed": 1, "accel": 0, "jerk": 1}, "points": [[1, 2]]})"),
               {"limits.accel=0", "> 0 mm/s^2"});
  expect_names(json_error(R"({"axes": 2, "limits": {"feed": 1, "accel": 1, "jerk": 1},
                              "axis_limits": [{"v_max": -1}, {}], "points": [[1, 2]]})"),
               {"axis_limits[0].v_max=-1", "> 0 mm/s"});
  expect_names(json_error(R"({"axes": 2, "pulses_per_mm": [100, 0],
                              "limits": {"feed": 1, "accel": 1, "jerk": 1}, "points": [[1, 2]]})"),
               {"pulses_per_mm[1]=0", "> 0"});
  PathFileOptions o;
  o.jerk = -1;
  expect_names(gcode_error("G1 F60 X1\n", o), {"jerk=-1", "> 0 mm/s^3"});
  o = {};
  o.feed_limit = 0;
  expect_names(gcode_error("G0 X1\n", o), {"feed_limit=0", "> 0 mm/s"});
}

TEST(PathFileErrors, BadJerksNameThePointTheValueAndTheBound) {
  const auto with_jerks = [](const std::string& jerks) {
    return json_error("{\"axes\": 2, \"limits\": {\"feed\": 10, \"accel\": 100, \"jerk\": 1000},\n"
                      "\"points\": [[1, 2], {\"to\": [3, 4], \"jerks\": " + jerks + "}]}");
  };
  EXPECT_EQ(with_jerks("[1, 1000, 0.5, 999.999]"), "");
  expect_names(with_jerks("[100, 0, 100, 100]"), {"points[1].jerks[1]=0", "> 0 mm/s^3"});
  expect_names(with_jerks("[100, 100, -5, 100]"), {"points[1].jerks[2]=-5", "> 0 mm/s^3"});
  expect_names(with_jerks("[100, 100, 100, \"NaN\"]"), {"points[1].jerks[3]=\"NaN\"", "a finite number"});
  expect_names(with_jerks("[1000.5, 100, 100, 100]"), {"points[1].jerks[0]=1000.5", "<= limits.jerk=1000 mm/s^3"});
  expect_names(with_jerks("[100, 100, 100]"), {"points[1].jerks=[100,100,100]", "needs 4 jerks", "has 3"});
  expect_names(with_jerks("[100, 100, 100, 100, 100]"), {"points[1].jerks=", "needs 4 jerks", "has 5"});
  expect_names(with_jerks("100"), {"points[1].jerks=100", "JSON array"});
  // Not JSON numbers: the line and column where the parser stopped.
  expect_names(with_jerks("[100, 1e, 100, 100]"), {"line 2 col", "not JSON"});
  expect_names(with_jerks("[NaN, 100, 100, 100]"), {"line 2 col", "not JSON"});
  expect_names(with_jerks("[1e999, 100, 100, 100]"), {"line 2 col", "1e999", "not a finite number"});
  // Only in a point object.
  expect_names(json_error(R"({"axes": 2, "limits": {"feed": 10, "accel": 100, "jerk": 1000},
                              "jerks": [1, 1, 1, 1], "points": [[1, 2]]})"),
               {"path.jerks", "unknown key"});
}

// ---- plan_path ---------------------------------------------------------------------

TEST(PathPlanner, BadRequestsNameTheMoveAndItsSourceLine) {
  const auto error_of = [](const PathRequest& r) {
    const PathResult p = plan_path(Planner{}, r, PulseTiming{});
    const Error* e = std::get_if<Error>(&p);
    return e ? *e : Error{"", ""};
  };
  PathRequest ok;
  ok.axes = 2;
  ok.limits = {10000, 1e5, 1e6};
  ok.moves = {{{1000, 1000}, 5000, 3}, {{0, 2000}, 5000, 7}};
  EXPECT_EQ(error_of(ok).parameter, "");

  PathRequest r = ok;
  r.axes = 5;
  EXPECT_EQ(error_of(r).parameter, "axes");
  r = ok;
  r.start = {1};
  EXPECT_EQ(error_of(r).parameter, "start");
  r = ok;
  r.limits.a = 0;
  EXPECT_EQ(error_of(r).parameter, "limits.a");
  r = ok;
  r.moves.clear();
  EXPECT_EQ(error_of(r).parameter, "moves");
  r = ok;
  r.moves[1].target_pulses = {1, 2, 3};
  Error e = error_of(r);
  EXPECT_EQ(e.parameter, "target_pulses");
  EXPECT_EQ(e.message.rfind("move 1 (line 7): ", 0), 0u) << e.message;
  r = ok;
  r.moves[1].target_pulses = {0, int64_t(1) << 31};
  e = error_of(r);
  EXPECT_EQ(e.parameter, "target_pulses");
  expect_names(e.message, {"move 1 (line 7)", "target_pulses[1]=2147483648", "2147483646"});
  r = ok;
  r.moves[0].feed = -1;
  e = error_of(r);
  EXPECT_EQ(e.parameter, "feed");
  expect_names(e.message, {"move 0 (line 3)", "feed=-1"});
  // A line plan_line refuses: a path jerk whose lead share is below the
  // planner's range; from a JSON file, the point.
  r = ok;
  r.limits.j = 11;
  r.source = PathSource::kPoint;
  e = error_of(r);
  EXPECT_EQ(e.parameter, "j_path");
  EXPECT_EQ(e.message.rfind("move 0 (point 3): lead axis", 0), 0u) << e.message;
}

TEST(PathPlanner, BadJerksNameTheMoveItsSourceAndTheBound) {
  const auto error_of = [](const PathRequest& r) {
    const PathResult p = plan_path(Planner{}, r, PulseTiming{});
    const Error* e = std::get_if<Error>(&p);
    return e ? *e : Error{"", ""};
  };
  PathRequest ok;
  ok.axes = 2;
  ok.limits = {10000, 1e5, 1e6};
  ok.source = PathSource::kPoint;
  ok.moves = {{{1000, 1000}, 5000, 0}, {{0, 2000}, 5000, 1}, {{0, 2000}, 5000, 2}};
  ok.moves[1].jerks = std::array<double, 4>{2e5, 1e6, 5e5, 3e4};
  EXPECT_EQ(error_of(ok).parameter, "");
  for (double bad : {0.0, -1.0, std::nan(""), HUGE_VAL, 1e6 * (1 + 1e-12)}) {
    PathRequest r = ok;
    r.moves[1].jerks = std::array<double, 4>{1e6, bad, 1e6, 1e6};
    const Error e = error_of(r);
    EXPECT_EQ(e.parameter, "jerks") << bad;
    EXPECT_EQ(e.message.rfind("move 1 (point 1): jerks[1] (Ts2)=", 0), 0u) << e.message;
    expect_names(e.message, {"<= limits.j=1000000 pulses/s^3"});
  }
  // Also on a move to where the axes already are (skipped, never planned).
  PathRequest r = ok;
  r.moves[2].jerks = std::array<double, 4>{1e6, 1e6, 1e6, 2e6};
  Error e = error_of(r);
  EXPECT_EQ(e.parameter, "jerks");
  EXPECT_EQ(e.message.rfind("move 2 (point 2): jerks[3] (Te2)=2000000", 0), 0u) << e.message;
  // A jerk whose lead share is below the planner's range: plan_line's error.
  r = ok;
  r.moves[0].jerks = std::array<double, 4>{1, 1e6, 1e6, 1e6};
  e = error_of(r);
  EXPECT_EQ(e.parameter, "jerks");
  EXPECT_EQ(e.message.rfind("move 0 (point 0): lead axis", 0), 0u) << e.message;
}

TEST(PathPlanner, ZeroLengthMovesAreSkippedNotRefused) {
  PathRequest r;
  r.axes = 2;
  r.start = {5, 5};
  r.limits = {20000, 1e6, 1e8};
  r.moves = {{{5, 5}, 20000, 1}, {{500, -300}, 20000, 2}, {{500, -300}, 20000, 3}, {{-20, 7}, 20000, 4}};
  const PathPlan p = plan_or_fail(r);
  ASSERT_EQ(p.skipped.size(), 2u);
  EXPECT_EQ(p.skipped[0].move, 0u);
  EXPECT_EQ(p.skipped[1].source_line, 3);
  ASSERT_EQ(p.moves.size(), 2u);
  expect_exact_path(r, p, true, "skips");
}

TEST(PathPlanner, Paper003SquareEndsEveryMoveExactlyOnItsTarget) {
  // The paper's limits as printed: v_max 0.6 mm/s, a_max 0.009 mm/s^2, j_max
  // 1.01e5 mm/s^3 (the feed is the file's F36, 0.6 mm/s).
  PathFileOptions o;
  o.feed_limit = 0.6;
  o.accel = 0.009;
  o.jerk = 1.01e5;
  const auto loaded = cli::load_path_file(kExamples + "/paper003_square.gcode", o);
  ASSERT_TRUE(std::holds_alternative<PathProgram>(loaded)) << std::get<std::string>(loaded);
  const PathProgram& program = std::get<PathProgram>(loaded);
  const std::vector<std::vector<int64_t>> corners{{1200, 8000}, {7200, 8000}, {7200, 14000}, {1200, 14000}};
  EXPECT_EQ(targets(program), corners);
  const PathRequest r = cli::to_path_request(program);
  const PathPlan p = plan_or_fail(r);
  ASSERT_EQ(p.moves.size(), 4u);
  expect_exact_path(r, p, false, "paper 003 square");  // 2e10 clocks: closed form only
  std::printf("paper 003 square: %zu rows, %.1f s, max line deviation %.3g pulse\n", p.axes[0].rows.size(),
              p.duration_s, p.max_line_deviation);
}

TEST(PathPlanner, Paper002CornerEndsEveryMoveExactlyOnItsTarget) {
  const auto loaded = cli::load_path_file(kExamples + "/paper002_corner.json");
  ASSERT_TRUE(std::holds_alternative<PathProgram>(loaded)) << std::get<std::string>(loaded);
  const PathProgram& program = std::get<PathProgram>(loaded);
  EXPECT_EQ(targets(program), (std::vector<std::vector<int64_t>>{{7071, 7071}, {0, 14142}}));
  const PathRequest r = cli::to_path_request(program);
  EXPECT_DOUBLE_EQ(r.limits.a, 1e5);  // 1 m/s^2 at 100 pulses/mm
  EXPECT_DOUBLE_EQ(r.limits.j, 1e6);  // 10 m/s^3
  const PathPlan p = plan_or_fail(r);
  ASSERT_EQ(p.moves.size(), 2u);
  const double measured = expect_exact_path(r, p, true, "paper 002 corner");
  std::printf("paper 002 corner: %zu rows, %.4f s, max line deviation %.3g pulse (clock by clock %.3g)\n",
              p.axes[0].rows.size(), p.duration_s, p.max_line_deviation, measured);
}

TEST(PathPlanner, Paper002AsymmetricCornerRunsEachLinesJerksAndEndsExactly) {
  const auto loaded = cli::load_path_file(kExamples + "/paper002_asymmetric.json");
  ASSERT_TRUE(std::holds_alternative<PathProgram>(loaded)) << std::get<std::string>(loaded);
  const PathProgram& program = std::get<PathProgram>(loaded);
  EXPECT_EQ(targets(program), (std::vector<std::vector<int64_t>>{{7071, 7071}, {0, 14142}}));
  const PathRequest r = cli::to_path_request(program);
  ASSERT_TRUE(r.moves[0].jerks && r.moves[1].jerks);
  EXPECT_DOUBLE_EQ((*r.moves[0].jerks)[0], 136610);  // 1366.1 mm/s^3 at 100 pulses/mm
  EXPECT_DOUBLE_EQ((*r.moves[1].jerks)[3], 2870);
  const PathPlan p = plan_or_fail(r);
  ASSERT_EQ(p.moves.size(), 2u);
  const double measured = expect_exact_path(r, p, true, "paper 002 asymmetric corner");
  expect_lines_as_plan_line(r, p, "paper 002 asymmetric corner");
  for (const PlannedPathMove& m : p.moves) {
    expect_lead_runs_the_jerks(m, *r.moves[m.move].jerks, "paper 002 asymmetric corner move " +
                                                               std::to_string(m.move));
  }
  // The same file without its jerks: the symmetric corner, the rows of
  // every jerk at limits.jerk.
  PathRequest symmetric = r, full = r;
  for (PathMove& m : symmetric.moves) m.jerks.reset();
  for (PathMove& m : full.moves) m.jerks = std::array<double, 4>{r.limits.j, r.limits.j, r.limits.j, r.limits.j};
  const PathPlan s = plan_or_fail(symmetric), f = plan_or_fail(full);
  for (size_t i = 0; i < 2; ++i) EXPECT_TRUE(s.axes[i].rows == f.axes[i].rows) << "axis " << i;
  EXPECT_GT(p.total_clocks, s.total_clocks);
  std::printf("paper 002 asymmetric corner: %zu rows, %.4f s (symmetric %.4f s), max line deviation %.3g pulse "
              "(clock by clock %.3g)\n",
              p.axes[0].rows.size(), p.duration_s, s.duration_s, p.max_line_deviation, measured);
}

namespace {

// Random G-code paths: points in both directions on every axis, some
// axes still, some moves of a few pulses, some to where the axes are
// already; parsed, checked against the rounding, planned and checked.
void random_paths(size_t axes, int count, uint64_t seed) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto log_u = [&](double lo, double hi) {
    return std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * u(g));
  };
  double worst_reported = 0, worst_measured = 0;
  double plan_seconds = 0;
  size_t planned_moves = 0, clock_checked = 0;
  for (int n = 0; n < count; ++n) {
    // Every third path short and fast enough to run clock by clock.
    const bool short_path = n % 3 == 0;
    PathFileOptions o;
    o.axes = axes;
    const double ppm = std::round(log_u(50, 400));
    o.pulses_per_mm.assign(axes, ppm);
    if (n % 10 == 5) o.pulses_per_mm[axes - 1] = std::round(ppm * 1.6);  // axes of different resolution
    o.feed_limit = short_path ? 100 : log_u(20, 250);
    o.accel = short_path ? log_u(2000, 20000) : log_u(200, 20000);
    o.jerk = short_path ? log_u(1e6, 1e7) : log_u(1e4, 1e7);
    const double range = short_path ? 0.5 : 30;
    std::string text = "G21 G90\n";
    std::vector<double> mm(axes, 0.0);
    std::vector<std::vector<int64_t>> expected;
    const int moves = 3 + int(g() % 6);
    for (int k = 0; k < moves; ++k) {
      const int kind = int(g() % 20);
      for (size_t i = 0; i < axes; ++i) {
        if (kind == 0) break;  // to where the axes are already
        if (kind == 1) {
          mm[i] += std::round(6 * u(g) - 3) / 100;  // a few pulses
        } else if (g() % 8 != 0) {
          mm[i] = (2 * u(g) - 1) * range;  // else this axis stays still
        }
        mm[i] = std::stod(mm_text(mm[i]));  // as the file says it
      }
      text += g() % 6 == 0 ? "G0" : "G1";
      for (size_t i = 0; i < axes; ++i) text += " " + std::string(1, "XYZ"[i]) + mm_text(mm[i]);
      text += " F" + std::to_string(int(60 * (short_path ? log_u(20, 100) : log_u(5, 200)))) + "\n";
      std::vector<int64_t> t(axes);
      for (size_t i = 0; i < axes; ++i) t[i] = std::llround(mm[i] * o.pulses_per_mm[i]);
      expected.push_back(t);
    }
    const std::string what = std::to_string(axes) + "-axis path " + std::to_string(n);
    PathProgram program;
    try {
      program = cli::parse_path_gcode(text, o);
    } catch (const input::Error& e) {
      ADD_FAILURE() << what << ": " << e.what() << "\n" << text;
      continue;
    }
    EXPECT_EQ(targets(program), expected) << what;
    const PathRequest r = cli::to_path_request(program);
    const auto t0 = std::chrono::steady_clock::now();
    const PathResult result = plan_path(Planner{}, r, PulseTiming{});
    plan_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (const Error* e = std::get_if<Error>(&result)) {
      ADD_FAILURE() << what << ": " << e->parameter << ": " << e->message << "\n" << text;
      continue;
    }
    const PathPlan& p = std::get<PathPlan>(result);
    planned_moves += p.moves.size();
    const bool per_clock = p.total_clocks < 3'000'000;
    clock_checked += per_clock;
    const double measured = expect_exact_path(r, p, per_clock, what + "\n" + text);
    worst_reported = std::max(worst_reported, p.max_line_deviation);
    worst_measured = std::max(worst_measured, measured);
  }
  std::printf("%d random %zu-axis paths, %zu moves: max line deviation %.3g pulse (clock by clock on %zu paths: "
              "%.3g), plan_path %.0f us per move\n",
              count, axes, planned_moves, worst_reported, clock_checked, worst_measured,
              1e6 * plan_seconds / double(std::max<size_t>(1, planned_moves)));
}

}  // namespace

TEST(PathPlanner, RandomTwoAxisPathsEndEveryMoveExactly) { random_paths(2, 100, 11); }

TEST(PathPlanner, RandomThreeAxisPathsEndEveryMoveExactly) { random_paths(3, 30, 13); }

// Random paths in pulses on 2 and 3 axes, most lines with their own
// random jerks down to 1/50 of the path's jerk limit, some axes still:
// every move ends exactly, each line is plan_line's and its lead runs the
// requested jerks.
TEST(PathPlanner, RandomPathsWithAsymmetricJerksEndEveryMoveExactly) {
  std::mt19937_64 g(31);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto log_u = [&](double lo, double hi) {
    return std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * u(g));
  };
  size_t with_jerks = 0, clock_checked = 0;
  const int count = 40;
  for (int n = 0; n < count; ++n) {
    PathRequest r;
    r.axes = 2 + size_t(n % 2);
    r.limits = {log_u(5e3, 4e4), log_u(1e6, 8e6), log_u(2e8, 4e9)};
    std::vector<int64_t> at(r.axes, 0);
    const int moves = 2 + int(g() % 4);
    for (int k = 0; k < moves; ++k) {
      PathMove m;
      m.target_pulses = at;
      do {
        for (size_t i = 0; i < r.axes; ++i) {
          if (g() % 6 == 0) continue;  // this axis still
          m.target_pulses[i] = at[i] + int64_t(std::llround((2 * u(g) - 1) * log_u(20, 6000)));
        }
      } while (m.target_pulses == at);
      m.feed = r.limits.v * log_u(0.3, 1.5);
      m.source_line = k;
      if (g() % 4 != 0) {
        m.jerks.emplace();
        for (double& j : *m.jerks) j = r.limits.j * log_u(0.02, 1);
        ++with_jerks;
      }
      at = m.target_pulses;
      r.moves.push_back(m);
    }
    const std::string what = std::to_string(r.axes) + "-axis path " + std::to_string(n);
    const PathPlan p = plan_or_fail(r);
    if (p.moves.empty()) continue;
    const bool per_clock = p.total_clocks < 3'000'000;
    clock_checked += per_clock;
    expect_exact_path(r, p, per_clock, what);
    expect_lines_as_plan_line(r, p, what);
    for (const PlannedPathMove& m : p.moves) {
      if (r.moves[m.move].jerks) {
        expect_lead_runs_the_jerks(m, *r.moves[m.move].jerks, what + " move " + std::to_string(m.move));
      }
    }
  }
  std::printf("%d random paths, %zu lines with their own jerks, %zu paths checked clock by clock\n", count,
              with_jerks, clock_checked);
}
