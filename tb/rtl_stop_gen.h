// Thin adapter between the Verilated sc_stop_gen and the model's types
// (StopGen::Inputs in, the four outputs back). Knows nothing of the checks.
#pragma once

#include <memory>

#include "stop_gen.h"

class Vsc_stop_gen;

namespace sc {

template <class V>
class VerilatedTop;

struct StopOutputs {
  bool active = false;
  bool done = false;
  bool overshoot = false;
  int64_t jerk = 0;  // JerkW bits, sign-extended
  bool operator==(const StopOutputs&) const = default;
};

// The model's outputs in the same shape.
inline StopOutputs outputs_of(const StopGen& m) { return {m.active(), m.done(), m.overshoot(), m.jerk()}; }

class RtlStopGen {
 public:
  RtlStopGen();
  ~RtlStopGen();
  RtlStopGen(const RtlStopGen&) = delete;
  RtlStopGen& operator=(const RtlStopGen&) = delete;

  void reset(int cycles = 2);
  // Outputs of the current clock (before its edge), for the inputs driven now.
  StopOutputs outputs() const;
  // Drive the inputs, then one clock edge.
  void step(const StopGen::Inputs& in);

 private:
  std::unique_ptr<VerilatedTop<Vsc_stop_gen>> top_;
};

}  // namespace sc
