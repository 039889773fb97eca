// Bit-exact model of rtl/sc_multi_axis_core.sv: Axes open-loop axes
// (AxisCore, each as sc_axis_core #(.SyncStart(1))) executing one shared row
// sequence: one row push into every axis, one start, one stop.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "axis_core.h"

namespace sc {

// Inputs of sc_multi_axis_core for one clock. The shared ports are the
// fields here; `axis[a]` holds axis a's own ports (cfg, row jerk/acc0/vel0/
// phase/flags, pos_frac0, stop limits, guards, limits). The shared fields of
// axis[a] (enable, row_push, row_replace, retarget_row, fifo_flush, start,
// abort, stop, the row's clocks) are not read.
struct MultiCoreInputs {
  bool enable = false;
  bool row_push = false;
  bool row_replace = false;
  uint32_t retarget_row = 0;
  uint32_t row_clocks = 0;
  bool fifo_flush = false;
  bool start = false;
  bool abort = false;
  bool stop = false;
  std::array<CoreInputs, MaxAxes> axis{};
};

// Every output, per axis (axis[a] for a < axes).
struct MultiCoreOutputs {
  size_t axes = 0;
  std::array<CoreOutputs, MaxAxes> axis{};
  bool operator==(const MultiCoreOutputs& o) const {
    if (axes != o.axes) return false;
    for (size_t a = 0; a < axes; ++a) {
      if (!(axis[a] == o.axis[a])) return false;
    }
    return true;
  }
};

class MultiAxisCore {
 public:
  // 1 .. MaxAxes axes (throws std::invalid_argument naming `axes` otherwise).
  explicit MultiAxisCore(size_t axes);
  void reset();
  void step(const MultiCoreInputs& in);
  MultiCoreOutputs outputs() const;
  void read_outputs(MultiCoreOutputs& o) const;
  bool outputs_equal(const MultiCoreOutputs& o) const;

  size_t axes() const { return axes_.size(); }
  const AxisCore& axis(size_t a) const { return axes_[a]; }

 private:
  std::vector<AxisCore> axes_;
  CoreInputs scratch_{};  // one axis's inputs of this clock
};

}  // namespace sc
