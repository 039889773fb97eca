// Runs one planned move: load the table, start, run to done and a quiet
// tail, with RTL and model in lockstep (or the model alone), collecting the
// pin checks, peaks and throughput.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fst_output.h"
#include "lockstep.h"
#include "pin_monitor.h"
#include "stop_check.h"
#include "planner.h"

namespace sc {

enum class SimEngine {
  Lockstep,   // Verilated RTL and model, compared every clock
  RtlOnly,    // Verilated RTL with the pin checks
  ModelOnly,  // model step() every clock with the pin checks
  ModelFast,  // model fast_forward(): closed form between pulses
};
const char* engine_name(SimEngine e);
// The --engine names, and the engine of one of them (CLI::IsMember checks
// the name first; anything else is the default, lockstep).
const std::vector<std::string>& sim_engine_names();
SimEngine sim_engine_from_name(const std::string& name);

class RtlCore;

// One open-loop core run by one engine: the Verilated RTL and/or the model
// stepped together, compared every clock in lockstep, the pin monitor on
// every clock the outputs are read. The adapter of run_move and run_stream.
class CoreDriver {
 public:
  // fst_path: the RTL's waveform (opened before reset; input::Error when the
  // engine runs no RTL or the file cannot be written).
  CoreDriver(SimEngine engine, const PinRules& rules, size_t max_mismatches = 1, const std::string& fst_path = {},
             uint64_t fst_from = 0, uint64_t fst_to = 0);
  ~CoreDriver();
  // One clock with `ci`. held: ci equals the previous clock's inputs and
  // pushes no row, so both sides take the cheaper hold-the-inputs path.
  void tick(const CoreInputs& ci, bool held = false);
  // The model alone (ModelFast): n clocks with `in` held in closed form; the
  // pin monitor sees the last (AxisCore::clocks_to_next_event() says how far
  // no pin moves).
  void jump(const CoreInputs& in, uint64_t n);
  // The outputs of the last clock (the RTL's when it runs).
  const CoreOutputs& out() const { return *cur_; }
  uint64_t clock() const { return clock_; }
  // The comparer reached its mismatch limit: the run stops.
  bool stopped() const { return stopped_; }
  AxisCore& model() { return model_; }
  LockstepChecker& checker() { return checker_; }
  PinMonitor& pins() { return pins_; }
  // Closes the RTL's waveform (no-op without one).
  void close_trace();

 private:
  SimEngine engine_;
  std::unique_ptr<RtlCore> rtl_;
  AxisCore model_;
  LockstepChecker checker_;
  PinMonitor pins_;
  CoreOutputs out_;
  const CoreOutputs* cur_ = &out_;
  uint64_t clock_ = 0;
  bool stopped_ = false;
};

// A retarget pushed this many clocks after the START clock: `rows` (FIFO
// words) replace the plan from row number `row` on, the first with
// ROW_PUSH.REPLACE. The run must then end on `distance`, or, refused, on
// the plan's own (scurve::plan_retarget). At namespace scope: clang takes a
// nested struct with member initializers for not default-constructible
// inside its enclosing class, which std::optional<> of it then remembers.
struct SimRetarget {
  uint64_t at_clock = 0;
  uint32_t row = 0;
  std::vector<Row> rows;
  int64_t distance = 0;
  uint64_t clocks = 0;  // the new rows' clocks
};

struct SimOptions {
  SimEngine engine = SimEngine::Lockstep;
  uint64_t tail_clocks = 0;  // 0: automatic (covers the longest pulse timing)
  std::string fst_path;      // RTL waveform (tracing build only); input::Error when unwritable
  uint64_t fst_from = 0, fst_to = kDefaultFstWindow;
  size_t max_mismatches = 1;
  std::function<void(double)> progress;  // fraction done, every ~16 M clocks
  // A controlled stop (the core's stop input, CMD.STOP) this many clocks
  // after the START clock. The run then ends at rest and is checked by the
  // stop monitor (tb/stop_check.h) instead of against the move's endpoint.
  std::optional<uint64_t> stop_at;
  uint64_t stop_jerk = StopJerkReset, stop_acc = StopAccReset;  // executor LSBs
  using Retarget = SimRetarget;
  std::optional<Retarget> retarget;
};


struct SimResult {
  std::string name;
  SimEngine engine = SimEngine::Lockstep;
  int64_t distance = 0;
  uint64_t clocks = 0;          // reset release to done
  uint64_t total_clocks = 0;    // including load and tail
  int64_t pulses = 0;           // net STEP pulses counted on the pins
  int64_t pulse_count_reg = 0;  // the core's own counter
  int64_t final_error = 0;      // distance (a stopped run: its end position) - pulses
  double duration_s = 0;        // start to done
  double peak_velocity = 0, peak_acceleration = 0, peak_jerk = 0;  // from the reference every clock
  uint64_t mismatches = 0;
  uint64_t matched_clocks = 0;
  std::string first_mismatch;
  std::vector<std::string> pin_errors;
  std::vector<PhaseRun> phase_runs;
  std::vector<DutyTrend> trends;
  std::vector<DutyTrend> expected_trends;
  double wall_s = 0;
  double clocks_per_s = 0;
  StopReport stop;
  // The retarget (SimOptions::retarget), if any: taken or refused.
  bool retarget_requested = false, retarget_taken = false;
  uint32_t retarget_row = 0;
  int64_t retarget_distance = 0;
  std::vector<std::string> failures;  // everything that makes the run fail
  bool pass() const { return failures.empty(); }
  // The failures, one a line (for a test's failure message).
  std::string failure_lines() const {
    std::string s;
    for (const std::string& f : failures) s += f + "\n";
    return s;
  }
};

struct Limits4Check {
  double v_max = 0, a_max = 0, j_max = 0;  // pulses/s^k; 0 = not checked
};

SimResult run_move(const Plan& plan, const PulseTiming& timing, const Limits4Check& limits,
                   const SimOptions& opt);

// The clock-by-clock inputs that load a move and start it: one row pushed
// per clock, then one clock with start; `base` supplies enable, timing.
// The last element's inputs, with start dropped, are what a run then holds.
std::vector<CoreInputs> load_sequence(const std::vector<Segment>& rows, u128 pos_frac0, const CoreInputs& base);
// The same for rows as pushed (a test may drop or alter some).
std::vector<CoreInputs> load_sequence(const std::vector<Row>& rows, u128 pos_frac0, const CoreInputs& base);

}  // namespace sc
