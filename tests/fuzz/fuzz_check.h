// What every harness asserts beyond "no crash, no sanitizer report": a
// refused input gets one line that says why (the tools print it after
// "error: " and exit 2). A failed assertion aborts, which the fuzzer reports.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

namespace fuzz {

inline void require(bool ok, const char* what, const std::string& detail) {
  if (ok) return;
  std::fprintf(stderr, "fuzz check failed: %s: %s\n", what, detail.c_str());
  std::abort();
}

// Non-empty, one line, no control characters (text from the input is shown
// escaped, so a file cannot break the line or send terminal escapes).
inline void one_line_message(const std::string& msg) {
  require(!msg.empty(), "error message empty", msg);
  for (const char c : msg) {
    const auto u = static_cast<unsigned char>(c);
    require(u >= 0x20 && u != 0x7f, "control character in error message", msg);
  }
}

}  // namespace fuzz
