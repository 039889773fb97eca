#include "lockstep.h"

#include <fmt/format.h>

#include <algorithm>

namespace sc {

std::string hex_bits(uint64_t v, int width) {
  if (width < 64) v &= (uint64_t(1) << width) - 1;
  return fmt::format("0x{:0{}x}", v, (width + 3) / 4);
}

SignalValues render_outputs(const CoreOutputs& o) {
  return {
      {"step_o", hex_bits(uint64_t(o.step), 1)},
      {"dir_o", hex_bits(uint64_t(o.dir), 1)},
      {"en_o", hex_bits(uint64_t(o.en), 1)},
      {"busy_o", hex_bits(uint64_t(o.busy), 1)},
      {"done_o", hex_bits(uint64_t(o.done), 1)},
      {"phase_o", hex_bits(uint64_t(o.phase), PhaseW)},
      {"fault_table_o", hex_bits(uint64_t(o.fault_table), 1)},
      {"fault_overrun_o", hex_bits(uint64_t(o.fault_overrun), 1)},
      {"pulse_count_o", hex_bits(int64_t(o.pulse_count), 32)},
      {"ref_pos_int_o", hex_bits(int64_t(o.ref_pos_int), 32)},
      {"ref_pos_frac_o", to_hex_u128(o.ref_pos_frac, FracBits)},
      {"ref_vel_o", to_hex_u128(u128(o.ref_vel), VelW)},
      {"ref_acc_o", to_hex_u128(u128(i128(o.ref_acc)), AccW)},
      {"ref_jerk_o", to_hex_u128(u128(i128(o.ref_jerk)), JerkW)},
      {"seg_idx_o", hex_bits(uint64_t(o.seg_idx), 8)},
      {"step_pending_o", hex_bits(int64_t(o.step_pending), PendW)},
      {"underrun_o", hex_bits(uint64_t(o.underrun), 1)},
      {"discont_o", hex_bits(uint64_t(o.discont), 1)},
      {"guard_o", hex_bits(uint64_t(o.guard), 1)},
      {"reach_o", hex_bits(uint64_t(o.reach), 1)},
      {"stopping_o", hex_bits(uint64_t(o.stopping), 1)},
      {"overshoot_o", hex_bits(uint64_t(o.overshoot), 1)},
      {"move_done_o", hex_bits(uint64_t(o.move_done), 1)},
      {"move_idx_o", hex_bits(uint64_t(o.move_idx), MoveIdxW)},
      {"boundary_pos_o", hex_bits(int64_t(o.boundary_pos), 32)},
      {"fifo_level_o", hex_bits(uint64_t(o.fifo_level), RowLevelW)},
      {"fifo_full_o", hex_bits(uint64_t(o.fifo_full), 1)},
      {"row_count_o", hex_bits(uint64_t(o.row_count), RowCountW)},
      {"retarget_refused_o", hex_bits(uint64_t(o.retarget_refused), 1)},
      {"lim_trip_fwd_o", hex_bits(uint64_t(o.lim_trip_fwd), 1)},
      {"lim_trip_rev_o", hex_bits(uint64_t(o.lim_trip_rev), 1)},
  };
}

SignalValues render_loop_outputs(const LoopOutputs& o) {
  return {
      {"fault_ferr_o", hex_bits(uint64_t(o.fault_ferr), 1)},
      {"in_pos_o", hex_bits(uint64_t(o.in_pos), 1)},
      {"enc_pos_o", hex_bits(int64_t(o.enc_pos), EncCntW)},
      {"enc_illegal_o", hex_bits(uint64_t(o.enc_illegal), EncIllW)},
      {"enc_index_o", hex_bits(uint64_t(o.enc_index), 1)},
      {"ctl_active_o", hex_bits(uint64_t(o.ctl_active), 1)},
      {"ctl_state_o", hex_bits(uint64_t(o.ctl_state), CtlStW)},
      {"u_o", hex_bits(int64_t(o.u), CtlW)},
      {"v_cmd_o", hex_bits(int64_t(o.v_cmd), CtlW)},
      {"e_p_o", hex_bits(int64_t(o.e_p), CtlW)},
      {"e_v_o", hex_bits(int64_t(o.e_v), CtlW)},
      {"w_p1_o", hex_bits(int64_t(o.w_p1), WgtW)},
      {"w_p2_o", hex_bits(int64_t(o.w_p2), WgtW)},
      {"w_v1_o", hex_bits(int64_t(o.w_v1), WgtW)},
      {"w_v2_o", hex_bits(int64_t(o.w_v2), WgtW)},
      {"nco_phase_o", hex_bits(int64_t(o.nco_phase), NcoW)},
  };
}

SignalValues render_multi_outputs(const MultiCoreOutputs& o) {
  SignalValues all;
  for (size_t a = 0; a < o.axes; ++a) {
    for (auto& [name, value] : render_outputs(o.axis[a])) all.emplace_back(fmt::format("ax{}.{}", a, name), value);
    if (!o.servo) continue;
    for (auto& [name, value] : render_loop_outputs(o.loop[a])) {
      all.emplace_back(fmt::format("ax{}.{}", a, name), value);
    }
  }
  return all;
}

std::string Mismatch::to_string() const {
  std::string s = fmt::format("clock {} signal {}: rtl={} model={}", clock, signal, rtl, model);
  if (!context.empty()) s += "\n" + context;
  return s;
}

void LockstepLog::add(uint64_t clock, const SignalValues& rtl, const SignalValues& model,
                      const std::vector<std::pair<uint64_t, SignalValues>>& earlier_in) {
  auto earlier = earlier_in;
  std::sort(earlier.begin(), earlier.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::string context;
  for (const auto& [c, v] : earlier) {
    std::string line = fmt::format("  clock {:>10} (match)", c);
    for (size_t i = 0; i < v.size() && i < rtl.size(); ++i) {
      if (rtl[i].second != model[i].second) line += fmt::format(" {}={}", v[i].first, v[i].second);
    }
    context += line + "\n";
  }
  for (size_t i = 0; i < rtl.size() && i < model.size(); ++i) {
    if (rtl[i].second != model[i].second) {
      errors_.push_back({clock, rtl[i].first, rtl[i].second, model[i].second, context});
      if (errors_.size() >= max_errors_) return;
    }
  }
  // The structs differ in a field the render does not show: still a mismatch.
  if (errors_.empty() || errors_.back().clock != clock) {
    errors_.push_back({clock, "(unrendered field)", "?", "?", context});
  }
}

std::string LockstepLog::finish() const {
  if (compared_nothing()) return "lockstep: nothing compared";
  if (errors_.empty()) return fmt::format("lockstep: {} clocks matched, 0 mismatches", matched_);
  return fmt::format("lockstep: {} clocks matched, {} mismatching clocks; first:\n{}", matched_, mismatch_clocks_,
                     errors_.front().to_string());
}

}  // namespace sc
