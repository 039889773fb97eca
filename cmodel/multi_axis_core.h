// Bit-exact model of rtl/sc_multi_axis_core.sv: Axes axes executing one
// shared row sequence (one row push into every axis, one start, one stop),
// open loop (Servo = 0: AxisCore, each as sc_axis_core #(.SyncStart(1))) or
// closed-loop capable (Servo = 1: ServoAxis, sc_servo_axis #(.SyncStart(1))).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "axis_core.h"
#include "servo_axis.h"

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
  std::array<LoopInputs, MaxAxes> loop{};  // Servo = 1 only
};

// Every output, per axis (axis[a] for a < axes).
struct MultiCoreOutputs {
  size_t axes = 0;
  bool servo = false;
  std::array<CoreOutputs, MaxAxes> axis{};
  std::array<LoopOutputs, MaxAxes> loop{};  // Servo = 1 only (all 0 otherwise)
  bool operator==(const MultiCoreOutputs& o) const {
    if (axes != o.axes || servo != o.servo) return false;
    for (size_t a = 0; a < axes; ++a) {
      if (!(axis[a] == o.axis[a]) || (servo && !(loop[a] == o.loop[a]))) return false;
    }
    return true;
  }
};

class MultiAxisCore {
 public:
  // 1 .. MaxAxes axes (throws std::invalid_argument naming `axes` otherwise);
  // servo: the Servo = 1 core.
  explicit MultiAxisCore(size_t axes, bool servo = false);
  void reset();
  void step(const MultiCoreInputs& in);
  MultiCoreOutputs outputs() const;
  void read_outputs(MultiCoreOutputs& o) const;
  bool outputs_equal(const MultiCoreOutputs& o) const;

  size_t axes() const { return axes_; }
  bool servo() const { return !servos_.empty(); }
  // Axis a's open-loop core (a servo axis's own, with Servo = 1).
  const AxisCore& axis(size_t a) const { return servos_.empty() ? cores_[a] : servos_[a].core(); }
  const ServoAxis& servo_axis(size_t a) const { return servos_.at(a); }

 private:
  void step_open(const MultiCoreInputs& in);
  void step_servo(const MultiCoreInputs& in);
  ProfileExec& exec_of(size_t a) { return servos_.empty() ? cores_[a].exec() : servos_[a].exec(); }
  // The shared row reach evaluator: its state to every executor before the
  // clock, the executors' requests arbitrated into it after.
  void reach_ports();
  void step_reach();
  size_t axes_;
  RowReach reach_;                  // the one evaluator of the soft-limit look-ahead
  size_t reach_owner_ = 0;          // the axis whose row it evaluates (or last did)
  std::vector<AxisCore> cores_;     // Servo = 0
  std::vector<ServoAxis> servos_;   // Servo = 1
  CoreInputs scratch_{};            // one axis's inputs of this clock
  ServoInputs servo_scratch_{};
};

}  // namespace sc
