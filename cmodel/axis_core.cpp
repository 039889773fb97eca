#include "axis_core.h"

#include <algorithm>

namespace sc {

void AxisCore::reset() {
  exec_.reset();
  sg_.reset();
  in_q_ = InputRegs{};
  arm_ = false;
  arm_fwd_ = true;
  arm_cnt_ = 0;
  exec_started_ = false;
  rate_ = false;
  rate_trip_ = false;
}

bool AxisCore::busy() const {
  return exec_.state().run || exec_.state().step_req || sg_.busy() || arm_;
}

namespace {
const CoreExtInputs kNoExt{};
}  // namespace

void AxisCore::step(const CoreInputs& in) {
  latch_write(in);
  clock_edge<false>(kNoExt);
  exec_in_.row_push = false;
  exec_in_.row_replace = false;
  exec_in_.fifo_flush = false;
  latch_inputs(in);
}

void AxisCore::step(const CoreInputs& in, const CoreExtInputs& x) {
  latch_write(in);
  clock_edge<true>(x);
  exec_in_.row_push = false;
  exec_in_.row_replace = false;
  exec_in_.fifo_flush = false;
  latch_inputs(in);
}

void AxisCore::step(const CoreInputs& in, const SyncInputs& s) {
  latch_write(in);
  clock_edge<false, true>(kNoExt, s);
  exec_in_.row_push = false;
  exec_in_.row_replace = false;
  exec_in_.fifo_flush = false;
  latch_inputs(in);
}

void AxisCore::step(const CoreInputs& in, const CoreExtInputs& x, const SyncInputs& s) {
  latch_write(in);
  clock_edge<true, true>(x, s);
  exec_in_.row_push = false;
  exec_in_.row_replace = false;
  exec_in_.fifo_flush = false;
  latch_inputs(in);
}

bool AxisCore::start_able() const {
  return in_q_.start && !busy() && in_q_.enable && start_into_limit() == 0;
}

bool AxisCore::start_able(const CoreExtInputs& x) const {
  return in_q_.start && !busy(x) && in_q_.enable && start_into_limit() == 0;
}

bool AxisCore::arm_drop() const { return arm_ && (in_q_.abort || in_q_.stop || into_limit() != 0); }

bool AxisCore::arm_ready() const {
  return arm_ && !arm_drop() && sg_.state().dir == arm_fwd_ && arm_cnt_ >= in_q_.cfg.setup &&
         exec_.start_ready(in_q_.soft.en);
}

bool AxisCore::fault_abort() const { return (in_q_.lim_hard && into_limit() != 0) || rate_trip_; }

void AxisCore::latch_write(const CoreInputs& in) {
  ProfileExec::Inputs& ei = exec_in_;
  ei.row_push = in.row_push;
  ei.row_replace = in.row_replace;
  ei.retarget_row = in.retarget_row;
  ei.fifo_flush = in.fifo_flush;
  if (in.row_push) ei.row = in.row;
}

void AxisCore::latch_inputs(const CoreInputs& in) {
  in_q_.enable = in.enable;
  in_q_.start = in.start;
  in_q_.abort = in.abort;
  in_q_.stop = in.stop;
  in_q_.lim_fwd = in.lim_fwd;
  in_q_.lim_rev = in.lim_rev;
  in_q_.lim_hard = in.lim_hard;
  in_q_.stop_jerk = in.stop_jerk & ((uint64_t(1) << JerkW) - 1);
  in_q_.stop_acc = in.stop_acc;
  in_q_.guard = in.guard.masked();
  in_q_.soft = in.soft;
  in_q_.cfg = in.cfg;
  in_q_.pos_frac0 = mask_bits(in.pos_frac0, FracBits);
}

unsigned AxisCore::into_limit() const {
  const ProfileExec::State& e = exec_.state();
  const bool ref_moving = e.run && e.vel != 0;
  const bool into_fwd = in_q_.lim_fwd && (arm_ ? arm_fwd_ : (ref_moving && e.vel > 0));
  const bool into_rev = in_q_.lim_rev && (arm_ ? !arm_fwd_ : (ref_moving && e.vel < 0));
  return unsigned(into_fwd) | (unsigned(into_rev) << 1);
}

unsigned AxisCore::start_into_limit() const {
  if (exec_.fifo_level() == 0) return 0;  // an empty FIFO is the table fault
  const bool fwd = exec_.head_forward();
  return fwd ? (in_q_.lim_fwd ? 4u : 0u) : (in_q_.lim_rev ? 8u : 0u);
}

template <bool kExt, bool kSync>
void AxisCore::clock_edge(const CoreExtInputs& x, const SyncInputs& s) {
  // Every sub-block input below is a register output (the core's input
  // stage, the arming state, the executor's step request or, with kExt,
  // the external source's registers), as in the RTL.
  const ProfileExec::State& e = exec_.state();
  const bool start_req = in_q_.start && !(kExt ? busy(x) : busy()) && in_q_.enable;
  const bool start_ok = start_req && start_into_limit() == 0 && (!kSync || s.start_ok);
  const bool lim_act = into_limit() != 0;
  bool arm_d = arm_, arm_fwd_d = arm_fwd_, exec_start = false;
  uint16_t arm_cnt_d = arm_cnt_;
  if (start_ok) {
    arm_d = true;
    arm_fwd_d = exec_.head_forward();
    arm_cnt_d = 0;
  } else if (arm_) {
    if (in_q_.abort || in_q_.stop || lim_act || (kSync && s.drop)) {
      arm_d = false;
    } else if (sg_.state().dir != arm_fwd_) {
      arm_cnt_d = 0;
    } else if (arm_cnt_ >= in_q_.cfg.setup) {
      // set up (and the head row's reach known): start now, or (kSync)
      // hold until every axis is
      if (exec_.start_ready(in_q_.soft.en) && (!kSync || s.go)) {
        arm_d = false;
        exec_start = true;
      }
    } else {
      arm_cnt_d = uint16_t(arm_cnt_ + 1);
    }
  }
  const bool use_ext = kExt && x.sel;
  // Step-rate guard: three steps short of a full queue, the executor stops
  // the clock after.
  const int pend = sg_.state().pend;
  const bool rate_trip_d = !use_ext && e.run && (pend >= kPendNearFull || pend <= -kPendNearFull);
  StepGen::Inputs si;
  si.cfg = in_q_.cfg;
  si.clear = start_ok;
  si.step_req = use_ext ? x.req : e.step_req;
  si.step_fwd = use_ext ? x.fwd : e.step_fwd;
  const bool ref_moving = e.run && e.vel != 0;
  si.dir_hint_valid = arm_ || ref_moving || (use_ext && x.hint_valid);
  si.dir_hint = arm_ ? arm_fwd_ : (!kExt || ref_moving) ? e.vel >= 0 : x.hint;
  ProfileExec::Inputs& ei = exec_in_;
  ei.pos_frac0 = in_q_.pos_frac0;
  ei.start = exec_start;
  ei.abort = in_q_.abort || (lim_act && in_q_.lim_hard) || rate_trip_ || (kExt && x.abort);
  ei.stop = in_q_.stop || (lim_act && !in_q_.lim_hard);
  ei.stop_jerk = in_q_.stop_jerk;
  ei.stop_acc = in_q_.stop_acc;
  ei.guard = in_q_.guard;
  ei.soft = in_q_.soft;
  ei.reach_veto = kSync && s.reach_veto;
  sg_.step(si);  // uses the executor's current (registered) outputs
  exec_.step(ei);
  if constexpr (kExt) exec_started_ = exec_start;
  rate_ = !start_ok && (rate_ || rate_trip_);
  rate_trip_ = rate_trip_d;
  arm_ = arm_d;
  arm_fwd_ = arm_fwd_d;
  arm_cnt_ = arm_cnt_d;
}

bool AxisCore::inputs_settled(const CoreInputs& in) const {
  // An active limit is never jumped over: it acts on the clock motion turns into it.
  return !in.start && !in.abort && !in.stop && !in.row_push && !in.fifo_flush && !in_q_.start && !in_q_.abort &&
         !in_q_.stop && !in.lim_fwd && !in.lim_rev && !in_q_.lim_fwd && !in_q_.lim_rev &&
         in_q_.lim_hard == in.lim_hard && in_q_.enable == in.enable && in_q_.cfg == in.cfg &&
         in_q_.stop_jerk == (in.stop_jerk & ((uint64_t(1) << JerkW) - 1)) && in_q_.stop_acc == in.stop_acc &&
         in_q_.guard == in.guard.masked() && in_q_.soft == in.soft &&
         in_q_.pos_frac0 == mask_bits(in.pos_frac0, FracBits);
}
CoreOutputs AxisCore::outputs() const {
  CoreOutputs o;
  read_outputs(o);
  return o;
}

void AxisCore::read_outputs(CoreOutputs& o) const {
  const ProfileExec::State& e = exec_.state();
  const StepGen::State& s = sg_.state();
  o.step = s.step;
  o.dir = s.dir;
  o.en = in_q_.enable;
  o.busy = busy();
  o.done = done();
  o.phase = o.done ? uint8_t(Phase::PhDone) : uint8_t(e.phase);
  o.fault_table = e.fault;
  o.fault_overrun = fault_overrun();
  o.underrun = e.underrun;
  o.discont = e.discont;
  o.guard = e.guard;
  o.reach = e.reach;
  o.stopping = e.stop;
  o.overshoot = exec_.overshoot();
  o.move_done = e.move_done;
  o.move_idx = e.move_idx;
  o.boundary_pos = e.bpos;
  o.fifo_level = uint8_t(exec_.fifo_level());
  o.fifo_full = exec_.fifo_full();
  o.row_count = e.rows;
  o.retarget_refused = e.refused;
  o.pulse_count = s.count;
  o.ref_pos_int = e.pint;
  o.ref_pos_frac = e.frac;
  o.ref_vel = e.vel;
  o.ref_acc = e.acc;
  o.ref_jerk = exec_.jerk();
  o.seg_idx = e.idx;
  o.step_pending = s.pend;
  o.lim_trip_fwd = lim_trip(true, o.busy);
  o.lim_trip_rev = lim_trip(false, o.busy);
}

void AxisCore::tick() { clock_edge<false>(kNoExt); }

bool AxisCore::outputs_equal(const CoreOutputs& o) const {
  const ProfileExec::State& e = exec_.state();
  const StepGen::State& s = sg_.state();
  const bool is_done = done();
  return o.step == s.step && o.dir == s.dir && o.pulse_count == s.count && o.ref_pos_int == e.pint &&
         o.ref_pos_frac == e.frac && o.ref_vel == e.vel && o.ref_acc == e.acc && o.ref_jerk == exec_.jerk() &&
         o.done == is_done && o.busy == busy() && o.en == in_q_.enable &&
         o.phase == (is_done ? uint8_t(Phase::PhDone) : uint8_t(e.phase)) && o.fault_table == e.fault &&
         o.fault_overrun == fault_overrun() && o.seg_idx == e.idx && o.step_pending == s.pend &&
         o.underrun == e.underrun && o.discont == e.discont && o.guard == e.guard && o.reach == e.reach &&
         o.stopping == e.stop &&
         o.overshoot == exec_.overshoot() && o.move_done == e.move_done &&
         o.move_idx == e.move_idx && o.boundary_pos == e.bpos && o.fifo_level == exec_.fifo_level() &&
         o.fifo_full == exec_.fifo_full() && o.row_count == e.rows && o.retarget_refused == e.refused &&
         o.lim_trip_fwd == lim_trip(true, busy()) &&
         o.lim_trip_rev == lim_trip(false, busy());
}

bool AxisCore::lim_trip(bool fwd, bool busy_now) const {
  if (!(fwd ? in_q_.lim_fwd : in_q_.lim_rev)) return false;
  const bool start_req = in_q_.start && in_q_.enable && !busy_now;
  return (into_limit() & (fwd ? 1u : 2u)) != 0 || (start_req && (start_into_limit() & (fwd ? 4u : 8u)) != 0);
}

uint64_t AxisCore::clocks_to_next_event(const CoreInputs& in) const {
  const ProfileExec::State& e = exec_.state();
  const bool dir_settled = !(e.run && e.vel != 0) || (e.vel >= 0) == sg_.state().dir;
  if (!sg_.idle() || !dir_settled || e.step_req || arm_ || rate_trip_ || !inputs_settled(in) ||
      !exec_.reach_idle()) {
    return 0;
  }
  const uint64_t ev = exec_.clocks_to_next_event();
  return ev == 0 && !e.run ? UINT64_MAX : ev;  // idle: only counters move
}

void AxisCore::fast_forward(const CoreInputs& in, uint64_t n) {
  while (n > 0) {
    const uint64_t ev = clocks_to_next_event(in);
    if (ev > 1) {
      const uint64_t k = std::min<uint64_t>(ev - 1, n);
      if (exec_.state().run) {
        exec_.advance(k);
      } else {
        exec_.idle_clocks();
      }
      sg_.jump_idle(k);
      n -= k;
      if (n == 0) break;
    }
    step(in);
    --n;
  }
}

}  // namespace sc
