// Test harness of the controlled stop: random start states in physical
// ranges and a tiny integrator that applies jerk_o exactly like the
// executor; the closed form and the property checker, which know nothing of
// the generator's algorithm, are tb/stop_check.h.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "fixed_point.h"
#include "rtl_stop_gen.h"
#include "stop_check.h"
#include "stop_gen.h"

namespace sc::stoptest {

using namespace sc::stopcheck;  // closed form, feasibility, property checker (tb/stop_check.h)

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
    chk.clock(s.a, j);
    s.clock(j);
    chk.after_clock(s.v);
    m.step(quiet);
    if (rtl) rtl->step(quiet);
    ++clk;
  }
  r.clocks = clk;
  if (m.active()) r.errors.push_back("no rest within " + std::to_string(max_clocks) + " clocks");
  chk.at_end(s.v, s.a);
  for (int i = 0; i < tail; ++i) {
    compare(clk + i);
    const int64_t j = m.jerk();
    s.clock(j);
    chk.after_rest(s.v, s.a, j, s.last_step != 0);
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
