#include "scurve/servo_config.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>
#include <utility>

namespace scurve {

using namespace hw;

namespace {

uint32_t coef(double v) { return uint32_t(std::llround(v * double(1u << CoefFrac))); }

std::string show(double v) { return fmt::format("{}", v); }

// A setting in physical units within [lo, hi] (finite): the error names the
// flag, the value and the bound.
std::optional<Error> in_range(const char* name, double v, double lo, double hi, const char* unit) {
  if (std::isfinite(v) && v >= lo && v <= hi) return std::nullopt;
  return Error{name, fmt::format("{}={}: must be a finite number in [{}, {}]{}{}", name, show(v), show(lo), show(hi),
                                 *unit ? " " : "", unit)};
}
int32_t wgt(double v) { return int32_t(std::llround(v * double(1 << WgtFrac))); }

}  // namespace

const char* controller_kind_name(ControllerKind k) { return k == ControllerKind::kPidAw ? "pid-aw" : "neuron"; }

PidGains realised_pid_gains(const NeuronConfig& n, double rate_hz) {
  // The normalisation of sc_neuron_pi: wn_i = floor(|w_i| 2^NWgtFrac / (|w_1| + |w_2|)).
  const int64_t a1 = std::abs(int64_t(n.w_p1)), a2 = std::abs(int64_t(n.w_p2));
  const int64_t sum = a1 + a2;
  auto wn = [&](int64_t a) { return sum == 0 ? 0.0 : double((a << NWgtFrac) / sum) / double(1 << NWgtFrac); };
  const double k = double(n.k_p) / double(1u << CoefFrac);
  PidGains g;
  g.kp = k * wn(a2) * rate_hz;
  g.ki = k * wn(a1) * rate_hz * rate_hz;
  g.kd = double(n.k_v) / double(1u << CoefFrac);
  g.kb = double(n.kb) / double(1u << CoefFrac) * rate_hz;
  return g;
}

ControllerParams controller_defaults(double rate_hz) {
  ControllerParams p;
  p.rate_hz = rate_hz;
  if (!(rate_hz > 0) || !std::isfinite(rate_hz)) return p;  // to_servo_config names the bad rate
  const double s = kTunedControlRate / rate_hz;
  p.k_v *= s;
  p.k_p *= std::max(1.0, s);
  p.w_p1 *= s;
  p.fixed_w_p1 *= s;
  p.w_p1_max *= s;
  return p;
}

ServoConfigResult to_servo_config(const ControllerParams& p, double counts_per_step, const PulseTiming& t,
                                  Clock clock) {
  if (std::string e = check_clock(clock); !e.empty()) return Error{"clock_hz", e};
  const double f = clock.hz;
  ServoConfig c;
  c.enable = true;
  c.closed_loop = p.closed_loop;
  c.timing = t;
  if (p.enc_filt < 0 || p.enc_filt > kMaxEncFilter) {
    return Error{"enc_filt", fmt::format("enc-filter={} outside 0..{}", p.enc_filt, kMaxEncFilter)};
  }
  NeuronConfig& n = c.ctl;
  n.enc_filt = uint8_t(p.enc_filt);
  const double div = std::round(f / p.rate_hz);
  if (!(div >= kMinControlDiv && div <= kMaxControlDiv)) {
    return Error{"rate_hz", fmt::format("ctl-rate={} Hz: needs {}..{} Hz ({}..{} clocks)", p.rate_hz,
                                        f / kMaxControlDiv, f / kMinControlDiv, kMinControlDiv, kMaxControlDiv)};
  }
  n.div = uint16_t(div);
  const double cps = counts_per_step;
  const int shift = int(std::lround(std::log2(cps)));
  if (!(cps >= 1) || std::ldexp(1.0, shift) != cps || shift >= (1 << EncShiftW)) {
    return Error{"counts_per_step", fmt::format("counts-per-step={} must be a power of two 1..{}", cps,
                                                1 << ((1 << EncShiftW) - 1))};
  }
  n.shift = uint8_t(shift);
  // Physical settings: ranges the register words can hold with this encoder
  // ratio, so no value is silently clamped.
  const double q16 = max_pulses(cps);
  for (const auto& [name, v, lo, hi, unit] : {
           std::tuple{"ctl-rate", p.rate_hz, 1.0, f, "Hz"},
           std::tuple{"v-lim", p.v_lim, 0.0, kMaxSpeed, "pulses/s"},
           std::tuple{"u-lim", p.u_lim, 0.0, kMaxSpeed, "pulses/s"},
           std::tuple{"ferr-lim", p.ferr_lim, 1.0, q16, "pulses"},
           std::tuple{"inpos-win", p.inpos_win, 0.0, q16, "pulses"},
           std::tuple{"inpos-hold", p.inpos_hold_s, 0.0, kMaxInposHold, "s"},
           std::tuple{"settle-rate", p.settle_rate, 0.0, kMaxSpeed, "pulses/s"},
           std::tuple{"learn-dz-p", p.learn_dz_p, 0.0, q16, "pulses"},
           std::tuple{"learn-dz-v", p.learn_dz_v, 0.0, q16, "pulses/period"},
       }) {
    if (auto e = in_range(name, v, lo, hi, unit)) return *e;
  }
  n.ff_en = p.ff;
  n.ferr_stop = p.ferr_stop;
  if (p.learn_shift < 0 || p.learn_shift > kMaxLearnShift) {
    return Error{"learn_shift", fmt::format("learn-shift={} outside 0..{}", p.learn_shift, kMaxLearnShift)};
  }
  n.learn_shift = uint8_t(p.learn_shift);
  const double q8 = double(1 << CtlFrac);
  n.learn_dz_p = uint32_t(std::llround(p.learn_dz_p * cps * q8));
  n.learn_dz_v = uint32_t(std::llround(p.learn_dz_v * cps * q8));
  for (const auto& [name, v] : {std::pair{"k-p", p.k_p}, std::pair{"k-v", p.k_v}, std::pair{"kb", p.kb},
                                std::pair{"eta-p1", p.eta_p1}, std::pair{"eta-p2", p.eta_p2},
                                std::pair{"eta-v1", p.eta_v1}, std::pair{"eta-v2", p.eta_v2}}) {
    if (auto e = in_range(name, v, 0.0, kMaxCoef, "")) return *e;
  }
  n.k_p = coef(p.k_p);
  n.k_v = coef(p.k_v);
  n.kb = coef(p.kb);
  const double k = p.adaptive ? 1.0 : 0.0;
  n.eta_p1 = coef(p.eta_p1 * k);
  n.eta_p2 = coef(p.eta_p2 * k);
  n.eta_v1 = coef(p.eta_v1 * k);
  n.eta_v2 = coef(p.eta_v2 * k);
  for (const auto& [name, v] : {std::pair{"w-p1", p.w_p1}, std::pair{"fixed-w-p1", p.fixed_w_p1},
                                std::pair{"w-p2", p.w_p2}, std::pair{"w-v1", p.w_v1}, std::pair{"w-v2", p.w_v2},
                                std::pair{"w-min", p.w_min}, std::pair{"w-p1-max", p.w_p1_max},
                                std::pair{"w-p2-max", p.w_p2_max}, std::pair{"w-v1-max", p.w_v1_max},
                                std::pair{"w-v2-max", p.w_v2_max}}) {
    if (auto e = in_range(name, v, -kMaxWeight, kMaxWeight, "")) return *e;
  }
  // Each weight's bounds must be ordered (the controller clamps into
  // [w_min, w_max]; an empty interval has no meaning).
  for (const auto& [name, hi] : {std::pair{"w-p1-max", p.w_p1_max}, std::pair{"w-p2-max", p.w_p2_max},
                                 std::pair{"w-v1-max", p.w_v1_max}, std::pair{"w-v2-max", p.w_v2_max}}) {
    if (hi < p.w_min) {
      return Error{name, fmt::format("{}={}: below w-min={} (the weight's interval would be empty)", name, show(hi),
                                     show(p.w_min))};
    }
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
  for (const auto& [name, v, words] : {std::tuple{"v-lim", p.v_lim, p.v_lim * per},
                                       std::tuple{"settle-rate", p.settle_rate, p.settle_rate * per}}) {
    if (words > 2147483647.0) {
      return Error{name, fmt::format("{}={} pulses/s: {} counts per control period exceed the register", name,
                                     show(v), words / q8)};
    }
  }
  n.v_lim = uint32_t(std::llround(p.v_lim * per));
  n.u_lim = uint32_t(std::llround(u_lim * per));
  n.ferr_lim = uint32_t(std::llround(p.ferr_lim * cps * q8));
  n.inpos_win = uint32_t(std::llround(p.inpos_win * cps * q8));
  n.settle_rate = uint32_t(std::llround(p.settle_rate * per));
  const double hold = std::ceil(p.inpos_hold_s * p.rate_hz);
  if (hold > 65535.0) {
    return Error{"inpos-hold", fmt::format("inpos-hold={} s: {} control periods exceed 65535", show(p.inpos_hold_s), hold)};
  }
  n.inpos_hold = uint16_t(std::max(hold, 1.0));
  if (p.kind == ControllerKind::kPidAw) {
    // The position loop's fixed-gain incremental PI is the PID's P and I:
    // du = K (wn_1 e + wn_2 (e - e_prev)) per period, so K = Kp T + Ki T^2
    // and the weights split K in the ratio Ki T : Kp (the larger at 64, the
    // other scaled: the normalised weight carries the ratio to 2^-16); the D
    // term K_V (e - e_prev) is Kd (per period and per second alike); the
    // back-calculation KB = Kb T.
    for (const auto& [name, v] : {std::pair{"pid-kp", p.pid_kp}, std::pair{"pid-ki", p.pid_ki},
                                  std::pair{"pid-kd", p.pid_kd}, std::pair{"pid-kb", p.pid_kb}}) {
      if (!(std::isfinite(v) && v >= 0)) {
        return Error{name, fmt::format("{}={}: must be a finite number >= 0", name, show(v))};
      }
    }
    const double T = div / f;
    const double kp = p.pid_kp * T, ki = p.pid_ki * T * T;
    for (const auto& [name, v, words] : {std::tuple{"pid-kp", p.pid_kp, kp + ki}, std::tuple{"pid-ki", p.pid_ki, kp + ki},
                                         std::tuple{"pid-kd", p.pid_kd, p.pid_kd},
                                         std::tuple{"pid-kb", p.pid_kb, p.pid_kb * T}}) {
      if (words > kMaxCoef) {
        return Error{name, fmt::format("{}={}: {} per control period of {} s exceeds the register's {}", name,
                                       show(v), show(words), show(T), show(kMaxCoef))};
      }
    }
    n.pid = true;
    n.k_p = coef(kp + ki);
    const double big = 64.0;
    n.w_p1 = wgt(ki >= kp ? big : big * ki / kp);
    n.w_p2 = wgt(kp >= ki ? big : big * kp / ki);
    n.k_v = coef(p.pid_kd);
    n.kb = coef(p.pid_kb * T);
    n.eta_p1 = n.eta_p2 = n.eta_v1 = n.eta_v2 = 0;
  }
  return c;
}

}  // namespace scurve
