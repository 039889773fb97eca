#include "path_cli.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "multi_run.h"
#include "planner.h"
#include "rtl_multi_axis_core.h"
#include "scurve/cli/path_file.h"
#include "scurve/cli/user_input.h"
#include "scurve/path_planner.h"

namespace sc {

using scurve::cli::bad_input;
using scurve::cli::real_flag;

void add_path_command(CLI::App& app, PathCli& p) {
  CLI::App* c = app.add_subcommand(
      "path", "plan a path file (JSON points or G-code) with exact stops and run it on the multi-axis core");
  p.cmd = c;
  c->add_option("FILE", p.file, "path file: .json points or G-code (G0/G1 X Y Z F, G90/G91, G21)")->required();
  scurve::cli::int_flag(c, "--axes", p.axes, 1, 3,
                        "axes: G-code 1 to 3 (X, X Y, X Y Z; default 2), JSON must match its \"axes\"");
  c->add_option("--pulses-per-mm", p.pulses_per_mm,
                "pulses per mm, one per axis (default: the file's, else 100 = 10 um per pulse)")
      ->expected(1, 4);
  real_flag(c, "--feed-limit", p.feed_limit, "G-code: highest feed and G0's, mm/s (default 100)", 0, 1e6);
  real_flag(c, "--accel", p.accel, "G-code: path acceleration, mm/s^2 (default 1000)", 0, 1e9);
  real_flag(c, "--jerk", p.jerk, "G-code: path jerk, mm/s^3 (default 10000)", 0, 1e12);
  c->add_option("--junction", p.junction, "junctions: exact-stop (every axis at rest at every corner)")
      ->check(CLI::IsMember({"exact-stop"}));
  c->add_option("--engine", p.engine, "lockstep (default: RTL and model, every clock compared) | model")
      ->check(CLI::IsMember({"lockstep", "model"}));
  scurve::cli::add_timing_flags(c, p.timing);
  scurve::cli::add_output_flags(c, p.timing);
}

namespace {

nlohmann::json report_json(const scurve::cli::PathProgram& prog, const scurve::PathPlan& plan,
                           const MultiRunResult& r, const std::string& engine, const std::vector<std::string>& fails) {
  nlohmann::json out;
  out["engine"] = engine;
  out["axes"] = prog.axes;
  out["pulses_per_mm"] = prog.pulses_per_mm;
  out["moves"] = nlohmann::json::array();
  for (size_t k = 0; k < plan.moves.size(); ++k) {
    const scurve::PlannedPathMove& m = plan.moves[k];
    nlohmann::json j{{"move", m.move},
                     {"source_line", m.source_line},
                     {"target", m.target},
                     {"v_path", m.v_path},
                     {"planned_start_clock", m.start_clock},
                     {"planned_clocks", m.line.total_clocks}};
    if (k < r.move_ends.size()) {
      std::vector<int64_t> end;
      for (size_t a = 0; a < prog.axes; ++a) end.push_back(int64_t(r.move_ends[k].ref_pos[a]) + prog.start[a]);
      j["end_clock"] = r.move_ends[k].clock;
      j["end_position"] = end;
    }
    out["moves"].push_back(j);
  }
  out["skipped_moves"] = plan.skipped.size();
  std::vector<int64_t> final_pos;
  for (size_t a = 0; a < prog.axes; ++a) final_pos.push_back(int64_t(r.ref_pos[a]) + prog.start[a]);
  out["final_position"] = final_pos;
  out["pin_steps"] = r.pin_steps;
  out["clocks"] = r.clocks;
  out["duration_s"] = double(r.clocks) / double(ClkHz);
  out["planned_duration_s"] = plan.duration_s;
  out["path_length_pulses"] = plan.path_length;
  out["contour_error_max_pulses"] = r.contour_max;
  out["contour_error_rms_pulses"] = r.contour_rms;
  out["planned_max_line_deviation_pulses"] = plan.max_line_deviation;
  out["peak_path_velocity"] = r.peak_path_velocity;
  out["peak_path_acceleration"] = r.peak_path_acceleration;
  out["peak_axis_velocity"] = r.peak_velocity;
  out["peak_axis_acceleration"] = r.peak_acceleration;
  out["peak_axis_jerk"] = r.peak_jerk;
  out["mismatches"] = r.mismatches;
  out["compared_clocks"] = r.compared;
  out["wall_s"] = r.wall_seconds;
  out["clocks_per_s"] = r.wall_seconds > 0 ? double(r.clocks) / r.wall_seconds : 0.0;
  out["failures"] = fails;
  out["pass"] = fails.empty();
  return out;
}

std::string report_table(const scurve::cli::PathProgram& prog, const scurve::PathPlan& plan,
                         const MultiRunResult& r, const std::string& engine, const std::vector<std::string>& fails) {
  std::string t = fmt::format("{:>4} {:>6} {:>28} {:>12} {:>12} {:>28}\n", "move", "line", "target (pulses)",
                              "v path p/s", "end clock", "end position");
  auto join = [](const auto& v) { return fmt::format("{}", fmt::join(v, " ")); };
  for (size_t k = 0; k < plan.moves.size(); ++k) {
    const scurve::PlannedPathMove& m = plan.moves[k];
    std::string end = "-", clock = "-";
    if (k < r.move_ends.size()) {
      std::vector<int64_t> e;
      for (size_t a = 0; a < prog.axes; ++a) e.push_back(int64_t(r.move_ends[k].ref_pos[a]) + prog.start[a]);
      end = join(e);
      clock = std::to_string(r.move_ends[k].clock);
    }
    t += fmt::format("{:>4} {:>6} {:>28} {:>12.1f} {:>12} {:>28}\n", m.move, m.source_line, join(m.target), m.v_path,
                     clock, end);
  }
  std::vector<int64_t> final_pos;
  for (size_t a = 0; a < prog.axes; ++a) final_pos.push_back(int64_t(r.ref_pos[a]) + prog.start[a]);
  t += fmt::format("engine {}: {} axes, {} moves ({} skipped), {} clocks = {:.6f} s (planned {:.6f} s)\n", engine,
                   prog.axes, plan.moves.size(), plan.skipped.size(), r.clocks, double(r.clocks) / double(ClkHz),
                   plan.duration_s);
  t += fmt::format("final position {} (pins {})\n", join(final_pos), join(r.pin_steps));
  t += fmt::format("contour error: max {:.3g} pulses, rms {:.3g} pulses (planned line deviation {:.3g})\n",
                   r.contour_max, r.contour_rms, plan.max_line_deviation);
  t += fmt::format("peak path velocity {:.1f} pulses/s, acceleration {:.4g} pulses/s^2\n", r.peak_path_velocity,
                   r.peak_path_acceleration);
  for (size_t a = 0; a < prog.axes; ++a) {
    t += fmt::format("  axis {}: peak velocity {:.1f}, acceleration {:.4g}, jerk {:.4g}\n", a, r.peak_velocity[a],
                     r.peak_acceleration[a], r.peak_jerk[a]);
  }
  t += fmt::format("mismatches {} over {} clocks; {:.2f} s wall, {:.3g} clocks/s\n", r.mismatches, r.compared,
                   r.wall_seconds, r.wall_seconds > 0 ? double(r.clocks) / r.wall_seconds : 0.0);
  for (const std::string& f : fails) t += "FAIL: " + f + "\n";
  t += fails.empty() ? "PASS\n" : "FAIL\n";
  return t;
}

}  // namespace

int run_path_cli(const PathCli& p) {
  scurve::cli::PathFileOptions fo;
  fo.axes = p.axes;
  if (p.feed_limit > 0) fo.feed_limit = p.feed_limit;
  if (p.accel > 0) fo.accel = p.accel;
  if (p.jerk > 0) fo.jerk = p.jerk;
  try {
    for (size_t i = 0; i < p.pulses_per_mm.size(); ++i) {
      fo.pulses_per_mm.push_back(
          scurve::input::parse_real(fmt::format("pulses-per-mm[{}]", i), p.pulses_per_mm[i], 1e-3, 1e7));
    }
  } catch (const scurve::input::Error& e) {
    return bad_input(e.what());
  }
  auto loaded = scurve::cli::load_path_file(p.file, fo);
  if (const std::string* e = std::get_if<std::string>(&loaded)) return bad_input(*e);
  const scurve::cli::PathProgram& prog = std::get<scurve::cli::PathProgram>(loaded);
  if (p.engine == "lockstep" && !RtlMultiAxisCore::supported(prog.axes)) {
    return bad_input(fmt::format("axes={}: the RTL is built for 2 and 3 axes (use --engine model)", prog.axes));
  }
  const PulseTiming timing = to_model(scurve::cli::to_timing(p.timing));
  auto planned = scurve::plan_path(scurve::Planner{model_clock()}, scurve::cli::to_path_request(prog), to_host(timing));
  if (const scurve::Error* e = std::get_if<scurve::Error>(&planned)) return bad_input(e->message);
  const scurve::PathPlan& plan = std::get<scurve::PathPlan>(planned);
  if (plan.moves.empty()) return bad_input("FILE=" + p.file + ": every move is to where the axes already are");

  MultiRows rows;
  for (const scurve::PathAxisRows& ax : plan.axes) {
    std::vector<Row> r;
    r.reserve(ax.rows.size());
    for (size_t k = 0; k < ax.rows.size(); ++k) r.push_back(Row{to_model(ax.rows[k]), row_flags(ax.flags[k])});
    rows.rows.push_back(std::move(r));
    rows.pos_frac0.push_back(ax.pos_frac0);
  }
  MultiRunOptions o;
  o.rtl = p.engine == "lockstep";
  o.timing = timing;
  o.measure_line = false;
  // The plan's clocks, the arming of each START and a margin: a path that
  // does not come to rest by then fails (it does not run on without end).
  o.max_clocks = plan.total_clocks + 1'000'000;
  // The polyline in the reference's coordinates (REF_POS starts at 0): each
  // move's start point with the fraction the plan starts it from, the end
  // mid-pulse on the last target.
  const double one = std::ldexp(1.0, FracBits);
  for (const scurve::PlannedPathMove& m : plan.moves) {
    std::vector<double> v;
    for (size_t a = 0; a < prog.axes; ++a) {
      v.push_back(double(m.start[a] - prog.start[a]) + double(m.line.axes[a].pos_frac0) / one);
    }
    o.polyline.push_back(std::move(v));
  }
  std::vector<double> last;
  for (size_t a = 0; a < prog.axes; ++a) last.push_back(double(plan.moves.back().target[a] - prog.start[a]) + 0.5);
  o.polyline.push_back(std::move(last));
  const bool tty = isatty(2);
  o.progress = [&](double x) {
    if (tty) std::fprintf(stderr, "\r[path %3.0f%%]", 100 * std::min(1.0, x));
  };
  const MultiRunResult r = run_multi(rows, o);
  if (tty) std::fputs("\n", stderr);

  // The independent checks: every move ends on its target on every axis,
  // the pins agree, the reference stays on the polyline.
  std::vector<std::string> fails = r.errors;
  if (r.mismatches > 0) fails.push_back(fmt::format("{} mismatching clocks", r.mismatches));
  if (r.move_ends.size() != plan.moves.size()) {
    fails.push_back(fmt::format("{} of {} moves completed", r.move_ends.size(), plan.moves.size()));
  }
  for (size_t k = 0; k < std::min(r.move_ends.size(), plan.moves.size()); ++k) {
    for (size_t a = 0; a < prog.axes; ++a) {
      const int64_t end = int64_t(r.move_ends[k].ref_pos[a]) + prog.start[a];
      if (end != plan.moves[k].target[a]) {
        fails.push_back(fmt::format("move {} axis {}: ended at {}, target {}", plan.moves[k].move, a, end,
                                    plan.moves[k].target[a]));
      }
    }
  }
  for (size_t a = 0; a < prog.axes; ++a) {
    if (r.pin_steps[a] != int64_t(r.ref_pos[a])) {
      fails.push_back(fmt::format("axis {}: {} net steps on the pins, REF_POS {}", a, r.pin_steps[a], r.ref_pos[a]));
    }
  }
  if (r.contour_max >= 0.01) fails.push_back(fmt::format("contour error {:.3g} pulses >= 0.01", r.contour_max));

  const nlohmann::json out = report_json(prog, plan, r, p.engine, fails);
  if (p.timing.json) {
    std::cout << out.dump(2) << "\n";
  } else {
    std::cout << report_table(prog, plan, r, p.engine, fails);
  }
  if (!scurve::cli::write_json_file(p.timing.json_out, out)) {
    return bad_input("--json-out: cannot write " + p.timing.json_out);
  }
  return fails.empty() ? 0 : 1;
}

}  // namespace sc
