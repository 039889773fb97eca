#include "lockstep.h"

#include <fmt/format.h>

#include <algorithm>

namespace sc {

std::vector<std::pair<std::string, std::string>> render_outputs(const CoreOutputs& o) {
  return {
      {"step_o", fmt::format("{}", int(o.step))},
      {"dir_o", fmt::format("{}", int(o.dir))},
      {"en_o", fmt::format("{}", int(o.en))},
      {"busy_o", fmt::format("{}", int(o.busy))},
      {"done_o", fmt::format("{}", int(o.done))},
      {"phase_o", fmt::format("{}", int(o.phase))},
      {"fault_table_o", fmt::format("{}", int(o.fault_table))},
      {"fault_overrun_o", fmt::format("{}", int(o.fault_overrun))},
      {"pulse_count_o", fmt::format("{}", o.pulse_count)},
      {"ref_pos_int_o", fmt::format("{}", o.ref_pos_int)},
      {"ref_pos_frac_o", to_hex_u128(o.ref_pos_frac, FracBits)},
      {"ref_vel_o", to_hex_u128(u128(o.ref_vel), VelW)},
      {"ref_acc_o", to_hex_u128(u128(i128(o.ref_acc)), AccW)},
      {"ref_jerk_o", to_hex_u128(u128(i128(o.ref_jerk)), JerkW)},
      {"seg_idx_o", fmt::format("{}", int(o.seg_idx))},
      {"step_pending_o", fmt::format("{}", int(o.step_pending))},
  };
}

std::string Mismatch::to_string() const {
  std::string s = fmt::format("clock {} signal {}: rtl={} model={}", clock, signal, rtl, model);
  if (!context.empty()) s += "\n" + context;
  return s;
}

void LockstepChecker::report(uint64_t clock, const CoreOutputs& rtl, const CoreOutputs& model) {
  ++mismatch_clocks_;
  if (errors_.size() >= max_errors_) return;
  const auto r = render_outputs(rtl);
  const auto m = render_outputs(model);
  // Context: the matched clocks just before, oldest first (RTL == model there).
  std::vector<Entry> ctx;
  for (const Entry& e : ring_) {
    if (e.clock != UINT64_MAX && e.clock < clock && clock - e.clock <= kContext) ctx.push_back(e);
  }
  std::sort(ctx.begin(), ctx.end(), [](const Entry& a, const Entry& b) { return a.clock < b.clock; });
  std::string context;
  for (const Entry& e : ctx) {
    const auto v = render_outputs(e.out);
    std::string line = fmt::format("  clock {:>10} (match)", e.clock);
    for (size_t i = 0; i < v.size(); ++i) {
      if (r[i].second != m[i].second) line += fmt::format(" {}={}", v[i].first, v[i].second);
    }
    context += line + "\n";
  }
  for (size_t i = 0; i < r.size(); ++i) {
    if (r[i].second != m[i].second) {
      errors_.push_back({clock, r[i].first, r[i].second, m[i].second, context});
      if (errors_.size() >= max_errors_) break;
    }
  }
}

std::string LockstepChecker::finish() const {
  if (matched_ == 0 && mismatch_clocks_ == 0) return "lockstep: nothing compared";
  if (errors_.empty()) return fmt::format("lockstep: {} clocks matched, 0 mismatches", matched_);
  std::string s = fmt::format("lockstep: {} clocks matched, {} mismatching clocks; first:\n{}", matched_,
                              mismatch_clocks_, errors_.front().to_string());
  return s;
}

}  // namespace sc
