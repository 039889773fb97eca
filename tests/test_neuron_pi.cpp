// sc_neuron_pi model: the fixed-point update against a double-precision
// reference of the same equations, saturation and back-calculation
// anti-windup, the dead zone, the in-position and following-error logic.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "neuron_pi.h"

namespace sc {
namespace {

constexpr double kQ = double(1 << CtlFrac);
constexpr double kW = double(1 << WgtFrac);
constexpr double kN = double(1 << NWgtFrac);
constexpr double kC = double(1 << CoefFrac);

NeuronConfig base_cfg() {
  NeuronConfig c;
  c.div = 400;
  c.shift = 0;
  c.ff_en = true;
  c.learn_shift = 10;
  c.learn_dz_p = 0;
  c.learn_dz_v = 0;
  c.k_p = uint32_t(0.05 * kC);
  c.k_v = uint32_t(0.10 * kC);
  c.kb = uint32_t(1.0 * kC);
  c.eta_p1 = uint32_t(0.20 * kC);
  c.eta_p2 = uint32_t(0.20 * kC);
  c.eta_v1 = uint32_t(0.15 * kC);
  c.eta_v2 = uint32_t(0.10 * kC);
  c.w_p1 = int32_t(2.0 * kW);
  c.w_p2 = int32_t(30.0 * kW);
  c.w_v1 = int32_t(40.0 * kW);
  c.w_v2 = int32_t(10.0 * kW);
  c.w_min = int32_t(-100.0 * kW);
  c.w_p1_max = c.w_p2_max = c.w_v1_max = c.w_v2_max = int32_t(100.0 * kW);
  c.v_lim = uint32_t(50.0 * kQ);
  c.u_lim = uint32_t(60.0 * kQ);
  c.ferr_lim = uint32_t(1000.0 * kQ);
  c.inpos_win = 0;
  c.inpos_hold = 3;
  c.settle_rate = uint32_t(0.05 * kQ);
  return c;
}

// Run one control period (strobe + FSM to idle); returns the clocks used.
// A controller after one clock with start and `c`; `in` is left with start low.
NeuronPi started(const NeuronConfig& c, NeuronPi::Inputs& in) {
  NeuronPi n;
  in.start = true;
  n.step(c, in);
  in.start = false;
  return n;
}

int run_period(NeuronPi& n, const NeuronConfig& c, const NeuronPi::Inputs& in) {
  int clocks = 0;
  for (int i = 0; i < c.div; ++i) {
    n.step(c, in);
    ++clocks;
  }
  return clocks;
}

// The same equations in double precision (docs/closed_loop.md).
struct RefLoop {
  double w1, w2, ep, acc, es;
};
struct RefOut {
  double wn1, wn2, e, out, acc, es, w1, w2;
};
RefOut ref_update(const RefLoop& L, double r, double y, double bias, double k, double kb, double lim, double eta1,
                  double eta2, double ls, double dz, double wmin, double wmax) {
  RefOut o;
  const double sum = std::fabs(L.w1) + std::fabs(L.w2);
  o.wn1 = sum > 0 ? L.w1 / sum : 0;
  o.wn2 = sum > 0 ? L.w2 / sum : 0;
  o.e = r - y;
  const double x2 = o.e - L.ep;
  const double du = k * (o.wn1 * o.e + o.wn2 * x2);
  o.acc = L.acc + du - kb * L.es;
  const double tot = o.acc + bias;
  o.out = std::clamp(tot, -lim, lim);
  o.es = tot - o.out;
  // Hebb products: e on the multiplier's B port saturates at 2^(MulBW-1-CtlFrac)
  // counts and e*x at the CtlW word (2^(CtlW-1-CtlFrac) counts^2).
  const bool learn = std::fabs(o.e) > dz;
  const double eb_max = std::ldexp(1.0, MulBW - 1 - CtlFrac), h_max = std::ldexp(1.0, CtlW - 1 - CtlFrac);
  const double eb = std::clamp(o.e, -eb_max, eb_max);
  const double h1 = std::clamp(o.e * eb, -h_max, h_max), h2 = std::clamp(x2 * eb, -h_max, h_max);
  o.w1 = std::clamp(L.w1 + (learn ? eta1 * h1 / std::ldexp(1.0, int(ls)) : 0.0), wmin, wmax);
  o.w2 = std::clamp(L.w2 + (learn ? eta2 * h2 / std::ldexp(1.0, int(ls)) : 0.0), wmin, wmax);
  return o;
}

// Fixed point vs double, one period at a time from the same state, over
// random errors from a fraction of a count to hundreds of counts.
// Tolerances (stated): normalised weights 2 LSB (2^-15), loop outputs
// 1e-4 counts/period + 2^-15 relative, weights 1e-4 + 1e-5 relative.
TEST(NeuronPi, FixedPointMatchesDoubleReference) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  NeuronConfig c = base_cfg();
  NeuronPi::Inputs in;
  NeuronPi n = started(c, in);
  double max_dn = 0, max_dout = 0, max_dw = 0;
  int32_t enc = 0;
  int64_t refq = 0;  // reference in Q.CtlFrac counts + 1/2
  for (int k = 0; k < 3000; ++k) {
    const NeuronPi::State s0 = n.state();
    // next snapshot inputs
    const double scale = std::pow(10.0, 3.0 * std::fabs(uni(rng)) - 1.0);  // 0.1 .. 100 counts
    refq += int64_t(std::llround(uni(rng) * scale * kQ));
    enc += int32_t(std::llround(uni(rng) * 2.0));
    in.ref_int = int32_t(refq >> CtlFrac);
    in.ref_frac = uint32_t(refq & ((1 << CtlFrac) - 1));
    in.enc_pos = enc;
    in.ref_vel = int32_t(uni(rng) * 1e-3 * std::ldexp(1.0, VffFrac));
    run_period(n, c, in);
    const NeuronPi::State& s1 = n.state();
    ASSERT_EQ(s1.st, CtlStIdle);
    if (k == 0) continue;  // the first period only sets P_prev
    // position loop
    const double r = (double(refq) - kQ / 2) / kQ;
    const double y = double(enc);
    const RefLoop Lp{s0.lp[0].w1 / kW, s0.lp[0].w2 / kW, s0.lp[0].ep / kQ, s0.acc(0) / kQ, s0.es(0) / kQ};
    const RefOut op = ref_update(Lp, r, y, 0.0, c.k_p / kC, c.kb / kC, c.v_lim / kQ, c.eta_p1 / kC, c.eta_p2 / kC,
                                 c.learn_shift, c.learn_dz_p / kQ, c.w_min / kW, c.w_p1_max / kW);
    // speed loop (its inputs from the fixed-point pos loop, so errors do not compound)
    const double vff = s1.vff() / kQ;
    EXPECT_NEAR(vff, in.ref_vel / std::ldexp(1.0, VffFrac) * c.div, 2.0 / kQ);
    const double vmeas = s1.vmeas / kQ;
    const RefLoop Lv{s0.lp[1].w1 / kW, s0.lp[1].w2 / kW, s0.lp[1].ep / kQ, s0.acc(1) / kQ, s0.es(1) / kQ};
    const RefOut ov = ref_update(Lv, s1.out_p / kQ + vff, vmeas, vff, c.k_v / kC, c.kb / kC, c.u_lim / kQ,
                                 c.eta_v1 / kC, c.eta_v2 / kC, c.learn_shift, c.learn_dz_v / kQ, c.w_min / kW,
                                 c.w_v1_max / kW);
    const double dn = std::max({std::fabs(s1.lp[0].n1 / kN - op.wn1), std::fabs(s1.lp[0].n2 / kN - op.wn2),
                                std::fabs(s1.lp[1].n1 / kN - ov.wn1), std::fabs(s1.lp[1].n2 / kN - ov.wn2)});
    const double dout_p = std::fabs(s1.out_p / kQ - op.out);
    const double dout_v = std::fabs(s1.u / kQ - ov.out);
    const double dw = std::max({std::fabs(s1.lp[0].w1 / kW - op.w1), std::fabs(s1.lp[0].w2 / kW - op.w2),
                                std::fabs(s1.lp[1].w1 / kW - ov.w1), std::fabs(s1.lp[1].w2 / kW - ov.w2)});
    ASSERT_LE(dn, 2.0 / kN) << "period " << k;
    ASSERT_LE(dout_p, 1e-4 + std::fabs(op.out) * std::ldexp(1.0, -15)) << "period " << k;
    ASSERT_LE(dout_v, 1e-4 + std::fabs(ov.out) * std::ldexp(1.0, -15)) << "period " << k;
    ASSERT_LE(dw, 1e-4 + 1e-5 * std::fabs(op.w1)) << "period " << k;
    max_dn = std::max(max_dn, dn);
    max_dout = std::max({max_dout, dout_p, dout_v});
    max_dw = std::max(max_dw, dw);
  }
  std::printf("max |fixed - double|: normalised weight %.3g, loop output %.3g counts/period, weight %.3g\n", max_dn,
              max_dout, max_dw);
}

// CL_CFG.PID: paper 003's PID with back-calculation, in double precision
// (docs/closed_loop.md): P and I from the fixed weights, D = Kd x2 outside
// the accumulator, u = clamp(acc + d, +-u_lim), es = tot - u, the integral
// reduced by Kb es(k-1); no learning, no speed loop.
NeuronConfig pid_cfg(double k, double w1, double w2, double kd, double kb, double u_lim) {
  NeuronConfig c = base_cfg();
  c.pid = true;
  c.k_p = uint32_t(std::llround(k * kC));
  c.w_p1 = int32_t(std::llround(w1 * kW));
  c.w_p2 = int32_t(std::llround(w2 * kW));
  c.k_v = uint32_t(std::llround(kd * kC));
  c.kb = uint32_t(std::llround(kb * kC));
  c.u_lim = uint32_t(std::llround(u_lim * kQ));
  c.ferr_lim = uint32_t(30000 * kQ);  // no following-error fault in the error ranges used here
  return c;
}

TEST(PidAw, FixedPointMatchesDoubleReferenceAndNeverLearns) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  const NeuronConfig c = pid_cfg(0.3, 0.5, 60.0, 0.8, 0.25, 40.0);
  NeuronPi::Inputs in;
  NeuronPi n = started(c, in);
  double acc = 0, es = 0, ep = 0, max_du = 0;
  int clamped = 0;
  int32_t enc = 0;
  int64_t refq = 0;
  for (int k = 0; k < 3000; ++k) {
    const NeuronPi::State s0 = n.state();
    const double scale = std::pow(10.0, 3.0 * std::fabs(uni(rng)) - 1.0);
    refq += int64_t(std::llround(uni(rng) * scale * kQ)) - refq / 64;  // a walk pulled back to 0
    enc += int32_t(std::llround(uni(rng) * 2.0));
    in.ref_int = int32_t(refq >> CtlFrac);
    in.ref_frac = uint32_t(refq & ((1 << CtlFrac) - 1));
    in.enc_pos = enc;
    in.ref_vel = int32_t(uni(rng) * 1e-3 * std::ldexp(1.0, VffFrac));  // no feed-forward in PID mode
    run_period(n, c, in);
    const NeuronPi::State& s1 = n.state();
    ASSERT_EQ(s1.st, CtlStIdle);
    // the weights are the loaded ones, the speed loop never ran
    ASSERT_EQ(s1.lp[0].w1, c.w_p1);
    ASSERT_EQ(s1.lp[0].w2, c.w_p2);
    ASSERT_EQ(s1.lp[1].ep, 0);
    ASSERT_EQ(s1.acc(1), 0);
    if (k == 0) {
      acc = s1.acc(0) / kQ;
      es = s1.es(0) / kQ;
      ep = s1.lp[0].ep / kQ;
      continue;
    }
    // reference from the fixed-point state before the period (no compounding)
    acc = s0.acc(0) / kQ;
    es = s0.es(0) / kQ;
    ep = s0.lp[0].ep / kQ;
    const double sum = std::fabs(c.w_p1 / kW) + std::fabs(c.w_p2 / kW);
    const double wn1 = s1.lp[0].n1 / kN, wn2 = s1.lp[0].n2 / kN;
    ASSERT_NEAR(wn1, c.w_p1 / kW / sum, 1.0 / kN);
    ASSERT_NEAR(wn2, c.w_p2 / kW / sum, 1.0 / kN);
    const double e = (double(refq) - kQ / 2) / kQ - double(enc);
    const double x2 = e - ep;
    const double acc1 = acc + c.k_p / kC * (wn1 * e + wn2 * x2) - c.kb / kC * es;
    const double tot = acc1 + c.k_v / kC * x2;
    const double lim = c.u_lim / kQ;
    const double u = std::clamp(tot, -lim, lim);
    if (u != tot) ++clamped;
    const double du = std::fabs(s1.u / kQ - u);
    ASSERT_LE(du, 1e-4 + std::fabs(u) * std::ldexp(1.0, -15)) << "period " << k;
    ASSERT_NEAR(s1.acc(0) / kQ, acc1, 1e-4 + std::fabs(acc1) * std::ldexp(1.0, -15)) << "period " << k;
    ASSERT_NEAR(s1.es(0) / kQ, tot - u, 1e-4 + std::fabs(tot) * std::ldexp(1.0, -15)) << "period " << k;
    EXPECT_EQ(s1.out_p, s1.u);  // v_cmd shows the PID's output too
    max_du = std::max(max_du, du);
  }
  EXPECT_GT(clamped, 100);  // the output limit and the back-calculation were exercised
  std::printf("PID: max |fixed - double| %.3g counts/period; %d of 3000 periods at the limit\n", max_du, clamped);
}

TEST(PidAw, PeriodEndsAfterThePositionLoop) {
  const NeuronConfig c = pid_cfg(0.3, 0.5, 60.0, 0.8, 0.25, 40.0);
  NeuronPi::Inputs in;
  NeuronPi n = started(c, in);
  for (int i = 0; i < c.div; ++i) n.step(c, in);  // initialisation and the first period
  int busy = 0;
  for (int i = 0; i < c.div; ++i) {
    n.step(c, in);
    if (n.state().st != CtlStIdle) ++busy;
  }
  // Vff + the position loop up to Out: 1 + (3 + 2 x 17 + 10 + 5 + 6)
  EXPECT_EQ(busy, 1 + 3 + 2 * (NWgtFrac + 1) + 10 + 5 + 6);
}

// Without back-calculation the integral winds up while the output is
// clamped and the error persists; with it the excess is bled off, and the
// PID leaves the limit sooner once the error reverses.
TEST(PidAw, BackCalculationBoundsTheIntegralWhileClamped) {
  for (const int sign : {1, -1}) {
    double peak[2] = {0, 0};
    int unclamp_period[2] = {0, 0};
    for (int aw = 0; aw < 2; ++aw) {
      const NeuronConfig c = pid_cfg(0.2, 20.0, 20.0, 0.0, aw ? 0.5 : 0.0, 5.0);
      NeuronPi::Inputs in;
      NeuronPi n = started(c, in);
      in.ref_int = sign * 200;  // a 200-count error the clamped output (5 counts/period) cannot close
      for (int k = 0; k < 300; ++k) {
        run_period(n, c, in);
        const NeuronPi::State& s = n.state();
        peak[aw] = std::max(peak[aw], std::fabs(s.acc(0) / kQ));
        ASSERT_LE(std::fabs(s.u / kQ), 5.0 + 1e-9);
      }
      in.ref_int = -sign * 200;  // the error reverses: count the periods until u leaves its limit
      for (int k = 0; k < 5000; ++k) {
        run_period(n, c, in);
        if (sign * n.state().u / kQ < 5.0 - 1e-6) {
          unclamp_period[aw] = k;
          break;
        }
        unclamp_period[aw] = k + 1;
      }
    }
    EXPECT_GT(peak[0], 100.0) << "sign " << sign << ": winds up without back-calculation";
    EXPECT_LT(peak[1], 50.0) << "sign " << sign << ": bounded with Kb = 0.5";
    EXPECT_LT(unclamp_period[1] * 10, unclamp_period[0]) << "sign " << sign;
  }
}

TEST(NeuronPi, DatapathFitsTheControlPeriod) {
  NeuronConfig c = base_cfg();
  NeuronPi::Inputs in;
  NeuronPi n = started(c, in);
  int init = n.state().st == CtlStInit ? 1 : 0;
  for (int i = 0; i < c.div; ++i) {  // initialisation, then the first period
    n.step(c, in);
    if (n.state().st == CtlStInit) ++init;
  }
  EXPECT_EQ(init, NeuronPi::kInitSteps);
  int busy = 0;
  for (int i = 0; i < c.div; ++i) {
    n.step(c, in);
    if (n.state().st != CtlStIdle) ++busy;
  }
  // VFF + 2 x (divider set-up 3 + 2 divisions of 17 clocks + error 10 + multiplier/sum 5
  //            + accumulate/limit 6 + 2 weight updates of 6)
  EXPECT_EQ(busy, NeuronPi::kBusyClocks);
  EXPECT_EQ(NeuronPi::kBusyClocks, 1 + 2 * (3 + 2 * (NWgtFrac + 1) + 10 + 5 + 6 + 12));
  EXPECT_LT(NeuronPi::kBusyClocks, NeuronPi::kMinDiv);
}

// Back-calculation with Kb = 1 removes the whole excess every period, so a
// saturated loop's accumulator is its limit plus that period's increment
// du = K (wn1 e + wn2 (e - e_prev)), never more: acc(k) = lim + du(k) once
// the output is clamped. Both loops, both signs: a position error held at
// +-199.5 counts clamps the position loop at v_lim (5 counts/period) in the
// first period, and its output, held at +-5, clamps the speed loop at u_lim
// (3) a few periods later. The first period carries the proportional kick
// (e - e_prev = e: du = K_p e = 9.975); after it du = K_p wn_p1 e = 0.623 in
// the position loop and K_v wn_v1 e_v = 0.4 in the speed loop (0.5 in its
// first period). With Kb = 0 the accumulator winds up far beyond and takes
// much longer to come back once the error reverses.
TEST(NeuronPi, SaturationAndBackCalculationAntiWindup) {
  struct Run {
    double first_acc_p = 0, max_acc_p = 0, max_acc_v = 0;  // |accumulator|, counts/period
    double end_acc_p = 0, end_acc_v = 0, end_out_p = 0, end_u = 0;
    int recover_periods = 0;
  };
  auto run = [](uint32_t kb, int sign) {
    NeuronConfig c = base_cfg();
    c.kb = kb;
    c.eta_p1 = c.eta_p2 = c.eta_v1 = c.eta_v2 = 0;
    c.v_lim = uint32_t(5.0 * kQ);
    c.u_lim = uint32_t(3.0 * kQ);
    NeuronPi::Inputs in;
    NeuronPi n = started(c, in);
    in.ref_int = sign > 0 ? 200 : -199;  // P* - 1/2 = +-199.5 counts, held
    Run r;
    for (int k = 0; k < 300; ++k) {
      run_period(n, c, in);
      const double acc_p = n.state().acc(0) / kQ, acc_v = n.state().acc(1) / kQ;
      if (k == 0) r.first_acc_p = acc_p;
      r.max_acc_p = std::max(r.max_acc_p, std::fabs(acc_p));
      r.max_acc_v = std::max(r.max_acc_v, std::fabs(acc_v));
      EXPECT_LE(std::abs(n.state().out_p), int32_t(c.v_lim));
      EXPECT_LE(std::abs(n.state().u), int32_t(c.u_lim));
      if (kb != 0) {
        if (k >= 1) EXPECT_LE(std::fabs(acc_p), 5.0 + 0.6235 + 1e-3) << "period " << k << ", sign " << sign;
        EXPECT_LE(std::fabs(acc_v), 3.0 + 0.5 + 1e-3) << "period " << k << ", sign " << sign;
      }
    }
    r.end_acc_p = n.state().acc(0) / kQ;
    r.end_acc_v = n.state().acc(1) / kQ;
    r.end_out_p = n.state().out_p / kQ;
    r.end_u = n.state().u / kQ;
    in.ref_int = sign > 0 ? -199 : 200;  // the error reverses
    while (sign * n.state().out_p > 0 && r.recover_periods < 100000) {
      run_period(n, c, in);
      ++r.recover_periods;
    }
    return r;
  };
  for (const int sign : {1, -1}) {
    const Run aw = run(uint32_t(1.0 * kC), sign);
    EXPECT_NEAR(aw.first_acc_p, sign * 9.975, 1e-3) << "sign " << sign << ": the first period's increment K_p e";
    EXPECT_NEAR(aw.end_acc_p, sign * (5.0 + 0.6234), 1e-3) << "sign " << sign << ": v_lim + K_p wn_p1 e";
    EXPECT_NEAR(aw.end_acc_v, sign * (3.0 + 0.4), 1e-3) << "sign " << sign << ": u_lim + K_v wn_v1 e_v";
    EXPECT_EQ(aw.end_out_p, sign * 5.0);
    EXPECT_EQ(aw.end_u, sign * 3.0);
    const Run wu = run(0, sign);
    EXPECT_GT(wu.max_acc_p, 50.0) << "sign " << sign << ": winds up without back-calculation";
    EXPECT_GT(wu.max_acc_v, 50.0) << "sign " << sign << ": winds up without back-calculation";
    EXPECT_LT(aw.recover_periods * 5, wu.recover_periods) << "sign " << sign;
    std::printf("sign %+d: peak accumulator Kb=1 %.3f / %.3f, Kb=0 %.1f / %.1f counts/period (position / speed); "
                "recovery %d vs %d periods\n",
                sign, aw.max_acc_p, aw.max_acc_v, wu.max_acc_p, wu.max_acc_v, aw.recover_periods,
                wu.recover_periods);
  }
}

TEST(NeuronPi, WeightsStayWithinBounds) {
  NeuronConfig c = base_cfg();
  c.learn_shift = 0;  // very fast learning
  c.w_min = int32_t(0.5 * kW);
  c.w_p1_max = int32_t(20.0 * kW);
  c.w_p2_max = int32_t(15.0 * kW);
  c.w_v1_max = int32_t(10.0 * kW);
  c.w_v2_max = int32_t(5.0 * kW);
  NeuronPi::Inputs in;
  NeuronPi n = started(c, in);
  std::mt19937 rng(5);
  // Each weight against its own bound (all four differ), each reaching it.
  const int32_t w_max[4] = {c.w_p1_max, c.w_p2_max, c.w_v1_max, c.w_v2_max};
  const char* w_name[4] = {"w_p1", "w_p2", "w_v1", "w_v2"};
  bool at_max[4] = {false, false, false, false};
  for (int k = 0; k < 500; ++k) {
    in.ref_int = int32_t(rng() % 400) - 200;
    run_period(n, c, in);
    const NeuronPi::State& st = n.state();
    const int32_t w[4] = {st.lp[0].w1, st.lp[0].w2, st.lp[1].w1, st.lp[1].w2};
    for (int i = 0; i < 4; ++i) {
      ASSERT_GE(w[i], c.w_min) << w_name[i] << ", period " << k;
      ASSERT_LE(w[i], w_max[i]) << w_name[i] << ", period " << k;
      at_max[i] = at_max[i] || w[i] == w_max[i];
    }
    for (const auto& l : st.lp) ASSERT_LE(std::abs(l.n1) + std::abs(l.n2), (1 << NWgtFrac) + 1);
  }
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(at_max[i]) << w_name[i] << " never reached its bound";
}

TEST(NeuronPi, DeadZoneStopsLearning) {
  NeuronConfig c = base_cfg();
  c.learn_dz_p = uint32_t(1.0 * kQ);
  NeuronPi::Inputs in;
  NeuronPi n = started(c, in);
  for (int k = 0; k < 50; ++k) {
    in.ref_int = (k & 1);  // |e| <= 1/2 count
    run_period(n, c, in);
  }
  EXPECT_EQ(n.state().lp[0].w1, c.w_p1);
  EXPECT_EQ(n.state().lp[0].w2, c.w_p2);
}

TEST(NeuronPi, FollowingErrorFaultStopsAndLatches) {
  NeuronConfig c = base_cfg();
  c.ferr_lim = uint32_t(10.0 * kQ);
  NeuronPi::Inputs in;
  NeuronPi n = started(c, in);
  in.ref_int = 5;
  for (int k = 0; k < 3; ++k) run_period(n, c, in);
  EXPECT_TRUE(n.state().active);
  EXPECT_FALSE(n.state().ferr);
  in.ref_int = 11;  // |e| = 10.5 counts > 10
  for (int k = 0; k < 2; ++k) run_period(n, c, in);
  EXPECT_TRUE(n.state().ferr);
  EXPECT_FALSE(n.state().active);
  EXPECT_EQ(n.state().u, 0);
  in.ref_int = 0;
  for (int k = 0; k < 3; ++k) run_period(n, c, in);
  EXPECT_TRUE(n.state().ferr);  // latched until the next start
  in.start = true;
  n.step(c, in);
  EXPECT_FALSE(n.state().ferr);
  EXPECT_TRUE(n.state().active);
}

TEST(NeuronPi, InPositionNeedsHoldWithoutSteps) {
  NeuronConfig c = base_cfg();
  c.inpos_hold = 4;
  NeuronPi::Inputs in;
  NeuronPi n = started(c, in);
  in.ref_done = true;
  in.ref_int = 0;
  in.cmd_busy = true;  // steps still being commanded: never in position
  for (int k = 0; k < 10; ++k) run_period(n, c, in);
  EXPECT_FALSE(n.state().in_pos);
  in.cmd_busy = false;
  int periods = 0;
  while (!n.state().in_pos && periods < 20) {
    run_period(n, c, in);
    ++periods;
  }
  EXPECT_TRUE(n.state().in_pos);
  EXPECT_FALSE(n.state().active);
  EXPECT_EQ(n.state().u, 0);
  EXPECT_EQ(periods, 5);  // one period to clear the "moved" flag, then 4 of hold
}

}  // namespace
}  // namespace sc
