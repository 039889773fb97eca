// Thin adapter between the Verilated sc_axis_core and the model's types:
// packs seg_t, sign-extends the wide outputs. Knows nothing of the checks.
#pragma once

#include <memory>
#include <string>

#include "axis_core.h"

class Vsc_axis_core;

namespace sc {

template <class V>
class VerilatedTop;

class RtlCore {
 public:
  RtlCore();
  ~RtlCore();
  RtlCore(const RtlCore&) = delete;
  RtlCore& operator=(const RtlCore&) = delete;

  // Hold rst_ni low for `cycles` clocks.
  void reset(int cycles = 4);
  // One clock: apply inputs, rising edge, falling edge.
  void step(const CoreInputs& in);
  CoreOutputs outputs() const;
  void read_outputs(CoreOutputs& o) const;  // fill in place (per-clock path)
  // One clock with the inputs of the previous step() held.
  void tick();

  // FST waveform (needs the tracing build) of the clocks in [from, to);
  // trace_close() leaves it whole at its path or throws input::Error (an
  // unclosed waveform is not kept).
  bool trace_supported() const;
  void trace_open(const std::string& path, uint64_t from_clock, uint64_t to_clock);
  void trace_close();

 private:
  std::unique_ptr<VerilatedTop<Vsc_axis_core>> top_;
  CoreInputs last_{};  // what the ports are driven with (seg data aside)
};

}  // namespace sc
