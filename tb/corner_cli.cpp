#include "corner_cli.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <vector>

#include "multi_run.h"
#include "planner.h"
#include "scurve/cli/user_input.h"
#include "scurve/corner_search.h"

namespace sc {

using scurve::cli::bad_input;

namespace {

// Paper 002's own figures (its GA-tuned shape on its model), metres.
constexpr double kPaperContourError = 4.0348e-7;
constexpr double kPaperCornerError = 3.9319e-7;

// The two lines as one row stream: the first ends its move (MOVE_END), the
// second the stream; each line's start fractions for a START of its own.
MultiRows corner_rows(const scurve::CornerPlan& plan) {
  MultiRows m;
  const size_t axes = plan.lines[0].axes.size();
  m.rows.resize(axes);
  for (size_t k = 0; k < 2; ++k) {
    std::vector<u128> fracs;
    for (size_t a = 0; a < axes; ++a) {
      const scurve::Plan& p = plan.lines[k].axes[a];
      std::vector<Segment> segs;
      for (const scurve::Segment& s : p.segments) segs.push_back(to_model(s));
      for (const Row& r : move_rows(segs, /*stream_end=*/k == 1)) m.rows[a].push_back(r);
      fracs.push_back(p.pos_frac0);
      if (k == 0) m.pos_frac0.push_back(p.pos_frac0);
    }
    m.move_frac0.push_back(std::move(fracs));
  }
  return m;
}

struct ShapeRun {
  MultiRunResult result;
  std::vector<std::string> fails;
};

// One shape on the multi-axis core: each axis on its integer target at the
// corner and at the end, pins = REF_POS, the reference on the two lines.
ShapeRun run_shape(const scurve::CornerPlan& plan, bool rtl, const char* name) {
  const MultiRows rows = corner_rows(plan);
  MultiRunOptions o;
  o.rtl = rtl;
  o.measure_line = false;
  uint64_t clocks = 0;
  for (const scurve::LinePlan& l : plan.lines) clocks += l.total_clocks;
  o.max_clocks = clocks + 1'000'000;
  const double one = std::ldexp(1.0, FracBits);
  std::vector<double> origin, corner, end;
  for (size_t a = 0; a < 2; ++a) {
    origin.push_back(double(plan.lines[0].axes[a].pos_frac0) / one);
    corner.push_back(double(plan.distances[0][a]) + double(plan.lines[1].axes[a].pos_frac0) / one);
    end.push_back(double(plan.distances[0][a] + plan.distances[1][a]) + 0.5);
  }
  o.polyline = {origin, corner, end};
  const bool tty = isatty(2);
  o.progress = [&](double x) {
    if (tty) std::fprintf(stderr, "\r[corner %s %3.0f%%]", name, 100 * std::min(1.0, x));
  };
  ShapeRun s{run_multi(rows, o), {}};
  if (tty) std::fputs("\n", stderr);
  const MultiRunResult& r = s.result;
  s.fails = r.errors;
  if (r.mismatches > 0) s.fails.push_back(fmt::format("{} mismatching clocks", r.mismatches));
  if (r.move_ends.size() != 2) s.fails.push_back(fmt::format("{} of 2 lines completed", r.move_ends.size()));
  for (size_t k = 0; k < std::min<size_t>(2, r.move_ends.size()); ++k) {
    for (size_t a = 0; a < 2; ++a) {
      const int64_t want = plan.distances[0][a] + (k == 1 ? plan.distances[1][a] : 0);
      if (r.move_ends[k].ref_pos[a] != want) {
        s.fails.push_back(fmt::format("line {} axis {}: ended at {}, target {}", k + 1, a, r.move_ends[k].ref_pos[a],
                                      want));
      }
    }
  }
  for (size_t a = 0; a < 2; ++a) {
    if (r.pin_steps[a] != int64_t(r.ref_pos[a])) {
      s.fails.push_back(fmt::format("axis {}: {} net steps on the pins, REF_POS {}", a, r.pin_steps[a], r.ref_pos[a]));
    }
  }
  if (r.contour_max >= 0.01) s.fails.push_back(fmt::format("contour error {:.3g} pulses >= 0.01", r.contour_max));
  return s;
}

nlohmann::json shape_json(const scurve::CornerCandidate& c) {
  return {{"times_first_s", c.times.first},
          {"times_second_s", c.times.second},
          {"jerks_first_m_per_s3", c.first_jerks},
          {"jerks_second_m_per_s3", c.second_jerks},
          {"fitness", c.score.fitness},
          {"contour_error_m", c.score.contour_error},
          {"contour_error_max_m", c.score.contour_error_max},
          {"corner_error_m", c.score.corner_error},
          {"duration_s", c.score.duration},
          {"dwell_s", c.score.dwell}};
}

}  // namespace

void add_corner_command(CLI::App& app, CornerCli& c) {
  CLI::App* cmd = app.add_subcommand(
      "corner", "paper 002's corner: search its asymmetric jerks, score them beside the paper, run both shapes");
  c.cmd = cmd;
  scurve::cli::int_flag(cmd, "--seed", c.seed, 0, int64_t(1) << 53, "the search's random seed (default 1)");
  scurve::cli::int_flag(cmd, "--budget", c.budget, 20, 1'000'000,
                        "fitness evaluations of the search (default 2000: about a minute)");
  cmd->add_option("--engine", c.engine,
                  "lockstep (default: RTL and model every clock) | model | none (the search and its scores only)")
      ->check(CLI::IsMember({"lockstep", "model", "none"}));
  scurve::cli::add_output_flags(cmd, c.output);
}

int run_corner_cli(const CornerCli& c) {
  scurve::CornerRequest req;
  req.seed = c.seed;
  req.budget = c.budget;
  const auto searched = scurve::search_corner(req);
  if (const auto* e = std::get_if<scurve::Error>(&searched)) return bad_input(e->message);
  const scurve::CornerSearchResult& s = std::get<scurve::CornerSearchResult>(searched);

  nlohmann::json out;
  out["request"] = {{"line_length_m", req.line_length}, {"feed_m_per_s", req.feed}, {"accel_m_per_s2", req.accel},
                    {"jerk_m_per_s3", req.jerk}, {"pulses_per_m", req.pulses_per_metre},
                    {"stop_tolerance_m", req.stop_tolerance}, {"servo_bandwidth_hz", req.servo_x.bandwidth_hz},
                    {"seed", req.seed}, {"budget", req.budget}};
  out["symmetric"] = shape_json(s.symmetric);
  out["searched"] = shape_json(s.best);
  out["evaluations"] = s.evaluations;
  out["generations"] = s.generations;
  out["paper"] = {{"contour_error_m", kPaperContourError}, {"corner_error_m", kPaperCornerError},
                  {"fitness", 10000 * (0.8 * kPaperContourError + 0.2 * kPaperCornerError)}};
  std::vector<std::string> fails;
  if (s.best.score.fitness > s.symmetric.score.fitness) fails.push_back("the search ended above the symmetric shape");

  std::string table = fmt::format(
      "paper 002 corner: 2 lines of {} m at 45 and 135 degrees, feed {} m/s, A {} m/s^2, J {} m/s^3, exact stop "
      "fine {} m; errors on a {} Hz servo model per axis\n",
      req.line_length, req.feed, req.accel, req.jerk, req.stop_tolerance, req.servo_x.bandwidth_hz);
  table += fmt::format("{:<10} {:>12} {:>14} {:>14} {:>10}  {}\n", "shape", "fitness", "contour (m)", "corner (m)",
                       "time (s)", "Ts1 Ts2 Te1 Te2 (s), line 1 | line 2");
  auto row = [&](const char* name, const scurve::CornerCandidate& k) {
    table += fmt::format("{:<10} {:>12.4g} {:>14.4g} {:>14.4g} {:>10.4f}  {:.4f} | {:.4f}\n", name, k.score.fitness,
                         k.score.contour_error, k.score.corner_error, k.score.duration,
                         fmt::join(k.times.first, " "), fmt::join(k.times.second, " "));
  };
  row("symmetric", s.symmetric);
  row("searched", s.best);
  table += fmt::format("{:<10} {:>12.4g} {:>14.4g} {:>14.4g} {:>10}  (its GA-tuned shape on its own model)\n",
                       "paper 002", 10000 * (0.8 * kPaperContourError + 0.2 * kPaperCornerError),
                       kPaperContourError, kPaperCornerError, "-");
  table += fmt::format("search: genetic algorithm then compass search, seed {}, {} evaluations, {} generations\n",
                       req.seed, s.evaluations, s.generations);

  nlohmann::json runs = nlohmann::json::object();
  if (c.engine != "none") {
    const bool rtl = c.engine == "lockstep";
    for (const auto& [name, cand] : {std::pair{"symmetric", &s.symmetric}, std::pair{"searched", &s.best}}) {
      const auto planned = scurve::plan_corner(req, cand->times);
      if (const auto* e = std::get_if<scurve::Error>(&planned)) return bad_input(e->message);
      const ShapeRun run = run_shape(std::get<scurve::CornerPlan>(planned), rtl, name);
      const MultiRunResult& r = run.result;
      std::vector<std::vector<int32_t>> ends;
      for (const MultiMoveEnd& e : r.move_ends) ends.push_back(e.ref_pos);
      runs[name] = {{"clocks", r.clocks},         {"line_ends", ends},        {"pin_steps", r.pin_steps},
                    {"mismatches", r.mismatches}, {"compared_clocks", r.compared},
                    {"contour_error_max_pulses", r.contour_max},           {"wall_s", r.wall_seconds},
                    {"failures", run.fails}};
      table += fmt::format("{} {}: {} clocks, lines end at ({}) and ({}), pins ({}), contour error {:.3g} pulses, "
                           "{} mismatches over {} clocks, {:.1f} s wall\n",
                           c.engine, name, r.clocks,
                           r.move_ends.size() > 0 ? fmt::format("{}", fmt::join(r.move_ends[0].ref_pos, ", ")) : "-",
                           r.move_ends.size() > 1 ? fmt::format("{}", fmt::join(r.move_ends[1].ref_pos, ", ")) : "-",
                           fmt::join(r.pin_steps, ", "), r.contour_max, r.mismatches, r.compared, r.wall_seconds);
      for (const std::string& f : run.fails) fails.push_back(fmt::format("{}: {}", name, f));
    }
  }
  out["runs"] = runs;
  out["engine"] = c.engine;
  out["failures"] = fails;
  out["pass"] = fails.empty();
  for (const std::string& f : fails) table += "FAIL: " + f + "\n";
  table += fails.empty() ? "PASS\n" : "FAIL\n";
  if (c.output.json) {
    std::cout << out.dump(2) << "\n";
  } else {
    std::cout << table;
  }
  if (!scurve::cli::write_json_file(c.output.json_out, out)) {
    return bad_input("--json-out: cannot write " + c.output.json_out);
  }
  return fails.empty() ? 0 : 1;
}

}  // namespace sc
