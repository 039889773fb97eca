// scurve: plan S-curve moves and run them on the RTL and the bit-exact model.
//   scurve plan --distance L --v-start VS --v-cruise VC --v-end VE --a-max A --j-max J [--json]
//   scurve sim  (same move flags | --group 1 2 3 4) [--engine ...] [--json]
//   scurve regs (same move flags) [--uart] [--no-start] [--closed-loop] [--json]   register writes
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
#include "planner.h"
#include "regs_cli.h"
#include "report.h"
#include "scenarios.h"
#include "sim_run.h"
#include "tool_commands.h"

namespace {

using namespace sc;

struct MoveFlags {
  int64_t distance = 0;
  double v_start = 0, v_cruise = 0, v_end = 0, a_max = 0, j_max = 0;
  std::string profile = "scurve";
  std::vector<double> jerks;  // ts1 ts2 te1 te2
  bool adjust_end_speed = false;
  int pulse_high = PulseTiming{}.high, pulse_low = PulseTiming{}.low;
  int dir_setup = PulseTiming{}.setup, dir_hold = PulseTiming{}.hold;
  bool json = false;
  std::string json_out;
};

bool write_json_file(const std::string& path, const nlohmann::json& j) {
  if (path.empty()) return true;
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) return false;
  const std::string s = j.dump(2) + "\n";
  const bool ok = std::fwrite(s.data(), 1, s.size(), f) == s.size();
  return std::fclose(f) == 0 && ok;
}

void add_move_flags(CLI::App* app, MoveFlags& f, std::vector<CLI::Option*>& move_opts) {
  move_opts.push_back(app->add_option("--distance", f.distance, "move length in pulses (sign = direction)"));
  move_opts.push_back(app->add_option("--v-start", f.v_start, "start speed, pulses/s"));
  move_opts.push_back(app->add_option("--v-cruise", f.v_cruise, "cruise speed, pulses/s"));
  move_opts.push_back(app->add_option("--v-end", f.v_end, "end speed, pulses/s"));
  move_opts.push_back(app->add_option("--a-max", f.a_max, "acceleration limit, pulses/s^2"));
  move_opts.push_back(app->add_option("--j-max", f.j_max, "jerk limit, pulses/s^3 (scurve)"));
  move_opts.push_back(app->add_option("--profile", f.profile, "scurve | trapezoid")
                          ->check(CLI::IsMember({"scurve", "trapezoid"})));
  move_opts.push_back(app->add_option("--jerks", f.jerks,
                                      "asymmetric jerks Ts1 Ts2 Te1 Te2 (paper 002), pulses/s^3")
                          ->expected(4));
  move_opts.push_back(app->add_flag("--adjust-end-speed", f.adjust_end_speed,
                                    "use the closest reachable end speed instead of failing"));
  app->add_option("--pulse-high", f.pulse_high, "STEP high time, clocks")->check(CLI::Range(1, 65535));
  app->add_option("--pulse-low", f.pulse_low, "minimum STEP low time, clocks")->check(CLI::Range(1, 65535));
  app->add_option("--dir-setup", f.dir_setup, "DIR setup before STEP rise, clocks")->check(CLI::Range(0, 65535));
  app->add_option("--dir-hold", f.dir_hold, "DIR hold after STEP rise, clocks")->check(CLI::Range(0, 65535));
  app->add_flag("--json", f.json, "print one JSON object");
  app->add_option("--json-out", f.json_out, "also write the JSON object to this file");
}

MoveRequest to_request(const MoveFlags& f) {
  MoveRequest r;
  r.distance = f.distance;
  r.v_start = f.v_start;
  r.v_cruise = f.v_cruise;
  r.v_end = f.v_end;
  r.a_max = f.a_max;
  r.j_max = f.j_max;
  r.kind = f.profile == "trapezoid" ? ProfileKind::Trapezoid : ProfileKind::SCurve;
  if (f.jerks.size() == 4) r.jerks = std::array<double, 4>{f.jerks[0], f.jerks[1], f.jerks[2], f.jerks[3]};
  r.adjust_end_speed = f.adjust_end_speed;
  return r;
}

PulseTiming to_timing(const MoveFlags& f) {
  PulseTiming t;
  t.high = uint16_t(f.pulse_high);
  t.low = uint16_t(f.pulse_low);
  t.setup = uint16_t(f.dir_setup);
  t.hold = uint16_t(f.dir_hold);
  return t;
}

int bad_input(const std::string& msg) {
  std::fprintf(stderr, "error: %s\n", msg.c_str());
  return 2;
}

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

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"scurve: jerk-limited S-curve step generator - planner, RTL/model simulation"};
  app.require_subcommand(1);

  MoveFlags pf;
  std::vector<CLI::Option*> plan_opts;
  CLI::App* plan_cmd = app.add_subcommand("plan", "plan a move and print its segment table");
  add_move_flags(plan_cmd, pf, plan_opts);

  MoveFlags rf;  // scurve regs (issue 5, tb/regs_cli.h)
  std::vector<CLI::Option*> regs_opts;
  RegsCliFlags regs_flags;
  CLI::App* regs_cmd = app.add_subcommand("regs", "plan a move and print it as register writes (AXI4-Lite, --uart frames)");
  add_move_flags(regs_cmd, rf, regs_opts);
  add_regs_flags(regs_cmd, regs_flags);

  MoveFlags sf;
  std::vector<CLI::Option*> sim_opts;
  std::vector<int> groups;
  std::string engine = "lockstep";
  std::string fst;
  uint64_t fst_from = 0, fst_to = UINT64_MAX;
  unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
  CLI::App* sim_cmd = app.add_subcommand("sim", "run a move on the RTL and the model in lockstep");
  add_move_flags(sim_cmd, sf, sim_opts);
  auto* gopt = sim_cmd->add_option("--group", groups, "paper 000 Table 2 group(s) 1..4 (L=30000, a=500, j=2500)")
                   ->check(CLI::Range(1, 4));
  for (CLI::Option* o : sim_opts) gopt->excludes(o);
  sim_cmd->add_option("--engine", engine, "lockstep | rtl | model | model-fast")
      ->check(CLI::IsMember({"lockstep", "rtl", "model", "model-fast"}));
  sim_cmd->add_option("--fst", fst, "write an FST waveform of the RTL (tracing build)");
  sim_cmd->add_option("--fst-from", fst_from, "first clock to trace");
  sim_cmd->add_option("--fst-to", fst_to, "clock after the last one to trace");
  sim_cmd->add_option("--jobs", jobs, "parallel runs (default: cores)")->check(CLI::Range(1, 64));
  ClosedLoopCli closed_loop;  // --closed-loop and its plant/controller flags (tb/closed_loop_cli.h)
  add_closed_loop_flags(sim_cmd, closed_loop);

  auto tools = add_tool_commands(app);  // diff, regress (issue 4, tb/tools/tool_commands.h)

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return bad_input(e.what());
  }

  if (int rc = 0; run_tool_command(*tools, &rc)) return rc;

  if (*plan_cmd) {
    const MoveRequest req = to_request(pf);
    const PlanResult r = plan_move(req, to_timing(pf));
    if (const auto* e = std::get_if<PlanError>(&r)) return bad_input(e->message);
    const Plan& p = std::get<Plan>(r);
    const nlohmann::json j = plan_to_json(p);
    if (pf.json) {
      std::cout << j.dump(2) << "\n";
    } else {
      std::cout << plan_to_table(p);
    }
    if (!write_json_file(pf.json_out, j)) return bad_input("--json-out: cannot write " + pf.json_out);
    return 0;
  }

  if (*regs_cmd) {
    const PlanResult r = plan_move(to_request(rf), to_timing(rf));
    if (const auto* e = std::get_if<PlanError>(&r)) return bad_input(e->message);
    return run_regs_cli(regs_flags, std::get<Plan>(r), to_timing(rf), rf.json);
  }

  // ---- sim ----------------------------------------------------------------
  struct Job {
    std::string name;
    MoveRequest req;
  };
  std::vector<Job> jobs_list;
  if (!groups.empty()) {
    for (int g : groups) jobs_list.push_back({paper_group_name(g), paper_group(g)});
  } else {
    jobs_list.push_back({"move", to_request(sf)});
  }
  const PulseTiming timing = to_timing(sf);
  if (closed_loop.enabled || closed_loop.compare) {
    std::vector<std::pair<std::string, MoveRequest>> cl_jobs;
    for (const Job& j : jobs_list) cl_jobs.emplace_back(j.name, j.req);
    return run_closed_loop_cli(closed_loop, cl_jobs, timing, engine, jobs, sf.json);
  }
  std::vector<Plan> plans;
  for (const Job& j : jobs_list) {
    const PlanResult r = plan_move(j.req, timing);
    if (const auto* e = std::get_if<PlanError>(&r)) return bad_input(e->message);
    plans.push_back(std::get<Plan>(r));
  }
  SimOptions opt;
  opt.engine = engine == "rtl" ? SimEngine::RtlOnly
               : engine == "model" ? SimEngine::ModelOnly
               : engine == "model-fast" ? SimEngine::ModelFast
                                        : SimEngine::Lockstep;
  if (!fst.empty() && jobs_list.size() != 1) return bad_input("--fst: trace one run at a time");
  opt.fst_path = fst;
  opt.fst_from = fst_from;
  opt.fst_to = fst_to;

  std::vector<SimResult> results(jobs_list.size());
  Progress progress(jobs_list.size());
  std::atomic<size_t> next{0};
  auto worker = [&]() {
    for (size_t i = next++; i < jobs_list.size(); i = next++) {
      SimOptions o = opt;
      o.progress = [&, i](double f) { progress.set(i, f); };
      try {
        results[i] = run_move(plans[i], timing, limits_of(jobs_list[i].req, plans[i].v_end_used), o);
      } catch (const std::exception& e) {
        results[i].failures.push_back(e.what());
      }
      results[i].name = jobs_list[i].name;
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < std::min<size_t>(jobs, jobs_list.size()); ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  progress.done();

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
