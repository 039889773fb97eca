// Checks of a controlled stop that know nothing of the stop generator's
// algorithm: the continuous closed-form minimum stop (long double), the
// discrete feasibility of a stop without reversal, a property checker fed
// the motion clock by clock, and a monitor that applies them to a core's
// reference outputs (the stop tests and `scurve sim --stop-at`).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "axis_core.h"
#include "fixed_point.h"

namespace sc::stopcheck {

using ld = long double;

inline constexpr ld kF = ClkHz;
inline const ld kLsb = std::ldexp(ld(1), FracBits);

// A stop's start state and limits in executor LSBs.
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

// Discrete feasibility: ramping |a| to 0 at J per clock (the least velocity
// any stop can use) keeps v >= 0.
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

// Properties of a stop, checked clock by clock from the motion alone.
class StopChecker {
 public:
  explicit StopChecker(const StopCase& c)
      : dir_(c.v > 0 || (c.v == 0 && c.a > 0) ? 1 : -1), feasible_(discrete_feasible(c)),
        J_(std::clamp<i128>(c.j, 1, (i128(1) << (JerkW - 1)) - 1)),
        D_(std::clamp<i128>(c.d, 1, (i128(1) << (AccW - 1)) - 1)) {}
  // One clock while the stop runs: the acceleration before it and the jerk applied.
  void clock(int64_t a, int64_t jerk) {
    if (i128(jerk < 0 ? -i128(jerk) : i128(jerk)) > J_) fail("|jerk| > J");
    const i128 absa = a < 0 ? -i128(a) : i128(a);
    if (absa <= D_) a_in_limit_ = true;
    const i128 a1 = i128(a) + jerk;
    if (a_in_limit_ && (a1 > D_ || a1 < -D_)) fail("|a| above D after reaching it");
    ++clocks_;
  }
  // The velocity after a clock of the stop.
  void after_clock(i128 v) {
    if (feasible_ && v * dir_ < 0) fail("velocity reversal");
  }
  // At the end: at rest.
  void at_end(i128 v, int64_t a) {
    if (v != 0 || a != 0) fail("not at rest at the end of the stop");
  }
  // Any clock after rest: nothing moves.
  void after_rest(i128 v, int64_t a, int64_t jerk, bool stepped) {
    if (jerk != 0 || stepped || v != 0 || a != 0) fail("motion after rest");
  }
  bool feasible() const { return feasible_; }
  int dir() const { return dir_; }
  uint64_t clocks() const { return clocks_; }
  const std::vector<std::string>& errors() const { return errors_; }

 private:
  void fail(const std::string& what) {
    if (errors_.size() < 4) errors_.push_back("stop clock " + std::to_string(clocks_) + ": " + what);
  }
  int dir_;
  bool feasible_;
  i128 J_, D_;
  bool a_in_limit_ = false;
  uint64_t clocks_ = 0;
  std::vector<std::string> errors_;
};

// The reference position in LSBs of the position fraction.
inline ld position_lsb(const CoreOutputs& o) { return ld(o.ref_pos_int) * kLsb + ld(o.ref_pos_frac); }

// Watches a core's outputs after every clock and checks the first controlled
// stop it shows: from the first STOPPING clock (which shows the state the
// stop starts from) to the clock STOPPING falls, the properties above; at
// the end rest, not busy, not done, phase STOP, FIFO empty, OVERSHOOT exactly
// when the start state could not stop without reversal, and a stopping
// distance within one pulse of the closed form.
//
// On the closed-loop axis (`reference_only`) the executor's reference is
// watched alone: the step generator still follows the controller when the
// reference has come to rest, so the axis' busy and done are checked at the
// end of the run (in position, not done), not at the end of the stop.
class StopMonitor {
 public:
  StopMonitor(uint64_t stop_jerk, uint64_t stop_acc, bool reference_only = false)
      : j_(stop_jerk), d_(stop_acc), reference_only_(reference_only) {}

  void on_clock(const CoreOutputs& o) {
    if (ended_) return;
    if (!seen_) {
      if (!o.stopping) return;
      seen_ = true;
      start_ = StopCase{o.ref_vel, o.ref_acc, j_, d_};
      props_.emplace(start_);
      cf_ = closed_form(ld(o.ref_vel), ld(o.ref_acc), ld(j_), ld(d_));
      pos0_ = position_lsb(o);
      if (o.phase != uint8_t(Phase::PhStop)) fail("the phase while stopping is not STOP");
      if (!o.fifo_full) fail("a row is taken while stopping (FIFO not full)");
    }
    StopChecker& p = *props_;
    p.after_clock(o.ref_vel);
    if (o.stopping) {
      p.clock(o.ref_acc, o.ref_jerk);
      return;
    }
    ended_ = true;
    p.at_end(o.ref_vel, o.ref_acc);
    if (!reference_only_ && o.busy) fail("busy after the stop");
    if (!reference_only_ && o.done) fail("a stopped move reads done");
    if (o.phase != uint8_t(Phase::PhStop)) fail("the phase after the stop is not STOP");
    if (o.fifo_level != 0) fail("rows left in the FIFO after the stop");
    overshoot_ = o.overshoot;
    if (o.overshoot != !p.feasible()) {
      fail(o.overshoot ? "OVERSHOOT for a start state that can stop without reversal"
                       : "no OVERSHOOT for a start state that cannot stop without reversal");
    }
    distance_ = (position_lsb(o) - pos0_) * p.dir() / kLsb;
    if (p.feasible() && std::fabs(double(excess())) >= 1.0) {
      fail("stopping distance " + std::to_string(double(distance_)) + " pulses, closed form " +
           std::to_string(double(cf_.dist / kLsb)) + ": not within one pulse");
    }
  }

  bool seen() const { return seen_; }
  bool ended() const { return ended_; }
  bool feasible() const { return props_ && props_->feasible(); }
  bool overshoot() const { return overshoot_; }
  const StopCase& start() const { return start_; }
  uint64_t clocks() const { return props_ ? props_->clocks() : 0; }
  ld distance() const { return distance_; }                   // pulses, in the stop's direction
  ld closed_form_distance() const { return cf_.dist / kLsb; }  // pulses
  ld closed_form_time() const { return cf_.time; }             // clocks
  ld excess() const { return distance_ - cf_.dist / kLsb; }    // pulses
  int dir() const { return props_ ? props_->dir() : 1; }
  // The monitor's own findings and the property checker's.
  std::vector<std::string> errors() const {
    std::vector<std::string> e = errors_;
    if (props_) e.insert(e.end(), props_->errors().begin(), props_->errors().end());
    return e;
  }

 private:
  void fail(const std::string& what) {
    if (errors_.size() < 4) errors_.push_back(what);
  }
  uint64_t j_, d_;
  bool reference_only_ = false;
  bool seen_ = false, ended_ = false, overshoot_ = false;
  StopCase start_;
  std::optional<StopChecker> props_;  // once the stop is seen
  ClosedForm cf_;
  ld pos0_ = 0, distance_ = 0;
  std::vector<std::string> errors_;
};

}  // namespace sc::stopcheck

namespace sc {

// What a controlled stop did (`--stop-at`), for tables and JSON.
struct StopReport {
  bool requested = false;
  bool taken = false;             // the core stopped (not: the move ended first)
  uint64_t at_clock = 0;          // clocks after START
  uint64_t clocks = 0;            // stopping time
  double v0 = 0, a0 = 0;          // the state it stopped from, pulses/s and pulses/s^2
  double distance = 0;            // stopping distance, pulses (in the direction of motion)
  double closed_form_distance = 0;  // continuous minimum for the stop limits, pulses
  bool overshoot = false;         // the start state could not stop without reversal
  int64_t end_position = 0;       // reference position at rest, pulses
  bool by_fault = false;          // started by a fault (following error), not by CMD.STOP at at_clock
};

// The report of a stop requested `at_clock` clocks after START, from the
// monitor that watched it and the reference position at rest.
inline StopReport stop_report(const stopcheck::StopMonitor& m, uint64_t at_clock, int64_t end_position) {
  StopReport r;
  r.requested = true;
  r.taken = m.seen();
  r.at_clock = at_clock;
  r.end_position = end_position;
  r.clocks = m.clocks();
  r.v0 = vel_to_phys(m.start().v);
  r.a0 = acc_to_phys(m.start().a);
  r.distance = double(m.distance());
  r.closed_form_distance = double(m.closed_form_distance());
  r.overshoot = m.overshoot();
  return r;
}

}  // namespace sc
