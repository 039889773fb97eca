// Bit-exact model of rtl/sc_servo_axis.sv: the open-loop core (AxisCore:
// arming, profile executor, step generator) + quadrature decoder + neuron-PI
// cascade + step NCO as the core's external step source, one clock per
// step(). The plant is outside: the caller drives enc_a/enc_b.
#pragma once

#include <cstdint>

#include "axis_core.h"
#include "neuron_pi.h"
#include "profile_exec.h"
#include "quad_decoder.h"
#include "step_gen.h"
#include "step_nco.h"

namespace sc {

// Quasi-static configuration of sc_servo_axis (its cfg_* inputs).
struct ServoConfig {
  bool enable = true;
  bool closed_loop = true;
  PulseTiming timing{};
  NeuronConfig ctl{};  // the closed-loop configuration (incl. the decoder's enc_filt)
  bool operator==(const ServoConfig&) const = default;
};

// Inputs of sc_servo_axis for one clock.
struct ServoInputs {
  ServoConfig cfg{};
  bool row_push = false;
  bool row_replace = false;  // retarget (as CoreInputs)
  uint32_t retarget_row = 0;
  Row row{};
  bool fifo_flush = false;
  u128 pos_frac0 = 0;
  bool start = false;
  bool abort = false;
  bool stop = false;
  uint64_t stop_jerk = StopJerkReset;  // controlled-stop limits (as CoreInputs)
  uint64_t stop_acc = StopAccReset;
  GuardLimits guard{};   // row guards (as CoreInputs)
  SoftWindow soft{};     // soft-limit look-ahead (as CoreInputs)
  bool lim_fwd = false;  // limits (as CoreInputs)
  bool lim_rev = false;
  bool lim_hard = false;
  bool enc_a = false;
  bool enc_b = false;
  bool enc_z = false;  // index
};

// Every output of sc_servo_axis, as the lockstep checker compares them.
struct ServoOutputs {
  bool step = false, dir = false, en = false;
  bool busy = false, done = false;
  uint8_t phase = 0;
  bool fault_table = false, fault_overrun = false, fault_ferr = false, in_pos = false;
  bool underrun = false, discont = false, guard = false, reach = false, move_done = false, fifo_full = false;
  bool stopping = false, overshoot = false;
  bool lim_trip_fwd = false, lim_trip_rev = false;
  uint32_t move_idx = 0;
  int32_t boundary_pos = 0;
  uint8_t fifo_level = 0;
  uint32_t row_count = 0;
  bool retarget_refused = false;
  int32_t pulse_count = 0;
  int32_t enc_pos = 0;
  uint16_t enc_illegal = 0;
  bool enc_index = false;  // filtered Z, in step with enc_pos
  int32_t ref_pos_int = 0;
  uint32_t ref_frac_hi = 0;
  int32_t ref_vel = 0;  // Q.VffFrac pulses/clock
  bool ref_done = false;
  bool ctl_active = false;
  uint8_t ctl_state = 0;
  int32_t u = 0, v_cmd = 0, e_p = 0, e_v = 0;
  int32_t w_p1 = 0, w_p2 = 0, w_v1 = 0, w_v2 = 0;
  int32_t wn_p1 = 0, wn_p2 = 0, wn_v1 = 0, wn_v2 = 0;
  int64_t nco_phase = 0;
  int8_t step_pending = 0;
  bool operator==(const ServoOutputs&) const = default;
};

// The loop's own ports of one axis of sc_multi_axis_core #(.Servo(1)) (the
// rest of ServoInputs is the open-loop core's, CoreInputs).
struct LoopInputs {
  bool closed_loop = true;
  NeuronConfig ctl{};
  bool enc_a = false, enc_b = false, enc_z = false;
};

// The loop's outputs of one axis of sc_multi_axis_core #(.Servo(1)) (the
// rest is CoreOutputs, read_core_outputs()).
struct LoopOutputs {
  bool fault_ferr = false, in_pos = false;
  int32_t enc_pos = 0;
  uint16_t enc_illegal = 0;
  bool enc_index = false;
  bool ctl_active = false;
  uint8_t ctl_state = 0;
  int32_t u = 0, v_cmd = 0, e_p = 0, e_v = 0;
  int32_t w_p1 = 0, w_p2 = 0, w_v1 = 0, w_v2 = 0;
  int64_t nco_phase = 0;
  bool operator==(const LoopOutputs&) const = default;
};

class ServoAxis {
 public:
  ServoAxis() { reset(); }
  void reset();
  void step(const ServoInputs& in);
  // One clock of sc_servo_axis #(.SyncStart(1)): one axis of a multi-axis
  // core, `s` formed from every axis's state before this clock.
  void step(const ServoInputs& in, const SyncInputs& s);
  ServoOutputs outputs() const;
  // The synchronisation outputs (start_able_o, arm_ready_o, arm_drop_o,
  // fault_abort_o), from the current state.
  bool start_able() const { return core_.start_able(ext_inputs()); }
  bool arm_ready() const { return core_.arm_ready(); }
  bool reach_bad() const { return core_.reach_bad(); }
  bool arm_drop() const { return core_.arm_drop(); }
  bool fault_abort() const { return core_.fault_abort(ext_inputs()); }
  // The outputs sc_multi_axis_core takes from this axis: the core's set
  // (busy, done and phase with the loop's) and the loop's.
  void read_core_outputs(CoreOutputs& o) const;
  void read_loop_outputs(LoopOutputs& o) const;

  bool busy() const;
  bool done() const;
  // The reference position P* - 1/2 in pulses (double; for metrics).
  double ref_position() const;

  const AxisCore& core() const { return core_; }
  const ProfileExec& exec() const { return core_.exec(); }
  ProfileExec& exec() { return core_.exec(); }
  const QuadDecoder& decoder() const { return dec_; }
  const NeuronPi& ctl() const { return ctl_; }
  const StepNco& nco() const { return nco_; }
  const StepGen& step_gen() const { return core_.step_gen(); }
  NeuronPi& mutable_ctl() { return ctl_; }
  AxisCore& mutable_core() { return core_; }  // for fault-injection tests only

  // Register-stage view of a configuration (what the RTL's _q flops hold).
  static ServoConfig registered(const ServoConfig& c);

 private:
  static ServoConfig zero_config() {
    ServoConfig c;
    c.enable = false;
    c.closed_loop = false;
    c.timing = PulseTiming{0, 0, 0, 0};
    c.ctl = ctl_cfg_zero();
    return c;
  }
  // The servo's own input registers (closed_q and the controller's cfg
  // registers; enable and the pulse timing are the core's). The core's
  // registers hold start, abort and pos_frac0.
  struct InputRegs {
    ServoConfig cfg = zero_config();
  };
  // The core's ext_* inputs: the NCO and the controller's current registers.
  CoreExtInputs ext_inputs() const;
  template <bool kSync>
  void step_impl(const ServoInputs& in, const SyncInputs& s);
  AxisCore core_;
  QuadDecoder dec_;
  NeuronPi ctl_;
  StepNco nco_;
  InputRegs in_q_;
  CoreInputs core_in_{};  // reused every clock: no per-clock construction
  ServoConfig last_cfg_in_{};
  bool have_last_cfg_ = false;
};

}  // namespace sc
