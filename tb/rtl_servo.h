// Thin adapter between the Verilated sc_servo_axis and the model's types
// (ServoInputs / ServoOutputs): packs wide ports, sign-extends outputs.
#pragma once

#include <memory>
#include <string>

#include "servo_axis.h"

class Vsc_servo_axis;

namespace sc {

template <class V>
class VerilatedTop;

class RtlServo {
 public:
  RtlServo();
  ~RtlServo();
  RtlServo(const RtlServo&) = delete;
  RtlServo& operator=(const RtlServo&) = delete;

  void reset(int cycles = 4);
  void step(const ServoInputs& in);
  ServoOutputs outputs() const;

  // As RtlCore's: trace_close() or no file.
  bool trace_supported() const;
  void trace_open(const std::string& path, uint64_t from_clock, uint64_t to_clock);
  void trace_close();

 private:
  void apply_cfg(const ServoConfig& c);
  std::unique_ptr<VerilatedTop<Vsc_servo_axis>> top_;
  u128 pos_frac0_ = 0;
  GuardLimits guard_{};  // the guard inputs as driven
  SoftWindow soft_{};    // the soft-limit inputs as driven
  ServoConfig cfg_{};
  bool cfg_set_ = false;
};

}  // namespace sc
