// The waveform flags of the benches (scurve sim, sc_bench): --fst,
// --fst-from, --fst-to, read through the validation layer.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

namespace sc {

struct FstFlags {
  std::string path;
  uint64_t from = 0, to = 0;
  CLI::Option *from_opt = nullptr, *to_opt = nullptr;
  // After parsing: applies the default window length when --fst-to is not
  // given and checks the window; "" or one line naming the flag.
  std::string resolve();
};

// `what`: whose waveform ("the RTL"). The path is checked when parsed.
void add_fst_flags(CLI::App* app, FstFlags& f, const std::string& what);

}  // namespace sc
