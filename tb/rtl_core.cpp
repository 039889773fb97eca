#include "rtl_core.h"

#include "Vsc_axis_core.h"
#include "verilated_top.h"

namespace sc {

RtlCore::RtlCore() : top_(std::make_unique<VerilatedTop<Vsc_axis_core>>("sc_axis_core")) {
  Vsc_axis_core& m = top_->top();
  // Drive every input once so last_ mirrors the ports.
  m.enable_i = last_.enable;
  m.cfg_high_i = last_.cfg.high;
  m.cfg_low_i = last_.cfg.low;
  m.cfg_setup_i = last_.cfg.setup;
  m.cfg_hold_i = last_.cfg.hold;
  m.row_push_i = 0;
  drive_retarget(m, last_.row_replace, last_.retarget_row);
  m.fifo_flush_i = 0;
  put_bits(m.pos_frac0_i, 0, FracBits, 0);
  m.start_i = 0;
  m.abort_i = 0;
  drive_stop(m, last_.stop, last_.stop_jerk, last_.stop_acc);
  drive_limits(m, last_.lim_fwd, last_.lim_rev, last_.lim_hard);
  drive_guards(m, last_.guard);
  drive_soft(m, last_.soft);
  // No external step source on the plain core (ExtStep = 0).
  m.ext_sel_i = 0;
  m.ext_req_i = 0;
  m.ext_fwd_i = 0;
  m.ext_hint_valid_i = 0;
  m.ext_hint_i = 0;
  m.ext_busy_i = 0;
  m.ext_abort_i = 0;
  m.ext_done_i = 0;
  // One axis: no start synchronisation (SyncStart = 0 ignores these).
  m.sync_start_ok_i = 0;
  m.sync_go_i = 0;
  m.sync_drop_i = 0;
  m.eval();
}

RtlCore::~RtlCore() = default;

void RtlCore::reset(int cycles) { top_->reset(cycles); }

void RtlCore::tick() { top_->tick(); }

void RtlCore::step(const CoreInputs& in) {
  Vsc_axis_core& m = top_->top();
  // Inputs are written only when they change (cheaper, and no store right
  // before eval() to bytes the model then loads with a wider access).
  if (in.enable != last_.enable) m.enable_i = in.enable;
  if (!(in.cfg == last_.cfg)) {
    m.cfg_high_i = in.cfg.high;
    m.cfg_low_i = in.cfg.low;
    m.cfg_setup_i = in.cfg.setup;
    m.cfg_hold_i = in.cfg.hold;
  }
  if (in.row_push != last_.row_push) m.row_push_i = in.row_push;
  if (in.row_push) drive_row(m, in.row);
  if (in.row_replace != last_.row_replace || in.retarget_row != last_.retarget_row) {
    drive_retarget(m, in.row_replace, in.retarget_row);
  }
  if (in.fifo_flush != last_.fifo_flush) m.fifo_flush_i = in.fifo_flush;
  if (in.pos_frac0 != last_.pos_frac0) put_bits(m.pos_frac0_i, 0, FracBits, in.pos_frac0);
  if (in.start != last_.start) m.start_i = in.start;
  if (in.abort != last_.abort) m.abort_i = in.abort;
  if (in.stop != last_.stop || in.stop_jerk != last_.stop_jerk || in.stop_acc != last_.stop_acc) {
    drive_stop(m, in.stop, in.stop_jerk, in.stop_acc);
  }
  if (!(in.guard == last_.guard)) drive_guards(m, in.guard);
  if (!(in.soft == last_.soft)) drive_soft(m, in.soft);
  if (in.lim_fwd != last_.lim_fwd || in.lim_rev != last_.lim_rev || in.lim_hard != last_.lim_hard) {
    drive_limits(m, in.lim_fwd, in.lim_rev, in.lim_hard);
  }
  last_.enable = in.enable;
  last_.cfg = in.cfg;
  last_.row_push = in.row_push;
  last_.row_replace = in.row_replace;
  last_.retarget_row = in.retarget_row;
  last_.fifo_flush = in.fifo_flush;
  last_.pos_frac0 = in.pos_frac0;
  last_.start = in.start;
  last_.abort = in.abort;
  last_.stop = in.stop;
  last_.stop_jerk = in.stop_jerk;
  last_.stop_acc = in.stop_acc;
  last_.guard = in.guard;
  last_.soft = in.soft;
  last_.lim_fwd = in.lim_fwd;
  last_.lim_rev = in.lim_rev;
  last_.lim_hard = in.lim_hard;
  tick();
}

CoreOutputs RtlCore::outputs() const {
  CoreOutputs o;
  read_outputs(o);
  return o;
}

void RtlCore::read_outputs(CoreOutputs& o) const {
  const Vsc_axis_core& m = top_->top();
  static_assert(FracBits > 64 && FracBits <= 96 && VelW > 64 && VelW <= 96, "3-word wide ports");
  read_axis_outputs(m, o);
  const auto& f = m.ref_pos_frac_o;
  o.ref_pos_frac = (u128(f[2]) << 64) | (uint64_t(f[1]) << 32) | f[0];
  const auto& v = m.ref_vel_o;
  // Sign-extend bit VelW-1 of the top word (bits 64..VelW-1).
  const int64_t v_hi = int64_t(uint64_t(v[2]) << (128 - VelW)) >> (128 - VelW);
  o.ref_vel = i128((u128(uint64_t(v_hi)) << 64) | (uint64_t(v[1]) << 32) | v[0]);
  o.ref_acc = int64_t(m.ref_acc_o);
  static_assert(AccW == 64, "ref_acc_o needs no sign extension");
  o.ref_jerk = int64_t(uint64_t(m.ref_jerk_o) << (64 - JerkW)) >> (64 - JerkW);
  o.seg_idx = m.seg_idx_o;
  o.step_pending = int8_t(uint8_t(m.step_pending_o << (8 - PendW))) >> (8 - PendW);
}

bool RtlCore::trace_supported() const { return VerilatedTop<Vsc_axis_core>::trace_supported(); }

void RtlCore::trace_open(const std::string& path, uint64_t from_clock, uint64_t to_clock) {
  top_->trace_open(path, from_clock, to_clock);
}

void RtlCore::trace_close() { top_->trace_close(); }

}  // namespace sc
