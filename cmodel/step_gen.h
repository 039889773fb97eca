// Bit-exact model of rtl/sc_step_gen.sv.
#pragma once

#include <cstdint>

#include "fixed_point.h"

namespace sc {

struct PulseTiming {
  uint16_t high = 50;   // STEP high time, clocks (2.5 us at 20 MHz)
  uint16_t low = 50;    // minimum STEP low time, clocks
  uint16_t setup = 100; // DIR change to STEP rising edge, clocks
  uint16_t hold = 100;  // STEP rising edge to DIR change, clocks
  bool operator==(const PulseTiming&) const = default;
};

class StepGen {
 public:
  struct Inputs {
    PulseTiming cfg{};
    bool clear = false;
    bool step_req = false;
    bool step_fwd = true;
    bool dir_hint_valid = false;
    bool dir_hint = true;  // forward
  };
  struct State {
    bool step = false;
    bool dir = true;
    uint16_t high_left = 0;
    uint16_t low_cnt = 0xffff;
    uint16_t since_rise = 0xffff;
    uint16_t since_dir = 0xffff;
    int8_t pend = 0;
    bool overrun = false;
    int32_t count = 0;
    bool operator==(const State&) const = default;
  };
  static constexpr uint16_t kCntMax = uint16_t((1u << PulseTimeW) - 1);
  static constexpr int kPendMax = (1 << (PendW - 1)) - 1;
  static constexpr int kPendMin = -(1 << (PendW - 1));

  StepGen() { reset(); }
  void reset() { q_ = State{}; }
  void step(const Inputs& in);
  bool busy() const { return q_.pend != 0 || q_.step; }
  // Nothing but saturating counters moves while idle (and DIR already
  // points where the hint says - the caller checks): jump k clocks.
  bool idle() const { return q_.pend == 0 && !q_.step; }
  void jump_idle(uint64_t k);

  const State& state() const { return q_; }
  State& mutable_state() { return q_; }

 private:
  State q_;
};

}  // namespace sc
