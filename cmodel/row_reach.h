// Bit-exact model of rtl/sc_row_reach.sv: the furthest positions a row
// reaches, forward and backward, for the soft-limit look-ahead. Same
// registers, same micro-program and clock count; step() is one clock.
#pragma once

#include <cstdint>

#include "fixed_point.h"

namespace sc {

class RowReach {
 public:
  static constexpr int kW = ReachAccW;                 // datapath width (the RTL's W)
  static constexpr int kDivSh = FracBits - ReachFrac;  // S is divided by 2^kDivSh
  static constexpr int64_t kReachMax = (int64_t(1) << (ReachW - 1)) - 1;
  static constexpr int64_t kReachMin = -(int64_t(1) << (ReachW - 1));

  enum class St : uint8_t { Idle, Ld, Run, Dec, Done };
  enum class Ph : uint8_t { Start, A, K, Vk, Vn, Sn, Srch, Step, St };
  enum class MSel : uint8_t { Nm1, K, Mid, Hi };

  struct Inputs {
    bool start = false;
    bool abort = false;
    uint32_t clocks = 0;
    int64_t jerk = 0;  // JerkW bits, sign-extended
    int64_t acc0 = 0;  // AccW bits
    i128 vel0 = 0;     // VelW bits, sign-extended
  };
  struct State {
    St st = St::Idle;
    Ph ph = Ph::Start;
    uint8_t pc = 0, cnt = 0;
    MSel msel = MSel::Nm1;
    uint32_t nm1 = 0, k = 0, lo = 0, hi = 0;
    int64_t j = 0, a = 0;
    i128 v = 0;
    i128 acc = 0, mcd = 0;  // kW bits, sign-extended
    uint64_t mlr = 0;       // ReachW bits
    uint8_t r3 = 0;
    bool one = false, kc = false, clsk = false, clsn = false, ref = false, srch2 = false;
    int64_t fwd = 0, rev = 0;  // ReachW bits
    bool operator==(const State&) const = default;
  };

  RowReach() { reset(); }
  void reset() { q_ = State{}; }
  void step(const Inputs& in);

  bool busy() const { return q_.st != St::Idle; }
  bool done() const { return q_.st == St::Done; }
  int64_t reach_fwd() const { return q_.fwd; }  // max S(n), 2^-ReachFrac pulses, rounded up
  int64_t reach_rev() const { return q_.rev; }  // min S(n), rounded down
  const State& state() const { return q_; }

 private:
  State q_;
};

}  // namespace sc
