#include "scurve/servo_config.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace scurve {

using namespace hw;

namespace {

uint32_t coef(double v) { return uint32_t(std::llround(v * double(1u << CoefFrac))); }
int32_t wgt(double v) { return int32_t(std::llround(v * double(1 << WgtFrac))); }

}  // namespace

ServoConfigResult to_servo_config(const ControllerParams& p, double counts_per_step, const PulseTiming& t,
                                  Clock clock) {
  if (std::string e = check_clock(clock); !e.empty()) return Error{"clock_hz", e};
  const double f = clock.hz;
  ServoConfig c;
  c.enable = true;
  c.closed_loop = p.closed_loop;
  c.timing = t;
  if (p.enc_filt < 0 || p.enc_filt >= (1 << EncFiltW)) {
    return Error{"enc_filt", fmt::format("enc-filter={} outside 0..{}", p.enc_filt, (1 << EncFiltW) - 1)};
  }
  NeuronConfig& n = c.ctl;
  n.enc_filt = uint8_t(p.enc_filt);
  const double div = std::round(f / p.rate_hz);
  if (!(div >= kMinControlDiv && div < 65536)) {
    return Error{"rate_hz", fmt::format("ctl-rate={} Hz: needs {}..{} Hz ({}..65535 clocks)", p.rate_hz, f / 65535.0,
                                        f / kMinControlDiv, kMinControlDiv)};
  }
  n.div = uint16_t(div);
  const double cps = counts_per_step;
  const int shift = int(std::lround(std::log2(cps)));
  if (!(cps >= 1) || std::ldexp(1.0, shift) != cps || shift >= (1 << EncShiftW)) {
    return Error{"counts_per_step", fmt::format("counts-per-step={} must be a power of two 1..{}", cps,
                                                1 << ((1 << EncShiftW) - 1))};
  }
  n.shift = uint8_t(shift);
  n.ff_en = p.ff;
  if (p.learn_shift < 0 || p.learn_shift >= (1 << LearnShW)) {
    return Error{"learn_shift", fmt::format("learn-shift={} outside 0..31", p.learn_shift)};
  }
  n.learn_shift = uint8_t(p.learn_shift);
  const double q8 = double(1 << CtlFrac);
  n.learn_dz_p = uint32_t(std::llround(p.learn_dz_p * cps * q8));
  n.learn_dz_v = uint32_t(std::llround(p.learn_dz_v * cps * q8));
  const double cmax = double(1u << (CoefW - CoefFrac));
  for (double v : {p.k_p, p.k_v, p.kb, p.eta_p1, p.eta_p2, p.eta_v1, p.eta_v2}) {
    if (!(v >= 0 && v < cmax)) return Error{"gain", fmt::format("gain/learning rate {} outside [0, {})", v, cmax)};
  }
  n.k_p = coef(p.k_p);
  n.k_v = coef(p.k_v);
  n.kb = coef(p.kb);
  const double k = p.adaptive ? 1.0 : 0.0;
  n.eta_p1 = coef(p.eta_p1 * k);
  n.eta_p2 = coef(p.eta_p2 * k);
  n.eta_v1 = coef(p.eta_v1 * k);
  n.eta_v2 = coef(p.eta_v2 * k);
  const double wmax = double(1 << (WgtW - 1 - WgtFrac));
  for (double v : {p.w_p1, p.w_p2, p.w_v1, p.w_v2, p.w_min, p.w_p1_max, p.w_p2_max, p.w_v1_max, p.w_v2_max}) {
    if (!(v > -wmax && v < wmax)) return Error{"weight", fmt::format("weight {} outside (-{}, {})", v, wmax, wmax)};
  }
  n.w_p1 = wgt(p.adaptive ? p.w_p1 : p.fixed_w_p1);
  n.w_p2 = wgt(p.w_p2);
  n.w_v1 = wgt(p.w_v1);
  n.w_v2 = wgt(p.w_v2);
  n.w_min = wgt(p.w_min);
  n.w_p1_max = wgt(p.w_p1_max);
  n.w_p2_max = wgt(p.w_p2_max);
  n.w_v1_max = wgt(p.w_v1_max);
  n.w_v2_max = wgt(p.w_v2_max);
  // speeds: pulses/s -> counts per control period, Q.CtlFrac
  const double per = div / f * cps * q8;
  const double rate_limit = f / (double(t.high) + double(t.low));
  const double u_lim = p.u_lim > 0 ? p.u_lim : 0.9 * rate_limit;
  if (u_lim > rate_limit) {
    return Error{"u_lim", fmt::format("u-lim={} pulses/s above the step-rate limit {}", u_lim, rate_limit)};
  }
  n.v_lim = uint32_t(std::llround(std::min(p.v_lim * per, 2147483647.0)));
  n.u_lim = uint32_t(std::llround(u_lim * per));
  n.ferr_lim = uint32_t(std::llround(std::min(p.ferr_lim * cps * q8, 2147483647.0)));
  n.inpos_win = uint32_t(std::llround(p.inpos_win * cps * q8));
  n.settle_rate = uint32_t(std::llround(p.settle_rate * per));
  const double hold = std::ceil(p.inpos_hold_s * p.rate_hz);
  n.inpos_hold = uint16_t(std::clamp(hold, 1.0, 65535.0));
  return c;
}

}  // namespace scurve
