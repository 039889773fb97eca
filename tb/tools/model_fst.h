// FST waveform of the model's outputs under the same names as the Verilated
// RTL's top-level ports (scope sc_axis_core, "phase_o [3:0]", ...) and the same time
// base (clock N at time 50 N), so GTKWave shows both side by side and
// `scurve diff rtl.fst model.fst` compares them port by port.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "axis_core.h"
#include "fst_output.h"

namespace sc {

class ModelFstWriter {
 public:
  // Clocks in [from, to) are written (a value change only when it changes).
  // `param` names the user's flag in errors (input::Error).
  ModelFstWriter(const std::string& param, const std::string& path, uint64_t from, uint64_t to);
  ~ModelFstWriter();
  ModelFstWriter(const ModelFstWriter&) = delete;
  ModelFstWriter& operator=(const ModelFstWriter&) = delete;

  void on_clock(uint64_t clock, const CoreOutputs& o) {
    if (clock >= from_ && clock < to_) [[unlikely]] write(clock, o);
  }
  // The waveform whole at its path, or input::Error; without close() the
  // file is not written.
  void close(uint64_t end_clock);

 private:
  void write(uint64_t clock, const CoreOutputs& o);
  std::unique_ptr<FstOutput> out_;
  void* ctx_ = nullptr;
  uint64_t from_, to_;
  std::vector<uint32_t> handles_;
  std::vector<std::string> last_;
  bool first_ = true;
};

}  // namespace sc
