#include "servo_axis.h"

namespace sc {

ServoConfig ServoAxis::registered(const ServoConfig& c) {
  ServoConfig r = c;
  r.ctl = ctl_cfg_masked(c.ctl);
  return r;
}

void ServoAxis::reset() {
  core_.reset();
  dec_.reset();
  ctl_.reset();
  nco_.reset();
  in_q_ = InputRegs{};
  core_in_ = CoreInputs{};
  have_last_cfg_ = false;
}

CoreExtInputs ServoAxis::ext_inputs() const {
  const NeuronPi::State& c = ctl_.state();
  const StepNco::State& n = nco_.state();
  CoreExtInputs x;
  x.sel = in_q_.cfg.closed_loop;
  x.req = n.req;
  x.fwd = n.fwd;
  x.hint_valid = c.active && c.u != 0;
  x.hint = c.u >= 0;
  x.busy = c.active || n.req;
  x.abort = c.ferr && !in_q_.cfg.ctl.ferr_stop;
  x.done = c.in_pos && core_.exec().state().finished;  // a stopped stream is not done
  return x;
}

bool ServoAxis::busy() const { return core_.busy(ext_inputs()); }

bool ServoAxis::done() const { return core_.done(ext_inputs()); }

double ServoAxis::ref_position() const {
  const ProfileExec::State& e = core_.exec().state();
  return double(e.pint) + double(e.frac) / kTwoPowFrac - 0.5;
}

void ServoAxis::step(const ServoInputs& in) { step_impl<false>(in, SyncInputs{}); }

void ServoAxis::step(const ServoInputs& in, const SyncInputs& s) { step_impl<true>(in, s); }

template <bool kSync>
void ServoAxis::step_impl(const ServoInputs& in, const SyncInputs& s) {
  const ServoConfig& cq = in_q_.cfg;
  const ProfileExec::State& e = core_.exec().state();
  const NeuronPi::State& c = ctl_.state();
  const StepNco::State& n = nco_.state();
  const bool closed = cq.closed_loop;

  // Inputs of every submodule from the current (registered) state, before
  // any of them clocks.
  const CoreExtInputs x = ext_inputs();
  CoreInputs& ki = core_in_;
  ki.enable = in.cfg.enable;
  ki.cfg = in.cfg.timing;
  ki.row_push = in.row_push;
  ki.row_replace = in.row_replace;
  ki.retarget_row = in.retarget_row;
  if (in.row_push) ki.row = in.row;
  ki.fifo_flush = in.fifo_flush;
  ki.pos_frac0 = in.pos_frac0;
  ki.start = in.start;
  ki.abort = in.abort;
  // A following-error fault with FERR_STOP stops the reference under control
  // while the loop runs.
  ki.stop = in.stop || (c.ferr && cq.ctl.ferr_stop && c.active);
  ki.stop_jerk = in.stop_jerk;
  ki.stop_acc = in.stop_acc;
  ki.guard = in.guard;
  ki.soft = in.soft;
  ki.lim_fwd = in.lim_fwd;
  ki.lim_rev = in.lim_rev;
  ki.lim_hard = in.lim_hard;

  NeuronPi::Inputs ci;
  ci.stop = core_.abort_q();
  ci.ref_int = e.pint;
  ci.ref_frac = uint32_t(e.frac >> (FracBits - CtlFrac));
  ci.ref_vel = int32_t(e.vel >> (VelW - MulAW));
  ci.ref_done = !e.run;  // finished, or at rest after a controlled stop
  ci.enc_pos = dec_.state().count;
  ci.cmd_busy = n.req || core_.step_gen().busy();
  ci.nco_req = n.req;

  // Backpressure: the NCO holds while the step queue is within one step of
  // either end (one request may still be in flight).
  const int pend = core_.step_gen().state().pend;
  const bool queue_near_full = pend >= StepGen::kPendMax - 1 || pend <= StepGen::kPendMin + 1;
  const bool nco_run = c.active && !queue_near_full;
  const int32_t nco_u = c.u;

  // exec_start_o is a function of the core's registers: the controller and
  // the NCO start with the executor, after arming.
  if constexpr (kSync) {
    core_.step(ki, x, s);
  } else {
    core_.step(ki, x);
  }
  const bool exec_start = core_.exec_started();
  ci.start = exec_start && closed;
  nco_.step(cq.ctl.div, cq.ctl.shift, exec_start, nco_run, nco_u);
  ctl_.step(cq.ctl, ci);
  dec_.step(in.enc_a, in.enc_b, in.enc_z, cq.ctl.enc_filt);

  // in_q_.cfg always holds registered(cfg of the previous clock); the
  // compare keeps the per-clock cost low while the configuration is static.
  if (!have_last_cfg_ || !(in.cfg == last_cfg_in_)) [[unlikely]] {
    last_cfg_in_ = in.cfg;
    have_last_cfg_ = true;
    in_q_.cfg = registered(in.cfg);
  }
}

void ServoAxis::read_core_outputs(CoreOutputs& o) const {
  core_.read_outputs(o);
  const CoreExtInputs x = ext_inputs();
  o.busy = core_.busy(x);
  o.done = core_.done(x);
  o.phase = ctl_.state().ferr ? uint8_t(Phase::PhFault) : core_.phase(x);
  o.lim_trip_fwd = core_.lim_trip(true, o.busy);
  o.lim_trip_rev = core_.lim_trip(false, o.busy);
}

void ServoAxis::read_loop_outputs(LoopOutputs& o) const {
  const NeuronPi::State& c = ctl_.state();
  o.fault_ferr = c.ferr;
  o.in_pos = c.in_pos;
  o.enc_pos = dec_.state().count;
  o.enc_illegal = dec_.state().illegal;
  o.enc_index = dec_.index();
  o.ctl_active = c.active;
  o.ctl_state = c.st;
  o.u = c.u;
  o.v_cmd = c.out_p;
  o.e_p = c.lp[0].ep;
  o.e_v = c.lp[1].ep;
  o.w_p1 = c.lp[0].w1;
  o.w_p2 = c.lp[0].w2;
  o.w_v1 = c.lp[1].w1;
  o.w_v2 = c.lp[1].w2;
  o.nco_phase = nco_.state().acc;
}

ServoOutputs ServoAxis::outputs() const {
  const ProfileExec::State& e = core_.exec().state();
  const StepGen::State& s = core_.step_gen().state();
  const NeuronPi::State& c = ctl_.state();
  const CoreExtInputs x = ext_inputs();
  ServoOutputs o;
  o.step = s.step;
  o.dir = s.dir;
  o.en = core_.enable_q();
  o.busy = core_.busy(x);
  o.done = core_.done(x);
  o.phase = c.ferr ? uint8_t(Phase::PhFault) : core_.phase(x);
  o.fault_table = e.fault;
  o.fault_overrun = core_.fault_overrun();
  o.fault_ferr = c.ferr;
  o.in_pos = c.in_pos;
  o.underrun = e.underrun;
  o.discont = e.discont;
  o.guard = e.guard;
  o.reach = e.reach;
  o.stopping = e.stop;
  o.overshoot = core_.exec().overshoot();
  o.lim_trip_fwd = core_.lim_trip(true, o.busy);
  o.lim_trip_rev = core_.lim_trip(false, o.busy);
  o.move_done = e.move_done;
  o.move_idx = e.move_idx;
  o.boundary_pos = e.bpos;
  o.fifo_level = uint8_t(core_.exec().fifo_level());
  o.fifo_full = core_.exec().fifo_full();
  o.row_count = e.rows;
  o.retarget_refused = e.refused;
  o.pulse_count = s.count;
  o.enc_pos = dec_.state().count;
  o.enc_illegal = dec_.state().illegal;
  o.enc_index = dec_.index();
  o.ref_pos_int = e.pint;
  o.ref_frac_hi = uint32_t(e.frac >> (FracBits - MulAW));
  o.ref_vel = int32_t(e.vel >> (VelW - MulAW));
  o.ref_done = e.finished;
  o.ctl_active = c.active;
  o.ctl_state = c.st;
  o.u = c.u;
  o.v_cmd = c.out_p;
  o.e_p = c.lp[0].ep;
  o.e_v = c.lp[1].ep;
  o.w_p1 = c.lp[0].w1;
  o.w_p2 = c.lp[0].w2;
  o.w_v1 = c.lp[1].w1;
  o.w_v2 = c.lp[1].w2;
  o.wn_p1 = c.lp[0].n1;
  o.wn_p2 = c.lp[0].n2;
  o.wn_v1 = c.lp[1].n1;
  o.wn_v2 = c.lp[1].n2;
  o.nco_phase = nco_.state().acc;
  o.step_pending = s.pend;
  return o;
}

}  // namespace sc
