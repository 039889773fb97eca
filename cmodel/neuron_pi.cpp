#include "neuron_pi.h"

namespace sc {

namespace {

constexpr int kAluW = CtlW + 2;
constexpr int32_t kBMax = (int32_t(1) << (MulBW - 1)) - 1;
constexpr unsigned kQuoW = NWgtFrac + 1;
constexpr unsigned kRemW = WgtW + 2;
constexpr unsigned kSumW = WgtW + 1;
constexpr unsigned kDbitMask = 31;

inline int32_t wrap32(int64_t v) { return int32_t(uint32_t(uint64_t(v))); }
inline int32_t sext(int64_t v, int bits) { return int32_t(wrap_signed64(v, bits)); }
inline uint32_t u32(int32_t v) { return uint32_t(v); }

// Operand sources, configuration words and write data (the RTL's A*/B*/Cf*/W*).
enum ASrc { ARf, AT, ARef, AZero };
enum BSrc { BRf, BCfg, BPfb, BVmeas, BZero };
enum Cfg {
  CfDzP, CfDzV, CfFerr, CfWin, CfVLim, CfULim, CfWMin, CfWP1Max, CfWV1Max, CfWP2Max, CfWV2Max,
  CfWP1, CfWV1, CfWP2, CfWV2, CfKP, CfKV, CfKb, CfEtaP1, CfEtaV1, CfEtaP2, CfEtaV2
};
enum WSrc { WWrap, WSat, WMul, WDiv, WZero };
enum MbSrc { MbRf, MbCfg, MbEb, MbDivSh };

// Unsigned words zero-, weights sign-extended (as cfg_val).
int64_t cfg_value(const NeuronConfig& c, int sel) {
  switch (sel) {
    case CfDzP: return c.learn_dz_p;
    case CfDzV: return c.learn_dz_v;
    case CfFerr: return c.ferr_lim;
    case CfWin: return c.inpos_win;
    case CfVLim: return c.v_lim;
    case CfULim: return c.u_lim;
    case CfWMin: return sext(c.w_min, WgtW);
    case CfWP1Max: return sext(c.w_p1_max, WgtW);
    case CfWV1Max: return sext(c.w_v1_max, WgtW);
    case CfWP2Max: return sext(c.w_p2_max, WgtW);
    case CfWV2Max: return sext(c.w_v2_max, WgtW);
    case CfWP1: return sext(c.w_p1, WgtW);
    case CfWV1: return sext(c.w_v1, WgtW);
    case CfWP2: return sext(c.w_p2, WgtW);
    case CfWV2: return sext(c.w_v2, WgtW);
    case CfKP: return c.k_p & ((1u << CoefW) - 1);
    case CfKV: return c.k_v & ((1u << CoefW) - 1);
    case CfKb: return c.kb & ((1u << CoefW) - 1);
    case CfEtaP1: return c.eta_p1 & ((1u << CoefW) - 1);
    case CfEtaV1: return c.eta_v1 & ((1u << CoefW) - 1);
    case CfEtaP2: return c.eta_p2 & ((1u << CoefW) - 1);
    case CfEtaV2: return c.eta_v2 & ((1u << CoefW) - 1);
    default: return 0;
  }
}

// The control word of one micro-program step (the RTL's decode always_comb).
struct Ctl {
  uint8_t ra = 0, rb = 0;
  ASrc a = AZero;
  BSrc b = BZero;
  int cfg = CfWMin;
  bool sub = false, abs = false;
  bool mul_a_vq = false;
  MbSrc mb = MbRf;
  bool s20 = false, ls = false;
  bool we = false;
  uint8_t wa = 0;
  WSrc w = WWrap;
  bool t_we = false;
};

}  // namespace

// state_o: the phase of a micro-program step (the RTL's st)
uint8_t NeuronPi::phase_of(uint8_t upc) {
  if (upc == UpcIdle) return CtlStIdle;
  if (upc < UpcVff) return CtlStInit;
  if (upc == UpcVff) return CtlStVff;
  if (upc <= UpcDiv2) return CtlStDiv;
  if (upc <= UpcWin) return CtlStErr;
  if (upc == UpcT1) return CtlStT1;
  if (upc <= UpcSum) return CtlStT2;
  if (upc == UpcDu) return CtlStDu;
  if (upc <= UpcOut) return CtlStBc;
  if (upc == UpcH1) return CtlStH1;
  if (upc <= UpcW4) return CtlStDw1;
  if (upc == UpcH2) return CtlStH2;
  return CtlStDw2;
}

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
  const uint8_t s = q.sel ? 1 : 0;
  const bool hush_now = !q.sel && q.fin;
  const unsigned shift = cfg.shift & ((1u << EncShiftW) - 1);
  const unsigned ls = cfg.learn_shift & ((1u << LearnShW) - 1);
  const uint8_t upc = q.upc;
  const bool w2nd = upc >= UpcH2;
  const uint8_t u2 = w2nd ? uint8_t(upc - 6) : upc;

  // ---- decode -------------------------------------------------------------------------
  Ctl c;
  switch (upc) {
    case UpcIdle: break;
    case UpcVff:
      c.mul_a_vq = true; c.mb = MbDivSh; c.we = true; c.wa = RfVff; c.w = WMul;
      break;
    case UpcSet1: case UpcSet2: case UpcSet3: case UpcDiv1: case UpcDiv2:
      
      c.rb = uint8_t(((upc == UpcSet1 || upc == UpcDiv1) ? RfW1 : RfW2) | s);
      c.a = upc == UpcSet2 ? AT : AZero;
      c.b = BRf;
      c.abs = true;
      c.t_we = upc == UpcSet1;
      c.we = (upc == UpcDiv1 || upc == UpcDiv2) && q.dbit == 0;
      c.wa = uint8_t((upc == UpcDiv1 ? RfN1 : RfN2) | s);
      c.w = WDiv;
      break;
    case UpcRef:
      c.a = q.sel ? ARf : ARef; c.ra = RfOutP; c.rb = RfVff;
      c.b = (q.sel && cfg.ff_en) ? BRf : BZero; c.t_we = true;
      break;
    case UpcErr:
      c.a = AT; c.b = q.sel ? BVmeas : BPfb; c.sub = true; c.we = true; c.wa = RfEraw;
      break;
    case UpcAbs:
      c.rb = RfEraw; c.b = BRf; c.abs = true; c.t_we = true;
      break;
    case UpcEq: case UpcX2:
      c.ra = RfEraw; c.rb = uint8_t(RfEp | s);
      c.a = (upc == UpcX2 && hush_now) ? AZero : ARf; c.b = BRf; c.sub = true;
      c.we = upc == UpcX2; c.wa = RfX2;
      break;
    case UpcE: case UpcEp:
      c.ra = RfEraw; c.a = (upc == UpcE && hush_now) ? AZero : ARf;
      c.we = true; c.wa = upc == UpcE ? uint8_t(RfE) : uint8_t(RfEp | s);
      break;
    case UpcLearn: case UpcFerr: case UpcWin:
      c.a = AT; c.b = BCfg; c.sub = true;
      c.cfg = upc == UpcLearn ? (q.sel ? CfDzV : CfDzP) : upc == UpcFerr ? CfFerr : CfWin;
      if (upc == UpcLearn && cfg.pid) {  // PID: no learning; the multiplier forms d = K_V x2
        c.ra = RfX2; c.mb = MbCfg; c.cfg = CfKV; c.s20 = true; c.we = true; c.wa = RfH; c.w = WMul;
      }
      break;
    case UpcT1:
      c.ra = RfE; c.rb = uint8_t(RfN1 | s); c.we = true; c.wa = RfT1; c.w = WMul;
      break;
    case UpcT2:
      c.ra = RfX2; c.rb = uint8_t(RfN2 | s); c.we = true; c.wa = RfT2; c.w = WMul;
      break;
    case UpcSum:
      c.ra = RfT1; c.rb = RfT2; c.a = ARf; c.b = BRf; c.we = true; c.wa = RfSum; c.w = WSat;
      break;
    case UpcDu: case UpcBc:
      
      c.ra = upc == UpcDu ? uint8_t(RfSum) : uint8_t(RfEs | s);
      c.mb = MbCfg; c.cfg = upc == UpcBc ? CfKb : q.sel ? CfKV : CfKP; c.s20 = true;
      c.we = true; c.wa = upc == UpcDu ? RfDu : RfBc; c.w = WMul;
      break;
    case UpcAcc1:
      c.ra = uint8_t(RfAcc | s); c.rb = RfDu; c.a = ARf; c.b = BRf; c.t_we = true;
      break;
    case UpcAcc2:
      c.rb = RfBc; c.a = AT; c.b = BRf; c.sub = true;
      c.we = true; c.wa = uint8_t(RfAcc | s); c.w = q.hush ? WZero : WSat;
      break;
    case UpcTot:
      c.ra = uint8_t(RfAcc | s); c.rb = cfg.pid ? RfH : RfVff; c.a = ARf;
      c.b = ((q.sel && cfg.ff_en) || (cfg.pid && !q.hush)) ? BRf : BZero; c.we = true; c.wa = RfTot; c.w = WSat;
      break;
    case UpcHi: case UpcLo:
      c.ra = RfTot; c.a = ARf; c.b = BCfg; c.cfg = (q.sel || cfg.pid) ? CfULim : CfVLim;
      c.sub = upc == UpcHi; c.wa = uint8_t(RfEs | s);
      break;  // write enable and data depend on the sum (below)
    case UpcOut:
      c.ra = RfTot; c.rb = uint8_t(RfEs | s); c.a = ARf; c.b = BRf; c.sub = true;
      c.we = !q.sel; c.wa = RfOutP;
      break;
    case UpcH1: case UpcH2:
      c.ra = upc == UpcH1 ? RfE : RfX2; c.rb = RfE; c.mb = MbEb;
      c.we = true; c.wa = RfH; c.w = WMul;
      break;
    case UpcDw1: case UpcDw2:
      c.ra = RfH; c.mb = MbCfg;
      c.cfg = upc == UpcDw1 ? (q.sel ? CfEtaV1 : CfEtaP1) : (q.sel ? CfEtaV2 : CfEtaP2);
      c.s20 = true; c.ls = true; c.we = true; c.wa = RfDw; c.w = WMul;
      break;
    default:
      if (upc >= UpcW1 && upc <= UpcW8) {
        const uint8_t pair = uint8_t((w2nd ? RfW2 : RfW1) | s);
        const int wmax = w2nd ? (q.sel ? CfWV2Max : CfWP2Max) : (q.sel ? CfWV1Max : CfWP1Max);
        
        c.cfg = u2 == UpcW3 ? CfWMin : u2 == UpcW4 ? (q.over ? wmax : CfWMin) : wmax;
        if (u2 == UpcW1) {  // T = w + dw
          c.ra = pair; c.rb = RfDw; c.a = ARf; c.b = BRf; c.t_we = true;
        } else if (u2 == UpcW2 || u2 == UpcW3) {  // T - w_max > 0 ?  T - w_min < 0 ?
          c.a = AT; c.b = BCfg; c.sub = true;
        } else {  // w = w_max, w_min or T (then within both)
          c.a = (q.over || q.under) ? AZero : AT;
          c.b = (q.over || q.under) ? BCfg : BZero;
          c.we = true; c.wa = pair;
        }
      } else if (upc >= UpcInit && upc < UpcInit + kInitSteps) {
        // start: e_prev, acc, es, out_p, vff = 0; weights = their initial values
        static constexpr uint8_t kWa[kInitSteps] = {RfEp, RfEp + 1, RfAcc, RfAcc + 1, RfEs, RfEs + 1,
                                                   RfOutP, RfVff, RfW1, RfW1 + 1, RfW2, RfW2 + 1};
        static constexpr int kCf[4] = {CfWP1, CfWV1, CfWP2, CfWV2};
        const int k = upc - UpcInit;
        c.we = true; c.wa = kWa[k];
        c.b = k < 8 ? BZero : BCfg;
        if (k >= 8) c.cfg = kCf[k - 8];
      }
      break;
  }

  // ---- datapath -----------------------------------------------------------------------
  const int32_t rf_a = q.rf[c.ra];
  const int32_t rf_b = q.rf[c.rb];
  const int64_t cfg_val = cfg_value(cfg, c.cfg);
  const int64_t alu_a = c.a == ARf ? rf_a : c.a == AT ? q.t : c.a == ARef ? q.ref : 0;
  const int64_t alu_b = c.b == BRf ? rf_b : c.b == BCfg ? cfg_val : c.b == BPfb ? q.pfb : c.b == BVmeas ? q.vmeas : 0;
  const bool sub = c.abs ? alu_b < 0 : c.sub;
  const int64_t alu_r = wrap_signed64(sub ? alu_a - alu_b : alu_a + alu_b, kAluW);
  const bool alu_n = alu_r < 0;
  const bool alu_z = alu_r == 0;
  const int32_t alu_sat = sat32(alu_r);

  // multiplier
  int32_t e_b = 0;
  if (q.learn) e_b = rf_b > kBMax ? kBMax : rf_b < -kBMax ? -kBMax : rf_b;
  const uint32_t div_sh = uint32_t(cfg.div) << shift;
  const int32_t mul_a = c.mul_a_vq ? q.vq : rf_a;
  const int32_t mul_b = c.mb == MbRf    ? sext(rf_b, MulBW)
                        : c.mb == MbCfg ? sext(cfg_val, MulBW)
                        : c.mb == MbEb  ? e_b
                                        : sext(int64_t(div_sh) << (NWgtFrac - (VffFrac - CtlFrac)), MulBW);
  const unsigned mul_sh = (c.s20 ? CoefFrac : NWgtFrac) + (c.ls ? ls : 0);
  const int32_t mul_y = mul_round_sat(mul_a, mul_b, mul_sh);

  // divider step (sign: the weight on port B)
  const bool div_ge = q.drem >= q.dsum;
  const uint32_t div_rem_sub = div_ge ? q.drem - q.dsum : q.drem;
  const uint32_t div_quo = ((q.dquo << 1) | uint32_t(div_ge)) & ((1u << kQuoW) - 1);
  const uint32_t div_res = q.dsum == 0 ? 0 : div_quo;
  const int32_t div_wn = sext(rf_b < 0 ? -int64_t(div_res) : int64_t(div_res), NWgtW);

  // e_p rounded to whole steps, saturated
  const unsigned step_sh = CtlFrac + shift;
  const int64_t corr_full = (int64_t(q.eraw) + (int64_t(1) << (step_sh - 1))) >> step_sh;
  const int64_t cmax = (int64_t(1) << (CorrW - 1)) - 1;
  const int32_t corr_steps = int32_t(corr_full > cmax ? cmax : corr_full < -cmax ? -cmax : corr_full);

  // limit steps: es = tot - lim when > 0 (else 0); es = tot + lim when < 0
  if (upc == UpcHi) {
    c.we = true;
    c.w = (alu_n || alu_z) ? WZero : WWrap;
  } else if (upc == UpcLo) {
    c.we = alu_n;
  }

  State d = q;
  d.mv = q.mv || in.cmd_busy;
  if (q.corr != 0 && in.nco_req) d.corr = sext(int64_t(q.corr) + (q.corr < 0 ? 1 : -1), CorrW);
  if (c.t_we) d.t = alu_r;
  if (c.we) {
    const int32_t wd = c.w == WSat ? alu_sat : c.w == WMul ? mul_y : c.w == WDiv ? div_wn : c.w == WZero ? 0 : wrap32(alu_r);
    d.rf[c.wa] = wd;
    switch (c.wa) {
      case RfOutP: d.out_p = wd; break;
      case RfEp: d.lp[0].ep = wd; break;
      case RfEp + 1: d.lp[1].ep = wd; break;
      case RfW1: d.lp[0].w1 = sext(wd, WgtW); break;
      case RfW1 + 1: d.lp[1].w1 = sext(wd, WgtW); break;
      case RfW2: d.lp[0].w2 = sext(wd, WgtW); break;
      case RfW2 + 1: d.lp[1].w2 = sext(wd, WgtW); break;
      case RfN1: d.lp[0].n1 = sext(wd, NWgtW); break;
      case RfN1 + 1: d.lp[1].n1 = sext(wd, NWgtW); break;
      case RfN2: d.lp[0].n2 = sext(wd, NWgtW); break;
      case RfN2 + 1: d.lp[1].n2 = sext(wd, NWgtW); break;
      default: break;
    }
  }

  // ---- sequencing, flags, snapshot, settling ----------------------------------------------
  if (q.active) {
    if (q.cnt == 0) {
      d.cnt = uint16_t(cfg.div - 1);
      if (upc == UpcIdle) {
        // snapshot: P* - 1/2 (the integer target L once the reference is done), P, V
        const uint32_t r = in.ref_done ? u32(in.ref_int) << CtlFrac
                                       : ((u32(in.ref_int) << CtlFrac) | in.ref_frac) - (1u << (CtlFrac - 1));
        d.ref = int32_t(r << shift);
        d.pfb = int32_t(u32(in.enc_pos) << CtlFrac);
        d.vmeas = int32_t((u32(in.enc_pos) << CtlFrac) - u32(q.pfb));
        d.vq = in.ref_vel;
        d.fin = in.ref_done;
        d.mvs = q.mv || in.cmd_busy;
        d.mv = false;
        d.sel = false;
        d.upc = UpcVff;
      }
    } else {
      d.cnt = uint16_t(q.cnt - 1);
    }
  }

  if (upc != UpcIdle) d.upc = uint8_t(upc + 1);
  if (upc == UpcInit + kInitSteps - 1) d.upc = UpcIdle;  // wait for the first snapshot
  switch (upc) {
    case UpcSet1: d.drem = uint32_t(alu_r) & ((1u << kRemW) - 1); break;
    case UpcSet2:
      d.dsum = uint32_t(alu_r) & ((1u << kSumW) - 1);
      d.dbit = NWgtFrac;
      d.dquo = 0;
      break;
    case UpcSet3:
      d.drem = uint32_t(alu_r) & ((1u << kRemW) - 1);
      d.dbit = NWgtFrac;
      d.dquo = 0;
      break;
    case UpcDiv1: case UpcDiv2:
      d.drem = (div_rem_sub << 1) & ((1u << kRemW) - 1);
      d.dquo = div_quo;
      d.dbit = uint8_t((q.dbit - 1) & kDbitMask);
      if (q.dbit != 0) d.upc = upc;
      break;
    case UpcErr: d.eraw = wrap32(alu_r); break;
    case UpcEq: d.eq = alu_z; break;
    case UpcEp: if (!q.sel) d.hush = hush_now; break;
    case UpcLearn: d.learn = !cfg.pid && !hush_now && !alu_n && !alu_z; break;
    case UpcFerr:
      if (!q.sel && !alu_n && !alu_z) {
        d.ferr = true;
        if (!cfg.ferr_stop) {  // controlled: the loop keeps tracking the stopping reference
          d.active = false;
          d.u = 0;
          d.upc = UpcIdle;
        }
      }
      break;
    case UpcWin:
      if (!q.sel) {
        if (q.fin && !q.mvs && q.corr == 0 && q.eq) {
          d.hold = uint16_t(q.hold + 1);
          if (d.hold >= cfg.inpos_hold) {
            d.hold = 0;
            if (alu_n || alu_z || corr_steps == 0) {  // |e_p| <= win
              d.in_pos = true;
              d.active = false;
              d.u = 0;
              d.upc = UpcIdle;
            } else {
              d.corr = corr_steps;
            }
          }
        } else {
          d.hold = 0;
        }
      }
      break;
    case UpcOut:
      if (q.sel || cfg.pid) d.u = wrap32(alu_r);
      if (cfg.pid) d.upc = UpcIdle;  // PID: no weight updates, no speed loop
      break;
    default: break;
  }
  if (upc >= UpcW1 && upc <= UpcW8 && upc != UpcH2 && upc != UpcDw2) {
    if (u2 == UpcW2) d.over = !alu_n && !alu_z;
    if (u2 == UpcW3) d.under = alu_n;
  }
  if (upc == UpcW8) {
    if (q.sel) {
      d.upc = UpcIdle;
    } else {
      d.sel = true;
      d.upc = UpcSet1;
    }
  }

  if (q.fin && d.active) {
    const int32_t r = int32_t(cfg.settle_rate);
    d.u = d.corr == 0 ? 0 : d.corr < 0 ? int32_t(-int64_t(r)) : r;
  }

  if (in.start) {
    d.active = true;
    d.in_pos = false;
    d.ferr = false;
    d.cnt = kInitSteps;  // the first snapshot follows the initialisation
    d.upc = UpcInit;
    d.sel = false;
    d.hold = 0;
    d.hush = false;
    d.corr = 0;
    d.fin = false;
    d.pfb = int32_t(u32(in.enc_pos) << CtlFrac);
    d.vmeas = 0;
    d.u = 0;
  } else if (in.stop) {
    d.active = false;
    d.upc = UpcIdle;
    d.u = 0;
  }
  d.st = phase_of(d.upc);
  q = d;
}

}  // namespace sc
