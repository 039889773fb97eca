// The one lockstep comparer of every bench, in the manner of Ibex's
// co-simulation: the caller steps RTL and model, compare() checks every
// compared output of the clock, errors() holds readable mismatch reports
// ("clock N signal X: rtl=0x.. model=0x.." plus the last few clocks), the
// run stops at the first by default, matched() counts the clocks that
// matched, and finish() flags a run that compared nothing.
//
// Lockstep<Outputs> works on any struct of compared outputs with
// operator==; a render function names and formats its signals, and runs
// only when a clock mismatches (the hot path is one equality test and a
// copy into the context ring). The SystemC scoreboard uses it from the
// C++20 side of the bench (tb/systemc/components.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "axis_core.h"
#include "multi_axis_core.h"

namespace sc {

// Every compared signal as (name, rendered value), in port order.
using SignalValues = std::vector<std::pair<std::string, std::string>>;

// Hex of the low `width` bits (two's complement for negative values).
std::string hex_bits(uint64_t v, int width);
inline std::string hex_bits(int64_t v, int width) { return hex_bits(uint64_t(v), width); }

struct Mismatch {
  uint64_t clock = 0;
  std::string signal;
  std::string rtl;
  std::string model;
  std::string context;  // the last clocks before the mismatch, one per line
  std::string to_string() const;
};

// Counters and report text, independent of the compared type.
class LockstepLog {
 public:
  // Keep checking after a mismatch?
  bool should_stop() const { return errors_.size() >= max_errors_; }
  const std::vector<Mismatch>& errors() const { return errors_; }
  uint64_t mismatches() const { return mismatch_clocks_; }
  uint64_t matched() const { return matched_; }
  bool compared_nothing() const { return matched_ == 0 && mismatch_clocks_ == 0; }
  // Summary at the end of a run (also flags a run that compared nothing).
  std::string finish() const;

 protected:
  explicit LockstepLog(size_t max_errors) : max_errors_(max_errors) {}
  // One mismatching clock: one Mismatch per differing signal (up to the
  // limit), each with the context lines (earlier matched clocks, oldest
  // first, showing the signals that differ now).
  void add(uint64_t clock, const SignalValues& rtl, const SignalValues& model,
           const std::vector<std::pair<uint64_t, SignalValues>>& earlier);
  size_t max_errors_;
  uint64_t matched_ = 0;
  uint64_t mismatch_clocks_ = 0;
  std::vector<Mismatch> errors_;
};

template <class Outputs>
class Lockstep : public LockstepLog {
 public:
  using Render = SignalValues (*)(const Outputs&);
  static constexpr size_t kContext = 8;

  explicit Lockstep(Render render, size_t max_errors = 1) : LockstepLog(max_errors), render_(render) {}

  // Compare one clock; true when every output matches.
  bool compare(uint64_t clock, const Outputs& rtl, const Outputs& model) {
    if (rtl == model) [[likely]] {
      Entry& e = ring_[clock & (kContext - 1)];
      e.clock = clock;
      e.out = rtl;
      ++matched_;
      return true;
    }
    report(clock, rtl, model);
    return false;
  }
  // Hot path without copies: fill slot(clock) with the RTL's outputs, then
  // check() them against a model that compares its state in place
  // (model.outputs_equal(rtl), model.outputs() only on a mismatch).
  Outputs& slot(uint64_t clock) {
    Entry& e = ring_[clock & (kContext - 1)];
    e.clock = clock;
    return e.out;
  }
  template <class Model>
  bool check(uint64_t clock, const Model& model) {
    Entry& e = ring_[clock & (kContext - 1)];
    if (model.outputs_equal(e.out)) [[likely]] {
      ++matched_;
      return true;
    }
    const Outputs rtl = e.out;
    e.clock = kNoClock;
    report(clock, rtl, model.outputs());
    return false;
  }

 private:
  static constexpr uint64_t kNoClock = UINT64_MAX;
  static_assert((kContext & (kContext - 1)) == 0, "the ring is indexed by clock & (kContext - 1)");
  struct Entry {
    uint64_t clock = kNoClock;
    Outputs out{};
  };
  void report(uint64_t clock, const Outputs& rtl, const Outputs& model) {
    ++mismatch_clocks_;
    if (errors_.size() >= max_errors_) return;
    std::vector<std::pair<uint64_t, SignalValues>> earlier;
    for (const Entry& e : ring_) {
      if (e.clock != kNoClock && e.clock < clock && clock - e.clock <= kContext) {
        earlier.emplace_back(e.clock, render_(e.out));
      }
    }
    add(clock, render_(rtl), render_(model), earlier);
  }
  Render render_;
  std::array<Entry, kContext> ring_{};
};

// The open-loop core (sc_axis_core) outputs.
SignalValues render_outputs(const CoreOutputs& o);

class LockstepChecker : public Lockstep<CoreOutputs> {
 public:
  explicit LockstepChecker(size_t max_errors = 1) : Lockstep<CoreOutputs>(&render_outputs, max_errors) {}
};

// The loop's outputs of one axis of the multi-axis core (Servo = 1).
SignalValues render_loop_outputs(const LoopOutputs& o);

// The multi-axis core (sc_multi_axis_core): every axis's outputs (with the
// loop's, Servo = 1), named "axN.<port>".
SignalValues render_multi_outputs(const MultiCoreOutputs& o);

class MultiLockstepChecker : public Lockstep<MultiCoreOutputs> {
 public:
  explicit MultiLockstepChecker(size_t max_errors = 1)
      : Lockstep<MultiCoreOutputs>(&render_multi_outputs, max_errors) {}
};

}  // namespace sc
