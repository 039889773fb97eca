#include "closed_loop_cli.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <string_view>
#include <vector>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "scenarios.h"
#include "scurve/cli/move_flags.h"
#include "scurve/cli/user_input.h"

namespace sc {

namespace {

// A plant setting a user can give: its flag, its scenario key, its range.
struct PlantParam {
  const char* flag;  // without "--"
  const char* key;   // in a scenario's "plant" object
  double lo, hi;
  bool integer;
  const char* what;
  void (*set)(PlantConfig&, double);
};

const std::vector<PlantParam>& plant_params() {
  static const std::vector<PlantParam> params = {
      {"f-n", "f_n", 0.1, 1e5, false, "rotor natural frequency, Hz", [](PlantConfig& p, double v) { p.f_n = v; }},
      {"zeta", "zeta", 1e-3, 10, false, "rotor damping ratio", [](PlantConfig& p, double v) { p.zeta = v; }},
      {"load-torque", "load_torque", 0, 100, false, "constant load torque, N m",
       [](PlantConfig& p, double v) { p.load_torque = v; }},
      {"inertia", "inertia", 1e-9, 10, false, "rotor + load inertia, kg m^2",
       [](PlantConfig& p, double v) { p.inertia = v; }},
      {"pulses-per-rev", "pulses_per_rev", 1, 1e7, false, "driver pulses per revolution",
       [](PlantConfig& p, double v) { p.pulses_per_rev = v; }},
      {"counts-per-step", "counts_per_step", 1, 64, false, "encoder counts per pulse (power of 2)",
       [](PlantConfig& p, double v) { p.counts_per_step = v; }},
      {"tau", "tau", 1e-6, 100, false, "first-order plant time constant, s", [](PlantConfig& p, double v) { p.tau = v; }},
      {"enc-noise", "noise_counts", 0, 1e6, false, "encoder position noise, sigma in counts",
       [](PlantConfig& p, double v) { p.noise_counts = v; }},
      {"enc-glitch-rate", "glitch_rate", 0, 1e7, false, "A/B glitches per second",
       [](PlantConfig& p, double v) { p.glitch_rate = v; }},
      {"enc-glitch-clocks", "glitch_clocks", 1, 65535, true, "glitch length, clocks",
       [](PlantConfig& p, double v) { p.glitch_clocks = int(v); }},
      {"plant-seed", "seed", 0, 9007199254740992.0, true, "noise/glitch seed",
       [](PlantConfig& p, double v) { p.seed = uint64_t(v); }},
  };
  return params;
}

// A flag's text through the validation layer; CLI11 reports it (exit 2).
double checked_flag(const char* flag, const std::string& text, double lo, double hi, bool integer) {
  try {
    return integer ? double(input::parse_int(flag, text, int64_t(lo), int64_t(hi)))
                   : input::parse_real(flag, text, lo, hi);
  } catch (const input::Error& e) {
    throw CLI::ValidationError(e.what());
  }
}

}  // namespace

void add_closed_loop_flags(CLI::App* sim, ClosedLoopCli& f) {
  const std::string g = "Closed loop";
  sim->add_flag("--closed-loop", f.enabled, "run sc_servo_axis in closed loop with the plant model")->group(g);
  sim->add_flag("--compare", f.compare,
                "comparison: adaptive vs fixed-gain PI, with/without feed-forward, S-curve vs trapezoid")
      ->group(g);
  sim->add_option("--weights-csv", f.weights_csv, "write the neuron weight trajectories (CSV; -<name> per run)")->group(g);
  sim->add_option("--scenario", f.scenario, "JSON file: {\"plant\": {...}, \"controller\": {...}}")->group(g);
  sim->add_option_function<std::string>(
         "--tail", [&f](const std::string& v) { f.tail_s = checked_flag("tail", v, 0, 10, false); },
         "quiet time after done for the residual vibration, s (0..10)")
      ->group(g);
  // plant: every number through the one table (flags and scenario keys alike)
  const std::string pg = "Plant";
  sim->add_option("--plant", f.plant_kind, "stepper | first-order")
      ->check(CLI::IsMember({"stepper", "first-order"}))->group(pg);
  for (const PlantParam& prm : plant_params()) {
    sim->add_option_function<std::string>(
           std::string("--") + prm.flag,
           [&f, &prm](const std::string& v) { prm.set(f.plant, checked_flag(prm.flag, v, prm.lo, prm.hi, prm.integer)); },
           fmt::format("{} ({}..{})", prm.what, prm.lo, prm.hi))
        ->group(pg);
  }
  sim->add_flag("--missed-steps", f.plant.missed_steps, "sinusoidal torque-angle curve: the rotor can slip")->group(pg);
  // controller
  const std::string cg = "Controller";
  ControllerParams& c = f.ctl;
  sim->add_option("--ctl-rate", c.rate_hz, "control rate, Hz")->group(cg);
  sim->add_flag("!--no-ff", c.ff, "no velocity feed-forward")->group(cg);
  sim->add_flag("!--fixed-gain", c.adaptive, "learning rates 0: fixed-gain PI cascade")->group(cg);
  sim->add_flag("!--open-loop", c.closed_loop, "same top, open-loop step path (baseline)")->group(cg);
  sim->add_option("--k-p", c.k_p, "position neuron gain K_p")->group(cg);
  sim->add_option("--k-v", c.k_v, "speed neuron gain K_v")->group(cg);
  sim->add_option("--kb", c.kb, "back-calculation anti-windup gain Kb")->group(cg);
  sim->add_option("--eta-p1", c.eta_p1, "learning rate, position loop, integral weight")->group(cg);
  sim->add_option("--eta-p2", c.eta_p2, "learning rate, position loop, proportional weight")->group(cg);
  sim->add_option("--eta-v1", c.eta_v1, "learning rate, speed loop, integral weight")->group(cg);
  sim->add_option("--eta-v2", c.eta_v2, "learning rate, speed loop, proportional weight")->group(cg);
  sim->add_option("--learn-shift", c.learn_shift, "Hebb scale 2^-n")->group(cg);
  sim->add_option("--learn-dz-p", c.learn_dz_p, "no position learning while |e_p| <= this, pulses")->group(cg);
  sim->add_option("--learn-dz-v", c.learn_dz_v, "no speed learning while |e_v| <= this, pulses/period")->group(cg);
  sim->add_option("--w-p1", c.w_p1, "initial weight, position integral")->group(cg);
  sim->add_option("--fixed-w-p1", c.fixed_w_p1, "position integral weight of the fixed-gain PI")->group(cg);
  sim->add_option("--w-p2", c.w_p2, "initial weight, position proportional")->group(cg);
  sim->add_option("--w-v1", c.w_v1, "initial weight, speed integral")->group(cg);
  sim->add_option("--w-v2", c.w_v2, "initial weight, speed proportional")->group(cg);
  sim->add_option("--w-min", c.w_min, "lower weight bound")->group(cg);
  sim->add_option("--w-p1-max", c.w_p1_max, "upper bound, position integral weight")->group(cg);
  sim->add_option("--w-p2-max", c.w_p2_max, "upper bound, position proportional weight")->group(cg);
  sim->add_option("--w-v1-max", c.w_v1_max, "upper bound, speed integral weight")->group(cg);
  sim->add_option("--w-v2-max", c.w_v2_max, "upper bound, speed proportional weight")->group(cg);
  sim->add_option("--v-lim", c.v_lim, "position-loop output limit, pulses/s")->group(cg);
  sim->add_option("--u-lim", c.u_lim, "speed-loop output limit, pulses/s (0: 90 % of the step-rate limit)")->group(cg);
  sim->add_option("--ferr-lim", c.ferr_lim, "following-error fault limit, pulses")->group(cg);
  sim->add_option("--inpos-win", c.inpos_win, "in-position window, pulses")->group(cg);
  sim->add_option("--inpos-hold", c.inpos_hold_s, "in-position hold time, s")->group(cg);
  sim->add_option("--settle-rate", c.settle_rate, "corrective step rate after the reference, pulses/s")->group(cg);
  sim->add_option("--enc-filter", c.enc_filt, "encoder glitch filter, clocks (0..15)")->group(cg);
}

std::string apply_scenario_json(const std::string& text, ControllerParams& c, PlantConfig& p) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const std::exception& e) {
    return std::string("scenario: not JSON: ") + e.what();
  }
  // Every key known and typed, the plant's numbers in the flags' ranges (one
  // table), so a typo is an error instead of the default plant.
  try {
    using namespace input;
    json_known_keys("scenario", j, {"_comment", "description", "plant", "controller"});
    if (j.contains("plant")) {
      const auto& q = json_object("scenario.plant", j["plant"]);
      std::vector<std::string_view> keys = {"kind", "missed_steps"};
      for (const PlantParam& prm : plant_params()) keys.push_back(prm.key);
      json_known_keys("scenario.plant", q, keys);
      if (q.contains("kind")) {
        const std::string kind = json_string("scenario.plant.kind", q["kind"]);
        if (kind != "stepper" && kind != "first-order") {
          throw Error("scenario.plant.kind", "'" + kind + "'", "must be stepper or first-order");
        }
        p.kind = kind == "first-order" ? PlantConfig::Kind::FirstOrder : PlantConfig::Kind::Stepper;
      }
      if (q.contains("missed_steps")) p.missed_steps = json_bool("scenario.plant.missed_steps", q["missed_steps"]);
      for (const PlantParam& prm : plant_params()) {
        if (!q.contains(prm.key)) continue;
        const std::string at = std::string("scenario.plant.") + prm.key;
        prm.set(p, prm.integer ? double(json_int(at, q[prm.key], int64_t(prm.lo), int64_t(prm.hi)))
                               : json_real(at, q[prm.key], prm.lo, prm.hi));
      }
    }
    if (j.contains("controller")) {
      const auto& q = json_object("scenario.controller", j["controller"]);
      json_known_keys("scenario.controller", q,
                      {"rate_hz", "k_p", "k_v", "kb", "eta_p1", "eta_p2", "eta_v1", "eta_v2", "learn_dz_p",
                       "learn_dz_v", "w_p1", "fixed_w_p1", "w_p2", "w_v1", "w_v2", "w_min", "w_p1_max", "w_p2_max",
                       "w_v1_max", "w_v2_max", "v_lim", "u_lim", "ferr_lim", "inpos_win", "inpos_hold_s",
                       "settle_rate", "ff", "adaptive", "learn_shift", "enc_filt"});
      // Ranges of the controller settings are checked where they become
      // register values (to_servo_config), for flags and scenarios alike.
      auto num = [&](const char* k, double& v) {
        if (q.contains(k)) v = json_real(std::string("scenario.controller.") + k, q[k], -1e12, 1e12);
      };
      for (const auto& [k, v] : std::initializer_list<std::pair<const char*, double*>>{
               {"rate_hz", &c.rate_hz}, {"k_p", &c.k_p}, {"k_v", &c.k_v}, {"kb", &c.kb}, {"eta_p1", &c.eta_p1},
               {"eta_p2", &c.eta_p2}, {"eta_v1", &c.eta_v1}, {"eta_v2", &c.eta_v2}, {"learn_dz_p", &c.learn_dz_p},
               {"learn_dz_v", &c.learn_dz_v}, {"w_p1", &c.w_p1}, {"fixed_w_p1", &c.fixed_w_p1}, {"w_p2", &c.w_p2},
               {"w_v1", &c.w_v1}, {"w_v2", &c.w_v2}, {"w_min", &c.w_min}, {"w_p1_max", &c.w_p1_max},
               {"w_p2_max", &c.w_p2_max}, {"w_v1_max", &c.w_v1_max}, {"w_v2_max", &c.w_v2_max}, {"v_lim", &c.v_lim},
               {"u_lim", &c.u_lim}, {"ferr_lim", &c.ferr_lim}, {"inpos_win", &c.inpos_win},
               {"inpos_hold_s", &c.inpos_hold_s}, {"settle_rate", &c.settle_rate}}) {
        num(k, *v);
      }
      if (q.contains("ff")) c.ff = json_bool("scenario.controller.ff", q["ff"]);
      if (q.contains("adaptive")) c.adaptive = json_bool("scenario.controller.adaptive", q["adaptive"]);
      if (q.contains("learn_shift")) c.learn_shift = int(json_int("scenario.controller.learn_shift", q["learn_shift"], 0, 31));
      if (q.contains("enc_filt")) c.enc_filt = int(json_int("scenario.controller.enc_filt", q["enc_filt"], 0, 15));
    }
  } catch (const std::exception& e) {
    return e.what();
  }
  return {};
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
                        const std::string& json_out) {
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
  ClEngine eng = engine == "rtl" ? ClEngine::RtlOnly
                 : (engine == "model" || engine == "model-fast") ? ClEngine::ModelOnly
                                                                 : ClEngine::Lockstep;
  {
    ServoConfig probe;
    if (std::string e = to_servo_config(f.ctl, f.plant, timing, probe); !e.empty()) {
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
        Job j{name + "/" + v.tag, req0, f.ctl};
        j.req.kind = v.kind;
        j.ctl.closed_loop = v.closed;
        j.ctl.adaptive = v.adaptive;
        j.ctl.ff = v.ff;
        list.push_back(j);
      }
    }
  } else {
    for (const auto& [name, req] : jobs) list.push_back({name, req, f.ctl});
  }
  std::vector<Plan> plans;
  for (const Job& j : list) {
    const PlanResult r = plan_move(j.req, timing);
    if (const auto* e = std::get_if<PlanError>(&r)) {
      std::fprintf(stderr, "error: %s\n", e->message.c_str());
      return 2;
    }
    plans.push_back(std::get<Plan>(r));
  }
  std::vector<ClosedLoopResult> results(list.size());
  std::atomic<size_t> next{0};
  auto worker = [&]() {
    for (size_t i = next++; i < list.size(); i = next++) {
      ClosedLoopOptions o;
      o.engine = eng;
      o.ctl = list[i].ctl;
      o.plant = f.plant;
      o.timing = timing;
      o.tail_s = f.tail_s;
      try {
        results[i] = run_closed_loop(plans[i], o);
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

  bool pass = true;
  for (const ClosedLoopResult& r : results) pass = pass && r.pass();
  if (!f.weights_csv.empty()) {
    for (const ClosedLoopResult& r : results) {
      const std::string p = csv_path(f.weights_csv, r.name, results.size() > 1);
      if (!write_weights_csv(p, r.weights)) {
        std::fprintf(stderr, "error: --weights-csv %s: cannot write\n", p.c_str());
        return 2;
      }
    }
  }
  // Paper-table verdict: below Table 3 and final error 0 for each paper group.
  std::vector<std::string> table_fail;
  if (!f.compare) {
    for (const ClosedLoopResult& r : results) {
      const int g = group_of(r.name);
      if (g == 0 || !f.ctl.closed_loop) continue;
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
    if (f.compare) {
      std::cout << comparison_table(results);
    } else {
      std::cout << closed_loop_table(results);
      bool any_group = false;
      for (const ClosedLoopResult& r : results) any_group = any_group || group_of(r.name) != 0;
      if (any_group && f.ctl.closed_loop) std::cout << "\n" << table3_layout(results);
    }
    for (const std::string& t : table_fail) std::cout << "FAIL: " << t << "\n";
  }
  return pass ? 0 : 1;
}

}  // namespace sc
