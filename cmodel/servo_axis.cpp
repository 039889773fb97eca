#include "servo_axis.h"

namespace sc {

ServoConfig ServoAxis::registered(const ServoConfig& c) {
  ServoConfig r = c;
  r.ctl = ctl_cfg_masked(c.ctl);
  return r;
}

void ServoAxis::reset() {
  exec_.reset();
  dec_.reset();
  ctl_.reset();
  nco_.reset();
  sg_.reset();
  in_q_ = InputRegs{};
  have_last_cfg_ = false;
}

bool ServoAxis::busy() const {
  return exec_.state().run || exec_.state().step_req || sg_.busy() || ctl_.state().active || nco_.state().req;
}

bool ServoAxis::done() const {
  const bool b = busy();
  return in_q_.cfg.closed_loop ? (ctl_.state().in_pos && !b) : (exec_.state().finished && !b);
}

double ServoAxis::ref_position() const {
  const ProfileExec::State& e = exec_.state();
  return double(e.pint) + double(e.frac) / kTwoPowFrac - 0.5;
}

void ServoAxis::step(const ServoInputs& in) {
  const ServoConfig& cq = in_q_.cfg;
  const ProfileExec::State& e = exec_.state();
  const NeuronPi::State& c = ctl_.state();
  const StepNco::State& n = nco_.state();
  const bool closed = cq.closed_loop;
  const bool start_ok = in_q_.start && !busy() && cq.enable;

  // Inputs of every submodule from the current (registered) state.
  ProfileExec::Inputs ei;
  ei.seg_we = in.seg_we;
  ei.seg_waddr = in.seg_waddr;
  ei.seg_wdata = in.seg_wdata;
  ei.seg_count = in_q_.seg_count;
  ei.pos_frac0 = in_q_.pos_frac0;
  ei.start = start_ok;
  ei.abort = in_q_.abort || c.ferr;

  NeuronPi::Inputs ci;
  ci.start = start_ok && closed;
  ci.stop = in_q_.abort;
  ci.ref_int = e.pint;
  ci.ref_frac = uint32_t(e.frac >> (FracBits - CtlFrac));
  ci.ref_vel = int32_t(e.vel >> (VelW - MulAW));
  ci.ref_done = e.finished;
  ci.enc_pos = dec_.state().count;
  ci.cmd_busy = n.req || sg_.busy();
  ci.nco_req = n.req;

  StepGen::Inputs si;
  si.cfg = cq.timing;
  si.clear = start_ok;
  si.step_req = closed ? n.req : e.step_req;
  si.step_fwd = closed ? n.fwd : e.step_fwd;
  si.dir_hint_valid = closed ? (c.active && c.u != 0) : (e.run && e.vel != 0);
  si.dir_hint = closed ? c.u >= 0 : e.vel >= 0;

  const bool nco_run = c.active;
  const int32_t nco_u = c.u;

  sg_.step(si);
  nco_.step(cq.ctl.div, cq.ctl.shift, start_ok, nco_run, nco_u);
  ctl_.step(cq.ctl, ci);
  dec_.step(in.enc_a, in.enc_b, cq.ctl.enc_filt);
  exec_.step(ei);

  in_q_.start = in.start;
  in_q_.abort = in.abort;
  in_q_.seg_count = uint8_t(in.seg_count & ((1u << SegCntW) - 1));
  in_q_.pos_frac0 = mask_bits(in.pos_frac0, FracBits);
  // in_q_.cfg always holds registered(cfg of the previous clock); the
  // compare keeps the per-clock cost low while the configuration is static.
  if (!have_last_cfg_ || !(in.cfg == last_cfg_in_)) [[unlikely]] {
    last_cfg_in_ = in.cfg;
    have_last_cfg_ = true;
    in_q_.cfg = registered(in.cfg);
  }
}

ServoOutputs ServoAxis::outputs() const {
  const ProfileExec::State& e = exec_.state();
  const StepGen::State& s = sg_.state();
  const NeuronPi::State& c = ctl_.state();
  ServoOutputs o;
  o.step = s.step;
  o.dir = s.dir;
  o.en = in_q_.cfg.enable;
  o.busy = busy();
  o.done = done();
  o.phase = c.ferr ? uint8_t(Phase::PhFault) : o.done ? uint8_t(Phase::PhDone) : uint8_t(e.phase);
  o.fault_table = e.fault;
  o.fault_overrun = s.overrun;
  o.fault_ferr = c.ferr;
  o.in_pos = c.in_pos;
  o.pulse_count = s.count;
  o.enc_pos = dec_.state().count;
  o.enc_illegal = dec_.state().illegal;
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
