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
  bool row_push = false;  // append `row` (ignored while the FIFO is full)
  bool row_replace = false;    // with row_push: the row replaces from retarget_row on (retarget)
  uint32_t retarget_row = 0;
  Row row{};
  bool fifo_flush = false;
  u128 pos_frac0 = 0;
  bool start = false;
  bool abort = false;          // immediate stop (e-stop)
  bool stop = false;           // controlled stop; while arming, the start is dropped
  // Controlled-stop limits (JerkW / AccW bits); default: the registers'
  // reset values.
  uint64_t stop_jerk = StopJerkReset;
  uint64_t stop_acc = StopAccReset;
  GuardLimits guard{};  // the executor's row guards (guard_*_i; 0 = none)
  SoftWindow soft{};    // the executor's soft-limit look-ahead (soft_*_i)
  // Limits (lim_fwd_i, lim_rev_i, lim_hard_i): a limit switch is active on
  // the + / - side; motion into it stops (hard: at once), a START toward it
  // is refused.
  bool lim_fwd = false;
  bool lim_rev = false;
  bool lim_hard = false;
};

// The external step source of sc_axis_core #(.ExtStep(1)) (its ext_*
// inputs): sc_servo_axis's NCO and controller. All false = ExtStep 0.
struct CoreExtInputs {
  bool sel = false;  // steps come from req/fwd instead of the executor's carry
  bool req = false;
  bool fwd = false;
  bool hint_valid = false;
  bool hint = false;
  bool busy = false;
  bool abort = false;  // aborts the executor (not the arming)
  bool done = false;   // replaces "executor finished" in done
};

// The start synchronisation inputs of sc_axis_core #(.SyncStart(1)) (its
// sync_* inputs), which sc_multi_axis_core forms from all its axes.
struct SyncInputs {
  bool start_ok = false;  // every axis can accept the START it sees (AND of start_able)
  bool go = false;        // every axis is armed with DIR set up (AND of arm_ready)
  bool drop = false;      // some axis drops its arming (OR of arm_drop)
  bool reach_veto = false;  // some axis refuses its head row (OR of reach_bad): none loads it
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
  bool underrun = false;
  bool discont = false;
  bool guard = false;  // a row broke a guard limit (until START)
  bool reach = false;  // the soft-limit look-ahead refused a row (until START)
  bool stopping = false;
  bool overshoot = false;
  bool move_done = false;
  uint32_t move_idx = 0;
  int32_t boundary_pos = 0;
  uint8_t fifo_level = 0;
  bool fifo_full = false;
  uint32_t row_count = 0;         // rows loaded since START
  bool retarget_refused = false;  // a replace was refused (one clock)
  int32_t pulse_count = 0;
  int32_t ref_pos_int = 0;
  u128 ref_pos_frac = 0;
  i128 ref_vel = 0;
  int64_t ref_acc = 0;
  int64_t ref_jerk = 0;
  uint8_t seg_idx = 0;
  int8_t step_pending = 0;
  bool lim_trip_fwd = false;  // the + limit stops motion or refuses a start
  bool lim_trip_rev = false;
  bool operator==(const CoreOutputs&) const = default;
};

class AxisCore {
 public:
  AxisCore() { reset(); }
  void reset();
  void step(const CoreInputs& in);
  // One clock of sc_axis_core #(.ExtStep(1)); `x` holds the ext_* inputs of
  // this clock (from the external source's registers, before its clock).
  void step(const CoreInputs& in, const CoreExtInputs& x);
  CoreOutputs outputs() const;
  // outputs() into an existing struct: a returned temporary written field by
  // field and then copied whole stalls on store forwarding (hot loops).
  void read_outputs(CoreOutputs& o) const;
  // outputs() == o, without building the struct (the lockstep hot path).
  bool outputs_equal(const CoreOutputs& o) const;
  // One clock of sc_axis_core #(.SyncStart(1)): one axis of a multi-axis
  // core, `s` formed from every axis's state before this clock.
  void step(const CoreInputs& in, const SyncInputs& s);
  // The synchronisation outputs (start_able_o, arm_ready_o, arm_drop_o,
  // fault_abort_o), from the current state.
  bool start_able() const;
  // reach_bad_o: the executor's look-ahead refuses the head row this clock.
  bool reach_bad() const { return exec_.reach_bad(in_q_.pos_frac0, in_q_.soft); }
  bool arm_ready() const;
  bool arm_drop() const;
  bool fault_abort() const;
  // One clock of sc_axis_core #(.ExtStep(1), .SyncStart(1)): one servo axis
  // of a multi-axis core; its start_able_o and fault_abort_o with the
  // external source's inputs `x` (its busy holds a start off, its abort
  // aborts every axis while this executor runs).
  void step(const CoreInputs& in, const CoreExtInputs& x, const SyncInputs& s);
  bool start_able(const CoreExtInputs& x) const;
  bool fault_abort(const CoreExtInputs& x) const { return fault_abort() || (x.abort && exec_.state().run); }
  // One clock holding the inputs of the previous step(), which must not have
  // pushed a row: the same as step(previous inputs), cheaper.
  void tick();

  bool busy() const;
  // fault_overrun_o: the step queue overflowed, or the step-rate guard
  // stopped the executor (both until the next START).
  bool fault_overrun() const { return sg_.state().overrun || rate_; }
  bool done() const { return exec_.state().finished && !busy(); }
  // busy_o, done_o and phase_o with the external source's inputs `x`.
  bool busy(const CoreExtInputs& x) const { return busy() || x.busy; }
  bool done(const CoreExtInputs& x) const { return (x.sel ? x.done : exec_.state().finished) && !busy(x); }
  uint8_t phase(const CoreExtInputs& x) const {
    return done(x) ? uint8_t(Phase::PhDone) : uint8_t(exec_.state().phase);
  }
  // exec_start_o of the clock last stepped with step(in, x): the executor
  // started (after arming).
  bool exec_started() const { return exec_started_; }
  // abort_o: abort as registered by the core, or a hard limit acting.
  bool abort_q() const { return in_q_.abort || (in_q_.lim_hard && (into_limit() & 3) != 0); }
  // en_o.
  bool enable_q() const { return in_q_.enable; }

  // Advance up to n clocks with `in` held (in must have no start, abort or
  // write); jumps in closed form while the step generator is idle and the
  // executor is between steps. Equal to n calls of step(in).
  void fast_forward(const CoreInputs& in, uint64_t n);
  // With `in` held, the clocks until the next one that emits a step, ends a
  // row or needs a per-clock step() (0: step() this clock): fast_forward()
  // over one less is a jump in closed form with no pin edge inside.
  uint64_t clocks_to_next_event(const CoreInputs& in) const;
  // True when holding `in` changes nothing in the input registers.
  bool inputs_settled(const CoreInputs& in) const;

  ProfileExec& exec() { return exec_; }
  StepGen& step_gen() { return sg_; }
  const ProfileExec& exec() const { return exec_; }
  const StepGen& step_gen() const { return sg_; }

 private:
  // The core's input register stage (mirrors en_q, start_q, abort_q, cfg_*_q,
  // pos_frac0_q): the row port and the flush are not registered.
  struct InputRegs {
    bool enable = false;
    bool start = false;
    bool abort = false;
    bool stop = false;
    uint64_t stop_jerk = 0;
    uint64_t stop_acc = 0;
    GuardLimits guard{};
    SoftWindow soft{};
    bool lim_fwd = false, lim_rev = false, lim_hard = false;
    PulseTiming cfg{0, 0, 0, 0};
    u128 pos_frac0 = 0;
  };
  ProfileExec exec_;
  StepGen sg_;
  InputRegs in_q_;
  // Start arming (mirrors arm_q, arm_fwd_q, arm_cnt_q).
  bool arm_ = false;
  bool arm_fwd_ = true;
  uint16_t arm_cnt_ = 0;
  bool exec_started_ = false;
  bool rate_ = false;       // the step-rate guard stopped the executor (rate_q)
  bool rate_trip_ = false;  // it stops it this clock (rate_trip_q)
  // |queued steps| at which the executor is stopped (the clock after):
  // three short of full.
  static constexpr int kPendNearFull = (1 << (PendW - 1)) - 3;
  ProfileExec::Inputs exec_in_{};  // reused every clock: no per-clock construction
  // Motion into an active limit (into_fwd bit 0, into_rev bit 1) and a
  // start refused toward one (bits 2 and 3: + and -), from the current state.
  unsigned into_limit() const;
  unsigned start_into_limit() const;
 public:
  // lim_trip_fwd_o / lim_trip_rev_o with busy_o = busy_now (the external
  // source's busy included).
  bool lim_trip(bool fwd, bool busy_now) const;
 private:
  void latch_write(const CoreInputs& in);
  void latch_inputs(const CoreInputs& in);
  // kExt = false is the plain core (ExtStep = 0): x is not read; kSync =
  // false the core without start synchronisation (SyncStart = 0): s is not read.
  template <bool kExt, bool kSync = false>
  void clock_edge(const CoreExtInputs& x, const SyncInputs& s = SyncInputs{});
};

}  // namespace sc
