// Pin-level checks of the STEP/DIR outputs at 20 MHz, independent of the
// RTL's implementation, on every bench that drives STEP/DIR: pulse high/low
// times, DIR setup/hold, the step accounting against a reference the pins
// do not produce themselves, and (open-loop profile) no pulse after done
// and the duty-cycle phases (rising, steady, falling, zero) against the
// phase the core reports. Lockstep cannot see a mistake RTL and model
// share; these checks can.
#pragma once

#include <climits>
#include <cstdint>
#include <string>
#include <vector>

#include "axis_core.h"

namespace sc {

enum class DutyTrend { Rising, Steady, Falling, Zero, None };
const char* trend_name(DutyTrend t);
DutyTrend trend_of_phase(uint8_t phase);
// The duty trends a table should show: its rows' phases, repeats merged, + zero.
std::vector<DutyTrend> expected_trends(const std::vector<Segment>& rows);

struct PhaseRun {
  uint8_t phase = 0;
  uint64_t pulses = 0;
  uint64_t min_interval = UINT64_MAX, max_interval = 0;  // clocks between rising edges
  uint64_t first_interval = 0, last_interval = 0;
  double duty_sum = 0;  // sum of high/interval over the run
  uint64_t trend_violations = 0;
  double mean_duty() const { return pulses ? duty_sum / double(pulses) : 0.0; }
};

// What the net STEP edges (rising edges, +1 with DIR high, -1 low) are
// checked against.
enum class StepAccounting {
  None,
  // Open loop: net edges + queued steps == the executor's integer reference
  // position one clock earlier (a request enters the queue the clock after
  // the position moves) - its value at the first clock, at every change and
  // at the end (queue empty). A dropped or doubled step fails it.
  ReferencePosition,
  // Closed loop: net edges == the step generator's pulse counter, which
  // clears to 0 when a move starts.
  PulseCounter,
};

struct PinRules {
  PulseTiming timing{};
  // The open-loop profile's rules: pulses only in a motion phase and never
  // after done, the run ends done, duty trends per phase. Off in closed
  // loop (corrective steps follow no profile phase).
  bool profile_phases = true;
  StepAccounting accounting = StepAccounting::None;
};

class PinMonitor {
 public:
  explicit PinMonitor(const PulseTiming& t, size_t max_errors = 20) : PinMonitor(PinRules{t}, max_errors) {}
  explicit PinMonitor(const PinRules& r, size_t max_errors = 20)
      : t_(r.timing), profile_(r.profile_phases), accounting_(r.accounting), max_errors_(max_errors) {}

  // Called once per clock with the pins after that clock's edge. `ref` is
  // the accounting reference (executor position or pulse counter) and
  // `queued` the steps requested but not yet on the pins (ReferencePosition).
  void on_clock(uint64_t clock, bool step, bool dir, bool done, uint8_t phase, int32_t ref = 0, int32_t queued = 0) {
    if (step != last_step_ || dir != last_dir_ || done != last_done_ || phase != last_phase_ || ref != last_ref_ ||
        queued != last_queued_) [[unlikely]] {
      on_change(clock, step, dir, done, phase, ref, queued);
    }
  }
  void on_clock(uint64_t clock, const CoreOutputs& o) {
    on_clock(clock, o.step, o.dir, o.done, o.phase, accounting_ == StepAccounting::None ? 0 : o.ref_pos_int,
             accounting_ == StepAccounting::None ? 0 : o.step_pending);
  }
  // Timing from now on (register-level benches program it per move).
  void set_timing(const PulseTiming& t) { t_ = t; }
  const PulseTiming& timing() const { return t_; }
  void finish(uint64_t clock);

  uint64_t rising_edges() const { return rises_; }
  int64_t net_steps() const { return net_; }
  const std::vector<std::string>& errors() const { return errors_; }
  const std::vector<PhaseRun>& runs() const { return runs_; }
  // Sequence of duty trends over the move, repeats merged, ending in Zero.
  std::vector<DutyTrend> trend_sequence() const;

 private:
  void on_change(uint64_t clock, bool step, bool dir, bool done, uint8_t phase, int32_t ref, int32_t queued);
  void check_accounting(uint64_t clock, bool rise, int32_t ref, int32_t queued, const char* when);
  void error(std::string s);
  PulseTiming t_;
  bool profile_;
  StepAccounting accounting_;
  size_t max_errors_;
  std::vector<std::string> errors_;
  bool last_step_ = false, last_dir_ = true, last_done_ = false;
  uint8_t last_phase_ = 0;
  // The first clock always counts as a change: it sets the origin.
  int32_t last_ref_ = 0, last_queued_ = INT32_MIN;
  int64_t ref_origin_ = 0;  // ReferencePosition: executor position at the first clock
  int64_t net_at_clear_ = 0;  // PulseCounter: net edges when the counter last cleared
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
