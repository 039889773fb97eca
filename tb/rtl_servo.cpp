#include "rtl_servo.h"

#include "Vsc_servo_axis.h"
#include "rtl_neuron_cfg.h"
#include "verilated_top.h"

namespace sc {

RtlServo::RtlServo() : top_(std::make_unique<VerilatedTop<Vsc_servo_axis>>("sc_servo_axis")) {
  drive_guards(top_->top(), guard_);
  drive_soft(top_->top(), soft_);
}

RtlServo::~RtlServo() = default;

void RtlServo::reset(int cycles) { top_->reset(cycles); }

void RtlServo::apply_cfg(const ServoConfig& c) {
  Vsc_servo_axis& m = top_->top();
  m.enable_i = c.enable;
  m.closed_loop_i = c.closed_loop;
  m.cfg_high_i = c.timing.high;
  m.cfg_low_i = c.timing.low;
  m.cfg_setup_i = c.timing.setup;
  m.cfg_hold_i = c.timing.hold;
  bind_neuron_config(m, c.ctl);
}

void RtlServo::step(const ServoInputs& in) {
  Vsc_servo_axis& m = top_->top();
  if (!cfg_set_ || !(in.cfg == cfg_)) [[unlikely]] {
    cfg_ = in.cfg;
    cfg_set_ = true;
    apply_cfg(cfg_);
  }
  m.row_push_i = in.row_push;
  if (in.row_push) drive_row(m, in.row);
  drive_retarget(m, in.row_replace, in.retarget_row);
  m.fifo_flush_i = in.fifo_flush;
  if (in.pos_frac0 != pos_frac0_) {
    pos_frac0_ = in.pos_frac0;
    put_bits(m.pos_frac0_i, 0, FracBits, in.pos_frac0);
  }
  m.start_i = in.start;
  m.abort_i = in.abort;
  drive_stop(m, in.stop, in.stop_jerk, in.stop_acc);
  drive_limits(m, in.lim_fwd, in.lim_rev, in.lim_hard);
  if (!(in.guard == guard_)) {
    guard_ = in.guard;
    drive_guards(m, guard_);
  }
  if (!(in.soft == soft_)) {
    soft_ = in.soft;
    drive_soft(m, soft_);
  }
  m.enc_a_i = in.enc_a;
  m.enc_b_i = in.enc_b;
  m.enc_z_i = in.enc_z;
  top_->tick();
}

ServoOutputs RtlServo::outputs() const {
  const Vsc_servo_axis& m = top_->top();
  ServoOutputs o;
  read_axis_outputs(m, o);
  o.fault_ferr = m.fault_ferr_o;
  o.in_pos = m.in_pos_o;
  o.enc_pos = int32_t(m.enc_pos_o);
  o.enc_illegal = uint16_t(m.enc_illegal_o);
  o.enc_index = m.enc_index_o;
  o.ref_frac_hi = uint32_t(m.ref_frac_hi_o);
  o.ref_vel = int32_t(m.ref_vel_o);
  o.ref_done = m.ref_done_o;
  o.ctl_active = m.ctl_active_o;
  o.ctl_state = m.ctl_state_o;
  o.u = int32_t(m.u_o);
  o.v_cmd = int32_t(m.v_cmd_o);
  o.e_p = int32_t(m.e_p_o);
  o.e_v = int32_t(m.e_v_o);
  o.w_p1 = sign_extend(m.w_p1_o, WgtW);
  o.w_p2 = sign_extend(m.w_p2_o, WgtW);
  o.w_v1 = sign_extend(m.w_v1_o, WgtW);
  o.w_v2 = sign_extend(m.w_v2_o, WgtW);
  o.wn_p1 = sign_extend(m.wn_p1_o, NWgtW);
  o.wn_p2 = sign_extend(m.wn_p2_o, NWgtW);
  o.wn_v1 = sign_extend(m.wn_v1_o, NWgtW);
  o.wn_v2 = sign_extend(m.wn_v2_o, NWgtW);
  o.nco_phase = wrap_signed64(int64_t(m.nco_phase_o), NcoW);
  o.step_pending = int8_t(wrap_signed64(m.step_pending_o, PendW));
  return o;
}

bool RtlServo::trace_supported() const { return VerilatedTop<Vsc_servo_axis>::trace_supported(); }

void RtlServo::trace_open(const std::string& path, uint64_t from_clock, uint64_t to_clock) {
  top_->trace_open(path, from_clock, to_clock);
}

void RtlServo::trace_close() { top_->trace_close(); }

}  // namespace sc
