// Lockstep checker in the manner of Ibex's co-simulation: the caller steps
// RTL and model, compare() checks every output of the clock, errors() holds
// readable mismatch reports ("clock N signal X: rtl=.. model=.."), the run
// stops at the first by default, and the last few clocks are kept as context.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "axis_core.h"

namespace sc {

struct Mismatch {
  uint64_t clock = 0;
  std::string signal;
  std::string rtl;
  std::string model;
  std::string context;  // the last clocks before the mismatch, one per line
  std::string to_string() const;
};

class LockstepChecker {
 public:
  explicit LockstepChecker(size_t max_errors = 1) : max_errors_(max_errors) {}

  // Compare one clock; true when every output matches. Cheap when equal.
  bool compare(uint64_t clock, const CoreOutputs& rtl, const CoreOutputs& model) {
    if (rtl == model) [[likely]] {
      ++matched_;
      ring_[clock & (kContext - 1)] = {clock, rtl};
      return true;
    }
    report(clock, rtl, model);
    return false;
  }
  // Hot path without copies: fill slot(clock) with the RTL's outputs, then
  // check() them against the model's state.
  CoreOutputs& slot(uint64_t clock) {
    Entry& e = ring_[clock & (kContext - 1)];
    e.clock = clock;
    return e.out;
  }
  bool check(uint64_t clock, const AxisCore& model) {
    const CoreOutputs& rtl = ring_[clock & (kContext - 1)].out;
    if (model.outputs_equal(rtl)) [[likely]] {
      ++matched_;
      return true;
    }
    const CoreOutputs copy = rtl;
    ring_[clock & (kContext - 1)].clock = UINT64_MAX;  // not a matched clock
    report(clock, copy, model.outputs());
    return false;
  }
  // Keep checking after a mismatch?
  bool should_stop() const { return errors_.size() >= max_errors_; }
  const std::vector<Mismatch>& errors() const { return errors_; }
  uint64_t mismatches() const { return mismatch_clocks_; }
  uint64_t matched() const { return matched_; }
  // Summary at the end of a run (also flags a run that compared nothing).
  std::string finish() const;

  static constexpr size_t kContext = 8;

 private:
  void report(uint64_t clock, const CoreOutputs& rtl, const CoreOutputs& model);
  struct Entry {
    uint64_t clock = UINT64_MAX;
    CoreOutputs out;
  };
  size_t max_errors_;
  uint64_t matched_ = 0;
  uint64_t mismatch_clocks_ = 0;
  std::vector<Mismatch> errors_;
  std::array<Entry, kContext> ring_{};
};

// Every compared signal as (name, rendered value), in port order.
std::vector<std::pair<std::string, std::string>> render_outputs(const CoreOutputs& o);

}  // namespace sc
