// Test harness of the controlled stop: random start states in physical
// ranges, the continuous closed-form minimum stop (long double), a tiny
// integrator that applies jerk_o exactly like the executor, and a property
// checker that knows nothing of the generator's algorithm.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "fixed_point.h"
#include "rtl_stop_gen.h"
#include "stop_gen.h"

namespace sc::stoptest {

using ld = long double;

inline constexpr ld kF = ClkHz;
inline const ld kLsb = std::ldexp(ld(1), FracBits);

struct StopCase {
  i128 v = 0;       // VelW bits
  int64_t a = 0;    // AccW bits
  uint64_t j = 1;   // stop jerk
  uint64_t d = 1;   // stop deceleration
};

// Continuous time-optimal stop from (v, a) with |jerk| <= J, |a| <= D, in
// LSB units and clocks: ramp an accelerating a to 0, an |a| above D into D,
// then the braking triangle or trapezoid that ends at v = a = 0.
struct ClosedForm {
  ld dist = 0;   // LSB of position
  ld time = 0;   // clocks
  bool feasible = true;
};
inline ClosedForm closed_form(ld v, ld a, ld J, ld D) {
  if (v < 0 || (v == 0 && a < 0)) {
    v = -v;
    a = -a;
  }
  ClosedForm c;
  auto seg = [&](ld jj, ld t) {
    c.dist += v * t + a * t * t / 2 + jj * t * t * t / 6;
    v += a * t + jj * t * t / 2;
    a += jj * t;
    c.time += t;
  };
  if (a > 0) seg(-J, a / J);
  a = std::min<ld>(a, 0);
  if (-a > D) seg(J, (-a - D) / J);
  const ld b = -a;
  if (v < b * b / (2 * J)) {
    c.feasible = false;
    return c;
  }
  const ld p = std::sqrt(J * v + b * b / 2);
  if (p <= D) {
    seg(-J, (p - b) / J);
    seg(J, p / J);
  } else {
    seg(-J, (D - b) / J);
    seg(0, (v - D * D / (2 * J)) / D);  // v is now what the ramp to D left
    seg(J, D / J);
  }
  return c;
}

// Discrete feasibility, independent of the generator: ramping |a| to 0 at
// J per clock (the least velocity any stop can use) keeps v >= 0.
inline bool discrete_feasible(const StopCase& c) {
  i128 v = c.v;
  i128 b = -i128(c.a);
  if (v < 0 || (v == 0 && c.a < 0)) {
    v = -v;
    b = -b;
  }
  if (b <= 0) return true;
  const i128 J = std::max<i128>(1, c.j);
  const i128 q = b / J, r = b % J;
  const i128 R = (q + 1) * r + J * q * (q + 1) / 2;  // b + (b-J) + ... + r
  return v >= R;
}

// Random start states: speeds up to 500 kHz, accelerations 1e3..1e7
// pulses/s^2 (sometimes above the stop limit, sometimes 0), jerks
// 1e4..1e10 pulses/s^3, both signs, tiny speeds; stops longer than
// max_clocks (closed form) are drawn again.
class CaseGen {
 public:
  explicit CaseGen(uint64_t seed) : g_(seed) {}
  StopCase next(ld max_clocks) {
    for (;;) {
      StopCase c;
      const ld J = logu(1e4, 1e10), D = logu(1e3, 1e7);
      c.j = std::max<uint64_t>(1, uint64_t(J * kLsb / (kF * kF * kF)));
      c.d = std::max<uint64_t>(1, uint64_t(D * kLsb / (kF * kF)));
      ld v = logu(1, 5e5) * kLsb / kF;
      const unsigned kind = g_() % 8;
      if (kind == 0) v = ld(g_() % 4096);  // tiny: a few LSB
      if (kind == 1) v = 0;
      ld a = logu(1e3, 1e7) * kLsb / (kF * kF);
      if (kind == 2) a = 0;
      if (kind == 3) a = ld(c.d) * logu(1, 10);  // above the stop limit
      c.v = i128(v);
      c.a = int64_t(a);
      if (g_() & 1) c.a = -c.a;
      if (g_() & 1) c.v = -c.v;
      const ClosedForm cf = closed_form(ld(c.v), ld(c.a), ld(c.j), ld(c.d));
      const ld ramp = std::fabs(ld(c.a)) / ld(c.j);
      if (cf.time > max_clocks || ramp > max_clocks / 4) continue;
      // A start that cannot stop reverses with up to ~a^2 / 2J and then stops
      // from there at D: keep that within the case limit too.
      const ld reverse_v = ld(c.a) * ld(c.a) / (2 * ld(c.j));
      if (!cf.feasible && (std::fabs(ld(c.v)) + reverse_v) > ld(c.d) * max_clocks / 8) continue;
      return c;
    }
  }

 private:
  ld logu(ld lo, ld hi) {
    std::uniform_real_distribution<double> u(std::log(double(lo)), std::log(double(hi)));
    return std::exp(ld(u(g_)));
  }
  std::mt19937_64 g_;
};

// The executor's integrator: pos += v; v += a; a += jerk, a step per carry
// (borrow) out of the 80-bit position fraction.
struct Integrator {
  u128 frac = u128(1) << (FracBits - 1);
  i128 steps = 0;
  i128 v = 0;
  int64_t a = 0;
  int last_step = 0;
  void clock(int64_t jerk) {
    const i128 sum = i128(frac) + v;
    last_step = 0;
    if (sum < 0) {
      --steps;
      last_step = -1;
      frac = u128(sum + i128(kOne));
    } else if (u128(sum) >= kOne) {
      ++steps;
      last_step = 1;
      frac = u128(sum) - kOne;
    } else {
      frac = u128(sum);
    }
    v += a;
    a += jerk;
  }
  ld distance() const {
    return ld(steps) + (ld(frac) - ld(u128(1) << (FracBits - 1))) / kLsb;
  }
};

// Properties of a stop, checked clock by clock from the motion alone.
class StopChecker {
 public:
  explicit StopChecker(const StopCase& c)
      : c_(c), dir_(c.v > 0 || (c.v == 0 && c.a > 0) ? 1 : -1), feasible_(discrete_feasible(c)),
        J_(std::clamp<i128>(c.j, 1, (i128(1) << (JerkW - 1)) - 1)),
        D_(std::clamp<i128>(c.d, 1, (i128(1) << (AccW - 1)) - 1)) {}
  // One clock while the stop runs: the state before it and the jerk applied.
  void clock(const Integrator& s, int64_t jerk) {
    if (i128(std::abs(jerk)) > J_) fail("|jerk| > J");
    const i128 absa = s.a < 0 ? -i128(s.a) : i128(s.a);
    if (absa <= D_) a_in_limit_ = true;
    const i128 a1 = i128(s.a) + jerk;
    if (a_in_limit_ && (a1 > D_ || a1 < -D_)) fail("|a| above D after reaching it");
    ++clocks_;
  }
  void after_clock(const Integrator& s) {
    if (feasible_ && s.v * dir_ < 0) fail("velocity reversal");
  }
  // At the end: at rest, nothing moves afterwards.
  void at_end(const Integrator& s) {
    if (s.v != 0 || s.a != 0) fail("not at rest at done");
  }
  void after_rest(const Integrator& s, int64_t jerk) {
    if (jerk != 0 || s.last_step != 0 || s.v != 0 || s.a != 0) fail("motion after rest");
  }
  bool feasible() const { return feasible_; }
  int dir() const { return dir_; }
  uint64_t clocks() const { return clocks_; }
  const std::vector<std::string>& errors() const { return errors_; }

 private:
  void fail(const std::string& what) {
    if (errors_.size() < 4) errors_.push_back("clock " + std::to_string(clocks_) + ": " + what);
  }
  StopCase c_;
  int dir_;
  bool feasible_;
  i128 J_, D_;
  bool a_in_limit_ = false;
  uint64_t clocks_ = 0;
  std::vector<std::string> errors_;
};

struct StopResult {
  uint64_t clocks = 0;
  ld distance = 0;      // pulses, in the start direction
  ld cf_distance = 0;   // closed form, pulses
  ld cf_time = 0;       // closed form, clocks
  bool cf_feasible = true;
  bool feasible = true;  // discrete
  bool overshoot = false;
  uint64_t mismatches = 0;
  std::string first_mismatch;
  std::vector<std::string> errors;
};

// Run one stop on the model (and the RTL in lockstep when given), the
// integrator driven by jerk_o; `tail` clocks after done check that nothing
// moves. Outputs are compared every clock.
inline StopResult run_stop(const StopCase& c, RtlStopGen* rtl, uint64_t max_clocks, int tail = 16) {
  StopResult r;
  StopGen m;
  const StopGen::Inputs start{true, c.v, c.a, c.j, c.d};
  m.step(start);
  if (rtl) rtl->step(start);
  Integrator s;
  s.v = c.v;
  s.a = c.a;
  StopChecker chk(c);
  auto compare = [&](uint64_t clk) {
    if (!rtl) return;
    const StopOutputs ro = rtl->outputs(), mo = outputs_of(m);
    if (!(ro == mo)) {
      if (r.mismatches++ == 0) {
        r.first_mismatch = "clock " + std::to_string(clk) + ": rtl active/done/over/jerk=" +
                           std::to_string(ro.active) + std::to_string(ro.done) + std::to_string(ro.overshoot) + "/" +
                           std::to_string(ro.jerk) + " model=" + std::to_string(mo.active) + std::to_string(mo.done) +
                           std::to_string(mo.overshoot) + "/" + std::to_string(mo.jerk);
      }
    }
  };
  const StopGen::Inputs quiet{};
  uint64_t clk = 0;
  while (m.active() && clk < max_clocks) {
    compare(clk);
    const int64_t j = m.jerk();
    chk.clock(s, j);
    s.clock(j);
    chk.after_clock(s);
    m.step(quiet);
    if (rtl) rtl->step(quiet);
    ++clk;
  }
  r.clocks = clk;
  if (m.active()) r.errors.push_back("no rest within " + std::to_string(max_clocks) + " clocks");
  chk.at_end(s);
  for (int i = 0; i < tail; ++i) {
    compare(clk + i);
    const int64_t j = m.jerk();
    s.clock(j);
    chk.after_rest(s, j);
    m.step(quiet);
    if (rtl) rtl->step(quiet);
  }
  r.distance = s.distance() * chk.dir();
  const ClosedForm cf = closed_form(ld(c.v), ld(c.a), ld(c.j), ld(c.d));
  r.cf_distance = cf.dist / kLsb;
  r.cf_time = cf.time;
  r.cf_feasible = cf.feasible;
  r.feasible = chk.feasible();
  r.overshoot = m.overshoot();
  for (const auto& e : chk.errors()) r.errors.push_back(e);
  if (!m.done()) r.errors.push_back("done_o not set at rest");
  return r;
}

inline std::string describe(const StopCase& c) {
  return "v=" + to_string_i128(c.v) + " a=" + std::to_string(c.a) + " J=" + std::to_string(c.j) +
         " D=" + std::to_string(c.d);
}

}  // namespace sc::stoptest
