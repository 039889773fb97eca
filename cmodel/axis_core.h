// Bit-exact model of rtl/sc_axis_core.sv (profile executor + step generator).
#pragma once

#include <cstdint>

#include "profile_exec.h"
#include "step_gen.h"

namespace sc {

// Inputs of sc_axis_core for one clock (what the testbench drives).
struct CoreInputs {
  bool enable = false;
  PulseTiming cfg{};
  bool seg_we = false;
  uint8_t seg_waddr = 0;
  Segment seg_wdata{};
  uint8_t seg_count = 0;
  u128 pos_frac0 = 0;
  bool start = false;
  bool abort = false;
};

// Every output of sc_axis_core, as the lockstep checker compares them.
struct CoreOutputs {
  bool step = false;
  bool dir = false;
  bool en = false;
  bool busy = false;
  bool done = false;
  uint8_t phase = 0;
  bool fault_table = false;
  bool fault_overrun = false;
  int32_t pulse_count = 0;
  int32_t ref_pos_int = 0;
  u128 ref_pos_frac = 0;
  i128 ref_vel = 0;
  int64_t ref_acc = 0;
  int64_t ref_jerk = 0;
  uint8_t seg_idx = 0;
  int8_t step_pending = 0;
  bool operator==(const CoreOutputs&) const = default;
};

class AxisCore {
 public:
  AxisCore() { reset(); }
  void reset();
  void step(const CoreInputs& in);
  CoreOutputs outputs() const;
  // outputs() == o, without building the struct (the lockstep hot path).
  bool outputs_equal(const CoreOutputs& o) const;
  // One clock holding the inputs of the previous step(), which must not have
  // written the table: the same as step(previous inputs), cheaper.
  void tick();

  bool busy() const;
  bool done() const { return exec_.state().finished && !busy(); }

  // Advance up to n clocks with `in` held (in must have no start, abort or
  // write); jumps in closed form while the step generator is idle and the
  // executor is between steps. Equal to n calls of step(in).
  void fast_forward(const CoreInputs& in, uint64_t n);
  // True when holding `in` changes nothing in the input registers.
  bool inputs_settled(const CoreInputs& in) const;

  ProfileExec& exec() { return exec_; }
  StepGen& step_gen() { return sg_; }
  const ProfileExec& exec() const { return exec_; }
  const StepGen& step_gen() const { return sg_; }

 private:
  // The core's input register stage (mirrors en_q, start_q, abort_q, cfg_*_q,
  // seg_count_q, pos_frac0_q): the table write port is not registered.
  struct InputRegs {
    bool enable = false;
    bool start = false;
    bool abort = false;
    PulseTiming cfg{0, 0, 0, 0};
    uint8_t seg_count = 0;
    u128 pos_frac0 = 0;
  };
  ProfileExec exec_;
  StepGen sg_;
  InputRegs in_q_;
  // Start arming (mirrors first_fwd_q, arm_q, arm_fwd_q, arm_cnt_q).
  bool first_fwd_ = true;
  bool arm_ = false;
  bool arm_fwd_ = true;
  uint16_t arm_cnt_ = 0;
  ProfileExec::Inputs exec_in_{};  // reused every clock: no per-clock construction
  void clock_edge();
};

}  // namespace sc
