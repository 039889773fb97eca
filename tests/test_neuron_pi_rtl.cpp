// sc_neuron_pi ALONE against its bit-exact model sc::NeuronPi, clock by
// clock. Inside the servo axis (test_closed_loop.cpp) realistic moves never
// reach most corner paths of the controller; here the controller's ports are
// driven directly with
//  - a random configuration per move: gains, Kb and learning rates up to
//    2^24-1, limits 0 / tiny / >= 2^31, weights of both signs at, near and
//    beyond their bounds (also inverted bounds), learn_shift 0..31, encoder
//    shift 0..7, learning dead zones 0 / small / huge, tiny following-error
//    limits, in-position hold 0..65535, any settle rate, cfg_div 128..400;
//  - random inputs: reference trajectories (through the int32 wrap), settle
//    phases (ref_done high, corrective steps counted on nco_req pulses from
//    a toy NCO driven by u, cmd_busy low for whole periods), and "chaos"
//    moves with encoder jumps, ref_int / ref_vel at the 32-bit extremes and
//    random handshakes; start and stop at random times (also mid-FSM,
//    start and stop together, restart while active) and a rare synchronous
//    reset.
// After every rising edge every output of the RTL is compared with the
// model's state; the first difference fails with seed, clock, signal, RTL
// value and model value. Coverage counters taken from the model prove that
// the stimulus reaches each corner path, and an injected one-bit weight
// difference proves that the comparison can fail.
//
// Soak: SC_NPI_SEED0 (first seed), SC_NPI_SEEDS (number of seeds) and
// SC_NPI_CLOCKS (clocks per seed) override the defaults.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <memory>
#include <optional>
#include <random>
#include <string>

#include "Vsc_neuron_pi.h"
#include "lockstep.h"
#include "neuron_pi.h"
#include "rtl_neuron_cfg.h"
#include "verilated_top.h"

namespace sc {
namespace {

uint64_t env_u64(const char* name, uint64_t dflt) {
  const char* v = std::getenv(name);
  return v && *v ? std::strtoull(v, nullptr, 0) : dflt;
}

// ---- the Verilated sc_neuron_pi (the adapter pattern of tb/verilated_top.h) ----------
class RtlNeuronPi : public VerilatedTop<Vsc_neuron_pi> {
 public:
  RtlNeuronPi() : VerilatedTop<Vsc_neuron_pi>("sc_neuron_pi") {}

  void set_config(const NeuronConfig& n) {
    bind_neuron_config(top(), n);
  }

  void set_inputs(const NeuronPi::Inputs& in) {
    Vsc_neuron_pi& m = top();
    m.start_i = in.start;
    m.stop_i = in.stop;
    m.ref_int_i = uint32_t(in.ref_int);
    m.ref_frac_i = port_bits(in.ref_frac, CtlFrac);
    m.ref_vel_i = uint32_t(in.ref_vel);
    m.ref_done_i = in.ref_done;
    m.enc_pos_i = uint32_t(in.enc_pos);
    m.cmd_busy_i = in.cmd_busy;
    m.nco_req_i = in.nco_req;
  }

  // One clock: rising edge (synchronous active-low reset), then falling edge.
  void clock(bool rst_n) {
    top().rst_ni = rst_n;
    tick();
  }
};

// ---- every output: RTL port (sign-extended by its width) vs model state -------------
constexpr int kNpiSignals = 16;
constexpr std::array<const char*, kNpiSignals> kNpiName = {
    "active_o", "in_pos_o", "fault_ferr_o", "u_o",    "v_cmd_o", "e_p_o",   "e_v_o",   "w_p1_o",
    "w_p2_o",   "w_v1_o",   "w_v2_o",       "wn_p1_o", "wn_p2_o", "wn_v1_o", "wn_v2_o", "state_o"};
constexpr std::array<int, kNpiSignals> kNpiWidth = {1,    1,    1,     CtlW,  CtlW,  CtlW,  CtlW,  WgtW,
                                                    WgtW, WgtW, WgtW, NWgtW, NWgtW, NWgtW, NWgtW, CtlStW};

struct NpiOutputs {
  std::array<int64_t, kNpiSignals> v{};
  bool operator==(const NpiOutputs&) const = default;
};

NpiOutputs rtl_outputs(const Vsc_neuron_pi& t) {
  return {{t.active_o, t.in_pos_o, t.fault_ferr_o, sign_extend(t.u_o, CtlW), sign_extend(t.v_cmd_o, CtlW),
           sign_extend(t.e_p_o, CtlW), sign_extend(t.e_v_o, CtlW), sign_extend(t.w_p1_o, WgtW),
           sign_extend(t.w_p2_o, WgtW), sign_extend(t.w_v1_o, WgtW), sign_extend(t.w_v2_o, WgtW),
           sign_extend(t.wn_p1_o, NWgtW), sign_extend(t.wn_p2_o, NWgtW), sign_extend(t.wn_v1_o, NWgtW),
           sign_extend(t.wn_v2_o, NWgtW), t.state_o}};
}

NpiOutputs model_outputs(const NeuronPi::State& s) {
  return {{s.active, s.in_pos, s.ferr, s.u, s.out_p, s.lp[0].ep, s.lp[1].ep, s.lp[0].w1, s.lp[0].w2, s.lp[1].w1,
           s.lp[1].w2, s.lp[0].n1, s.lp[0].n2, s.lp[1].n1, s.lp[1].n2, s.st}};
}

SignalValues render_npi(const NpiOutputs& o) {
  SignalValues v;
  for (int i = 0; i < kNpiSignals; ++i) v.emplace_back(kNpiName[i], hex_bits(o.v[i], kNpiWidth[i]));
  return v;
}

std::string cfg_str(const NeuronConfig& c) {
  std::string s;
  ctl_cfg_visit(c, [&s](const char* name, int64_t v) {
    s += fmt::format("{}{}={}", s.empty() ? "" : " ", name, v < 0 ? fmt::format("{}", v) : fmt::format("{:#x}", v));
  });
  return s;
}

std::string in_str(const NeuronPi::Inputs& i, bool rst_n) {
  return fmt::format(
      "rst_n={} start={} stop={} ref_int={} ref_frac={:#x} ref_vel={} ref_done={} enc_pos={} cmd_busy={} nco_req={}",
      rst_n, i.start, i.stop, i.ref_int, i.ref_frac, i.ref_vel, i.ref_done, i.enc_pos, i.cmd_busy, i.nco_req);
}

// ---- coverage: corner paths the stimulus must reach (seen in the model) ---------------
enum Cov {
  kPeriods, kInPos, kFerr, kHoldDone, kCorrSet, kCorrSat, kCorrSatDone, kCorrDone, kHush, kLearnOn, kLearnOff,
  kEbClamp, kEbMin, kSatT12, kLimP, kLimV, kLimZero, kLimHuge, kBackCalc, kWMin, kWMax, kWBeyond, kSatVff, kSatT,
  kSatDu, kSatH, kSatAcc, kSatTot, kDivZero, kDivBig, kWnOne, kX2Wrap, kRefWrap, kVmeasHuge, kSettleNeg,
  kStartMidFsm, kStopMidFsm, kStartStop, kReset, kPidPeriods, kPidD, kPidLim, kCovN
};
constexpr const char* kCovName[] = {
    "control periods", "in-position latched", "following-error fault", "hold reached", "corrective steps set",
    "corrective steps saturated", "saturated corrective steps run out", "corrective steps counted out",
    "settling (accumulators held)", "learning on", "learning off (dead zone)", "e clamped to the B port",
    "e = -2^24 clamped (x2 * e_b)", "T1 + T2 saturated", "v_lim limits", "u_lim limits",
    "limit 0", "limit >= 2^31", "back-calculation Kb*es", "weight clamped at w_min", "weight clamped at w_max",
    "weight beyond its bounds", "Vff saturated", "T1/T2 saturated", "du saturated", "Hebb product saturated",
    "accumulator saturated", "acc + feed-forward saturated", "division by |w1|+|w2| = 0",
    "division by |w1|+|w2| > 2^23", "|wn| = 1.0", "x2 = e - e_prev wraps", "speed ref out_p + Vff wraps",
    "encoder jump >= 2^14 counts/period", "settle rate >= 2^31 (u negative)",
    "start mid-FSM", "stop mid-FSM", "start and stop together", "synchronous reset mid-run",
    "PID periods (position loop alone)", "PID D term K_V x2 != 0", "PID output at u_lim"};

static_assert(std::size(kCovName) == kCovN);
using Coverage = std::array<uint64_t, kCovN>;

bool sat(int32_t v) { return v == INT32_MAX || v == INT32_MIN; }

void count(Coverage& c, bool& corr_sat, const NeuronConfig& cfg, const NeuronPi::Inputs& in, const NeuronPi::State& p,
           const NeuronPi::State& q) {
  const int s = p.sel ? 1 : 0;
  if (in.start) {
    if (p.active && p.st != CtlStIdle) ++c[kStartMidFsm];
    if (in.stop) ++c[kStartStop];
  } else if (in.stop && p.active && p.st != CtlStIdle) {
    ++c[kStopMidFsm];
  }
  if (!p.in_pos && q.in_pos) ++c[kInPos];
  if (!p.ferr && q.ferr) ++c[kFerr];
  if (p.corr == 0 && q.corr != 0) {
    ++c[kCorrSet];
    corr_sat = q.corr == (1 << (CorrW - 1)) - 1 || q.corr == -((1 << (CorrW - 1)) - 1);
    if (corr_sat) ++c[kCorrSat];
  }
  if (p.corr != 0 && q.corr == 0) {
    if (!in.start) ++c[kCorrDone];
    if (!in.start && corr_sat) ++c[kCorrSatDone];
    corr_sat = false;
  }
  if (in.start || in.stop) return;
  using N = NeuronPi;
  const bool hush_now = !p.sel && p.fin;
  switch (p.upc) {
    case UpcVff:
      ++c[kPeriods];
      if (sat(q.vff())) ++c[kSatVff];
      if (p.vmeas >= (1 << 30) || p.vmeas <= -(1 << 30)) ++c[kVmeasHuge];
      break;
    case UpcDiv1:
    case UpcDiv2:
      if (p.dbit == 0) {
        if (p.dsum == 0) ++c[kDivZero];
        if (p.dsum > (1u << (WgtW - 1))) ++c[kDivBig];
        const int32_t wn = p.upc == UpcDiv2 ? q.lp[s].n2 : q.lp[s].n1;
        if (wn == (1 << NWgtFrac) || wn == -(1 << NWgtFrac)) ++c[kWnOne];
      }
      break;
    case UpcRef:
      if (p.sel) {
        const int64_t ref = int64_t(p.rf[N::RfOutP]) + (cfg.ff_en ? p.vff() : 0);
        if (ref > INT32_MAX || ref < INT32_MIN) ++c[kRefWrap];
      }
      break;
    case UpcX2: {
      const int64_t e = hush_now ? 0 : p.rf[N::RfEraw];
      if (e - p.rf[N::RfEp + s] != int64_t(q.rf[N::RfX2])) ++c[kX2Wrap];
      break;
    }
    case UpcEp:
      if (!p.sel && q.hush) ++c[kHush];
      break;
    case UpcLearn:
      if (cfg.pid) {
        if (q.rf[N::RfH] != 0) ++c[kPidD];
      } else if (!hush_now) {
        ++c[q.learn ? kLearnOn : kLearnOff];
      }
      break;
    case UpcWin:
      if (!p.sel && p.fin && p.corr == 0 && q.hold == 0 && (q.in_pos || q.corr != 0)) ++c[kHoldDone];
      if (!p.sel && p.corr == 0 && q.corr != 0 && cfg.settle_rate >= (1u << 31)) ++c[kSettleNeg];
      break;
    case UpcT1:
      if (sat(q.rf[N::RfT1])) ++c[kSatT];
      break;
    case UpcT2:
      if (sat(q.rf[N::RfT2])) ++c[kSatT];
      break;
    case UpcSum: {
      const int64_t t12 = int64_t(p.rf[N::RfT1]) + p.rf[N::RfT2];
      if (t12 > INT32_MAX || t12 < INT32_MIN) ++c[kSatT12];
      break;
    }
    case UpcDu:
      if (sat(q.rf[N::RfDu])) ++c[kSatDu];
      break;
    case UpcOut:
      if (cfg.pid) ++c[kPidPeriods];
      break;
    case UpcAcc2:
      if (cfg.kb != 0 && p.es(s) != 0 && !p.hush) ++c[kBackCalc];
      if (sat(q.acc(s))) ++c[kSatAcc];
      break;
    case UpcTot: {
      const int64_t b = (cfg.pid && !p.hush) ? p.rf[N::RfH] : (p.sel && cfg.ff_en) ? p.vff() : 0;
      const int64_t tot = int64_t(p.acc(s)) + b;
      if (tot > INT32_MAX || tot < INT32_MIN) ++c[kSatTot];
      break;
    }
    case UpcLo: {
      const uint32_t lim = (p.sel || cfg.pid) ? cfg.u_lim : cfg.v_lim;
      if (q.es(s) != 0) ++c[cfg.pid ? kPidLim : p.sel ? kLimV : kLimP];
      if (lim == 0) ++c[kLimZero];
      if (lim >= (1u << 31)) ++c[kLimHuge];
      break;
    }
    case UpcH1:
      if (sat(q.rf[N::RfH])) ++c[kSatH];
      if (p.learn && (p.rf[N::RfE] > (1 << (MulBW - 1)) - 1 || p.rf[N::RfE] < -((1 << (MulBW - 1)) - 1))) ++c[kEbClamp];
      break;
    case UpcH2:
      if (sat(q.rf[N::RfH])) ++c[kSatH];
      if (p.learn && p.rf[N::RfE] == -(1 << (MulBW - 1)) &&
          NeuronPi::mul_round_sat(p.rf[N::RfX2], -((1 << (MulBW - 1)) - 1), CtlFrac) !=
              NeuronPi::mul_round_sat(p.rf[N::RfX2], -(1 << (MulBW - 1)), CtlFrac)) {
        ++c[kEbMin];  // the clamp changes the product
      }
      break;
    case UpcW1:
    case UpcW5: {
      const bool one = p.upc == UpcW1;
      const int32_t hi = one ? (p.sel ? cfg.w_v1_max : cfg.w_p1_max) : (p.sel ? cfg.w_v2_max : cfg.w_p2_max);
      const int32_t old = p.rf[(one ? N::RfW1 : N::RfW2) + s];
      const int64_t sum = int64_t(old) + p.rf[N::RfDw];
      if (sum > hi) ++c[kWMax];
      else if (sum < cfg.w_min) ++c[kWMin];
      if (old > hi || old < cfg.w_min) ++c[kWBeyond];
      break;
    }
    default:
      break;
  }
}

// ---- random numbers (mt19937_64 is specified bit-exactly; no std distributions) ------
class Rng {
 public:
  explicit Rng(uint64_t seed) : g_(seed) {}
  uint64_t u64() { return g_(); }
  uint32_t u32() { return uint32_t(g_() >> 32); }
  uint64_t below(uint64_t n) { return n ? g_() % n : 0; }
  int64_t range(int64_t lo, int64_t hi) { return lo + int64_t(below(uint64_t(hi - lo) + 1)); }
  bool chance(double p) { return double(g_() >> 11) * 0x1.0p-53 < p; }
  // log-uniform in [0, 2^maxbits): a random bit length, then random bits
  uint64_t logu(int maxbits) {
    const int b = int(below(uint64_t(maxbits) + 1));
    return b == 0 ? 0 : ((uint64_t(1) << (b - 1)) | (g_() & ((uint64_t(1) << (b - 1)) - 1)));
  }
  int64_t slogu(int maxbits) { return chance(0.5) ? int64_t(logu(maxbits)) : -int64_t(logu(maxbits)); }

 private:
  std::mt19937_64 g_;
};

// unsigned word: 0, tiny, log-uniform, the extremes around 2^31, anything
uint32_t pick_u32(Rng& r, uint32_t typical) {
  switch (r.below(8)) {
    case 0: return 0;
    case 1: return uint32_t(r.range(1, 16));
    case 2: return uint32_t(r.logu(32));
    case 3: {
      const uint32_t ext[] = {0x7fffffffu, 0x80000000u, 0x80000001u, 0xffffffffu, 0xfffffffeu, 0x40000000u};
      return ext[r.below(6)];
    }
    case 4: return r.u32();
    default: return uint32_t(std::min<uint64_t>(0xffffffffu, uint64_t(typical) * (r.logu(4) + 1) / 4 + r.below(8)));
  }
}

// coefficient (CoefW bits unsigned): 0, 1, typical * 2^[-3,3], up to 2^24-1
uint32_t pick_coef(Rng& r, uint32_t typical, bool wild) {
  const uint32_t cmax = (1u << CoefW) - 1;
  const int k = wild ? 6 : 10;
  switch (r.below(uint64_t(k))) {
    case 0: return 0;
    case 1: return wild ? cmax : uint32_t(r.range(1, 4));
    case 2: return uint32_t(r.logu(CoefW));
    case 3: return wild ? cmax - uint32_t(r.below(16)) : uint32_t(r.logu(CoefW));
    default: {
      const int sh = int(r.range(-3, 3));
      const uint64_t v = sh >= 0 ? uint64_t(typical) << sh : uint64_t(typical) >> -sh;
      return uint32_t(std::min<uint64_t>(cmax, v + r.below(64)));
    }
  }
}

constexpr int32_t kWMaxV = (1 << (WgtW - 1)) - 1, kWMinV = -(1 << (WgtW - 1));
int32_t clampw(int64_t v) { return int32_t(std::clamp<int64_t>(v, kWMinV, kWMaxV)); }

int32_t pick_w(Rng& r, int32_t typical) {
  switch (r.below(7)) {
    case 0: return 0;
    case 1: return r.chance(0.5) ? kWMaxV : kWMinV;
    case 2: return clampw(r.slogu(WgtW - 1));
    case 3: return sign_extend(r.u32(), WgtW);
    default: return clampw(int64_t(typical) + r.slogu(12));
  }
}

constexpr uint32_t kQ = 1u << CtlFrac;  // one count in Q.CtlFrac

// What one move looks like.
enum class Kind { Track, Settle, Chaos };
const char* kind_name(Kind k) { return k == Kind::Track ? "track" : k == Kind::Settle ? "settle" : "chaos"; }

NeuronConfig random_config(Rng& r, Kind kind) {
  const bool wild = kind == Kind::Chaos || r.chance(0.25);
  NeuronConfig c;
  c.div = uint16_t(r.chance(0.1) ? NeuronPi::kMinDiv : r.range(NeuronPi::kMinDiv, 600));
  c.shift = uint8_t(kind == Kind::Chaos && r.chance(0.3) ? 7 : r.below(8));  // 7: V* * div can saturate Vff
  c.ff_en = r.chance(0.7);
  c.learn_shift = uint8_t(r.chance(0.5) ? r.range(4, 14) : r.below(32));
  const uint32_t cnt = kQ << c.shift;  // one step, Q.CtlFrac counts
  auto dz = [&]() -> uint32_t {
    switch (r.below(6)) {
      case 0: return 0;
      case 1: return uint32_t(r.below(cnt * 2u));
      case 5: return uint32_t(r.range(1, 8)) << CtlFrac;  // whole counts: |e| == dz happens
      case 2: return uint32_t(r.range(0x40000000, 0xffffffff));
      case 3: return pick_u32(r, cnt);
      default: return uint32_t(r.logu(24));
    }
  };
  c.learn_dz_p = dz();
  c.learn_dz_v = dz();
  c.k_p = pick_coef(r, 4194, wild);     // 0.004
  c.k_v = pick_coef(r, 20972, wild);    // 0.02
  c.kb = pick_coef(r, 1u << 20, wild);  // 1.0
  c.eta_p1 = pick_coef(r, 209715, wild);
  c.eta_p2 = pick_coef(r, 209715, wild);
  c.eta_v1 = pick_coef(r, 157286, wild);
  c.eta_v2 = pick_coef(r, 104858, wild);
  // weights and bounds (Q.16): typical 0..127, sometimes beyond, inverted, negative
  c.w_min = r.chance(0.4) ? 0 : r.chance(0.5) ? pick_w(r, -(1 << 16)) : clampw(r.slogu(WgtW - 1));
  c.w_p1_max = pick_w(r, 1 << 15);
  c.w_p2_max = pick_w(r, 127 << 16);
  c.w_v1_max = pick_w(r, 127 << 16);
  c.w_v2_max = pick_w(r, 32 << 16);
  auto near = [&](int32_t lo, int32_t hi) {
    switch (r.below(5)) {
      case 0: return clampw(int64_t(hi) + r.range(-3, 3));
      case 1: return clampw(int64_t(lo) + r.range(-3, 3));
      case 2: return pick_w(r, 0);
      default: return clampw(int64_t(lo) + int64_t(r.below(uint64_t(std::max<int64_t>(1, int64_t(hi) - lo + 1)))));
    }
  };
  c.w_p1 = near(c.w_min, c.w_p1_max);
  c.w_p2 = near(c.w_min, c.w_p2_max);
  c.w_v1 = near(c.w_min, c.w_v1_max);
  c.w_v2 = near(c.w_min, c.w_v2_max);
  // limits, counts/period Q.16: realistic ~ a few steps/period
  const uint32_t per = uint32_t(std::min<uint64_t>(0x7fffffffu, uint64_t(cnt) * 4));
  c.v_lim = pick_u32(r, per);
  c.u_lim = pick_u32(r, per);
  switch (r.below(5)) {
    case 0: c.ferr_lim = uint32_t(r.below(64 * uint64_t(kQ))); break;  // tiny: trips on jumps
    case 1: c.ferr_lim = 0xffffffffu; break;
    case 2: c.ferr_lim = pick_u32(r, 0x10000000u); break;
    default: c.ferr_lim = uint32_t(std::min<uint64_t>(0xffffffffu, uint64_t(cnt) * r.range(50, 5000))); break;
  }
  switch (r.below(6)) {
    case 0: c.inpos_win = 0; break;
    case 1: c.inpos_win = uint32_t(int64_t(cnt / 2) + r.range(-2, 2)); break;
    case 2: c.inpos_win = uint32_t(r.below(uint64_t(cnt) * 4)); break;
    case 3: c.inpos_win = pick_u32(r, cnt); break;
    case 4: c.inpos_win = uint32_t(r.range(1, 4)) << CtlFrac; break;  // whole counts: |e| == win happens
    default: c.inpos_win = uint32_t(r.logu(20)); break;
  }
  switch (r.below(6)) {
    case 0: c.inpos_hold = 0; break;
    case 1: c.inpos_hold = 1; break;
    case 2: c.inpos_hold = r.chance(0.3) ? 65535 : uint16_t(r.logu(16)); break;
    default: c.inpos_hold = uint16_t(r.range(2, 12)); break;
  }
  // settle rate: from 1 step in a few periods to 1 step per clock; or anything
  const uint64_t step_per_clock = uint64_t(c.div) * cnt;
  switch (r.below(8)) {
    case 0: case 1: c.settle_rate = pick_u32(r, cnt); break;
    case 2: c.settle_rate = 0x80000000u | r.u32(); break;  // u = -sign(corr) * |rate| wraps
    default:
      c.settle_rate = uint32_t(std::min<uint64_t>(0x7fffffffu, step_per_clock / uint64_t(r.range(1, 400))));
      break;
  }
  // PID mode in about a quarter of the moves, drawn from bits already drawn
  // so that the cascade's moves keep their random stream
  c.pid = ((c.ferr_lim ^ c.inpos_win ^ c.k_p) & 3) == 1;
  return c;
}

// The first mismatch of a seed, with the values as numbers for the tests.
struct NpiMismatch {
  uint64_t clock = 0;
  std::string signal;
  int64_t rtl = 0, model = 0;
  std::string text;
};

// ---- the lockstep runner: stimulus, both clocked, all outputs compared ---------------
class NeuronLockstep {
 public:
  NeuronLockstep(uint64_t seed, bool fixed_config) : seed_(seed), fixed_(fixed_config), r_(seed) {
    if (fixed_) {
      // one plausible configuration for the whole run (a few extremes allowed)
      cfg_ = random_config(r_, Kind::Track);
      cfg_.ferr_lim = std::max<uint32_t>(cfg_.ferr_lim, 0x01000000u);
      cfg_.inpos_hold = uint16_t(r_.range(1, 6));
      cfg_.inpos_win = kQ << cfg_.shift;
    }
    rtl_.set_config(cfg_);
    rtl_.set_inputs(in_);
    for (int i = 0; i < 4; ++i) rtl_.clock(false);
    model_.reset();
    gap_left_ = r_.below(50);
    enc_ = r_.u32();
  }

  // One clock. Empty = every output matched.
  std::optional<NpiMismatch> step() {
    const NeuronPi::State prev = model_.state();
    bool rst_n = true;
    next_inputs(rst_n);
    rtl_.set_inputs(in_);
    if (cfg_dirty_) {
      rtl_.set_config(cfg_);
      cfg_dirty_ = false;
    }
    rtl_.clock(rst_n);
    if (rst_n) {
      model_.step(cfg_, in_);
      count(cov_, corr_sat_, cfg_, in_, prev, model_.state());
    } else {
      model_.reset();
      ++cov_[kReset];
    }
    ++clock_;
    return compare(rst_n);
  }

  std::optional<NpiMismatch> compare(bool rst_n = true) {
    const NpiOutputs rtl = rtl_outputs(rtl_.top()), model = model_outputs(model_.state());
    if (checker_.compare(clock_, rtl, model)) [[likely]] return std::nullopt;
    const Mismatch& e = checker_.errors().front();
    const size_t i = size_t(std::find(kNpiName.begin(), kNpiName.end(), e.signal) - kNpiName.begin());
    NpiMismatch m{clock_, e.signal, i < kNpiName.size() ? rtl.v[i] : 0, i < kNpiName.size() ? model.v[i] : 0, {}};
    const NeuronPi::State& q = model_.state();
    m.text = fmt::format(
        "seed {} {}\n  move {} ({}), model st={} sel={} cnt={} active={} fin={} hush={} corr={} hold={}\n"
        "  inputs: {}\n  cfg: {}",
        seed_, e.to_string(), moves_, kind_name(kind_), q.st, q.sel, q.cnt, q.active, q.fin, q.hush, q.corr, q.hold,
        in_str(in_, rst_n), cfg_str(cfg_));
    return m;
  }

  NeuronPi& model() { return model_; }
  // The next clock brings no start, stop or reset (the move goes on).
  bool steady_next_clock() const { return in_move_ && start_left_ == 0 && run_left_ > 1; }
  uint64_t clock() const { return clock_; }
  uint64_t moves() const { return moves_; }
  const Coverage& coverage() const { return cov_; }

 private:
  void begin_move() {
    ++moves_;
    const uint64_t k = r_.below(20);
    kind_ = k < 8 ? Kind::Track : k < 15 ? Kind::Settle : Kind::Chaos;
    if (!fixed_) {
      cfg_ = random_config(r_, kind_);
      cfg_dirty_ = true;
    }
    in_.start = true;
    in_.stop = r_.chance(0.04);
    start_left_ = r_.chance(0.05) ? int(r_.range(1, 3)) : 0;
    const unsigned sh = cfg_.shift & 7u;
    // run length until stop (if still active), restart or reset
    switch (r_.below(20)) {
      case 0: case 1: case 2: case 3: case 4: case 5: case 6: case 7:
        run_left_ = r_.below(3000);  // stop/restart within a few periods
        break;
      case 8: case 9: case 10: run_left_ = r_.range(15000, 60000); break;
      default: run_left_ = r_.range(3000, 15000); break;
    }
    end_ = r_.chance(0.15) ? End::Restart : r_.chance(0.03) ? End::Reset : End::Stop;
    mid_fsm_ = r_.chance(0.5);  // end while the FSM works through a period
    // plant / handshakes
    nco_mode_ = r_.chance(kind_ == Kind::Chaos ? 0.5 : 0.85) ? Nco::Plant : Nco::Random;
    req_p_ = r_.chance(0.5) ? 0.01 : 0.2;
    busy_random_ = kind_ == Kind::Chaos && r_.chance(0.5);
    busy_indep_ = r_.chance(0.3);
    pulse_len_ = int(r_.range(1, 40));
    delay_ = int(r_.below(8));
    missed_p_ = r_.chance(0.7) ? 0.0 : 0.05;
    noise_p_ = r_.chance(0.7) ? 0.0 : 1e-4;
    jump_at_ = r_.chance(0.2) ? r_.below(run_left_ + 1) : UINT64_MAX;
    chg_p_ = r_.chance(0.5) ? 0.002 : r_.chance(0.5) ? 0.02 : 0.2;
    phase_ = 0;
    t_ = 0;
    // reference
    if (r_.chance(0.15)) {  // around the int32 wrap of positions
      const int64_t off = r_.range(-5000, 5000);
      enc_ = uint32_t(int64_t(r_.chance(0.5) ? INT32_MAX : INT32_MIN) + off);
    }
    const uint32_t pulses = uint32_t(int32_t(enc_) >> sh);
    pos31_ = uint64_t(pulses) << 31 | (r_.u64() & ((uint64_t(1) << 31) - 1));
    if (kind_ == Kind::Track) {
      vmax_ = int64_t(r_.chance(0.1) ? (uint64_t(1) << 31) - 1 : r_.logu(31));
      acc_clocks_ = r_.range(1, 8000);
      cruise_clocks_ = r_.below(15000);
      if (r_.chance(0.5)) vmax_ = -vmax_;
      in_.ref_done = false;
    } else if (kind_ == Kind::Settle) {
      // at rest: target and encoder apart by a fraction of a step, a few
      // steps, many steps, or beyond the corrective-step range
      pos31_ &= ~((uint64_t(1) << 31) - 1);
      int64_t err;  // counts
      switch (r_.below(7)) {
        case 0:  // within a count, or at the in-position window
          err = r_.chance(0.5) ? r_.range(-1, 1)
                               : int64_t(cfg_.inpos_win >> CtlFrac) * (r_.chance(0.5) ? 1 : -1) + r_.range(0, 1);
          break;
        case 1: err = r_.range(-(int64_t(1) << sh), int64_t(1) << sh); break;
        case 2: err = r_.range(-20, 20) * (int64_t(1) << sh); break;
        case 3: err = r_.range(-40000, 40000); break;
        case 4: {
          // |e| = 2^31 or just below (32768 counts; saturates the
          // corrective steps at shift 0): needs ferr_lim >= 2^31
          const int64_t edge[] = {32768, -32768, 32767, -32767, 32766};
          err = r_.chance(0.6) ? 32768 : edge[r_.below(5)];
          if (!fixed_ && r_.chance(0.7)) {
            cfg_.shift = 0;
            cfg_.ferr_lim = 0xffffffffu;
            cfg_.inpos_hold = uint16_t(r_.range(0, 3));
            cfg_.inpos_win = uint32_t(r_.below(kQ));
            if (r_.chance(0.7)) {
              // 32767 corrective steps at one per clock run out within the move
              cfg_.settle_rate = uint32_t(cfg_.div) << CtlFrac;
              nco_mode_ = Nco::Plant;
              run_left_ = r_.range(40000, 50000);
              end_ = End::Stop;
            }
          }
          break;
        }
        default: err = r_.range(-200, 200); break;
      }
      enc_ = uint32_t(uint64_t(pulses) << (cfg_.shift & 7u)) - uint32_t(err);  // e = err counts
      in_.ref_done = !r_.chance(0.2);  // else a moment later
    } else {
      in_.ref_done = r_.chance(0.3);
      in_.ref_vel = int32_t(r_.u32());
    }
    vel_ = 0;
    ref_to_inputs();
    edge_walk_ = kind_ == Kind::Chaos && r_.chance(0.4);
    edge_ = edge_error();
    eb_walk_ = edge_walk_ && r_.chance(0.5);
    if (eb_walk_) {
      // |e| at the B-port edge 2^24 with learning at unit scale: the Hebb
      // product x2 * e_b shows e clamped to +-(2^24 - 1) in its last bit
      // when x2 is about half a count (weight updates stay inside the bounds)
      const uint32_t eb_edges[] = {0xff000000u, 0xff000000u, 0xff000000u, 0x01000000u, 0xff000001u, 0x00ffffffu};
      edge_ = eb_edges[r_.below(std::size(eb_edges))];
      if (!fixed_) {
        cfg_.shift = 0;
        cfg_.learn_shift = uint8_t(r_.below(4));
        cfg_.learn_dz_p = cfg_.learn_dz_v = 0;
        cfg_.eta_p1 = cfg_.eta_p2 = uint32_t(1u << (CoefFrac + cfg_.learn_shift)) - uint32_t(r_.below(2));
        cfg_.w_min = kWMinV;
        cfg_.w_p1_max = cfg_.w_p2_max = kWMaxV;
        cfg_.ferr_lim = 0xffffffffu;
      }
    }
    if (kind_ == Kind::Chaos && !eb_walk_ && r_.chance(0.5)) {
      // a word-edge position error at the first snapshot (e_prev = 0, so
      // x2 = e too) with weight ratios giving exact normalised weights:
      // wn = -1.0 (one weight 0) makes T1 or T2 saturate, wn1 = wn2 = +-0.5
      // makes T1 + T2 overflow before the gain
      const uint32_t e0 = r_.chance(0.5) ? (r_.chance(0.5) ? 0x80000000u : 0x7fffffffu) : edge_error();
      set_position_error(e0);
      if (!fixed_) {
        cfg_.ferr_lim = 0xffffffffu;
        if (r_.chance(0.5)) cfg_.eta_p1 = cfg_.eta_p2 = cfg_.eta_v1 = cfg_.eta_v2 = 0;
        for (int l = 0; l < 2; ++l) {
          int32_t& w1 = l ? cfg_.w_v1 : cfg_.w_p1;
          int32_t& w2 = l ? cfg_.w_v2 : cfg_.w_p2;
          // wn1 = wn2 = -0.5 with e = -2^31, +0.5 with e = 2^31 - 1: T1 + T2 = 2^31
          const int32_t sign = (l == 0 && r_.chance(0.7)) ? (int32_t(e0) < 0 ? -1 : 1) : (r_.chance(0.5) ? 1 : -1);
          const int32_t m = int32_t(r_.range(1, kWMaxV / 3)) * sign;
          switch (r_.below(4)) {
            case 0: w1 = 0; w2 = m; break;
            case 1: w1 = m; w2 = 0; break;
            case 2: w1 = w2 = m; break;
            default: w1 = 3 * m; w2 = m; break;
          }
          if (r_.chance(0.5)) cfg_.w_min = kWMinV;
        }
      }
    }
  }

  // A position error at a word or comparison edge (Q.CtlFrac).
  uint32_t edge_error() {
    const uint32_t fixed_edges[] = {0x80000000u, 0x7fffffffu, 0x7fff0000u, 0x80010000u, 0x01000000u, 0xff000000u,
                                    0x00ffffffu, 0xff000001u, 0xfeffffffu, 0x01000001u, 0x00010000u, 0xffff0000u};
    const uint32_t dz = cfg_.learn_dz_p, fl = cfg_.ferr_lim;
    switch (r_.below(4)) {
      case 0: return r_.chance(0.5) ? dz : dz + 1;
      case 1: return uint32_t(-int64_t(dz) - int64_t(r_.below(2)));
      case 2: return r_.chance(0.5) ? fl : fl + 1;
      default: return fixed_edges[r_.below(std::size(fixed_edges))];
    }
  }

  // P* - 1/2 - P = e at the next snapshot (ref_done low): picks ref_frac and
  // the low 16 bits of the encoder count (with shift > 0 the low `shift`
  // bits of e follow the reference).
  void set_position_error(uint32_t e) {
    const unsigned sh = cfg_.shift & 7u;
    in_.ref_done = false;
    in_.ref_frac = ((e >> sh) + (kQ >> 1)) & (kQ - 1);
    const uint32_t ref = (((uint32_t(in_.ref_int) << CtlFrac) | in_.ref_frac) - (kQ >> 1)) << sh;
    enc_ = (enc_ & ~(kQ - 1)) | ((ref - e) >> CtlFrac);
  }

  void ref_to_inputs() {
    in_.ref_int = int32_t(uint32_t(pos31_ >> 31));
    in_.ref_frac = uint32_t(pos31_ >> (31 - CtlFrac)) & (kQ - 1);
  }

  void random_word(uint32_t& w, bool sign) {
    switch (r_.below(6)) {
      case 0: w = sign ? 0x7fffffffu : 0xffffffffu; break;
      case 1: w = 0x80000000u; break;
      case 2: w = r_.u32(); break;
      case 3: w = 0; break;
      default: w = uint32_t(int64_t(int32_t(w)) + r_.slogu(31)); break;
    }
  }

  void next_inputs(bool& rst_n) {
    const NeuronPi::State& s = model_.state();  // == the RTL outputs
    in_.start = false;
    in_.stop = false;
    in_.nco_req = false;

    if (!in_move_) {
      // gap between moves: controller idle (or stopping); inputs still move
      if (r_.chance(0.001)) in_.stop = true;
      if (gap_left_ == 0) {
        in_move_ = true;
        begin_move();
      } else {
        --gap_left_;
      }
    } else if (start_left_ > 0) {  // start held for a few clocks
      --start_left_;
      in_.start = true;
    } else {
      ++t_;
      const bool done = !s.active && !in_.start;
      const bool wait_fsm = run_left_ == 0 && mid_fsm_ && s.active && s.st == CtlStIdle;
      if ((run_left_ == 0 && !wait_fsm) || (done && r_.chance(0.01))) {
        if (end_ == End::Restart && s.active) {
          begin_move();  // a new start while active (config may change)
        } else if (end_ == End::Reset) {
          rst_n = false;
          end_move();
        } else {
          in_.stop = s.active || r_.chance(0.2);
          end_move();
        }
      } else if (run_left_ > 0) {
        --run_left_;
      }
    }
    stimulus(s);
  }

  void end_move() {
    in_move_ = false;
    gap_left_ = r_.chance(0.3) ? 0 : r_.below(600);
  }

  void stimulus(const NeuronPi::State& s) {
    const unsigned sh = cfg_.shift & 7u;
    if (kind_ == Kind::Track && in_move_) {
      const int64_t a = vmax_ / acc_clocks_;
      if (t_ <= uint64_t(acc_clocks_)) vel_ += a;
      const uint64_t decel = uint64_t(acc_clocks_ + cruise_clocks_), end = decel + uint64_t(acc_clocks_);
      if (t_ > decel && t_ <= end) vel_ -= a;
      if (t_ > end) {
        vel_ = 0;
        in_.ref_done = true;
      }
      vel_ = std::clamp<int64_t>(vel_, -(int64_t(1) << 31), (int64_t(1) << 31) - 1);
      pos31_ += uint64_t(vel_);
      in_.ref_vel = int32_t(vel_);
      ref_to_inputs();
    } else if (kind_ == Kind::Settle && in_move_) {
      if (!in_.ref_done && r_.chance(0.002)) in_.ref_done = true;
      in_.ref_vel = 0;
    }
    if (edge_walk_ && in_move_ && r_.chance(2.0 / cfg_.div)) {
      // position errors at and around one edge, period after period (x2 small)
      const int64_t off = eb_walk_ ? r_.range(1 << 15, 1 << 16) * (r_.chance(0.5) ? 1 : -1) : r_.slogu(18);
      set_position_error(r_.chance(0.5) ? edge_ : edge_ + uint32_t(off));
    }
    if (kind_ == Kind::Chaos || !in_move_) {
      if (r_.chance(chg_p_)) {
        switch (r_.below(8)) {
          case 0: {
            uint32_t e = enc_;
            random_word(e, true);
            enc_ = e;
            break;
          }
          case 1: {
            uint32_t v = uint32_t(in_.ref_int);
            random_word(v, true);
            in_.ref_int = int32_t(v);
            break;
          }
          case 2: in_.ref_frac = r_.u32() & (kQ - 1); break;
          case 3: {
            uint32_t v = uint32_t(in_.ref_vel);
            random_word(v, true);
            in_.ref_vel = int32_t(v);
            break;
          }
          case 4: in_.ref_done = !in_.ref_done; break;
          case 5: {
            // speed-loop edges: a jump of 2^15 counts is vmeas = -2^31, 2^8 is 2^24
            const int32_t edge[] = {32768, 256, -256, 255, 257, -257, 32767};
            enc_ += r_.chance(0.3) ? uint32_t(edge[r_.below(std::size(edge))]) : uint32_t(r_.slogu(20));
            break;
          }
          case 6: set_position_error(edge_error()); break;
          default: in_.ref_int = int32_t(uint32_t(in_.ref_int) + uint32_t(r_.slogu(16))); break;
        }
      }
    }
    if (in_move_ && t_ == jump_at_) enc_ += uint32_t(r_.slogu(31));

    // step NCO and stepper: u (counts/period) -> steps; the encoder follows
    bool req = false;
    int dir = 1;
    if (nco_mode_ == Nco::Plant) {
      if (s.active) {
        const int64_t th = int64_t(cfg_.div) << (CtlFrac + sh);
        phase_ += s.u;
        if (phase_ >= th) {
          req = true;
          phase_ -= th;
        } else if (phase_ <= -th) {
          req = true;
          dir = -1;
          phase_ += th;
        }
        phase_ = std::clamp<int64_t>(phase_, -2 * th, 2 * th);
      } else {
        phase_ = 0;
      }
    } else {
      req = r_.chance(req_p_);
      dir = s.u >= 0 ? 1 : -1;
    }
    if (!in_move_ && !s.active && r_.chance(0.01)) req = true;  // a step still leaving after a stop
    in_.nco_req = req;
    if (req) {
      busy_left_ = pulse_len_;
      if (!r_.chance(missed_p_)) ring_[(ring_pos_ + delay_) & 15] += uint32_t(dir) << sh;
    }
    if (noise_p_ > 0 && r_.chance(noise_p_)) ring_[ring_pos_ & 15] += r_.chance(0.5) ? 1u : ~0u;
    enc_ += ring_[ring_pos_ & 15];
    ring_[ring_pos_ & 15] = 0;
    ++ring_pos_;
    in_.enc_pos = int32_t(enc_);
    if (busy_random_) {
      if (r_.chance(0.01)) busy_level_ = !busy_level_;
      in_.cmd_busy = busy_level_ || (req && !busy_indep_);  // (independent: never seen in the servo)
    } else {
      in_.cmd_busy = req || busy_left_ > 0;
      if (busy_left_ > 0) --busy_left_;
    }
  }

  enum class Nco { Plant, Random };
  enum class End { Stop, Restart, Reset };

  uint64_t seed_;
  bool fixed_;
  Rng r_;
  RtlNeuronPi rtl_;
  NeuronPi model_;
  Lockstep<NpiOutputs> checker_{&render_npi};
  NeuronConfig cfg_{};
  bool cfg_dirty_ = false;
  NeuronPi::Inputs in_{};
  uint64_t clock_ = 0, moves_ = 0;
  Coverage cov_{};
  bool corr_sat_ = false;

  bool in_move_ = false;
  uint64_t gap_left_ = 0, run_left_ = 0, t_ = 0, jump_at_ = UINT64_MAX;
  int start_left_ = 0;
  End end_ = End::Stop;
  Kind kind_ = Kind::Chaos;
  Nco nco_mode_ = Nco::Random;
  double req_p_ = 0, missed_p_ = 0, noise_p_ = 0, chg_p_ = 0;
  bool edge_walk_ = false, eb_walk_ = false, mid_fsm_ = false;
  uint32_t edge_ = 0;
  bool busy_random_ = false, busy_level_ = false, busy_indep_ = false;
  int pulse_len_ = 1, delay_ = 0, busy_left_ = 0;
  int64_t phase_ = 0, vel_ = 0, vmax_ = 0, acc_clocks_ = 1, cruise_clocks_ = 0;
  uint64_t pos31_ = 0;
  uint32_t enc_ = 0;
  std::array<uint32_t, 16> ring_{};
  uint32_t ring_pos_ = 0;
};

struct RunTotals {
  Coverage cov{};
  uint64_t clocks = 0, moves = 0;
};

// Runs `seeds` seeds of `clocks` clocks; fails on the first mismatch of a seed.
RunTotals run_seeds(uint64_t seed0, uint64_t seeds, uint64_t clocks, bool fixed_config) {
  RunTotals t;
  for (uint64_t seed = seed0; seed < seed0 + seeds; ++seed) {
    NeuronLockstep ls(seed, fixed_config);
    if (auto m = ls.compare()) {
      ADD_FAILURE() << "after reset: " << m->text;
      continue;
    }
    for (uint64_t i = 0; i < clocks; ++i) {
      if (auto m = ls.step()) [[unlikely]] {
        ADD_FAILURE() << (fixed_config ? "fixed config, " : "random configs, ") << m->text;
        break;
      }
    }
    for (int k = 0; k < kCovN; ++k) t.cov[k] += ls.coverage()[k];
    t.clocks += ls.clock();
    t.moves += ls.moves();
  }
  return t;
}

void print_coverage(const RunTotals& t) {
  for (int k = 0; k < kCovN; ++k) std::printf("  %-38s %10llu\n", kCovName[k], (unsigned long long)t.cov[k]);
}

// Random configuration per move, random inputs: every output equal every
// clock, and every listed corner path reached.
TEST(NeuronPiLockstep, RandomConfigsAndInputsMatchEveryClock) {
  const uint64_t seed0 = env_u64("SC_NPI_SEED0", 1), seeds = env_u64("SC_NPI_SEEDS", 10);
  const uint64_t clocks = env_u64("SC_NPI_CLOCKS", 300000);
  const auto t0 = std::chrono::steady_clock::now();
  const RunTotals t = run_seeds(seed0, seeds, clocks, false);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("seeds %llu..%llu: %llu clocks, %llu moves, %.2f s\n", (unsigned long long)seed0,
              (unsigned long long)(seed0 + seeds - 1), (unsigned long long)t.clocks, (unsigned long long)t.moves, s);
  print_coverage(t);
  EXPECT_EQ(t.clocks, seeds * clocks);
  for (int k = 0; k < kCovN; ++k) EXPECT_GT(t.cov[k], 0u) << "never reached: " << kCovName[k];
}

// One configuration held for a whole long run (many moves, no reconfiguration).
TEST(NeuronPiLockstep, FixedConfigLongRunsMatchEveryClock) {
  const uint64_t seed0 = env_u64("SC_NPI_SEED0", 1) + 1000;
  const uint64_t seeds = std::max<uint64_t>(1, env_u64("SC_NPI_SEEDS", 8) / 2);  // 4 by default
  const uint64_t clocks = env_u64("SC_NPI_CLOCKS", 300000);
  const RunTotals t = run_seeds(seed0, seeds, clocks, true);
  std::printf("fixed-config seeds %llu..%llu: %llu clocks, %llu moves\n", (unsigned long long)seed0,
              (unsigned long long)(seed0 + seeds - 1), (unsigned long long)t.clocks, (unsigned long long)t.moves);
  print_coverage(t);
  EXPECT_EQ(t.clocks, seeds * clocks);
  EXPECT_GT(t.cov[kPeriods], 1000u);
  EXPECT_GT(t.cov[kInPos], 0u);
}

// The comparison can fail: one flipped weight bit in the model (not in the
// RTL) is reported at the very next clock, naming the signal and both values.
TEST(NeuronPiLockstep, InjectedWeightDifferenceIsReported) {
  const uint64_t seed = 7;
  NeuronLockstep ls(seed, false);
  // run in lockstep until the controller is active, idle between two
  // periods (w_p1 is not written next clock) and the move goes on
  uint64_t i = 0;
  for (; i < 200000; ++i) {
    auto m = ls.step();
    ASSERT_FALSE(m) << m->text;
    const NeuronPi::State& q = ls.model().state();
    if (i > 5000 && q.active && q.st == CtlStIdle && q.cnt > 2 && ls.steady_next_clock()) break;
  }
  ASSERT_LT(i, 200000u) << "controller never active";
  NeuronPi::State& q = ls.model().mutable_state();
  const int32_t before = q.lp[0].w1;
  q.lp[0].w1 = sign_extend(uint32_t(before) ^ 0x8u, WgtW);
  const uint64_t at = ls.clock() + 1;
  auto m = ls.step();
  ASSERT_TRUE(m) << "the flipped weight bit was not reported";
  EXPECT_EQ(m->clock, at);
  EXPECT_EQ(m->signal, "w_p1_o");
  EXPECT_EQ(m->rtl, before);
  EXPECT_EQ(m->model, sign_extend(uint32_t(before) ^ 0x8u, WgtW));
  EXPECT_NE(m->text.find(fmt::format("seed {} clock {} signal w_p1_o: rtl={} model={}", seed, at,
                                     hex_bits(m->rtl, WgtW), hex_bits(m->model, WgtW))),
            std::string::npos)
      << m->text;
  std::printf("reported: %s\n", m->text.substr(0, m->text.find('\n')).c_str());
}

}  // namespace
}  // namespace sc
