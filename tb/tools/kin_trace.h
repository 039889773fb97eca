// Compact kinematics traces: one CSV row per clock at which a "held" signal
// (pins, phase, counters) changes, plus one row every `decimate` clocks for
// the smoothly varying reference (position fraction, velocity, acceleration,
// jerk). A 400 M-clock group run then writes ~100 k rows instead of 400 M.
// Values are the raw register values (bit-exact, decimal), so traces from
// the RTL and from the model can be compared exactly by `scurve diff`.
#pragma once

#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "axis_core.h"

namespace sc {

// Column names in file order (after "clock"); the first kHeldColumns are held.
const std::vector<std::string>& kin_trace_columns();
inline constexpr size_t kHeldColumns = 9;

class KinTraceWriter {
 public:
  // source: "rtl" or "model" (recorded in the header for the diff's report).
  KinTraceWriter(const std::string& path, const std::string& source, uint64_t decimate);
  ~KinTraceWriter();
  KinTraceWriter(const KinTraceWriter&) = delete;
  KinTraceWriter& operator=(const KinTraceWriter&) = delete;

  void on_clock(uint64_t clock, const CoreOutputs& o) {
    if (!have_last_ || held_changed(o) || clock >= next_sample_) [[unlikely]] write_row(clock, o);
  }
  // end_clock: the clock after the last one seen; recorded in a trailer so a
  // reader knows the held values last until then.
  void close(uint64_t end_clock);
  uint64_t rows() const { return rows_; }

 private:
  bool held_changed(const CoreOutputs& o) const {
    return o.step != last_.step || o.dir != last_.dir || o.en != last_.en || o.busy != last_.busy ||
           o.done != last_.done || o.phase != last_.phase || o.seg_idx != last_.seg_idx ||
           o.pulse_count != last_.pulse_count || o.step_pending != last_.step_pending;
  }
  void write_row(uint64_t clock, const CoreOutputs& o);
  std::FILE* f_ = nullptr;
  uint64_t decimate_;
  uint64_t next_sample_ = 0;
  CoreOutputs last_{};
  bool have_last_ = false;
  uint64_t rows_ = 0;
};

// A trace read back: header metadata and rows of strings (values are kept as
// text so 81-bit velocities compare exactly).
struct KinTrace {
  std::map<std::string, std::string> meta;  // from the "# key=value ..." lines (header, trailer)
  std::vector<std::string> columns;          // without "clock"
  std::vector<bool> held;                     // per column: exact between rows
  std::vector<uint64_t> clocks;
  std::vector<std::vector<std::string>> rows;
  // Clock after the last one the trace covers (trailer "end_clock=", else last row + 1).
  uint64_t end_clock = 0;
};
// Throws std::runtime_error with the file and line on a malformed trace.
KinTrace read_kin_trace(const std::string& path);

}  // namespace sc
