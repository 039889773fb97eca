// scurve: plan S-curve moves and run them on the RTL and the bit-exact model.
//   scurve plan --distance L --v-start VS --v-cruise VC --v-end VE --a-max A --j-max J [--clock-hz F] [--json]
//   scurve sim  (same move flags | --group 1 2 3 4) [--engine ...] [--stop-at T] [--json]
//   scurve regs (same move flags) [--uart] [--no-start] [--closed-loop] [--json]   register writes
//   scurve stream FILE [--engine ...] [--json]   a stream of moves with look-ahead junctions
//   scurve jog [--target V[:T] ...] [--stop] [--engine ...] [--json]   velocity mode (jog)
//   scurve path FILE [--axes N] [--engine lockstep|model] [--plot DIR] [--json]   a path file on the multi-axis core
//   scurve corner [--seed N] [--budget N] [--engine lockstep|model|none] [--json]   paper 002's corner, jerks searched
//   scurve home [--switch-at N] [--runs N] [--engine ...] [--json]   homing against a switch in the plant
//   scurve virtual-board [--pty-link PATH] [--speed X]   the board top behind a pseudo-terminal
//   scurve board --port DEV info|status|run|stream|stop|estop|clear|home|watch   a board over its UART
// plan and regs are the host commands (sw/, scurve::host_cli); sim, regress,
// diff run the RTL and the model.
// Exit codes: 0 ok, 1 a check failed, 2 bad input (one line on stderr).
#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <atomic>
#include <cstdio>
#include <iostream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <thread>

#include "closed_loop_cli.h"
#include "corner_cli.h"
#include "square_cli.h"
#include "fst_flags.h"
#include "planner.h"
#include "report.h"
#include "scurve/cli/host_commands.h"
#include "scurve/cli/move_flags.h"
#include "scenarios.h"
#include "sim_run.h"
#include "stream_run.h"
#include "homing_cli.h"
#include "jog_cli.h"
#include "path_cli.h"
#include "scurve/reg_encode.h"
#include "tool_commands.h"
#include "virtual_board.h"

namespace {

using namespace sc;

using scurve::cli::bad_input;
using scurve::cli::MoveFlags;
using scurve::cli::write_json_file;

// The limits a run is checked against: the request's (not the plan's own).
Limits4Check limits_of(const MoveRequest& r, double v_end_used) {
  Limits4Check l;
  l.v_max = std::max({r.v_cruise, r.v_start, v_end_used});
  l.a_max = r.a_max;
  if (r.kind == ProfileKind::SCurve) {
    l.j_max = r.jerks ? std::max({(*r.jerks)[0], (*r.jerks)[1], (*r.jerks)[2], (*r.jerks)[3]}) : r.j_max;
  }
  return l;
}

// The same limits in the model's time base: the model counts clocks, so a
// plan for a board at `clock` runs in the model as if time ran ClkHz/clock
// times faster (speeds x r, accelerations x r^2, jerks x r^3, r = ClkHz/clock).
Limits4Check at_model_clock(Limits4Check l, scurve::Clock clock) {
  const double r = double(ClkHz) / clock.hz;
  l.v_max *= r;
  l.a_max *= r * r;
  l.j_max *= r * r * r;
  return l;
}

// And a run's times and peaks back from the model's time base to the board's.
void to_board_clock(SimResult& s, scurve::Clock clock) {
  const double r = double(ClkHz) / clock.hz;
  s.duration_s *= r;
  s.peak_velocity /= r;
  s.peak_acceleration /= r * r;
  s.peak_jerk /= r * r * r;
  s.stop.v0 /= r;
  s.stop.a0 /= r * r;
}

// One progress line on a terminal for long runs.
class Progress {
 public:
  explicit Progress(size_t n) : frac_(n, 0.0), on_(isatty(2)) {}
  void set(size_t i, double f) {
    if (!on_) return;
    std::lock_guard<std::mutex> g(m_);
    frac_[i] = f;
    std::string s = "\r";
    for (size_t k = 0; k < frac_.size(); ++k) s += fmt::format("[{} {:3.0f}%] ", k + 1, 100 * frac_[k]);
    std::fputs(s.c_str(), stderr);
    std::fflush(stderr);
  }
  void done() {
    if (on_) std::fputs("\n", stderr);
  }

 private:
  std::mutex m_;
  std::vector<double> frac_;
  bool on_;
};

// scurve stream FILE: exit 0 pass, 1 a check failed, 2 bad input.
int run_stream_cli(const std::string& file, const std::string& engine, bool closed_loop, const MoveFlags& f) {
  if (closed_loop && engine == "model-fast") {
    return bad_input("--engine model-fast: the closed-loop axis has no fast-forward (use lockstep, rtl or model)");
  }
  auto loaded = scurve::cli::load_stream_file(file);
  if (const std::string* e = std::get_if<std::string>(&loaded)) return bad_input(*e);
  const StreamRequest& req = std::get<StreamRequest>(loaded);
  const PulseTiming timing = to_model(scurve::cli::to_timing(f));
  auto planned = plan_stream(req, timing);
  if (const scurve::Error* e = std::get_if<scurve::Error>(&planned)) return bad_input(e->message);
  const auto codes = scurve::stop_limit_codes(req.limits.j_max, req.limits.a_max);
  if (const scurve::Error* e = std::get_if<scurve::Error>(&codes)) return bad_input("limits: " + e->message);
  const SimEngine eng = sim_engine_from_name(engine);
  Progress progress(1);
  StreamRunResult r;
  if (closed_loop) {
    // The closed-loop axis with the default controller (for the control
    // rate) and plant of `scurve sim --closed-loop`.
    ClosedLoopOptions o;
    o.engine = eng == SimEngine::RtlOnly ? ClEngine::RtlOnly : eng == SimEngine::ModelOnly ? ClEngine::ModelOnly
                                                                                        : ClEngine::Lockstep;
    o.ctl = ControllerInput{}.resolve();
    o.timing = timing;
    o.tail_s = 0.01;
    o.stop_jerk = std::get<scurve::StopLimitCodes>(codes).jerk;
    o.stop_acc = std::get<scurve::StopLimitCodes>(codes).acc;
    o.progress = [&](double x) { progress.set(0, x); };
    r = run_closed_loop_stream(std::get<PlannedStream>(planned), req, o);
  } else {
    r = run_stream(std::get<PlannedStream>(planned), req, timing, eng, std::get<scurve::StopLimitCodes>(codes).jerk,
                   std::get<scurve::StopLimitCodes>(codes).acc, [&](double x) { progress.set(0, x); });
  }
  progress.done();
  const nlohmann::json out = stream_to_json(r);
  if (f.json) {
    std::cout << out.dump(2) << "\n";
  } else {
    std::cout << stream_table(r);
  }
  if (!write_json_file(f.json_out, out)) return bad_input("--json-out: cannot write " + f.json_out);
  return r.pass() ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"scurve: jerk-limited S-curve step generator - planner, RTL/model simulation"};
  app.require_subcommand(1);

  auto host = scurve::cli::add_host_commands(app);  // plan, regs

  MoveFlags sf;
  std::vector<CLI::Option*> sim_opts;
  std::vector<int> groups;
  std::string engine = "lockstep";
  FstFlags fst;
  unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
  CLI::App* sim_cmd = app.add_subcommand("sim", "run a move on the RTL and the model in lockstep");
  scurve::cli::add_move_flags(sim_cmd, sf, &sim_opts);
  scurve::cli::add_clock_flag(sim_cmd, sf);
  scurve::cli::add_output_flags(sim_cmd, sf);
  auto* gopt = sim_cmd->add_option_function<std::vector<std::string>>(
      "--group",
      [&groups](const std::vector<std::string>& v) {
        try {
          for (const std::string& g : v) groups.push_back(int(input::parse_int("group", g, 1, 4)));
        } catch (const input::Error& e) {
          throw CLI::ValidationError(e.what());
        }
      },
      "paper 000 Table 2 group(s) 1..4 (L=30000, a=500, j=2500)");
  for (CLI::Option* o : sim_opts) gopt->excludes(o);
  sim_cmd->add_option("--engine", engine, "lockstep | rtl | model | model-fast")
      ->check(CLI::IsMember(sim_engine_names()));
  add_fst_flags(sim_cmd, fst, "the RTL (engines lockstep, rtl)");
  scurve::cli::int_flag(sim_cmd, "--jobs", jobs, 1, 64, "parallel runs (default: cores)");
  scurve::cli::StopFlags stop_flags;  // --stop-at, --stop-jerk, --stop-acc
  scurve::cli::add_stop_flags(sim_cmd, stop_flags);
  scurve::cli::RetargetFlags retarget_flags;  // --retarget-at, --retarget-distance
  scurve::cli::add_retarget_flags(sim_cmd, retarget_flags);
  ClosedLoopCli closed_loop;  // --closed-loop and its plant/controller flags (tb/closed_loop_cli.h)
  add_closed_loop_flags(sim_cmd, closed_loop);

  // ---- stream: a stream file planned with look-ahead and run -----------------
  MoveFlags tf;
  std::string stream_file;
  std::string stream_engine = "lockstep";
  bool stream_closed_loop = false;
  CLI::App* stream_cmd = app.add_subcommand("stream", "plan a stream of moves (look-ahead junctions) and run it");
  stream_cmd->add_option("FILE", stream_file, "stream JSON: {\"limits\": {a_max, j_max, v_max}, \"moves\": [...]}")
      ->required();
  stream_cmd->add_option("--engine", stream_engine, "lockstep | rtl | model | model-fast")
      ->check(CLI::IsMember(sim_engine_names()));
  stream_cmd->add_flag("--closed-loop", stream_closed_loop,
                       "the closed-loop axis (default controller and plant of sim --closed-loop; not model-fast)");
  scurve::cli::add_timing_flags(stream_cmd, tf);
  scurve::cli::add_output_flags(stream_cmd, tf);

  // ---- jog: velocity mode -------------------------------------------------------
  JogCli jog;
  add_jog_command(app, jog);

  // ---- path: a path file on the multi-axis core ---------------------------------
  PathCli path;
  add_path_command(app, path);

  // ---- corner: paper 002's corner, its asymmetric jerks searched --------------------
  CornerCli corner;
  add_corner_command(app, corner);

  // ---- square: paper 003's X-Y square, closed loop -------------------------------
  SquareCli square;
  add_square_command(app, square);

  // ---- home: the homing sequence against a switch in the plant -----------------
  HomingCli home;
  add_homing_command(app, home);

  // ---- virtual-board: the board top behind a pseudo-terminal ---------------------
  VirtualBoardCli virtual_board;
  add_virtual_board_command(app, virtual_board);

  auto tools = add_tool_commands(app);  // diff, regress (tb/tools/tool_commands.h)

  if (const auto rc = scurve::cli::parse_command_line(app, argc, argv)) return *rc;

  if (int rc = 0; run_tool_command(*tools, &rc)) return rc;

  if (int rc = 0; host->run(&rc)) return rc;

  if (*home.cmd) return run_homing_cli(home);

  if (*jog.cmd) return run_jog_cli(jog);
  if (*path.cmd) return run_path_cli(path);
  if (*corner.cmd) return run_corner_cli(corner);
  if (*square.cmd) return run_square_cli(square);

  if (*virtual_board.cmd) return run_virtual_board_cli(virtual_board);

  if (*stream_cmd) return run_stream_cli(stream_file, stream_engine, stream_closed_loop, tf);

  // ---- sim ----------------------------------------------------------------
  struct Job {
    std::string name;
    MoveRequest req;
  };
  std::vector<Job> jobs_list;
  if (!groups.empty()) {
    for (int g : groups) jobs_list.push_back({paper_group_name(g), paper_group(g)});
  } else {
    if (std::string e = scurve::cli::check_move_flags(sf); !e.empty()) return bad_input(e + "; or give --group 1..4");
    jobs_list.push_back({"move", scurve::cli::to_request(sf)});
  }
  if (std::string e = fst.resolve(); !e.empty()) return bad_input(e);
  if (!fst.path.empty() && jobs_list.size() != 1) return bad_input("--fst: trace one run at a time (one --group)");
  if (!fst.path.empty() && (engine == "model" || engine == "model-fast")) {
    return bad_input(fmt::format("fst={}: --engine {} runs no RTL to trace (use lockstep or rtl)", fst.path, engine));
  }
  const PulseTiming timing = to_model(scurve::cli::to_timing(sf));
  if (std::string e = scurve::cli::check_clock_flag(sf.clock_hz); !e.empty()) return bad_input(e);
  const scurve::Clock clock = scurve::cli::to_clock(sf);
  if (clock != model_clock() && (closed_loop.enabled || closed_loop.compare)) {
    return bad_input(fmt::format("--clock-hz={}: the closed-loop bench runs at the model's {} Hz", sf.clock_hz, ClkHz));
  }
  if (closed_loop.enabled || closed_loop.compare) {
    std::vector<std::pair<std::string, MoveRequest>> cl_jobs;
    for (const Job& j : jobs_list) cl_jobs.emplace_back(j.name, j.req);
    closed_loop.fst_path = fst.path;
    closed_loop.fst_from = fst.from;
    closed_loop.fst_to = fst.to;
    if (retarget_flags.at_given || retarget_flags.distance_given) {
      return bad_input("--retarget-at: runs on the open-loop axis (not with --closed-loop)");
    }
    return run_closed_loop_cli(closed_loop, cl_jobs, timing, engine, jobs, sf.json, sf.json_out, stop_flags);
  }
  std::vector<Plan> plans;
  std::vector<scurve::cli::StopRequest> stops;
  std::vector<std::optional<SimOptions::Retarget>> retargets;
  for (const Job& j : jobs_list) {
    const PlanResult r = plan_move(j.req, timing, clock);
    if (const auto* e = std::get_if<PlanError>(&r)) return bad_input(e->message);
    plans.push_back(std::get<Plan>(r));
    const auto s = scurve::cli::resolve_stop_flags(stop_flags, j.req, to_host(plans.back()));
    if (const std::string* e = std::get_if<std::string>(&s)) return bad_input(*e);
    stops.push_back(std::get<scurve::cli::StopRequest>(s));
    const auto rt = scurve::cli::resolve_retarget_flags(retarget_flags, j.req, to_host(plans.back()),
                                                        scurve::cli::to_timing(sf));
    if (const std::string* e = std::get_if<std::string>(&rt)) return bad_input(*e);
    std::optional<SimOptions::Retarget> o;
    if (const auto& p = std::get<std::optional<scurve::RetargetPlan>>(rt)) {
      o.emplace();
      o->at_clock = uint64_t(std::llround(retarget_flags.at * clock.hz));
      o->row = p->row;
      o->rows = move_rows(to_model(p->plan).segments, true, p->acceleration);
      o->distance = p->distance;
      o->clocks = p->plan.total_clocks;
    }
    retargets.push_back(std::move(o));
  }
  SimOptions opt;
  opt.engine = sim_engine_from_name(engine);
  opt.fst_path = fst.path;
  opt.fst_from = fst.from;
  opt.fst_to = fst.to;

  std::vector<SimResult> results(jobs_list.size());
  std::vector<std::string> output_errors(jobs_list.size());  // an output file that could not be written
  Progress progress(jobs_list.size());
  std::atomic<size_t> next{0};
  auto worker = [&]() {
    for (size_t i = next++; i < jobs_list.size(); i = next++) {
      SimOptions o = opt;
      o.progress = [&, i](double f) { progress.set(i, f); };
      o.stop_at = stops[i].at_clock;
      o.stop_jerk = stops[i].codes.jerk;
      o.stop_acc = stops[i].codes.acc;
      o.retarget = retargets[i];
      try {
        results[i] = run_move(plans[i], timing, at_model_clock(limits_of(jobs_list[i].req, plans[i].v_end_used), clock),
                              o);
      } catch (const input::Error& e) {
        output_errors[i] = e.what();
      } catch (const std::exception& e) {
        results[i].failures.push_back(e.what());
      }
      to_board_clock(results[i], clock);
      results[i].name = jobs_list[i].name;
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < std::min<size_t>(jobs, jobs_list.size()); ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  progress.done();
  for (const std::string& e : output_errors) {
    if (!e.empty()) return bad_input(e);
  }

  bool pass = true;
  for (const SimResult& r : results) pass = pass && r.pass();
  nlohmann::json out;
  if (results.size() == 1) {
    out = sim_to_json(results[0]);
  } else {
    out["runs"] = nlohmann::json::array();
    for (const SimResult& r : results) out["runs"].push_back(sim_to_json(r));
    out["pass"] = pass;
  }
  if (sf.json) {
    std::cout << out.dump(2) << "\n";
  } else {
    std::cout << sim_table(results);
  }
  if (!write_json_file(sf.json_out, out)) return bad_input("--json-out: cannot write " + sf.json_out);
  return pass ? 0 : 1;
}
