#include "neuron_pi.h"

#include <algorithm>

namespace sc {

namespace {

constexpr int32_t kBMax = (int32_t(1) << (MulBW - 1)) - 1;
constexpr unsigned kQuoW = NWgtFrac + 1;
constexpr unsigned kRemW = WgtW + 2;
constexpr unsigned kDbitMask = 31;

inline int32_t wrap32(int64_t v) { return int32_t(uint32_t(uint64_t(v))); }
inline int32_t sext(int64_t v, int bits) { return int32_t(wrap_signed64(v, bits)); }
inline uint32_t abs_w(int32_t w) { return uint32_t(w < 0 ? -int64_t(w) : int64_t(w)) & ((1u << WgtW) - 1); }
inline uint32_t u32(int32_t v) { return uint32_t(v); }

}  // namespace

int32_t NeuronPi::mul_round_sat(int32_t a, int32_t b, unsigned sh) {
  const int64_t p = int64_t(a) * int64_t(b);
  const int64_t r = (p + (int64_t(1) << (sh - 1))) >> sh;
  return sat32(r);
}

void NeuronPi::step(const NeuronConfig& cfg, const Inputs& in) {
  State& q = q_;
  if (!in.start && !in.stop && counting_only() && (q.corr == 0 || !in.nco_req)) [[likely]] {
    q.mv = q.mv || in.cmd_busy;
    if (q.active) q.cnt = uint16_t(q.cnt - 1);
    return;
  }
  State d = q;
  d.mv = q.mv || in.cmd_busy;
  if (q.corr != 0 && in.nco_req) d.corr = sext(int64_t(q.corr) + (q.corr < 0 ? 1 : -1), CorrW);
  const int s = q.sel ? 1 : 0;
  const Loop& L = q.lp[s];
  const int32_t bias = (q.sel && cfg.ff_en) ? q.vff : 0;
  const int32_t cur_ref = q.sel ? wrap32(int64_t(q.out_p) + bias) : q.ref;
  const int32_t cur_fb = q.sel ? q.vmeas : q.pfb;
  const uint32_t cur_lim = q.sel ? cfg.u_lim : cfg.v_lim;
  const uint32_t cur_k = q.sel ? cfg.k_v : cfg.k_p;
  const uint32_t eta1 = q.sel ? cfg.eta_v1 : cfg.eta_p1;
  const uint32_t eta2 = q.sel ? cfg.eta_v2 : cfg.eta_p2;
  const unsigned shift = cfg.shift & ((1u << EncShiftW) - 1);
  const unsigned ls = cfg.learn_shift & ((1u << LearnShW) - 1);
  const unsigned hebb_sh = unsigned(CoefFrac + CtlFrac - WgtFrac) + ls;
  const int32_t e_b = !q.learn ? 0 : q.e > kBMax ? kBMax : q.e < -kBMax ? -kBMax : q.e;

  if (q.active) {
    if (q.cnt == 0) {
      d.cnt = uint16_t(cfg.div - 1);
      if (q.st == StIdle) {
        const uint32_t r = in.ref_done ? u32(in.ref_int) << CtlFrac
                                       : ((u32(in.ref_int) << CtlFrac) | in.ref_frac) - (1u << (CtlFrac - 1));
        d.ref = int32_t(r << shift);
        d.pfb = int32_t(u32(in.enc_pos) << CtlFrac);
        d.vmeas = int32_t((u32(in.enc_pos) << CtlFrac) - u32(q.pfb));
        d.vq = in.ref_vel;
        d.fin = in.ref_done;
        d.mvs = q.mv || in.cmd_busy;
        d.mv = false;
        d.st = StVff;
      }
    } else {
      d.cnt = uint16_t(q.cnt - 1);
    }
  }

  auto set_div = [&](int loop) {
    d.sel = loop != 0;
    d.dsel = false;
    d.dbit = NWgtFrac;
    d.dquo = 0;
    d.drem = abs_w(q.lp[loop].w1);
    d.dsum = abs_w(q.lp[loop].w1) + abs_w(q.lp[loop].w2);
  };

  switch (q.st) {
    case StIdle:
      break;
    case StVff:
      d.vff = mul_round_sat(q.vq, int32_t(cfg.div), unsigned(VffFrac - CtlFrac) - shift);
      set_div(0);
      d.st = StDiv;
      break;
    case StDiv: {
      // restoring division, quotient bits shifted in at the LSB (MSB first)
      const bool ge = q.drem >= q.dsum;
      const uint32_t sub = ge ? q.drem - q.dsum : q.drem;
      const uint32_t quo = ((q.dquo << 1) | uint32_t(ge)) & ((1u << kQuoW) - 1);
      d.drem = (sub << 1) & ((1u << kRemW) - 1);
      d.dquo = quo;
      d.dbit = uint8_t((q.dbit - 1) & kDbitMask);
      if (q.dbit == 0) {
        const bool neg = q.dsel ? L.w2 < 0 : L.w1 < 0;
        const uint32_t res = q.dsum == 0 ? 0 : quo;
        const int32_t wn = sext(neg ? -int64_t(res) : int64_t(res), NWgtW);
        if (!q.dsel) {
          d.lp[s].n1 = wn;
          d.dsel = true;
          d.dbit = NWgtFrac;
          d.dquo = 0;
          d.drem = abs_w(L.w2);
        } else {
          d.lp[s].n2 = wn;
          d.st = StErr;
        }
      }
      break;
    }
    case StErr: {
      const int32_t e_raw = wrap32(int64_t(cur_ref) - cur_fb);
      const uint32_t abs_e = e_raw < 0 ? uint32_t(-int64_t(e_raw)) : uint32_t(e_raw);
      const bool hush = !q.sel && q.fin;
      const int32_t e = hush ? 0 : e_raw;
      if (!q.sel) d.hush = hush;
      d.e = e;
      d.learn = !hush && abs_e > (q.sel ? cfg.learn_dz_v : cfg.learn_dz_p);
      d.x2 = wrap32(int64_t(e) - L.ep);
      d.lp[s].ep = q.sel ? e : e_raw;  // e_p_o: the raw position error
      d.st = StT1;
      if (!q.sel) {
        if (abs_e > cfg.ferr_lim) {
          d.ferr = true;
          d.active = false;
          d.u = 0;
          d.st = StIdle;
        } else if (q.fin && !q.mvs && q.corr == 0 && e_raw == L.ep) {
          d.hold = uint16_t(q.hold + 1);
          if (d.hold >= cfg.inpos_hold) {
            d.hold = 0;
            const unsigned sh = CtlFrac + shift;
            const int64_t full = (int64_t(e_raw) + (int64_t(1) << (sh - 1))) >> sh;
            const int64_t cmax = (int64_t(1) << (CorrW - 1)) - 1;
            const int32_t steps = int32_t(std::clamp<int64_t>(full, -cmax, cmax));
            if (abs_e <= cfg.inpos_win || steps == 0) {
              d.in_pos = true;
              d.active = false;
              d.u = 0;
              d.st = StIdle;
            } else {
              d.corr = steps;
            }
          }
        } else {
          d.hold = 0;
        }
      }
      break;
    }
    case StT1:
      d.t1 = mul_round_sat(q.e, L.n1, NWgtFrac);
      d.st = StT2;
      break;
    case StT2:
      d.t2 = mul_round_sat(q.x2, L.n2, NWgtFrac);
      d.st = StDu;
      break;
    case StDu:
      d.du = mul_round_sat(sat32(int64_t(q.t1) + q.t2), int32_t(cur_k), CoefFrac);
      d.st = StBc;
      break;
    case StBc: {
      const int32_t bc = mul_round_sat(L.es, int32_t(cfg.kb), CoefFrac);
      const int32_t acc_new = q.hush ? 0 : sat32(int64_t(L.acc) + q.du - bc);  // one saturation
      const int32_t tot = sat32(int64_t(acc_new) + bias);
      const int64_t lim = int64_t(cur_lim);
      const int32_t out = tot > lim ? wrap32(lim) : tot < -lim ? wrap32(-lim) : tot;
      const int32_t es = sat32(int64_t(tot) - out);
      d.lp[s].acc = acc_new;
      d.lp[s].es = es;
      if (q.sel) d.u = out; else d.out_p = out;
      d.st = StH1;
      break;
    }
    case StH1:
      d.h = mul_round_sat(q.e, e_b, CtlFrac);
      d.st = StDw1;
      break;
    case StH2:
      d.h = mul_round_sat(q.x2, e_b, CtlFrac);
      d.st = StDw2;
      break;
    case StDw1:
    case StDw2: {
      const int32_t dw = mul_round_sat(q.h, int32_t(q.st == StDw1 ? eta1 : eta2), hebb_sh);
      const int64_t sum = int64_t(q.st == StDw1 ? L.w1 : L.w2) + dw;
      const int32_t hi = q.st == StDw1 ? (q.sel ? cfg.w_v1_max : cfg.w_p1_max) : (q.sel ? cfg.w_v2_max : cfg.w_p2_max);
      const int32_t wn = sum > hi ? hi : sum < cfg.w_min ? cfg.w_min : sext(sum, WgtW);
      if (q.st == StDw1) {
        d.lp[s].w1 = wn;
        d.st = StH2;
      } else {
        d.lp[s].w2 = wn;
        if (q.sel) {
          d.st = StIdle;
        } else {
          set_div(1);
          d.st = StDiv;
        }
      }
      break;
    }
    default:
      d.st = StIdle;
      break;
  }

  if (q.fin && d.active) {
    const int32_t r = int32_t(cfg.settle_rate);
    d.u = d.corr == 0 ? 0 : d.corr < 0 ? int32_t(-int64_t(r)) : r;
  }

  if (in.start) {
    d.active = true;
    d.in_pos = false;
    d.ferr = false;
    d.cnt = 0;
    d.st = StIdle;
    d.sel = false;
    d.hold = 0;
    d.hush = false;
    d.corr = 0;
    d.fin = false;
    d.pfb = int32_t(u32(in.enc_pos) << CtlFrac);
    d.vmeas = 0;
    d.vff = 0;
    d.lp[0].w1 = cfg.w_p1;
    d.lp[0].w2 = cfg.w_p2;
    d.lp[1].w1 = cfg.w_v1;
    d.lp[1].w2 = cfg.w_v2;
    for (Loop& l : d.lp) {
      l.ep = 0;
      l.acc = 0;
      l.es = 0;
    }
    d.out_p = 0;
    d.u = 0;
  } else if (in.stop) {
    d.active = false;
    d.st = StIdle;
    d.u = 0;
  }
  q = d;
}

}  // namespace sc
