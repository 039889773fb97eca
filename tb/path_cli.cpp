#include "path_cli.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <optional>
#include <string_view>

#include "closed_loop_cli.h"
#include "closed_loop_run.h"
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
  c->add_option("--junction", p.junction,
                "junctions: exact-stop (every axis at rest at every corner) | exact-stop-fine (with --closed-loop: "
                "the next line starts once every axis is in position within --tolerance) | blend (the next line "
                "starts while the last decelerates, within --tolerance of the corner)")
      ->check(CLI::IsMember({"exact-stop", "exact-stop-fine", "blend"}));
  c->add_option("--tolerance", p.tolerance,
                "blend: the largest distance of the tool from a corner point; exact-stop-fine: the in-position "
                "window of every axis; mm (in pulses: times the smallest --pulses-per-mm)")
      ->type_name("MM");
  c->add_option("--engine", p.engine, "lockstep (default: RTL and model, every clock compared) | model")
      ->check(CLI::IsMember({"lockstep", "model"}));
  c->add_flag("--closed-loop", p.closed_loop,
              "every axis in its own closed loop (the --controller settings, by default the neuron-PI cascade) "
              "on the stepper plant model; lockstep: 2 axes");
  add_controller_flags(c, p.ctl, "Closed loop (with --closed-loop)");
  c->add_option("--plot", p.plot_dir,
                "write path_trace.csv (the reference sampled, at most ~200,000 samples) and path_xy.png, "
                "path_axes.png here (created if missing; python3 with matplotlib)")
      ->type_name("DIR");
  scurve::cli::add_timing_flags(c, p.timing);
  scurve::cli::add_output_flags(c, p.timing);
}

namespace {

// --plot: a trace of at most about this many samples (plus the move ends).
constexpr uint64_t kMaxTraceSamples = 200'000;
constexpr const char* kTraceCsv = "path_trace.csv";
constexpr const char* kPlotFiles[] = {"path_xy.png", "path_axes.png", kTraceCsv};

// Where the figures go and what draws them, all checked before the run.
struct PlotSetup {
  std::string dir, csv;
  std::string python, script;
  uint64_t every = 1;  // trace sample period, clocks
};

std::string last_line(const std::string& text) {
  const size_t end = text.find_last_not_of(" \t\r\n");
  if (end == std::string::npos) return "(no output)";
  const size_t begin = text.find_last_of('\n', end);
  const size_t from = begin == std::string::npos ? 0 : begin + 1;
  std::string line = text.substr(from, end + 1 - from);
  return line.size() > 300 ? line.substr(0, 300) + "..." : line;
}

// Runs argv (no shell) with its stdout and stderr collected in `output`; the
// exit status, or -1 when it could not be started (the reason in `output`).
int run_program(const std::vector<std::string>& argv, std::string& output) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) {
    output = std::strerror(errno);
    return -1;
  }
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_adddup2(&fa, fds[1], 1);
  posix_spawn_file_actions_adddup2(&fa, fds[1], 2);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, args[0], &fa, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  ::close(fds[1]);
  if (rc != 0) {
    ::close(fds[0]);
    output = argv[0] + ": " + std::strerror(rc);
    return -1;
  }
  char buf[4096];
  for (;;) {
    const ssize_t n = ::read(fds[0], buf, sizeof buf);
    if (n > 0) {
      output.append(buf, size_t(n));
    } else if (n == 0 || errno != EINTR) {
      break;
    }
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

// The directory (created if missing) and its files can be written, and
// python3 with matplotlib and the plot script are there: the one-line
// reason, or empty.
std::string prepare_plot(const std::string& dir, PlotSetup& s) {
  namespace fs = std::filesystem;
  auto why = [&dir](const std::string& text) { return fmt::format("--plot={}: {}", dir, text); };
  std::error_code ec;
  if (dir.empty()) return fmt::format("--plot='': required: a directory");
  // The script travels with the binaries (share/scurve next to bin/).
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  s.script = ((ec ? fs::path(".") : self.parent_path()).parent_path() / "share/scurve/plot_path.py").string();
  if (!fs::is_regular_file(s.script, ec)) return why("no plot script " + s.script + " (share/scurve/ next to bin/)");
  // Debian's matplotlib (python3-matplotlib) is /usr/bin/python3's; SCURVE_PYTHON names another.
  const char* env = std::getenv("SCURVE_PYTHON");
  s.python = env && *env ? env : ::access("/usr/bin/python3", X_OK) == 0 ? "/usr/bin/python3" : "python3";
  std::string out;
  const int rc = run_program({s.python, "-c", "import matplotlib, numpy"}, out);
  if (rc != 0) {
    return why(fmt::format("needs python3 with matplotlib (Debian: apt-get install python3-matplotlib): {}",
                           rc < 0 ? out : s.python + ": " + last_line(out)));
  }
  fs::create_directories(dir, ec);
  if (ec) return why("cannot create the directory: " + ec.message());
  if (!fs::is_directory(dir, ec)) return why("not a directory");
  if (::access(dir.c_str(), W_OK | X_OK) != 0) return why("directory is not writable");
  for (const char* f : kPlotFiles) {
    const fs::path path = fs::path(dir) / f;
    const fs::file_status st = fs::status(path, ec);
    if (fs::exists(st) && !fs::is_regular_file(st)) return why(path.string() + " exists and is not a regular file");
    if (fs::exists(st) && ::access(path.c_str(), W_OK) != 0) return why(path.string() + " is not writable");
  }
  s.dir = dir;
  s.csv = (fs::path(dir) / kTraceCsv).string();
  // A file can be made there (a read-only or special file system says so only now).
  const std::string probe = s.csv + ".part";
  std::FILE* f = std::fopen(probe.c_str(), "w");
  if (!f) return why(fmt::format("cannot write {}: {}", probe, std::strerror(errno)));
  std::fclose(f);
  std::remove(probe.c_str());
  return {};
}

// The figures from the trace: the script's last line when it fails or
// leaves a figure unwritten, else empty.
std::string draw_plots(const PlotSetup& s) {
  namespace fs = std::filesystem;
  std::vector<fs::path> figures;
  for (const char* f : kPlotFiles) {
    if (std::string_view(f) != kTraceCsv) figures.push_back(fs::path(s.dir) / f);
  }
  std::error_code ec;
  for (const fs::path& f : figures) fs::remove(f, ec);  // a stale figure must not pass for a new one
  std::string log;
  const int rc = run_program({s.python, s.script, s.csv, "--out-dir", s.dir}, log);
  if (rc != 0) return fmt::format("{} {} failed: {}", s.python, s.script, last_line(log));
  for (const fs::path& f : figures) {
    if (!fs::is_regular_file(f, ec) || fs::file_size(f, ec) == 0) {
      return fmt::format("{} {} wrote no {}", s.python, s.script, f.string());
    }
  }
  return {};
}

// The trace as CSV: "# key=value" lines (what the plot script needs besides
// the samples: the polyline, the resolution, the move ends), the header and
// one row per sample. Written to "<csv>.part" and renamed when whole; the
// reason it could not be, or empty.
std::string write_trace_csv(const PlotSetup& s, const std::string& file, const std::string& engine,
                            const scurve::cli::PathProgram& prog, const std::vector<std::vector<double>>& polyline,
                            const MultiRunResult& r, bool pass) {
  const MultiTrace& t = r.trace;
  const size_t n = prog.axes;
  std::string buf;
  auto out = std::back_inserter(buf);
  fmt::format_to(out, "# scurve path trace: the reference (closed loop: and the measured position) sampled from "
                      "START, at every move end and at the end\n");
  fmt::format_to(out, "# file={}\n# engine={}\n# axes={}\n# clk_hz={}\n# every_clocks={}\n# samples={}\n",
                 scurve::input::printable(file), engine, n, ClkHz, s.every, t.size());
  fmt::format_to(out, "# pulses_per_mm={}\n# start={}\n", fmt::join(prog.pulses_per_mm, ","),
                 fmt::join(prog.start, ","));
  // The planned polyline in the file's coordinates (pulses).
  for (const std::vector<double>& v : polyline) {
    std::vector<double> p;
    for (size_t a = 0; a < n; ++a) p.push_back(v[a] + double(prog.start[a]));
    fmt::format_to(out, "# vertex={}\n", fmt::join(p, ","));
  }
  std::vector<double> ends;
  for (const MultiMoveEnd& e : r.move_ends) ends.push_back(double(e.clock) / double(ClkHz));
  fmt::format_to(out, "# move_end_s={}\n# contour_max_pulses={}\n# pass={}\n", fmt::join(ends, ","), r.contour_max,
                 pass);
  fmt::format_to(out, "t_s");
  for (size_t a = 0; a < n; ++a) fmt::format_to(out, ",pos{}_pulses", a);
  for (size_t a = 0; a < n; ++a) fmt::format_to(out, ",vel{}_pulses_per_s", a);
  fmt::format_to(out, ",contour_error_pulses");
  const bool loop = !t.measured.empty();
  for (size_t a = 0; loop && a < n; ++a) fmt::format_to(out, ",meas{}_pulses", a);
  fmt::format_to(out, "\n");

  const std::string part = s.csv + ".part";
  std::FILE* f = std::fopen(part.c_str(), "w");
  if (!f) return fmt::format("cannot write {}: {}", part, std::strerror(errno));
  bool ok = true;
  for (size_t i = 0; i < t.size() && ok; ++i) {
    fmt::format_to(out, "{:.8f}", double(t.clock[i]) / double(ClkHz));
    // Positions in the file's coordinates: REF_POS is their floor.
    for (size_t a = 0; a < n; ++a) fmt::format_to(out, ",{:.9f}", t.pos[i * n + a] + double(prog.start[a]));
    for (size_t a = 0; a < n; ++a) fmt::format_to(out, ",{:.6f}", t.vel[i * n + a]);
    fmt::format_to(out, ",{:.6g}", t.contour[i]);
    for (size_t a = 0; loop && a < n; ++a) {
      fmt::format_to(out, ",{:.4f}", t.measured[i * n + a] + double(prog.start[a]));
    }
    fmt::format_to(out, "\n");
    if (buf.size() > (1u << 20)) {
      ok = std::fwrite(buf.data(), 1, buf.size(), f) == buf.size();
      buf.clear();
    }
  }
  ok = ok && std::fwrite(buf.data(), 1, buf.size(), f) == buf.size() && std::fflush(f) == 0;
  ok = std::fclose(f) == 0 && ok;
  if (!ok || std::rename(part.c_str(), s.csv.c_str()) != 0) {
    const std::string e = fmt::format("writing {} failed: {}", s.csv, std::strerror(errno));
    std::remove(part.c_str());
    return e;
  }
  return {};
}

nlohmann::json report_json(const scurve::cli::PathProgram& prog, const scurve::PathPlan& plan,
                           const MultiRunResult& r, const std::string& engine, const std::vector<std::string>& fails,
                           const PlotSetup* plot) {
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
                     {"planned_clocks", m.line.total_clocks},
                     {"blend_clocks", m.blend_clocks},
                     {"corner_deviation_pulses", m.corner_deviation}};
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
  out["exact_stop_duration_s"] = double(plan.exact_stop_clocks) / double(ClkHz);
  out["max_corner_deviation_pulses"] = plan.max_corner_deviation;
  out["path_length_pulses"] = plan.path_length;
  out["contour_error_max_pulses"] = r.contour_max;
  out["contour_error_rms_pulses"] = r.contour_rms;
  out["planned_max_line_deviation_pulses"] = plan.max_line_deviation;
  out["peak_path_velocity"] = r.peak_path_velocity;
  out["peak_path_acceleration"] = r.peak_path_acceleration;
  out["peak_axis_velocity"] = r.peak_velocity;
  out["peak_axis_acceleration"] = r.peak_acceleration;
  out["peak_axis_jerk"] = r.peak_jerk;
  out["junction_wait_clocks"] = r.junction_wait;
  out["corner_error_pulses"] = r.corner_error;
  out["closed_loop"] = !r.in_pos.empty();
  if (!r.in_pos.empty()) {
    out["measured_final_position"] = r.measured_pos;
    out["max_tracking_error_pulses"] = r.max_tracking_error;
    out["overshoot_pulses"] = r.overshoot;
    out["overshoot_percent"] = r.overshoot_percent;
    out["steady_state_error_pulses"] = r.final_error;
    out["in_position"] = r.in_pos;
    out["measured_contour_error_max_pulses"] = r.measured_contour_max;
    out["measured_contour_error_rms_pulses"] = r.measured_contour_rms;
  }
  out["mismatches"] = r.mismatches;
  out["compared_clocks"] = r.compared;
  out["wall_s"] = r.wall_seconds;
  out["clocks_per_s"] = r.wall_seconds > 0 ? double(r.clocks) / r.wall_seconds : 0.0;
  out["plot"] = nullptr;
  if (plot) {
    std::vector<std::string> files;
    for (const char* f : kPlotFiles) files.push_back((std::filesystem::path(plot->dir) / f).string());
    out["plot"] = {{"files", files}, {"samples", r.trace.size()}, {"every_clocks", plot->every}};
  }
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
  t += fmt::format("engine {}: {} axes, {} moves ({} skipped), {} clocks = {:.6f} s (planned {:.6f} s, with exact "
                   "stops {:.6f} s)\n", engine, prog.axes, plan.moves.size(), plan.skipped.size(), r.clocks,
                   double(r.clocks) / double(ClkHz), plan.duration_s, double(plan.exact_stop_clocks) / double(ClkHz));
  if (plan.max_corner_deviation > 0) {
    t += fmt::format("blended corners: max distance from a corner point {:.4g} pulses\n", plan.max_corner_deviation);
  }
  t += fmt::format("final position {} (pins {})\n", join(final_pos), join(r.pin_steps));
  t += fmt::format("contour error: max {:.3g} pulses, rms {:.3g} pulses (planned line deviation {:.3g})\n",
                   r.contour_max, r.contour_rms, plan.max_line_deviation);
  t += fmt::format("peak path velocity {:.1f} pulses/s, acceleration {:.4g} pulses/s^2\n", r.peak_path_velocity,
                   r.peak_path_acceleration);
  for (size_t a = 0; a < prog.axes; ++a) {
    t += fmt::format("  axis {}: peak velocity {:.1f}, acceleration {:.4g}, jerk {:.4g}\n", a, r.peak_velocity[a],
                     r.peak_acceleration[a], r.peak_jerk[a]);
  }
  for (size_t k = 0; k < r.junction_wait.size(); ++k) {
    t += fmt::format("corner {}: settled in {} clocks ({:.3f} ms) after the move's last row, measured {:.3g} pulses "
                     "from the corner\n", k + 1, r.junction_wait[k], 1e3 * double(r.junction_wait[k]) / double(ClkHz),
                     r.corner_error[k]);
  }
  if (!r.in_pos.empty()) {
    t += fmt::format("closed loop: measured contour error max {:.3g} pulses, rms {:.3g} pulses\n",
                     r.measured_contour_max, r.measured_contour_rms);
    for (size_t a = 0; a < prog.axes; ++a) {
      t += fmt::format("  axis {}: measured {:.0f}, max tracking error {:.3g} pulses, overshoot {:.3g} pulses "
                       "({:.3g} %), steady-state error {}, {}\n", a, r.measured_pos[a] + double(prog.start[a]),
                       r.max_tracking_error[a], r.overshoot[a], r.overshoot_percent[a], r.final_error[a],
                       r.in_pos[a] ? "in position" : "NOT in position");
    }
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
  const bool blend = p.junction == "blend", fine = p.junction == "exact-stop-fine";
  double tolerance_mm = 0;
  try {
    if (!p.closed_loop) {
      if (p.cmd->count("--controller") > 0) {
        throw scurve::input::Error("controller", scurve::controller_kind_name(p.ctl.values.kind),
                                   "needs --closed-loop");
      }
      for (size_t i = 0; i < p.ctl.given.size(); ++i) {
        const ControllerParam& prm = controller_params()[i];
        if (p.ctl.given[i]) {
          throw scurve::input::Error(prm.flag, fmt::format("{}", prm.get(p.ctl.values)),
                                     "a controller setting: needs --closed-loop");
        }
      }
    }
    if (fine && !p.closed_loop) {
      throw scurve::input::Error("junction", p.junction,
                                 "needs --closed-loop (the open loop has no measured position to settle)");
    }
    if ((blend || fine) && p.tolerance.empty()) {
      throw scurve::input::Error("tolerance", "(none)", "--junction " + p.junction + " needs --tolerance MM > 0");
    }
    if (!blend && !fine && !p.tolerance.empty()) {
      throw scurve::input::Error("tolerance", p.tolerance, "only with --junction blend or exact-stop-fine");
    }
    if (blend || fine) tolerance_mm = scurve::input::parse_real("tolerance", p.tolerance, 1e-9, 1e6);
  } catch (const scurve::input::Error& e) {
    return bad_input(e.what());
  }
  auto loaded = scurve::cli::load_path_file(p.file, fo);
  if (const std::string* e = std::get_if<std::string>(&loaded)) return bad_input(*e);
  const scurve::cli::PathProgram& prog = std::get<scurve::cli::PathProgram>(loaded);
  // The tolerance in pulse space: a deviation of d pulses is at most
  // d / (the smallest pulses per mm) mm on the table.
  const double tolerance =
      tolerance_mm * *std::min_element(prog.pulses_per_mm.begin(), prog.pulses_per_mm.end());
  if (p.engine == "lockstep" && !RtlMultiAxisCore::supported(prog.axes, p.closed_loop)) {
    return bad_input(fmt::format("axes={}: the RTL is built for 2 and 3 axes{} (use --engine model)", prog.axes,
                                 p.closed_loop ? ", 2 with --closed-loop" : ""));
  }
  const PulseTiming timing = to_model(scurve::cli::to_timing(p.timing));
  scurve::PathRequest request = scurve::cli::to_path_request(prog);
  if (blend) {
    request.junction = scurve::Junction::kBlend;
    request.tolerance = tolerance;
  }
  auto planned = scurve::plan_path(scurve::Planner{model_clock()}, request, to_host(timing));
  if (const scurve::Error* e = std::get_if<scurve::Error>(&planned)) return bad_input(e->message);
  const scurve::PathPlan& plan = std::get<scurve::PathPlan>(planned);
  if (plan.moves.empty()) return bad_input("FILE=" + p.file + ": every move is to where the axes already are");

  // --plot is checked (the directory made) once the path is known good, before the run.
  std::optional<PlotSetup> plot;
  if (p.cmd->count("--plot") > 0) {
    plot.emplace();
    if (const std::string e = prepare_plot(p.plot_dir, *plot); !e.empty()) return bad_input(e);
  }

  const MultiRows rows = path_rows(plan);
  MultiRunOptions o;
  o.rtl = p.engine == "lockstep";
  o.timing = timing;
  o.measure_line = false;
  o.contour_adjacent = blend;
  o.check_phases = !blend;
  // The plan's clocks, the arming of each START and a margin: a path that
  // does not come to rest by then fails (it does not run on without end).
  o.max_clocks = plan.total_clocks + 1'000'000;
  o.settle_each_move = fine;
  if (p.closed_loop) {
    MultiLoop loop;
    ServoConfig cfg;
    ControllerParams ctl = p.ctl.resolve();
    // exact-stop-fine: the in-position window is the tolerance (whole pulses:
    // the loop compares whole encoder counts).
    if (fine) ctl.inpos_win = std::floor(tolerance);
    if (const std::string e = to_servo_config(ctl, loop.plant, timing, cfg); !e.empty()) {
      return bad_input(e);
    }
    loop.ctl = cfg.ctl;
    o.loop = loop;
    // the loops settle after the reference (at every corner with exact-stop-fine)
    o.max_clocks += uint64_t(ClkHz) * (fine ? plan.moves.size() : 1);
  }
  o.polyline = path_polyline(plan);
  const bool tty = isatty(2);
  o.progress = [&](double x) {
    if (tty) std::fprintf(stderr, "\r[path %3.0f%%]", 100 * std::min(1.0, x));
  };
  if (plot) {
    // At most ~kMaxTraceSamples samples over the planned clocks (the move
    // ends and the last clock add a few).
    plot->every = std::max<uint64_t>(1, (plan.total_clocks + kMaxTraceSamples - 1) / kMaxTraceSamples);
    o.trace_every = plot->every;
  }
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
      // Where the plan puts the reference when the move's last row ends: its
      // target with exact stops; in a blend the target plus what the next
      // move covered by then (the last move: its target).
      const int64_t end = int64_t(r.move_ends[k].ref_pos[a]) + prog.start[a];
      const int64_t planned_end = int64_t(plan.moves[k].end_position[a] >> FracBits);
      if (end != planned_end) {
        fails.push_back(fmt::format("move {} axis {}: ended at {}, planned {} (target {})", plan.moves[k].move, a,
                                    end, planned_end, plan.moves[k].target[a]));
      }
    }
  }
  for (size_t a = 0; a < prog.axes; ++a) {
    if (r.pin_steps[a] != int64_t(r.ref_pos[a])) {
      fails.push_back(fmt::format("axis {}: {} net steps on the pins, REF_POS {}", a, r.pin_steps[a], r.ref_pos[a]));
    }
  }
  // Exact stops keep the reference on the lines; a blend within the
  // tolerance of each corner (which bounds its distance from the lines).
  const double contour_bound = blend ? tolerance * (1 + 1e-9) + 1e-6 : 0.01;
  if (r.contour_max >= contour_bound) {
    fails.push_back(fmt::format("contour error {:.3g} pulses >= {:.3g}", r.contour_max, contour_bound));
  }
  const scurve::PlannedPathMove& final_move = plan.moves.back();
  for (size_t a = 0; a < prog.axes && !r.ref_pos.empty(); ++a) {
    if (int64_t(r.ref_pos[a]) + prog.start[a] != final_move.target[a]) {
      fails.push_back(fmt::format("axis {}: ended at {}, the path's target {}", a,
                                  int64_t(r.ref_pos[a]) + prog.start[a], final_move.target[a]));
    }
  }
  // exact-stop-fine: each next line started with every axis within its
  // window of the corner (per axis: within sqrt(axes) windows in distance).
  const double corner_bound = std::sqrt(double(prog.axes)) * std::floor(tolerance) + 1e-9;
  for (size_t k = 0; k < r.corner_error.size(); ++k) {
    if (r.corner_error[k] > corner_bound) {
      fails.push_back(fmt::format("corner {}: the next line started {:.3g} pulses from the corner (> {:.3g})", k + 1,
                                  r.corner_error[k], corner_bound));
    }
  }
  for (size_t a = 0; a < r.in_pos.size(); ++a) {
    // The loop settles on the target (steady-state error 0) and tracks
    // within the single-axis closed loop's bound (the neuron cascade with
    // its feed-forward; the PID lags by about v / Kp by design and is
    // bounded by its following-error limit, a fault otherwise).
    if (!r.in_pos[a]) fails.push_back(fmt::format("axis {}: not in position at the end", a));
    if (r.final_error[a] != 0) fails.push_back(fmt::format("axis {}: steady-state error {}", a, r.final_error[a]));
    if (r.ferr[a]) fails.push_back(fmt::format("axis {}: following-error fault", a));
    if (p.ctl.values.kind == scurve::ControllerKind::kNeuron && r.max_tracking_error[a] >= kMaxErrorWithFf) {
      fails.push_back(fmt::format("axis {}: tracking error {:.3g} pulses >= {}", a, r.max_tracking_error[a],
                                  kMaxErrorWithFf));
    }
  }

  const nlohmann::json out = report_json(prog, plan, r, p.engine, fails, plot ? &*plot : nullptr);
  if (p.timing.json) {
    std::cout << out.dump(2) << "\n";
  } else {
    std::cout << report_table(prog, plan, r, p.engine, fails);
  }
  if (!scurve::cli::write_json_file(p.timing.json_out, out)) {
    return bad_input("--json-out: cannot write " + p.timing.json_out);
  }
  if (plot) {
    // The figures of a failed run too: that is when they are wanted.
    const std::string e = write_trace_csv(*plot, p.file, p.engine, prog, o.polyline, r, fails.empty());
    if (!e.empty()) return bad_input(fmt::format("--plot={}: {}", plot->dir, e));
    const std::string drawn = draw_plots(*plot);
    if (!drawn.empty()) return bad_input(fmt::format("--plot={}: {}", plot->dir, drawn));
    if (!p.timing.json) {
      std::cout << fmt::format("plot: {} ({} samples, every {} clocks)\n",
                               fmt::join(out["plot"]["files"].get<std::vector<std::string>>(), ", "),
                               r.trace.size(), plot->every);
    }
  }
  return fails.empty() ? 0 : 1;
}

}  // namespace sc
