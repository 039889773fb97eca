// Pin-level checks of the STEP/DIR/EN outputs at 20 MHz, independent of
// the RTL's implementation: pulse high/low times, DIR setup/hold, no pulse
// after done, and the duty-cycle phases (rising, steady, falling, zero)
// against the phase the core reports.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "axis_core.h"

namespace sc {

enum class DutyTrend { Rising, Steady, Falling, Zero, None };
const char* trend_name(DutyTrend t);
DutyTrend trend_of_phase(uint8_t phase);

struct PhaseRun {
  uint8_t phase = 0;
  uint64_t pulses = 0;
  uint64_t min_interval = UINT64_MAX, max_interval = 0;  // clocks between rising edges
  uint64_t first_interval = 0, last_interval = 0;
  double duty_sum = 0;  // sum of high/interval over the run
  uint64_t trend_violations = 0;
  double mean_duty() const { return pulses ? duty_sum / double(pulses) : 0.0; }
};

class PinMonitor {
 public:
  explicit PinMonitor(const PulseTiming& t, size_t max_errors = 20) : t_(t), max_errors_(max_errors) {}

  // Called once per clock with the outputs after that clock's edge.
  void on_clock(uint64_t clock, const CoreOutputs& o) {
    if (o.step != last_step_ || o.dir != last_dir_ || o.done != last_done_ || o.phase != last_phase_)
        [[unlikely]] {
      on_change(clock, o);
    }
  }
  void finish(uint64_t clock);

  uint64_t rising_edges() const { return rises_; }
  int64_t net_steps() const { return net_; }
  const std::vector<std::string>& errors() const { return errors_; }
  const std::vector<PhaseRun>& runs() const { return runs_; }
  // Sequence of duty trends over the move, repeats merged, ending in Zero.
  std::vector<DutyTrend> trend_sequence() const;

 private:
  void on_change(uint64_t clock, const CoreOutputs& o);
  void error(std::string s);
  PulseTiming t_;
  size_t max_errors_;
  std::vector<std::string> errors_;
  bool last_step_ = false, last_dir_ = true, last_done_ = false;
  uint8_t last_phase_ = 0;
  bool initialised_ = false;
  uint64_t last_rise_ = 0, last_fall_ = 0, last_dir_change_ = 0;
  bool any_rise_ = false, any_fall_ = false, any_dir_change_ = false;
  uint64_t rises_ = 0;
  int64_t net_ = 0;
  bool done_seen_ = false;
  uint64_t done_clock_ = 0;
  std::vector<PhaseRun> runs_;
};

}  // namespace sc
