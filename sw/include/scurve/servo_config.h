// Closed-loop controller settings: physical units in, the register values of
// the neuron-PI servo axis out (the words encode_servo_config() writes).
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <variant>

#include "scurve/planner.h"
#include "scurve/hw/layout.h"
#include "scurve/types.h"

namespace scurve {

// Shortest control period the time-multiplexed controller accepts, clocks.
inline constexpr int kMinControlDiv = 256;
// Longest control period, clocks (the width of cfg_div).
inline constexpr int kMaxControlDiv = (1 << hw::CtlCfgDivW) - 1;

// The ranges the register words can hold, for every user of the settings
// (to_servo_config, the command-line and scenario tables): gains and
// learning rates (unsigned Q.CoefFrac), weights (signed Q.WgtFrac), shifts.
inline constexpr double kMaxCoef = double(1u << (hw::CoefW - hw::CoefFrac)) - 1.0 / double(1u << hw::CoefFrac);
inline constexpr double kMaxWeight = double(1 << (hw::WgtW - 1 - hw::WgtFrac)) - 1.0 / double(1 << hw::WgtFrac);
// PID gains per second (Kp, Ki, Kb): the register bound depends on the
// control rate and is checked by to_servo_config; this is the flags' range.
inline constexpr double kMaxPidGain = 1e9;
inline constexpr int kMaxLearnShift = (1 << hw::LearnShW) - 1;
inline constexpr int kMaxEncFilter = (1 << hw::EncFiltW) - 1;
// Speeds (v_lim, u_lim, settle_rate), pulses/s; their per-period words are
// checked against the register at the configured rate as well.
inline constexpr double kMaxSpeed = 1e7;
// In-position hold time, s (the per-period count is checked at the rate).
inline constexpr double kMaxInposHold = 6.5535;
// Largest distance-like setting (ferr_lim, inpos_win, learning dead zones)
// in pulses: a Q.CtlFrac word below 2^31 counts.
inline double max_pulses(double counts_per_step) {
  return std::floor(2147483647.0 / (double(1 << hw::CtlFrac) * counts_per_step));
}

// Controller register values (fixed point, see docs/closed_loop.md): the
// struct generated from rtl/sc_pkg.sv (field widths, Q formats and units in
// docs/regmap.md); member defaults are the register reset values.
using NeuronConfig = hw::CtlCfg;

// Everything the closed-loop axis is configured with.
struct ServoConfig {
  bool enable = true;
  bool closed_loop = true;
  PulseTiming timing{};
  NeuronConfig ctl{};  // incl. the decoder's glitch filter (ctl.enc_filt)
};

// The position controller of the closed loop.
enum class ControllerKind {
  kNeuron,  // the neuron-PI cascade (paper 000): position loop, then speed loop
  kPidAw,   // paper 003's fixed-gain PID with back-calculation anti-windup:
            // the position loop alone, its output the step rate u (CL_CFG.PID)
};
const char* controller_kind_name(ControllerKind k);  // "neuron", "pid-aw"

// Controller settings in physical units.
struct ControllerParams {
  bool closed_loop = true;
  ControllerKind kind = ControllerKind::kNeuron;
  // PID (kind kPidAw), per second: u = Kp e + Ki integral(e) + Kd de/dt in
  // pulses/s for e in pulses, limited to u_lim; the integral is reduced by
  // Kb (u - sat(u)) (back-calculation, paper 003 eq. 15; Kb = 0: none).
  // Defaults: paper 003's X axis (Table 1) scaled to pulses
  // (docs/closed_loop.md, "Paper 003's square").
  double pid_kp = 65.5;    // 1/s
  double pid_ki = 6.55;    // 1/s^2
  double pid_kd = 0.0655;  // s^0 (pulses/s per pulse/s)
  double pid_kb = 0.5;     // 1/s
  double rate_hz = 10000;       // control rate (div = clock / rate)
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
  bool ferr_stop = false;       // the fault stops the reference under control (else at once)
  double inpos_win = 0;         // in-position window, pulses
  double inpos_hold_s = 0.005;  // in-position hold time
  double settle_rate = 500;     // pulses/s: corrective steps after the reference is done
  int enc_filt = 3;             // glitch filter, clocks
};

// The control rate the defaults of ControllerParams are tuned at.
inline constexpr double kTunedControlRate = 10000;

// The defaults for a control rate: ControllerParams{} at kTunedControlRate;
// at another rate the per-period settings that keep the tuned loop's gains
// per second (docs/closed_loop.md, "Control rate"), with s = 10 kHz / rate:
//  * k_v x s: the speed loop's integral gain per second, K_v w_v1' rate
//    (160/s), must stay below what the rotor's lightly damped resonance
//    allows (about 2 zeta w_n = 205/s for the default plant);
//  * k_p x max(1, s): the position loop's gain per second, K_p w_p2' rate,
//    is kept at 40/s below 10 kHz; above, K_p stays 0.004 per period, since
//    a smaller per-period gain leaves each increment of the incremental PI
//    a few LSB of the Q16 velocity word and its rounding dominates;
//  * w_p1, fixed_w_p1, w_p1_max x s: the position integral weight keeps
//    the ratio of the loop's integral to proportional gain per second.
// Everything else is per second or per pulse already, or not rate-bound.
ControllerParams controller_defaults(double rate_hz);

using ServoConfigResult = std::variant<ServoConfig, Error>;

// The PID gains the registers of a CL_CFG.PID configuration realise, per
// second at `rate_hz` (the hardware's normalised weights are truncated to
// Q1.NWgtFrac, so Ki and Kp differ from the requested ones by their
// quantisation; to_servo_config's choice keeps that below 2^-16 of K_P).
struct PidGains {
  double kp = 0, ki = 0, kd = 0, kb = 0;
};
PidGains realised_pid_gains(const NeuronConfig& n, double rate_hz);

// Register values for the settings, an encoder with `counts_per_step`
// counts per pulse (a power of two), this pulse timing and clock rate.
ServoConfigResult to_servo_config(const ControllerParams& p, double counts_per_step, const PulseTiming& t,
                                  Clock clock = Clock{});

}  // namespace scurve
