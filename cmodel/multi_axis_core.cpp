#include "multi_axis_core.h"

#include <stdexcept>
#include <string>

namespace sc {

MultiAxisCore::MultiAxisCore(size_t axes, bool servo) : axes_(axes) {
  if (axes < 1 || axes > size_t(MaxAxes)) {
    throw std::invalid_argument("axes=" + std::to_string(axes) + ": must be 1 .. " + std::to_string(MaxAxes));
  }
  if (servo) {
    servos_.resize(axes);
  } else {
    cores_.resize(axes);
  }
  for (size_t a = 0; a < axes; ++a) exec_of(a).share_reach();
  reset();
}

void MultiAxisCore::reset() {
  for (AxisCore& a : cores_) a.reset();
  for (ServoAxis& a : servos_) a.reset();
  reach_.reset();
  reach_owner_ = axes_ - 1;  // axis 0 first
}

void MultiAxisCore::step(const MultiCoreInputs& in) {
  reach_ports();
  if (servos_.empty()) {
    step_open(in);
  } else {
    step_servo(in);
  }
  step_reach();
}

void MultiAxisCore::reach_ports() {
  for (size_t a = 0; a < axes_; ++a) {
    ProfileExec::ReachPort& p = exec_of(a).reach_port();
    p.busy = reach_.busy();
    p.done = reach_.done() && a == reach_owner_;
    p.fwd = reach_.reach_fwd();
    p.rev = reach_.reach_rev();
  }
}

// sc_multi_axis_core's arbiter: while idle, the first requesting axis after
// the last one served starts; while busy, only that axis's abort reaches it.
void MultiAxisCore::step_reach() {
  RowReach::Inputs ri{};
  if (reach_.busy()) {
    ri.abort = exec_of(reach_owner_).reach_request().abort;
  } else {
    for (size_t i = 1; i <= axes_; ++i) {
      const size_t c = (reach_owner_ + i) % axes_;
      if (exec_of(c).reach_request().start) {
        ri = exec_of(c).reach_request();
        ri.abort = false;
        reach_owner_ = c;
        break;
      }
    }
  }
  reach_.step(ri);
}

namespace {

// The shared ports of sc_multi_axis_core onto one axis's inputs, with the
// stop and abort every axis broadcasts.
void apply_shared(const MultiCoreInputs& in, bool stopping_any, bool fault_any, CoreInputs& c) {
  c.enable = in.enable;
  c.row_push = in.row_push;
  c.row_replace = in.row_replace;
  c.retarget_row = in.retarget_row;
  c.row.seg.clocks = in.row_clocks;
  c.fifo_flush = in.fifo_flush;
  c.start = in.start;
  c.abort = in.abort || fault_any;
  c.stop = in.stop || stopping_any;
}

// The sync and broadcast signals from every axis's registers before this
// clock (sc_multi_axis_core's AND / OR across axes).
struct Broadcast {
  SyncInputs sync{true, true, false, false};
  bool stopping_any = false, fault_any = false;
};

template <class Axis>
Broadcast broadcast(const std::vector<Axis>& axes) {
  Broadcast b;
  for (const Axis& a : axes) {
    b.sync.start_ok = b.sync.start_ok && a.start_able();
    b.sync.go = b.sync.go && a.arm_ready();
    b.sync.drop = b.sync.drop || a.arm_drop();
    b.sync.reach_veto = b.sync.reach_veto || a.reach_bad();
    b.stopping_any = b.stopping_any || a.exec().state().stop;
    b.fault_any = b.fault_any || a.fault_abort();
  }
  return b;
}

}  // namespace

void MultiAxisCore::step_open(const MultiCoreInputs& in) {
  const Broadcast b = broadcast(cores_);
  for (size_t i = 0; i < axes_; ++i) {
    scratch_ = in.axis[i];
    apply_shared(in, b.stopping_any, b.fault_any, scratch_);
    cores_[i].step(scratch_, b.sync);
  }
}

void MultiAxisCore::step_servo(const MultiCoreInputs& in) {
  const Broadcast b = broadcast(servos_);
  for (size_t i = 0; i < axes_; ++i) {
    scratch_ = in.axis[i];
    apply_shared(in, b.stopping_any, b.fault_any, scratch_);
    const CoreInputs& c = scratch_;
    const LoopInputs& l = in.loop[i];
    ServoInputs& si = servo_scratch_;
    si.cfg.enable = c.enable;
    si.cfg.closed_loop = l.closed_loop;
    si.cfg.timing = c.cfg;
    si.cfg.ctl = l.ctl;
    si.row_push = c.row_push;
    si.row_replace = c.row_replace;
    si.retarget_row = c.retarget_row;
    if (c.row_push) si.row = c.row;
    si.fifo_flush = c.fifo_flush;
    si.pos_frac0 = c.pos_frac0;
    si.start = c.start;
    si.abort = c.abort;
    si.stop = c.stop;
    si.stop_jerk = c.stop_jerk;
    si.stop_acc = c.stop_acc;
    si.guard = c.guard;
    si.soft = c.soft;
    si.lim_fwd = c.lim_fwd;
    si.lim_rev = c.lim_rev;
    si.lim_hard = c.lim_hard;
    si.enc_a = l.enc_a;
    si.enc_b = l.enc_b;
    si.enc_z = l.enc_z;
    servos_[i].step(si, b.sync);
  }
}

MultiCoreOutputs MultiAxisCore::outputs() const {
  MultiCoreOutputs o;
  read_outputs(o);
  return o;
}

void MultiAxisCore::read_outputs(MultiCoreOutputs& o) const {
  o.axes = axes_;
  o.servo = servo();
  for (size_t a = 0; a < axes_; ++a) {
    if (servos_.empty()) {
      cores_[a].read_outputs(o.axis[a]);
    } else {
      servos_[a].read_core_outputs(o.axis[a]);
      servos_[a].read_loop_outputs(o.loop[a]);
    }
  }
}

bool MultiAxisCore::outputs_equal(const MultiCoreOutputs& o) const {
  if (o.axes != axes_ || o.servo != servo()) return false;
  if (servos_.empty()) {
    for (size_t a = 0; a < axes_; ++a) {
      if (!cores_[a].outputs_equal(o.axis[a])) return false;
    }
    return true;
  }
  return outputs() == o;
}

}  // namespace sc
