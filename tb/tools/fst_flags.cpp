#include "fst_flags.h"

#include <fmt/format.h>

#include "fst_output.h"
#include "scurve/cli/move_flags.h"

namespace sc {

namespace {
// Far beyond any run (2^50 clocks is 1.8 years at 20 MHz), and no wrap in ns.
constexpr int64_t kMaxClock = int64_t(1) << 50;
}  // namespace

void add_fst_flags(CLI::App* app, FstFlags& f, const std::string& what) {
  scurve::cli::output_file_flag(app, "--fst", f.path, fmt::format("FST waveform of {} (GTKWave)", what));
  f.from_opt = scurve::cli::int_flag(app, "--fst-from", f.from, 0, kMaxClock, "first clock in the waveform (default 0)");
  f.to_opt = scurve::cli::int_flag(
      app, "--fst-to", f.to, 1, kMaxClock,
      fmt::format("clock after the last one in the waveform (default: --fst-from + {})", kDefaultFstWindow));
}

std::string FstFlags::resolve() {
  if (!from_opt || !to_opt) return {};  // add_fst_flags() not called: no waveform flags
  if (path.empty()) {
    for (const CLI::Option* o : {from_opt, to_opt}) {
      if (o->count() > 0) return fmt::format("{}: sets the window of --fst, which is not given", o->get_name());
    }
    return {};
  }
  if (to_opt->count() == 0) {
    to = from + kDefaultFstWindow;
  } else if (to <= from) {
    return fmt::format("fst-to={}: must be greater than fst-from={} (the window is [from, to))", to, from);
  }
  return {};
}

}  // namespace sc
