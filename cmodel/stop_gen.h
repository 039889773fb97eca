// Bit-exact model of rtl/sc_stop_gen.sv: the jerk-limited controlled stop.
// Same registers, same update order, same widths; step() is one clock.
// constant_span()/advance() jump through long phases of constant jerk in
// closed form (tested equal to step()). Algorithm: docs/stop.md.
#pragma once

#include <cstdint>

#include "fixed_point.h"

namespace sc {

class StopGen {
 public:
  // Internal widths (the RTL's localparams).
  static constexpr int kVW = VelW + 1;  // mirrored velocity (may dip below 0 in an infeasible stop)
  static constexpr int kBW = AccW + 1;  // mirrored level b = -a (|acc| up to 2^63 after mirroring)
  static constexpr int kUW = 88;        // bound u >= R(b), signed
  static constexpr int kDW = 86;        // division registers remk, j2k
  static constexpr int kInfExp = 84;    // 2*msb(b0) - msb(J) >= this: R(b0) > any velocity

  struct Inputs {
    bool start = false;      // begin a stop from (vel, acc)
    i128 vel = 0;            // VelW bits, sign-extended: executor state from the next clock on
    int64_t acc = 0;         // AccW bits
    uint64_t stop_jerk = 0;  // JerkW bits, unsigned
    uint64_t stop_acc = 0;   // AccW bits, unsigned
  };
  struct State {
    bool active = false;
    bool done = false;
    bool neg = false;        // direction: the stop runs on (-v, -a)
    bool overshoot = false;  // sticky: the start state could not stop without reversal
    bool div = false;        // the division that tightens u is running
    bool uinf = false;       // u is "infinite" (R(b0) beyond the velocity range)
    bool clamp = false;      // level at D, off the J grid; the next step down goes to g
    i128 v = 0;              // mirrored velocity, kVW bits signed
    i128 b = 0;              // mirrored level (braking acceleration), kBW bits signed
    i128 u = 0;              // upper bound of the velocity the ramp-down path from b consumes
    i128 g = 0;              // grid level below D (valid while clamp)
    uint64_t j = 1;          // latched stop jerk, 1 .. 2^(JerkW-1)-1
    uint64_t d = 1;          // latched stop deceleration, 1 .. 2^(AccW-1)-1
    uint8_t k = 0;           // division bit
    uint8_t prep = 0;        // division set-up: 1 = J << k next, 2 = J << 2k next
    u128 rem = 0;            // division: remainder (level units)
    u128 jk = 0;             // J << k
    u128 j2k = 0;            // J << 2k
    u128 remk = 0;           // rem << k
    bool operator==(const State&) const = default;
  };
  enum class Move : uint8_t { Up, Land, Hold, Down };

  StopGen() { reset(); }
  void reset() { q_ = State{}; }
  void step(const Inputs& in);

  // Outputs (combinational from the registers, as in the RTL).
  bool active() const { return q_.active; }
  bool done() const { return q_.done; }
  bool overshoot() const { return q_.overshoot; }
  int64_t jerk() const;  // jerk the executor applies this clock: acc_d = acc_q + jerk

  // Clocks from now over which jerk() stays constant and advance() is exact
  // (assuming no start): 0 when idle, 1 when only step() is safe.
  uint64_t constant_span() const;
  // Advance n clocks (1 <= n <= constant_span()) in closed form.
  void advance(uint64_t n);

  const State& state() const { return q_; }
  State& mutable_state() { return q_; }  // for fault-injection tests only

  // The decision logic of one clock (shared by step() and jerk()).
  struct Next {
    Move move = Move::Hold;
    i128 v1 = 0;  // v - b
    i128 b1 = 0;  // next level
    i128 u1 = 0;  // bound for b1 (before the division's tightening)
    bool clamp1 = false;
  };
  Next decide() const;

 private:
  State q_;
};

// Position of the highest set bit (x > 0).
constexpr int msb_u128(u128 x) {
  int n = -1;
  while (x) {
    x >>= 1;
    ++n;
  }
  return n;
}

}  // namespace sc
