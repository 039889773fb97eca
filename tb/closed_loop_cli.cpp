#include "closed_loop_cli.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <string_view>
#include <vector>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "report.h"
#include "scenarios.h"
#include "scurve/cli/move_flags.h"
#include "scurve/cli/user_input.h"

namespace sc {

namespace {

// A flag's text through the validation layer; CLI11 reports it (exit 2)
// as given (a ConversionError: a ValidationError would get the flag's name
// put in front once more).
double checked_flag(const char* flag, const std::string& text, double lo, double hi, bool integer) {
  try {
    return integer ? double(input::parse_int(flag, text, int64_t(lo), int64_t(hi)))
                   : input::parse_real(flag, text, lo, hi);
  } catch (const input::Error& e) {
    throw CLI::ConversionError(e.what());
  }
}

// A number flag: every occurrence checked, the last one counts (as for the
// move flags), so "--k-p nan --k-p 0.004" is refused, not half-read.
CLI::Option* add_number_flag(CLI::App* sim, const char* flag, double lo, double hi, bool integer,
                             std::function<void(double)> set, const std::string& what) {
  return sim
      ->add_option_function<std::string>(
          std::string("--") + flag, [=](const std::string& v) { set(checked_flag(flag, v, lo, hi, integer)); }, what)
      ->each([=](const std::string& v) { checked_flag(flag, v, lo, hi, integer); })
      ->type_name(integer ? "INT" : "NUM")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
}

// One flag per table row, set(row index, value); the last of repeated
// flags counts (as for the move flags).
template <class Target, class Set>
void add_number_flags(CLI::App* sim, const std::vector<NumberParam<Target>>& params, Set set,
                      const std::string& group) {
  for (size_t i = 0; i < params.size(); ++i) {
    const NumberParam<Target>& prm = params[i];
    add_number_flag(sim, prm.flag, prm.lo, prm.hi, prm.integer, [set, i](double v) { set(i, v); },
                    fmt::format("{} ({}..{})", prm.what, prm.lo, prm.hi))
        ->group(group);
  }
}

// A file path flag: empty text is an error, not "no file".
CLI::Option* add_path_flag(CLI::App* sim, const char* flag, std::string& target, const std::string& what) {
  auto check = [flag](const std::string& v) {
    if (v.empty()) throw CLI::ConversionError(input::Error(flag, "''", "required, a file path").what());
  };
  return sim->add_option_function<std::string>(
                std::string("--") + flag,
                [&target, check](const std::string& v) {
                  check(v);
                  target = v;
                },
                what)
      ->each(check)
      ->type_name("FILE")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
}

}  // namespace

void add_controller_flags(CLI::App* cmd, ControllerInput& ctl, const std::string& group) {
  cmd->add_option_function<std::string>(
         "--controller",
         [&ctl](const std::string& v) {
           ctl.values.kind = v == "pid-aw" ? scurve::ControllerKind::kPidAw : scurve::ControllerKind::kNeuron;
         },
         "neuron (the adaptive neuron-PI cascade, default) | pid-aw (paper 003's fixed-gain PID with "
         "back-calculation anti-windup: --pid-kp/-ki/-kd/-kb, limited to --u-lim)")
      ->check(CLI::IsMember({"neuron", "pid-aw"}))
      ->group(group);
  add_number_flags(cmd, controller_params(), [&ctl](size_t i, double v) { ctl.set(i, v); }, group);
}

void add_closed_loop_flags(CLI::App* sim, ClosedLoopCli& f) {
  const std::string g = "Closed loop";
  sim->add_flag("--closed-loop", f.enabled, "run sc_servo_axis in closed loop with the plant model")
      ->disable_flag_override()
      ->group(g);
  sim->add_flag("--compare", f.compare,
                "comparison: adaptive vs fixed-gain PI, with/without feed-forward, S-curve vs trapezoid")
      ->disable_flag_override()
      ->group(g);
  add_path_flag(sim, "weights-csv", f.weights_csv, "write the neuron weight trajectories (CSV; -<name> per run)")
      ->group(g);
  add_path_flag(sim, "scenario", f.scenario, "JSON file: {\"plant\": {...}, \"controller\": {...}}")->group(g);
  add_number_flag(sim, "tail", 0, 10, false, [&f](double v) { f.tail_s = v; },
                  "quiet time after done for the residual vibration, s (0..10)")
      ->group(g);
  // plant and controller: every number through its table (flags and
  // scenario keys alike)
  const std::string pg = "Plant";
  sim->add_option("--plant", f.plant_kind, "stepper | first-order")
      ->check(CLI::IsMember({"stepper", "first-order"}))->group(pg);
  add_number_flags(sim, plant_params(), [&f](size_t i, double v) { plant_params()[i].set(f.plant, v); }, pg);
  sim->add_flag("--missed-steps", f.plant.missed_steps, "sinusoidal torque-angle curve: the rotor can slip")
      ->disable_flag_override()
      ->group(pg);
  const std::string cg = "Controller";
  add_controller_flags(sim, f.ctl, cg);
  ControllerParams& c = f.ctl.values;
  // Switches take no value ("--no-ff=false" would read as a double negation).
  sim->add_flag_callback("--no-ff", [&c] { c.ff = false; }, "no velocity feed-forward")
      ->disable_flag_override()
      ->group(cg);
  sim->add_flag_callback("--fixed-gain", [&c] { c.adaptive = false; }, "learning rates 0: fixed-gain PI cascade")
      ->disable_flag_override()
      ->group(cg);
  sim->add_flag_callback("--ferr-stop", [&c] { c.ferr_stop = true; },
                         "a following-error fault stops the reference under control (the stop limits) and the loop "
                         "keeps tracking it; default: the loop stops at once")
      ->disable_flag_override()
      ->group(cg);
  sim->add_flag_callback("--open-loop", [&c] { c.closed_loop = false; }, "same top, open-loop step path (baseline)")
      ->disable_flag_override()
      ->group(cg);
}

namespace {

int group_of(const std::string& name) {
  if (name.rfind("group", 0) == 0 && name.size() >= 6) {
    const int g = name[5] - '0';
    if (g >= 1 && g <= 4 && (name.size() == 6 || name[6] == '/')) return g;
  }
  return 0;
}

nlohmann::json result_json(const ClosedLoopResult& r) {
  nlohmann::json j;
  j["name"] = r.name;
  j["engine"] = cl_engine_name(r.engine);
  j["distance"] = r.distance;
  j["clocks"] = r.clocks;
  j["duration_s"] = r.duration_s;
  j["reference_duration_s"] = r.ref_duration_s;
  j["settle_time_s"] = r.settle_time_s;
  j["max_tracking_error"] = r.max_error;
  j["rmse"] = r.rmse;
  j["relative_error"] = r.relative_error;
  j["final_error"] = r.final_error;
  j["target"] = r.target;
  j["stop"] = stop_to_json(r.stop);
  j["positioning_accuracy"] = r.final_error == 0 ? 1.0 : 0.0;
  j["pulses"] = r.pulses;
  j["peak_jerk_encoder"] = r.peak_jerk_enc;
  j["peak_acceleration_encoder"] = r.peak_acc_enc;
  j["peak_jerk_reference_filtered"] = r.peak_jerk_ref;
  j["peak_acceleration_reference_filtered"] = r.peak_acc_ref;
  j["residual_vibration"] = r.residual_vib;
  j["residual_encoder_deviation"] = r.residual_enc;
  j["in_position"] = r.in_pos;
  j["fault_following_error"] = r.fault_ferr;
  j["encoder_illegal_transitions"] = r.enc_illegal;
  j["encoder_glitches_injected"] = r.glitches;
  j["mismatches"] = r.mismatches;
  j["matched_clocks"] = r.matched_clocks;
  if (!r.first_mismatch.empty()) j["first_mismatch"] = r.first_mismatch;
  j["wall_s"] = r.wall_s;
  j["clocks_per_s"] = r.clocks_per_s;
  j["real_time_ratio"] = r.clocks_per_s / ClkHz;
  if (!r.weights.empty()) {
    const WeightSample& w = r.weights.back();
    j["final_normalised_weights"] = {w.wn[0], w.wn[1], w.wn[2], w.wn[3]};
  }
  j["failures"] = r.failures;
  j["pass"] = r.pass();
  return j;
}

// Where an output file flag's file can go, checked before the (long) runs:
// its directory exists, and the path is not a directory or a device (the
// file is renamed into place). Empty, or the one-line reason.
std::string check_output_path(const char* flag, const std::string& given, const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path p(path);
  const fs::file_status st = fs::status(p, ec);
  if (fs::is_directory(st)) return input::Error(flag, given, path + " is a directory").what();
  if (fs::exists(st) && !fs::is_regular_file(st)) {
    return input::Error(flag, given, path + " exists and is not a regular file").what();
  }
  const fs::path dir = p.parent_path().empty() ? fs::path(".") : p.parent_path();
  if (!fs::is_directory(dir, ec)) return input::Error(flag, given, "no directory " + dir.string()).what();
  return {};
}

// Every setting of the table as used (the defaults for the rate included).
nlohmann::json controller_json(const ControllerParams& c) {
  nlohmann::json j;
  for (const ControllerParam& prm : controller_params()) {
    if (prm.integer) {
      j[prm.key] = int64_t(prm.get(c));
    } else {
      j[prm.key] = prm.get(c);
    }
  }
  j["kind"] = scurve::controller_kind_name(c.kind);
  j["ff"] = c.ff;
  j["adaptive"] = c.adaptive;
  j["ferr_stop"] = c.ferr_stop;
  j["closed_loop"] = c.closed_loop;
  return j;
}

std::string csv_path(const std::string& base, const std::string& name, bool several) {
  if (!several) return base;
  std::string n = name;
  for (char& ch : n) if (ch == '/' || ch == ' ') ch = '_';
  const size_t dot = base.find_last_of('.');
  if (dot == std::string::npos || base.find('/', dot) != std::string::npos) return base + "-" + n;
  return base.substr(0, dot) + "-" + n + base.substr(dot);
}

}  // namespace

std::string closed_loop_table(const std::vector<ClosedLoopResult>& rs) {
  std::string s = fmt::format("{:<24} {:>10} {:>8} {:>9} {:>8} {:>9} {:>6} {:>8} {:>10} {:>9} {:>8} {:>6} {:>8}\n",
                              "run", "clocks", "dur_s", "max_err", "rmse", "rel_err%", "final", "settle_s",
                              "jerk_enc", "resid_vib", "mismat", "pass", "Mclk/s");
  for (const ClosedLoopResult& r : rs) {
    s += fmt::format("{:<24} {:>10} {:>8.3f} {:>9.3f} {:>8.4f} {:>9.5f} {:>6} {:>8.4f} {:>10.0f} {:>9.3f} {:>8} {:>6} {:>8.2f}\n",
                     r.name, r.clocks, r.duration_s, r.max_error, r.rmse, 100 * r.relative_error, r.final_error,
                     r.settle_time_s, r.peak_jerk_enc, r.residual_vib, r.mismatches, r.pass() ? "yes" : "NO",
                     r.clocks_per_s / 1e6);
    s += stop_line(r.name, r.stop);
    for (const std::string& f : r.failures) s += "    FAIL: " + f + "\n";
  }
  return s;
}

std::string table3_layout(const std::vector<ClosedLoopResult>& rs) {
  std::string s = "Paper 000 Table 3 (hardware) vs ours (simulation, closed loop, lockstep RTL = model):\n";
  s += fmt::format("{:<6} | {:>17} | {:>17} | {:>19} | {:>21}\n", "Group", "Max Error (pul)", "RMSE (pul)",
                   "Relative Error", "Positioning Accuracy");
  s += fmt::format("{:<6} | {:>8} {:>8} | {:>8} {:>8} | {:>9} {:>9} | {:>10} {:>10}\n", "", "paper", "ours", "paper",
                   "ours", "paper", "ours", "paper", "ours");
  for (const ClosedLoopResult& r : rs) {
    const int g = group_of(r.name);
    if (g == 0) continue;
    const PaperRow& p = kPaperTable3[g - 1];
    s += fmt::format("{:<6} | {:>8.1f} {:>8.3f} | {:>8.3f} {:>8.4f} | {:>8.4f}% {:>8.5f}% | {:>10} {:>10}\n", g,
                     p.max_error, r.max_error, p.rmse, r.rmse, p.relative_pct, 100 * r.relative_error, "100%",
                     r.final_error == 0 ? "100%" : "0%");
  }
  s += "Relative error = RMSE / L (reproduces the paper for groups 1, 2, 4; its group 3 figure, 0.0448 %,\n"
       "fits neither RMSE/L nor max/L).\n";
  return s;
}

std::string comparison_table(const std::vector<ClosedLoopResult>& rs) {
  std::string s = fmt::format("{:<34} {:>8} {:>7} {:>9} {:>9} {:>8} {:>8} {:>9} {:>6}\n", "configuration", "max_err",
                              "rmse", "jerk_enc", "jerk_ref", "acc_enc", "acc_ref", "resid_vib", "final");
  for (const ClosedLoopResult& r : rs) {
    s += fmt::format("{:<34} {:>8.3f} {:>7.4f} {:>9.0f} {:>9.0f} {:>8.0f} {:>8.0f} {:>9.4f} {:>6}{}\n", r.name,
                     r.max_error, r.rmse, r.peak_jerk_enc, r.peak_jerk_ref, r.peak_acc_enc, r.peak_acc_ref,
                     r.residual_vib, r.final_error, r.pass() ? "" : "  (FAIL)");
  }
  s += "max_err/rmse: |P* - 1/2 - P| in pulses, every clock from start to done (settling included);\n"
       "jerk/acc (pulses/s^3, /s^2): position sampled at 1 kHz, two 50 ms moving averages, differences over 50 ms,\n"
       "from start to reference done, on the encoder (_enc) and, same filter, on the reference (_ref);\n"
       "resid_vib: peak-to-peak rotor angle (plant) in the tail after done, pulses.\n";
  return s;
}

int run_closed_loop_cli(ClosedLoopCli f, const std::vector<std::pair<std::string, MoveRequest>>& jobs,
                        const PulseTiming& timing, const std::string& engine, unsigned n_threads, bool json,
                        const std::string& json_out, const scurve::cli::StopFlags& stop) {
  if (!f.scenario.empty()) {
    std::ifstream in(f.scenario);
    if (!std::filesystem::is_regular_file(f.scenario) || !in) {
      std::fprintf(stderr, "error: --scenario %s: cannot read\n", f.scenario.c_str());
      return 2;
    }
    std::stringstream ss;
    ss << in.rdbuf();
    if (std::string e = apply_scenario_json(ss.str(), f.ctl, f.plant); !e.empty()) {
      std::fprintf(stderr, "error: %s\n", e.c_str());
      return 2;
    }
  }
  if (f.plant_kind == "first-order") f.plant.kind = PlantConfig::Kind::FirstOrder;
  const ControllerParams ctl = f.ctl.resolve();
  if (f.compare && ctl.kind == scurve::ControllerKind::kPidAw) {
    // the comparison's variants are the cascade's (adaptive, fixed gain, feed-forward)
    std::fprintf(stderr, "error: %s\n",
                 input::Error("controller", "pid-aw", "--compare compares the neuron cascade's variants; "
                                                      "compare the PID with scurve square")
                     .what());
    return 2;
  }
  ClEngine eng = engine == "rtl" ? ClEngine::RtlOnly
                 : (engine == "model" || engine == "model-fast") ? ClEngine::ModelOnly
                                                                 : ClEngine::Lockstep;
  {
    ServoConfig probe;
    if (std::string e = to_servo_config(ctl, f.plant, timing, probe); !e.empty()) {
      std::fprintf(stderr, "error: %s\n", e.c_str());
      return 2;
    }
  }
  struct Job {
    std::string name;
    MoveRequest req;
    ControllerParams ctl;
  };
  std::vector<Job> list;
  if (f.compare) {
    for (const auto& [name, req0] : jobs) {
      struct V {
        const char* tag;
        bool closed, adaptive, ff;
        ProfileKind kind;
      };
      const V vs[] = {
          {"adaptive+FF S-curve", true, true, true, ProfileKind::SCurve},
          {"fixed-gain+FF S-curve", true, false, true, ProfileKind::SCurve},
          {"adaptive noFF S-curve", true, true, false, ProfileKind::SCurve},
          {"fixed-gain noFF S-curve", true, false, false, ProfileKind::SCurve},
          {"adaptive+FF trapezoid", true, true, true, ProfileKind::Trapezoid},
          {"fixed-gain+FF trapezoid", true, false, true, ProfileKind::Trapezoid},
          {"open-loop S-curve", false, false, true, ProfileKind::SCurve},
          {"open-loop trapezoid", false, false, true, ProfileKind::Trapezoid},
      };
      for (const V& v : vs) {
        Job j{name + "/" + v.tag, req0, ctl};
        j.req.kind = v.kind;
        j.ctl.closed_loop = v.closed;
        j.ctl.adaptive = v.adaptive;
        j.ctl.ff = v.ff;
        list.push_back(j);
      }
    }
  } else {
    for (const auto& [name, req] : jobs) list.push_back({name, req, ctl});
  }
  // The weights' files can be written: refused now, not after the runs
  // (the path as given too: "dir/" is no file name for several runs either).
  if (!f.weights_csv.empty()) {
    std::vector<std::string> paths = {f.weights_csv};
    for (const Job& j : list) paths.push_back(csv_path(f.weights_csv, j.name, list.size() > 1));
    for (const std::string& path : paths) {
      const std::string e = check_output_path("weights-csv", f.weights_csv, path);
      if (!e.empty()) {
        std::fprintf(stderr, "error: %s\n", e.c_str());
        return 2;
      }
    }
  }
  const bool stop_given = stop.at_given || stop.jerk_given || stop.acc_given;
  if (stop_given && eng == ClEngine::RtlOnly) {
    std::fprintf(stderr, "error: --stop-at/--stop-jerk/--stop-acc with --closed-loop --engine rtl: the stop is "
                         "checked on the model's executor (use lockstep or model)\n");
    return 2;
  }
  std::vector<Plan> plans;
  std::vector<scurve::cli::StopRequest> stops;
  for (const Job& j : list) {
    const PlanResult r = plan_move(j.req, timing);
    if (const auto* e = std::get_if<PlanError>(&r)) {
      std::fprintf(stderr, "error: %s\n", e->message.c_str());
      return 2;
    }
    plans.push_back(std::get<Plan>(r));
    const auto s = scurve::cli::resolve_stop_flags(stop, j.req, to_host(plans.back()));
    if (const std::string* e = std::get_if<std::string>(&s)) {
      std::fprintf(stderr, "error: %s\n", e->c_str());
      return 2;
    }
    stops.push_back(std::get<scurve::cli::StopRequest>(s));
  }
  if (!f.fst_path.empty() && list.size() != 1) {
    std::fprintf(stderr, "error: --fst: trace one run at a time (one --group, no --compare)\n");
    return 2;
  }
  if (!f.fst_path.empty() && eng == ClEngine::ModelOnly) {
    std::fprintf(stderr, "error: fst=%s: --engine %s runs no RTL to trace (use lockstep or rtl)\n", f.fst_path.c_str(),
                 engine.c_str());
    return 2;
  }
  std::vector<ClosedLoopResult> results(list.size());
  std::vector<std::string> output_errors(list.size());  // an output file that could not be written
  std::atomic<size_t> next{0};
  auto worker = [&]() {
    for (size_t i = next++; i < list.size(); i = next++) {
      ClosedLoopOptions o;
      o.engine = eng;
      o.ctl = list[i].ctl;
      o.plant = f.plant;
      o.timing = timing;
      o.tail_s = f.tail_s;
      o.fst_path = f.fst_path;
      o.fst_from = f.fst_from;
      o.fst_to = f.fst_to;
      o.stop_at = stops[i].at_clock;
      o.stop_jerk = stops[i].codes.jerk;
      o.stop_acc = stops[i].codes.acc;
      // The comparison shows how far the loop falls behind without
      // feed-forward (up to 57 pulses on paper group 2): no bound there.
      if (f.compare && !o.ctl.ff) o.max_error_limit = 0.0;
      try {
        results[i] = run_closed_loop(plans[i], o);
      } catch (const input::Error& e) {
        output_errors[i] = e.what();
      } catch (const std::exception& e) {
        results[i].failures.push_back(e.what());
      }
      results[i].name = list[i].name;
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < std::max(1u, std::min<unsigned>(n_threads, unsigned(list.size()))); ++t) {
    pool.emplace_back(worker);
  }
  for (auto& t : pool) t.join();
  for (const std::string& e : output_errors) {
    if (!e.empty()) {
      std::fprintf(stderr, "error: %s\n", e.c_str());
      return 2;
    }
  }

  bool pass = true;
  for (const ClosedLoopResult& r : results) pass = pass && r.pass();
  if (!f.weights_csv.empty()) {
    std::vector<WeightsCsv> files;
    for (const ClosedLoopResult& r : results) {
      files.push_back({csv_path(f.weights_csv, r.name, results.size() > 1), &r.weights});
    }
    if (const std::string e = write_weights_csvs(files); !e.empty()) {
      std::fprintf(stderr, "error: %s\n", input::Error("weights-csv", f.weights_csv, "cannot write " + e).what());
      return 2;
    }
  }
  // Paper-table verdict: below Table 3 and final error 0 for each paper group.
  std::vector<std::string> table_fail;
  if (!f.compare) {
    for (const ClosedLoopResult& r : results) {
      const int g = group_of(r.name);
      // Paper 000's table measures its neuron cascade; the PID is held to its own lag bound.
      if (g == 0 || !ctl.closed_loop || ctl.kind == scurve::ControllerKind::kPidAw) continue;
      const PaperRow& p = kPaperTable3[g - 1];
      if (!(r.max_error < p.max_error)) table_fail.push_back(fmt::format("{}: max error {:.3f} >= paper {}", r.name, r.max_error, p.max_error));
      if (!(r.rmse < p.rmse)) table_fail.push_back(fmt::format("{}: RMSE {:.4f} >= paper {}", r.name, r.rmse, p.rmse));
    }
  }
  pass = pass && table_fail.empty();
  nlohmann::json out;
  out["runs"] = nlohmann::json::array();
  for (const ClosedLoopResult& r : results) out["runs"].push_back(result_json(r));
  out["plant"] = f.plant.describe();
  out["controller"] = controller_json(ctl);
  out["table3_failures"] = table_fail;
  out["pass"] = pass;
  if (!scurve::cli::write_json_file(json_out, out)) {
    std::fprintf(stderr, "error: --json-out: cannot write %s\n", json_out.c_str());
    return 2;
  }
  if (json) {
    std::cout << out.dump(2) << "\n";
  } else {
    std::cout << "plant: " << f.plant.describe() << "\n";
    if (ctl.kind == scurve::ControllerKind::kPidAw) {
      std::cout << fmt::format("controller: pid-aw, {} Hz, Kp {} /s, Ki {} /s^2, Kd {}, Kb {} /s, u_lim {} pulses/s "
                               "(0: 90 % of the step-rate limit)\n",
                               ctl.rate_hz, ctl.pid_kp, ctl.pid_ki, ctl.pid_kd, ctl.pid_kb, ctl.u_lim);
    } else {
      std::cout << fmt::format("controller: {} Hz, K_p {}, K_v {}, w_p1 <= {}{}\n", ctl.rate_hz, ctl.k_p, ctl.k_v,
                               ctl.w_p1_max, ctl.adaptive ? "" : fmt::format(" (fixed {})", ctl.fixed_w_p1));
    }
    if (f.compare) {
      std::cout << comparison_table(results);
    } else {
      std::cout << closed_loop_table(results);
      bool any_group = false;
      for (const ClosedLoopResult& r : results) any_group = any_group || group_of(r.name) != 0;
      if (any_group && ctl.closed_loop) std::cout << "\n" << table3_layout(results);
    }
    for (const std::string& t : table_fail) std::cout << "FAIL: " << t << "\n";
  }
  return pass ? 0 : 1;
}

}  // namespace sc
