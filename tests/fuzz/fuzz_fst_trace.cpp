// FST traces (`scurve diff A.fst B.fst`): the parts of the FST path that run
// in the tool's own process. The bytes are checked as an FST file (block
// chain, header bounds) and decoded as the reader child's record stream;
// both either accept or refuse with one line, within bounded memory. (The
// fstapi reader itself runs in a child process: a crash there is an exit 2
// of the diff, see tools.TraceDiff tests.)
#include <cstddef>
#include <cstdint>
#include <string>

#include "fst_check.h"
#include "fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string why = sc::fst_check(data, size);
  if (!why.empty()) fuzz::one_line_message(why);
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try {
    const sc::FstSignals s = sc::decode_fst_signals(bytes);
    fuzz::require(s.changes.size() == s.names.size(), "changes per signal", std::to_string(s.names.size()));
    // A decoded stream encodes back to a stream that decodes the same.
    std::string again = sc::encode_fst_header(s.end_time, s.names);
    for (size_t i = 0; i < s.changes.size(); ++i) {
      for (const auto& [t, v] : s.changes[i]) sc::append_fst_change(again, i, t, v);
    }
    const sc::FstSignals t = sc::decode_fst_signals(again);
    fuzz::require(t.names == s.names && t.changes == s.changes && t.end_time == s.end_time, "round trip", "");
  } catch (const std::exception& e) {
    fuzz::one_line_message(e.what());
  }
  return 0;
}
