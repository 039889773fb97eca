// Bit-exact model of rtl/sc_neuron_pi.sv: the position/speed single-neuron
// adaptive PI cascade on one microcoded datapath (register file, one 34-bit
// adder, one multiplier, a restoring divider), clock by clock: the same
// micro-program, registers, rounding ((p + 2^(s-1)) >> s), wrap and
// saturation. See the RTL header and docs/closed_loop.md for the equations.
#pragma once

#include <cstdint>

#include "fixed_point.h"
#include "sc_layout.h"

namespace sc {

// Controller configuration (the ctl_cfg_i vector of sc_neuron_pi): the
// generated sc::CtlCfg (rtl/sc_pkg.sv tags -> sc_layout.h); defaults = the
// register reset values.
using NeuronConfig = CtlCfg;

class NeuronPi {
 public:
  // Phase of the period (state_o): sc::CtlSt*; micro-program steps: sc::Upc*
  // (both generated from rtl/sc_pkg.sv, shared with the RTL).
  static constexpr int kInitSteps = UpcVff - UpcInit;
  // Register-file words; per-loop pairs at even addresses, + loop.
  enum Rf : uint8_t {
    RfEp = 0, RfAcc = 2, RfEs = 4, RfW1 = 6, RfW2 = 8, RfN1 = 10, RfN2 = 12, RfOutP = 14, RfVff = 15,
    RfE = 16, RfX2 = 17, RfT1 = 18, RfSum = 19, RfDu = 20, RfBc = 21, RfH = 22, RfDw = 23, RfEraw = 24,
    RfT2 = 25, RfTot = 26
  };
  // Clocks of work per control period (cfg.div must be larger).
  static constexpr int kBusyClocks = 1 + 2 * (2 + 2 * (NWgtFrac + 1) + 1 + 10 + 5 + 6 + 2 * 6);
  static constexpr int kMinDiv = 256;

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
  struct Loop {  // output copies of the per-loop words: [0] position, [1] speed
    int32_t w1 = 0, w2 = 0;   // WgtW
    int32_t n1 = 0, n2 = 0;   // NWgtW normalised
    int32_t ep = 0;           // e(k-1)
    bool operator==(const Loop&) const = default;
  };
  struct State {
    bool active = false, in_pos = false, ferr = false;
    uint16_t cnt = 0;
    uint8_t upc = UpcIdle;
    uint8_t st = CtlStIdle;  // phase of upc (state_o)
    bool sel = false;
    uint8_t dbit = 0;
    uint32_t drem = 0, dquo = 0, dsum = 0;
    uint16_t hold = 0;
    bool hush = false;
    int32_t corr = 0;  // CorrW, corrective steps still to issue
    bool learn = false, eq = false, over = false, under = false;
    int64_t t = 0;     // AluW exact intermediate
    int32_t eraw = 0;  // e_p for the corrective steps
    int32_t ref = 0, pfb = 0, vmeas = 0, vq = 0;
    bool fin = false;
    bool mv = false, mvs = false;
    int32_t u = 0, out_p = 0;  // outputs: u, v_cmd
    Loop lp[2];
    int32_t rf[32] = {};
    int32_t acc(int l) const { return rf[RfAcc + l]; }
    int32_t es(int l) const { return rf[RfEs + l]; }
    int32_t vff() const { return rf[RfVff]; }
    bool operator==(const State&) const = default;
  };

  NeuronPi() { reset(); }
  void reset() { q_ = State{}; }
  void step(const NeuronConfig& cfg, const Inputs& in);
  // Nothing but the strobe counter moves this clock (no start/stop)?
  bool counting_only() const { return !q_.active || (q_.upc == UpcIdle && q_.cnt != 0); }
  // Clocks until the next strobe (0 = this clock or inactive).
  uint16_t clocks_to_strobe() const { return q_.active ? q_.cnt : 0; }
  // Skip k clocks that only count (k <= cnt, active, idle FSM, no start/stop).
  void skip(uint16_t k) { if (q_.active) q_.cnt = uint16_t(q_.cnt - k); }

  const State& state() const { return q_; }
  State& mutable_state() { return q_; }

  static uint8_t phase_of(uint8_t upc);
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
