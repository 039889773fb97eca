// `scurve diff A B`: compare two traces (kinematics CSV from tools/kin_trace,
// or FST waveforms) and report the first divergence with context, plus a
// summary of how many signals and clocks differ.
#pragma once

#include <cstdint>
#include <istream>
#include <string>
#include <vector>

namespace sc {

struct SignalDiff {
  std::string signal;
  uint64_t first_clock = 0;
  std::string a, b;            // values at first_clock
  uint64_t differing_clocks = 0;
};

struct DiffReport {
  std::string format;          // "csv" or "fst"
  std::string a_name, b_name;  // file names (with the trace's source, if known)
  size_t compared_signals = 0;
  std::vector<std::string> only_in_a, only_in_b;
  uint64_t compared_clocks = 0;          // clocks covered by the comparison
  std::vector<SignalDiff> signals;       // every signal that differs, by first clock
  uint64_t differing_clocks = 0;         // clocks where any signal differs
  bool length_differs = false;
  uint64_t a_last_clock = 0, b_last_clock = 0;  // last clock each trace covers
  std::string context;                   // a few clocks around the first divergence
  bool identical() const { return signals.empty() && !length_differs; }
  std::string to_text() const;
};

struct DiffOptions {
  size_t context_rows = 3;                     // rows (CSV) or changes (FST) each side
  std::vector<std::string> ignore;             // signal names to leave out
  // FST time -> clock number: tb/rtl_core.cpp dumps clock N at time 50 N
  // (rising edge) and 50 N + 25 (falling edge).
  uint64_t fst_ticks_per_clock = 50;
};

// Dispatches on the extension (.fst) or the content; throws on unreadable input.
DiffReport diff_traces(const std::string& a, const std::string& b, const DiffOptions& opt = {});
DiffReport diff_kin_traces(const std::string& a, const std::string& b, const DiffOptions& opt);
// The same on two streams (names stand for the paths in the report).
DiffReport diff_kin_streams(std::istream& a, const std::string& a_name, std::istream& b, const std::string& b_name,
                            const DiffOptions& opt = {});
DiffReport diff_fst(const std::string& a, const std::string& b, const DiffOptions& opt);

}  // namespace sc
