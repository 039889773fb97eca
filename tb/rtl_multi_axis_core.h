// Adapter between the Verilated sc_multi_axis_core (built for 2 and 3
// axes, and for 2 closed-loop capable axes: Servo = 1) and the model's
// types: per-axis slices of the packed ports in and out. Knows nothing of
// the checks.
#pragma once

#include <cstddef>
#include <memory>

#include "multi_axis_core.h"

namespace sc {

class RtlMultiAxisCore {
 public:
  // The axis counts with a Verilated build (others throw std::invalid_argument).
  static bool supported(size_t axes, bool servo = false) { return servo ? axes == 2 : (axes == 2 || axes == 3); }
  explicit RtlMultiAxisCore(size_t axes, bool servo = false);
  ~RtlMultiAxisCore();
  RtlMultiAxisCore(const RtlMultiAxisCore&) = delete;
  RtlMultiAxisCore& operator=(const RtlMultiAxisCore&) = delete;

  size_t axes() const { return axes_; }
  bool servo() const { return servo_; }
  void reset(int cycles = 4);
  // One clock: apply inputs, rising edge, falling edge.
  void step(const MultiCoreInputs& in);
  MultiCoreOutputs outputs() const;
  void read_outputs(MultiCoreOutputs& o) const;

  struct Impl;

 private:
  size_t axes_;
  bool servo_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sc
