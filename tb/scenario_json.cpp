// The closed-loop settings a user gives as flags and as a scenario file:
// one table per target (plant, controller) and the scenario JSON reader.
// No Verilator, no SystemC: the fuzz harness links this alone.
#include "scenario_json.h"

#include <nlohmann/json.hpp>
#include <string_view>
#include <vector>

#include "scurve/cli/user_input.h"

namespace sc {

// Plant settings: physical ranges of the model (tb/plant.h).
const std::vector<PlantParam>& plant_params() {
#define SC_GET(f) [](const PlantConfig& p) { return double(p.f); }
#define SC_FIELD(f) [](PlantConfig& p, double v) { p.f = v; }, SC_GET(f)
  static const std::vector<PlantParam> params = {
      {"f-n", "f_n", 0.1, 1e5, false, "rotor natural frequency, Hz", SC_FIELD(f_n)},
      {"zeta", "zeta", 1e-3, 10, false, "rotor damping ratio", SC_FIELD(zeta)},
      {"load-torque", "load_torque", 0, 100, false, "constant load torque, N m", SC_FIELD(load_torque)},
      {"inertia", "inertia", 1e-9, 10, false, "rotor + load inertia, kg m^2", SC_FIELD(inertia)},
      {"pulses-per-rev", "pulses_per_rev", 1, 1e7, false, "driver pulses per revolution", SC_FIELD(pulses_per_rev)},
      {"counts-per-step", "counts_per_step", 1, 64, false, "encoder counts per pulse (power of 2)",
       SC_FIELD(counts_per_step)},
      {"tau", "tau", 1e-6, 100, false, "first-order plant time constant, s", SC_FIELD(tau)},
      {"enc-noise", "noise_counts", 0, 1e6, false, "encoder position noise, sigma in counts", SC_FIELD(noise_counts)},
      {"enc-glitch-rate", "glitch_rate", 0, 1e7, false, "A/B glitches per second", SC_FIELD(glitch_rate)},
      {"enc-glitch-clocks", "glitch_clocks", 1, 65535, true, "glitch length, clocks",
       [](PlantConfig& p, double v) { p.glitch_clocks = int(v); }, SC_GET(glitch_clocks)},
      {"plant-seed", "seed", 0, 9007199254740992.0, true, "noise/glitch seed",
       [](PlantConfig& p, double v) { p.seed = uint64_t(v); }, SC_GET(seed)},
  };
  return params;
#undef SC_FIELD
#undef SC_GET
}

// Controller settings: the ranges the register words hold (servo_config.h).
// Ranges that also depend on another setting (the control rate, the
// encoder's counts per pulse, the weight bounds' order) are checked
// together by to_servo_config, with one message naming both.
const std::vector<ControllerParam>& controller_params() {
#define SC_GET(f) [](const ControllerParams& c) { return double(c.f); }
#define SC_FIELD(f) [](ControllerParams& c, double v) { c.f = v; }, SC_GET(f)
#define SC_INT_FIELD(f) [](ControllerParams& c, double v) { c.f = int(v); }, SC_GET(f)
  using namespace scurve;
  const double pulses = max_pulses(1.0);  // the widest: one count per pulse
  static const std::vector<ControllerParam> params = {
      {"ctl-rate", "rate_hz", double(ClkHz) / kMaxControlDiv, double(ClkHz) / kMinControlDiv, false,
       "control rate, Hz", SC_FIELD(rate_hz)},
      {"k-p", "k_p", 0, kMaxCoef, false, "position neuron gain K_p, per control period", SC_FIELD(k_p)},
      {"k-v", "k_v", 0, kMaxCoef, false, "speed neuron gain K_v, per control period", SC_FIELD(k_v)},
      {"kb", "kb", 0, kMaxCoef, false, "back-calculation anti-windup gain Kb", SC_FIELD(kb)},
      {"pid-kp", "pid_kp", 0, kMaxPidGain, false, "PID (--controller pid-aw): proportional gain Kp, 1/s",
       SC_FIELD(pid_kp)},
      {"pid-ki", "pid_ki", 0, kMaxPidGain, false, "PID: integral gain Ki, 1/s^2", SC_FIELD(pid_ki)},
      {"pid-kd", "pid_kd", 0, kMaxCoef, false, "PID: derivative gain Kd (pulses/s per pulse/s)", SC_FIELD(pid_kd)},
      {"pid-kb", "pid_kb", 0, kMaxPidGain, false, "PID: back-calculation gain Kb, 1/s (0: no anti-windup)",
       SC_FIELD(pid_kb)},
      {"eta-p1", "eta_p1", 0, kMaxCoef, false, "learning rate, position loop, integral weight", SC_FIELD(eta_p1)},
      {"eta-p2", "eta_p2", 0, kMaxCoef, false, "learning rate, position loop, proportional weight", SC_FIELD(eta_p2)},
      {"eta-v1", "eta_v1", 0, kMaxCoef, false, "learning rate, speed loop, integral weight", SC_FIELD(eta_v1)},
      {"eta-v2", "eta_v2", 0, kMaxCoef, false, "learning rate, speed loop, proportional weight", SC_FIELD(eta_v2)},
      {"learn-shift", "learn_shift", 0, kMaxLearnShift, true, "Hebb scale 2^-n", SC_INT_FIELD(learn_shift)},
      {"learn-dz-p", "learn_dz_p", 0, pulses, false, "no position learning while |e_p| <= this, pulses",
       SC_FIELD(learn_dz_p)},
      {"learn-dz-v", "learn_dz_v", 0, pulses, false, "no speed learning while |e_v| <= this, pulses/period",
       SC_FIELD(learn_dz_v)},
      {"w-p1", "w_p1", -kMaxWeight, kMaxWeight, false, "initial weight, position integral", SC_FIELD(w_p1)},
      {"fixed-w-p1", "fixed_w_p1", -kMaxWeight, kMaxWeight, false, "position integral weight of the fixed-gain PI",
       SC_FIELD(fixed_w_p1)},
      {"w-p2", "w_p2", -kMaxWeight, kMaxWeight, false, "initial weight, position proportional", SC_FIELD(w_p2)},
      {"w-v1", "w_v1", -kMaxWeight, kMaxWeight, false, "initial weight, speed integral", SC_FIELD(w_v1)},
      {"w-v2", "w_v2", -kMaxWeight, kMaxWeight, false, "initial weight, speed proportional", SC_FIELD(w_v2)},
      {"w-min", "w_min", -kMaxWeight, kMaxWeight, false, "lower weight bound (all weights)", SC_FIELD(w_min)},
      {"w-p1-max", "w_p1_max", -kMaxWeight, kMaxWeight, false, "upper bound, position integral weight",
       SC_FIELD(w_p1_max)},
      {"w-p2-max", "w_p2_max", -kMaxWeight, kMaxWeight, false, "upper bound, position proportional weight",
       SC_FIELD(w_p2_max)},
      {"w-v1-max", "w_v1_max", -kMaxWeight, kMaxWeight, false, "upper bound, speed integral weight",
       SC_FIELD(w_v1_max)},
      {"w-v2-max", "w_v2_max", -kMaxWeight, kMaxWeight, false, "upper bound, speed proportional weight",
       SC_FIELD(w_v2_max)},
      {"v-lim", "v_lim", 0, kMaxSpeed, false, "position-loop output limit, pulses/s", SC_FIELD(v_lim)},
      {"u-lim", "u_lim", 0, kMaxSpeed, false, "speed-loop output limit, pulses/s (0: 90 % of the step-rate limit)",
       SC_FIELD(u_lim)},
      {"ferr-lim", "ferr_lim", 1, pulses, false, "following-error fault limit, pulses", SC_FIELD(ferr_lim)},
      {"inpos-win", "inpos_win", 0, pulses, false, "in-position window, pulses", SC_FIELD(inpos_win)},
      {"inpos-hold", "inpos_hold_s", 0, kMaxInposHold, false, "in-position hold time, s", SC_FIELD(inpos_hold_s)},
      {"settle-rate", "settle_rate", 0, kMaxSpeed, false, "corrective step rate after the reference, pulses/s",
       SC_FIELD(settle_rate)},
      {"enc-filter", "enc_filt", 0, kMaxEncFilter, true, "encoder glitch filter, clocks", SC_INT_FIELD(enc_filt)},
  };
  return params;
#undef SC_FIELD
#undef SC_INT_FIELD
#undef SC_GET
}

ControllerInput::ControllerInput() : given(controller_params().size(), false) {}

void ControllerInput::set(size_t param, double v) {
  controller_params()[param].set(values, v);
  given[param] = true;
}

ControllerParams ControllerInput::resolve() const {
  ControllerParams r = values;
  const ControllerParams defaults = scurve::controller_defaults(values.rate_hz);
  for (size_t i = 0; i < given.size(); ++i) {
    const ControllerParam& prm = controller_params()[i];
    if (!given[i]) prm.set(r, prm.get(defaults));
  }
  return r;
}

namespace {

// A scenario object's numbers through the same table as the flags.
template <class Target, class Set>
void apply_scenario_numbers(const std::string& where, const nlohmann::json& q,
                            const std::vector<NumberParam<Target>>& params, Set set) {
  for (size_t i = 0; i < params.size(); ++i) {
    const NumberParam<Target>& prm = params[i];
    if (!q.contains(prm.key)) continue;
    const std::string at = where + "." + prm.key;
    set(i, prm.integer ? double(input::json_int(at, q[prm.key], int64_t(prm.lo), int64_t(prm.hi)))
                       : input::json_real(at, q[prm.key], prm.lo, prm.hi));
  }
}

}  // namespace

std::string apply_scenario_json(const std::string& text, ControllerInput& c, PlantConfig& p) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const std::exception& e) {
    return "scenario: not JSON: " + input::printable(e.what());  // the parser quotes the input
  }
  // Every key known and typed, the numbers in the flags' ranges (the same
  // tables), so a typo is an error instead of the default.
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
      apply_scenario_numbers("scenario.plant", q, plant_params(),
                             [&p](size_t i, double v) { plant_params()[i].set(p, v); });
    }
    if (j.contains("controller")) {
      const auto& q = json_object("scenario.controller", j["controller"]);
      std::vector<std::string_view> keys = {"kind", "ff", "adaptive", "ferr_stop"};
      for (const ControllerParam& prm : controller_params()) keys.push_back(prm.key);
      json_known_keys("scenario.controller", q, keys);
      if (q.contains("kind")) {
        const std::string kind = json_string("scenario.controller.kind", q["kind"]);
        if (kind != "neuron" && kind != "pid-aw") {
          throw Error("scenario.controller.kind", "'" + kind + "'", "must be neuron or pid-aw");
        }
        c.values.kind = kind == "pid-aw" ? scurve::ControllerKind::kPidAw : scurve::ControllerKind::kNeuron;
      }
      if (q.contains("ff")) c.values.ff = json_bool("scenario.controller.ff", q["ff"]);
      if (q.contains("adaptive")) c.values.adaptive = json_bool("scenario.controller.adaptive", q["adaptive"]);
      if (q.contains("ferr_stop")) c.values.ferr_stop = json_bool("scenario.controller.ferr_stop", q["ferr_stop"]);
      apply_scenario_numbers("scenario.controller", q, controller_params(), [&c](size_t i, double v) { c.set(i, v); });
    }
  } catch (const std::exception& e) {
    return e.what();
  }
  return {};
}

}  // namespace sc
