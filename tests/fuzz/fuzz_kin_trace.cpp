// Kinematics traces (`scurve diff A.csv B.csv`): the input is split at the
// first 0x00 byte into two traces (or diffed against itself), and the diff
// either reports (an identical pair is identical) or refuses with one line
// naming the file, the line and the field.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>

#include "fuzz_check.h"
#include "trace_diff.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string all(reinterpret_cast<const char*>(data), size);
  const size_t cut = all.find('\0');
  const std::string a = all.substr(0, cut);
  const std::string b = cut == std::string::npos ? a : all.substr(cut + 1);
  std::istringstream ia(a), ib(b);
  sc::DiffOptions opt;
  opt.context_rows = 2;
  try {
    const sc::DiffReport rep = sc::diff_kin_streams(ia, "a.csv", ib, "b.csv", opt);
    (void)rep.to_text();
    if (cut == std::string::npos) fuzz::require(rep.identical(), "a trace differs from itself", rep.to_text());
  } catch (const std::exception& e) {
    fuzz::one_line_message(e.what());
  }
  return 0;
}
