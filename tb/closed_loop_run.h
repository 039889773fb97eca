// Closed-loop runs: one planned move through sc_servo_axis (Verilated RTL
// and/or the bit-exact model, compared every clock) with the plant model
// outside the DUT, and the tracking metrics of DESIGN.md.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "lockstep.h"
#include "plant.h"
#include "planner.h"
#include "servo_axis.h"

namespace sc {

// Controller settings in physical units; to_servo_config() turns them into
// the fixed-point cfg_* words of sc_servo_axis.
struct ControllerParams {
  bool closed_loop = true;
  double rate_hz = 10000;       // control rate (cfg_div = ClkHz / rate)
  bool ff = true;               // velocity feed-forward from V*
  bool adaptive = true;         // false: learning rates 0 (fixed-gain PI)
  double k_p = 0.004;           // position neuron gain K_p (per control period)
  double k_v = 0.02;            // speed neuron gain K_v
  double eta_p1 = 0.20, eta_p2 = 0.20, eta_v1 = 0.15, eta_v2 = 0.10;  // paper 000
  int learn_shift = 10;         // Hebb scale 2^-learn_shift (counts^2 -> weight)
  double learn_dz_p = 0.75;     // counts: no position-loop learning while |e_p| <= this
  double learn_dz_v = 1.5;      // counts/period: no speed-loop learning while |e_v| <= this
  double w_p1 = 0.0, w_p2 = 64, w_v1 = 64, w_v2 = 16;  // initial weights (w_p1 learns up)
  double fixed_w_p1 = 0.125;    // integral weight of the fixed-gain PI (adaptive: w_p1, learned)
  double w_min = 0.0;           // lower bound, all weights
  double w_p1_max = 0.5, w_p2_max = 127, w_v1_max = 127, w_v2_max = 32;  // upper bounds
  double kb = 1.0;              // back-calculation gain
  double v_lim = 5000;          // |position-loop output|, pulses/s
  double u_lim = 0;             // |u|, pulses/s (0: 90 % of the step-rate limit)
  double ferr_lim = 500;        // following-error fault, pulses
  double inpos_win = 0;         // in-position window, pulses
  double inpos_hold_s = 0.005;  // in-position hold time
  double settle_rate = 500;     // pulses/s: corrective steps after the reference is done
  int enc_filt = 3;             // glitch filter, clocks
};

// Error message (empty = ok) for parameters that cannot be encoded.
std::string to_servo_config(const ControllerParams& p, const PlantConfig& plant, const PulseTiming& t,
                            ServoConfig& out);

enum class ClEngine { Lockstep, RtlOnly, ModelOnly };
const char* cl_engine_name(ClEngine e);

struct ClosedLoopOptions {
  ClEngine engine = ClEngine::Lockstep;
  ControllerParams ctl{};
  PlantConfig plant{};
  PulseTiming timing{};
  double tail_s = 0.1;               // quiet time after done (residual vibration)
  uint32_t weight_every = 10;        // weight samples every N control periods
  size_t max_mismatches = 1;
  std::string fst_path;
  uint64_t fst_from = 0, fst_to = UINT64_MAX;
  std::function<void(double)> progress;
  // Test hook: called with the model before every clock (fault injection).
  std::function<void(uint64_t, ServoAxis&)> inject;
};

struct WeightSample {
  double t = 0;  // s since start
  double w[4] = {0, 0, 0, 0};   // w_p1 w_p2 w_v1 w_v2 (real)
  double wn[4] = {0, 0, 0, 0};  // normalised
  double e_p = 0;               // pulses
};

struct ClosedLoopResult {
  std::string name;
  ClEngine engine = ClEngine::Lockstep;
  int64_t distance = 0;
  uint64_t clocks = 0, total_clocks = 0;
  double duration_s = 0;          // start to done (in position)
  double ref_duration_s = 0;      // start to reference done
  double settle_time_s = 0;       // reference done to in position
  double max_error = 0;           // max |P* - 1/2 - P|, pulses, start to done
  double rmse = 0;
  double relative_error = 0;      // rmse / L
  int64_t final_error = 0;        // L - P after the tail, pulses
  int64_t pulses = 0;             // net STEP pulses (pins)
  double peak_jerk_enc = 0, peak_acc_enc = 0;  // from the encoder (filtered)
  double peak_jerk_ref = 0, peak_acc_ref = 0;  // same filter on the reference
  double residual_vib = 0;        // peak-to-peak rotor angle after done, pulses
  double residual_enc = 0;        // max |P - L| on the encoder after done, counts
  bool in_pos = false, fault_ferr = false, fault_overrun = false;
  uint64_t enc_illegal = 0, glitches = 0, slips = 0;
  uint64_t mismatches = 0, matched_clocks = 0;
  std::string first_mismatch;
  std::vector<std::string> pin_errors;  // pulse timing and step accounting
  std::vector<WeightSample> weights;
  double wall_s = 0, clocks_per_s = 0;
  std::vector<std::string> failures;
  bool pass() const { return failures.empty(); }
};

ClosedLoopResult run_closed_loop(const Plan& plan, const ClosedLoopOptions& opt);

// Field-by-field rendering of the outputs (mismatch reports).
SignalValues render_servo(const ServoOutputs& o);

bool write_weights_csv(const std::string& path, const std::vector<WeightSample>& w);

}  // namespace sc
