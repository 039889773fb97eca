#include "multi_axis_core.h"

#include <stdexcept>
#include <string>

namespace sc {

MultiAxisCore::MultiAxisCore(size_t axes) {
  if (axes < 1 || axes > size_t(MaxAxes)) {
    throw std::invalid_argument("axes=" + std::to_string(axes) + ": must be 1 .. " + std::to_string(MaxAxes));
  }
  axes_.resize(axes);
}

void MultiAxisCore::reset() {
  for (AxisCore& a : axes_) a.reset();
}

void MultiAxisCore::step(const MultiCoreInputs& in) {
  // The sync and broadcast signals come from every axis's registers before
  // this clock (sc_multi_axis_core's AND / OR across axes).
  SyncInputs s{true, true, false};
  bool stopping_any = false, fault_any = false;
  for (const AxisCore& a : axes_) {
    s.start_ok = s.start_ok && a.start_able();
    s.go = s.go && a.arm_ready();
    s.drop = s.drop || a.arm_drop();
    stopping_any = stopping_any || a.exec().state().stop;
    fault_any = fault_any || a.fault_abort();
  }
  for (size_t i = 0; i < axes_.size(); ++i) {
    scratch_ = in.axis[i];
    scratch_.enable = in.enable;
    scratch_.row_push = in.row_push;
    scratch_.row_replace = in.row_replace;
    scratch_.retarget_row = in.retarget_row;
    scratch_.row.seg.clocks = in.row_clocks;
    scratch_.fifo_flush = in.fifo_flush;
    scratch_.start = in.start;
    scratch_.abort = in.abort || fault_any;
    scratch_.stop = in.stop || stopping_any;
    axes_[i].step(scratch_, s);
  }
}

MultiCoreOutputs MultiAxisCore::outputs() const {
  MultiCoreOutputs o;
  read_outputs(o);
  return o;
}

void MultiAxisCore::read_outputs(MultiCoreOutputs& o) const {
  o.axes = axes_.size();
  for (size_t a = 0; a < axes_.size(); ++a) axes_[a].read_outputs(o.axis[a]);
}

bool MultiAxisCore::outputs_equal(const MultiCoreOutputs& o) const {
  if (o.axes != axes_.size()) return false;
  for (size_t a = 0; a < axes_.size(); ++a) {
    if (!axes_[a].outputs_equal(o.axis[a])) return false;
  }
  return true;
}

}  // namespace sc
