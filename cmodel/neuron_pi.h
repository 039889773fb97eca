// Bit-exact model of rtl/sc_neuron_pi.sv: the position/speed single-neuron
// adaptive PI cascade on one time-multiplexed datapath (one multiplier, a
// restoring divider), clock by clock: same FSM states, same registers, same
// rounding ((p + 2^(s-1)) >> s), wrap and saturation. See the RTL header and
// docs/closed_loop.md for the equations.
#pragma once

#include <cstdint>

#include "fixed_point.h"

namespace sc {

// Controller configuration (the cfg_* inputs of sc_neuron_pi).
struct NeuronConfig {
  uint16_t div = 2000;         // control period, clocks
  uint8_t shift = 0;           // log2(encoder counts per pulse)
  bool ff_en = true;           // velocity feed-forward from V*
  uint8_t learn_shift = 0;     // Hebb scale 2^-learn_shift
  uint32_t learn_dz_p = 0;     // no learning while |e| <= dz (Q.CtlFrac), position loop
  uint32_t learn_dz_v = 0;     //   speed loop
  uint32_t k_p = 0, k_v = 0;   // neuron gains, Q.CoefFrac
  uint32_t kb = 0;             // back-calculation gain, Q.CoefFrac
  uint32_t eta_p1 = 0, eta_p2 = 0, eta_v1 = 0, eta_v2 = 0;  // learning rates, Q.CoefFrac
  int32_t w_p1 = 0, w_p2 = 0, w_v1 = 0, w_v2 = 0;           // initial weights, Q.WgtFrac
  int32_t w_min = 0;                                        // lower bound, all weights
  int32_t w_p1_max = 0, w_p2_max = 0, w_v1_max = 0, w_v2_max = 0;  // upper bounds
  uint32_t v_lim = 0;          // |position-loop output| limit, counts/period Q.CtlFrac
  uint32_t u_lim = 0;          // |u| limit
  uint32_t ferr_lim = 0;       // following-error limit, counts Q.CtlFrac
  uint32_t inpos_win = 0;      // in-position window, counts Q.CtlFrac
  uint16_t inpos_hold = 1;     // control periods
  uint32_t settle_rate = 0;    // settle-phase corrective step rate, counts/period Q.CtlFrac
  bool operator==(const NeuronConfig&) const = default;
};

class NeuronPi {
 public:
  enum St : uint8_t { StIdle = 0, StVff, StDiv, StErr, StT1, StT2, StDu, StBc, StH1, StDw1, StH2, StDw2 };
  struct Inputs {
    bool start = false;
    bool stop = false;
    int32_t ref_int = 0;   // P* integer pulses
    uint32_t ref_frac = 0;  // top CtlFrac bits of the P* fraction
    int32_t ref_vel = 0;   // V*, Q.VffFrac pulses/clock
    bool ref_done = false;
    int32_t enc_pos = 0;
    bool cmd_busy = false;  // a step is requested/owed/on the pin
    bool nco_req = false;   // the NCO requests a step this clock
  };
  struct Loop {  // per-loop registers: [0] position, [1] speed
    int32_t w1 = 0, w2 = 0;   // WgtW
    int32_t n1 = 0, n2 = 0;   // NWgtW normalised
    int32_t ep = 0;           // e(k-1)
    int32_t acc = 0;
    int32_t es = 0;
    bool operator==(const Loop&) const = default;
  };
  struct State {
    bool active = false, in_pos = false, ferr = false;
    uint16_t cnt = 0;
    uint8_t st = StIdle;
    bool sel = false, dsel = false;
    uint8_t dbit = 0;
    uint32_t drem = 0, dquo = 0, dsum = 0;
    uint16_t hold = 0;
    int32_t ref = 0, pfb = 0, vmeas = 0, vq = 0;
    bool fin = false;
    bool mv = false, mvs = false;
    int32_t vff = 0;
    Loop lp[2];
    bool hush = false;
    int32_t corr = 0;  // CorrW, corrective steps still to issue
    int32_t out_p = 0, u = 0;
    int32_t e = 0, x2 = 0, t1 = 0, t2 = 0, du = 0, h = 0;
    bool learn = false;  // |e| > learning dead zone, set in StErr
    bool operator==(const State&) const = default;
  };

  NeuronPi() { reset(); }
  void reset() { q_ = State{}; }
  void step(const NeuronConfig& cfg, const Inputs& in);
  // Nothing but the strobe counter moves this clock (no start/stop)?
  bool counting_only() const { return !q_.active || (q_.st == StIdle && q_.cnt != 0); }
  // Clocks until the next strobe (0 = this clock or inactive).
  uint16_t clocks_to_strobe() const { return q_.active ? q_.cnt : 0; }
  // Skip k clocks that only count (k <= cnt, active, idle FSM, no start/stop).
  void skip(uint16_t k) { if (q_.active) q_.cnt = uint16_t(q_.cnt - k); }

  const State& state() const { return q_; }
  State& mutable_state() { return q_; }

  // The datapath's multiplier: round half up, arithmetic shift, saturate.
  static int32_t mul_round_sat(int32_t a, int32_t b, unsigned sh);
  static int32_t sat32(int64_t v) {
    return v > INT32_MAX ? INT32_MAX : v < INT32_MIN ? INT32_MIN : int32_t(v);
  }

 private:
  State q_;
};

static_assert(CtlW == 32 && MulAW == 32 && MulBW <= 31 && WgtW <= 31 && NWgtW <= 31,
              "NeuronPi holds the datapath words in int32_t");
static_assert(MulAW + MulBW <= 63, "NeuronPi products fit int64_t");

}  // namespace sc
