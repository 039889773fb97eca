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
#include <fstream>
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
  // reader knows the held values last until then. The trace is written to
  // "<path>.part" and renamed to <path> here, so a failed write (a full disk)
  // throws std::runtime_error and leaves no truncated trace behind.
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
  std::string path_, part_path_;
  uint64_t decimate_;
  uint64_t next_sample_ = 0;
  CoreOutputs last_{};
  bool have_last_ = false;
  uint64_t rows_ = 0;
};

// A trace read row by row (a group's traces are hundreds of MB: nothing is
// held but the current row). The header is checked when opening: known
// format line, numeric fields in range, unique column names; every value of a
// row must be a decimal integer in canonical form (no '+', no leading zeros),
// so equal text means an equal number. Errors are std::runtime_error naming
// the file, the line and the field.
class KinTraceReader {
 public:
  explicit KinTraceReader(const std::string& path);
  // A trace from a stream (kept by the caller); name stands for the path in messages.
  KinTraceReader(std::istream& in, const std::string& name);
  KinTraceReader(const KinTraceReader&) = delete;
  KinTraceReader& operator=(const KinTraceReader&) = delete;

  const std::string& path() const { return path_; }
  const std::map<std::string, std::string>& meta() const { return meta_; }  // "# key=value" lines
  const std::vector<std::string>& columns() const { return columns_; }      // without "clock"
  const std::vector<bool>& held() const { return held_; }                   // per column: exact between rows
  // The next data row (clocks strictly increase); false at the end of the file.
  bool next(uint64_t& clock, std::vector<std::string>& row);
  // Clock after the last one the trace covers (trailer "end_clock=", else the
  // last row + 1); final once next() has returned false.
  uint64_t end_clock() const;

 private:
  void read_header();
  void parse_meta(const std::string& line);
  std::ifstream file_;
  std::istream* in_ = &file_;
  std::string path_;
  size_t lineno_ = 0;
  std::map<std::string, std::string> meta_;
  std::vector<std::string> columns_;
  std::vector<bool> held_;
  bool have_row_ = false;
  uint64_t last_clock_ = 0;
  uint64_t trailer_end_ = 0;
  std::string line_;
};

// A whole trace in memory (small traces: tests, plots).
struct KinTrace {
  std::map<std::string, std::string> meta;
  std::vector<std::string> columns;
  std::vector<bool> held;
  std::vector<uint64_t> clocks;
  std::vector<std::vector<std::string>> rows;
  uint64_t end_clock = 0;
};
KinTrace read_kin_trace(const std::string& path);

}  // namespace sc
