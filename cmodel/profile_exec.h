// Bit-exact model of rtl/sc_profile_exec.sv: same state, same update order,
// same wrap. step() is one clock; fast_forward() jumps many clocks in closed
// form and is tested equal to step().
#pragma once

#include <array>
#include <cstdint>

#include "fixed_point.h"

namespace sc {

struct Segment {
  Phase phase = Phase::PhIdle;
  uint32_t clocks = 0;
  int64_t jerk = 0;  // JerkW bits, sign-extended
  int64_t acc0 = 0;  // AccW bits
  i128 vel0 = 0;     // VelW bits, sign-extended
  bool operator==(const Segment&) const = default;
};

class ProfileExec {
 public:
  struct Inputs {
    bool seg_we = false;
    uint8_t seg_waddr = 0;
    Segment seg_wdata{};
    uint8_t seg_count = 0;
    u128 pos_frac0 = 0;
    bool start = false;
    bool abort = false;
  };
  struct State {
    bool run = false;
    bool finished = false;
    bool fault = false;
    uint8_t idx = 0;
    uint8_t count = 0;
    uint32_t left = 0;
    int64_t jerk = 0;
    int64_t acc = 0;
    i128 vel = 0;
    u128 frac = 0;
    int32_t pint = 0;
    Phase phase = Phase::PhIdle;
    bool step_req = false;
    bool step_fwd = true;
    bool operator==(const State&) const = default;
  };

  ProfileExec() { reset(); }
  void reset();
  void step(const Inputs& in);

  // Clocks until the next clock that emits a step or ends the segment
  // (1 = the coming clock), assuming no inputs; 0 if the executor is idle
  // or a closed-form jump is not safe (velocity changes sign, would wrap).
  uint64_t clocks_to_next_event() const;
  // Clocks that advance() may cover in closed form: the rest of the current
  // segment except its last (reload) clock; 0 when not safe.
  uint64_t closed_form_span() const;
  // Advance k quiet clocks (k <= closed_form_span()) in closed form,
  // including the steps they emit; bit-exact with k calls of step().
  void advance(uint64_t k);
  // Advance up to n quiet clocks (no start/abort/writes): a whole segment
  // per advance(), step() for the reload clocks. Returns net steps emitted.
  // Equal to n calls of step() (stops early once idle).
  int64_t fast_forward(uint64_t n);

  const State& state() const { return q_; }
  State& mutable_state() { return q_; }  // for fault-injection tests only
  const Segment& segment(unsigned i) const { return mem_[i % MaxSegs]; }

 private:
  bool jump_safe() const;
  State q_;
  std::array<Segment, MaxSegs> mem_{};
};

}  // namespace sc
