#include "profile_exec.h"

#include <algorithm>

namespace sc {

void ProfileExec::reset() {
  q_ = State{};
  fifo_.reset();
  stop_.reset();
  reach_.reset();
  port_ = ReachPort{};
  req_ = RowReach::Inputs{};
}

GuardLimits GuardLimits::masked() const {
  return {mask_bits(vel, VelW), acc, jerk & ((uint64_t(1) << JerkW) - 1)};
}

bool GuardLimits::exceeded_by(const Segment& s) const {
  // Magnitudes as unsigned W-bit values, as the RTL's (|-2^(W-1)| fits).
  const u128 v = s.vel0 < 0 ? u128(-s.vel0) : u128(s.vel0);
  const uint64_t a = s.acc0 < 0 ? uint64_t(0) - uint64_t(s.acc0) : uint64_t(s.acc0);
  const uint64_t j = s.jerk < 0 ? uint64_t(0) - uint64_t(s.jerk) : uint64_t(s.jerk);
  return (vel != 0 && v > vel) || (acc != 0 && a > acc) || (jerk != 0 && j > jerk);
}

bool ProfileExec::head_forward() const {
  const Segment& h = fifo_.head().row.seg;
  return h.vel0 != 0 ? h.vel0 > 0 : h.acc0 != 0 ? h.acc0 > 0 : h.jerk >= 0;
}

bool ProfileExec::holding() const {
  return q_.run && !q_.stop && q_.left == 1 && (q_.flags & kRowHold) && q_.acc == 0 && q_.jerk == 0 &&
         q_.ends_in == q_.ends_out && !fifo_.full();
}

// Soft-limit look-ahead: the head row's reach from where it would start
// (after this clock's integration at a boundary, POS_FRAC0 at a START), on
// the top ReachFrac fraction bits, out of the window (or not yet known).
bool ProfileExec::reach_bad(u128 pos_frac0, const SoftWindow& soft) const {
  if (!soft.en) return false;
  if (q_.chk == 0) return true;
  const std::array<int64_t, 2>& hd_reach = side_[fifo_.rd()];
  int32_t p0_int = q_.pint;
  u128 p0_frac = mask_bits(pos_frac0, FracBits);
  if (q_.run) {
    const i128 sum = i128(q_.frac) + q_.vel;
    p0_int = sum < 0 ? add_wrap32(q_.pint, -1) : u128(sum) >= kOne ? add_wrap32(q_.pint, 1) : q_.pint;
    p0_frac = sum < 0 ? u128(sum + i128(kOne)) : u128(sum) >= kOne ? u128(sum) - kOne : u128(sum);
  }
  const i128 p0 = (i128(p0_int) << ReachFrac) | i128(p0_frac >> (FracBits - ReachFrac));
  const i128 fwd_int = (p0 + hd_reach[0]) >> ReachFrac;
  const i128 rev_int = (p0 + hd_reach[1]) >> ReachFrac;
  const bool out_fwd = fwd_int > soft.max && fwd_int > p0_int;
  const bool out_rev = rev_int < soft.min && rev_int < p0_int;
  return out_fwd || out_rev;
}

void ProfileExec::step(const Inputs& in) {
  // Mirrors the RTL's always_comb blocks; the FIFO's head is read before
  // its clock edge (asynchronous read).
  const bool fifo_empty = fifo_.empty();
  const Row& hd = fifo_.head().row;
  const uint8_t hd_ends = fifo_.head().ends;
  const uint32_t rows_now = q_.rows;
  const bool hold = !in.abort && holding();
  const bool boundary = q_.run && !q_.stop && !in.abort && q_.left == 1 && !hold;
  const i128 vel_end = wrap_signed(q_.vel + q_.acc, VelW);
  const int64_t acc_end = wrap_signed64(add_wrap64(q_.acc, q_.jerk), AccW);
  const bool continues = hd.seg.vel0 == vel_end && (hd.seg.acc0 == acc_end || (hd.flags & kRowAccStep));
  const bool at_rest = vel_end == 0 && acc_end == 0;
  const bool move_done = boundary && (q_.flags & kRowMoveEnd);
  const bool ends = (q_.flags & kRowStreamEnd) || (fifo_empty && at_rest);
  const bool over_guard = in.guard.exceeded_by(hd.seg);
  const uint8_t chk_now = q_.chk;
  const bool reach_bad = this->reach_bad(in.pos_frac0, in.soft);
  bool load = false;
  if (boundary) {
    load = !(q_.flags & kRowStreamEnd) && !fifo_empty && continues && !over_guard && !reach_bad && !in.reach_veto;
  } else if (!q_.run) {
    load = in.start && !fifo_empty && !over_guard && !reach_bad && !in.reach_veto;
  }
  const bool row_bad = load && hd.seg.clocks == 0;
  const bool stop_start = q_.run && !q_.stop && !in.abort &&
                          ((in.stop && !(boundary && !load && ends)) || (boundary && ((!load && !ends) || row_bad)));
  // The stop generator's outputs of this clock (from its registers).
  const bool sg_active = stop_.active();
  const int64_t sg_jerk = q_.stop && sg_active ? stop_.jerk() : 0;
  bool flush = false;

  // State is updated in place: each statement reads only fields that are
  // still at their current-clock value (no per-clock copy of the State).
  const bool was_running = q_.run;
  const bool was_stopping = q_.stop;
  const uint8_t flags_now = q_.flags;
  q_.step_req = false;
  if (was_running) {
    if (in.abort) {
      q_.run = false;
      q_.stop = false;
      q_.vel = 0;
      q_.acc = 0;
      q_.jerk = 0;
      q_.phase = Phase::PhAbort;
      flush = true;
    } else {
      const i128 sum = i128(q_.frac) + q_.vel;
      if (sum < 0) {
        q_.step_req = true;
        q_.step_fwd = false;
        q_.pint = add_wrap32(q_.pint, -1);
        q_.frac = u128(sum + i128(kOne));
      } else if (u128(sum) >= kOne) {
        q_.step_req = true;
        q_.step_fwd = true;
        q_.pint = add_wrap32(q_.pint, 1);
        q_.frac = u128(sum) - kOne;
      } else {
        q_.frac = u128(sum);
      }
      if (was_stopping) {
        if (sg_active) {
          q_.vel = vel_end;
          q_.acc = wrap_signed64(add_wrap64(q_.acc, sg_jerk), AccW);
        } else {
          q_.run = false;
          q_.stop = false;
        }
      } else if (hold) {
        // v constant, a = j = 0: the state stays; only the position moves
      } else if (q_.left == 1) {
        if (move_done) {
          ++q_.move_idx;
          q_.bpos = q_.pint;
        }
        if (!load && ends) {
          q_.run = false;
          q_.vel = 0;
          q_.acc = 0;
          q_.jerk = 0;
          q_.finished = true;
        } else if (!load) {
          q_.underrun = fifo_empty;
          q_.discont = !fifo_empty && !continues;
          q_.guard = !fifo_empty && continues && over_guard;
          q_.reach = !fifo_empty && continues && !over_guard && reach_bad;
        }
      } else {
        q_.left = q_.left - 1;
        q_.vel = wrap_signed(q_.vel + q_.acc, VelW);
        q_.acc = wrap_signed64(add_wrap64(q_.acc, q_.jerk), AccW);
      }
    }
  } else if (in.start) {
    q_.finished = false;
    q_.fault = false;
    q_.underrun = false;
    q_.discont = false;
    q_.guard = false;
    q_.reach = false;
    q_.frac = mask_bits(in.pos_frac0, FracBits);
    q_.move_idx = 0;
    q_.bpos = q_.pint;
    if (!load) {
      // an empty FIFO is the table fault; a head row over a guard limit or
      // out of the soft limits is refused with everything queued behind it
      q_.fault = fifo_empty;
      q_.guard = !fifo_empty && over_guard;
      q_.reach = !fifo_empty && !over_guard && reach_bad;
      q_.phase = Phase::PhFault;
      flush = !fifo_empty;
    }
  }

  if (stop_start) {
    q_.stop = true;
    q_.vel = vel_end;
    q_.acc = acc_end;
    q_.jerk = 0;
    q_.phase = Phase::PhStop;
    flush = true;
    if (row_bad) q_.fault = true;
  } else if (load) {
    if (hd.seg.clocks == 0) {
      q_.run = false;
      q_.fault = true;
      q_.phase = Phase::PhFault;
      q_.vel = 0;
      q_.acc = 0;
      q_.jerk = 0;
      flush = true;
    } else {
      q_.run = true;
      q_.idx = (!was_running || (flags_now & kRowMoveEnd)) ? 0 : uint8_t((q_.idx + 1) & ((1u << SegIdxW) - 1));
      q_.flags = hd.flags;
      q_.left = hd.seg.clocks;
      q_.jerk = hd.seg.jerk;
      q_.acc = hd.seg.acc0;
      q_.vel = hd.seg.vel0;
      q_.phase = hd.seg.phase;
    }
  }
  q_.move_done = move_done;

  Row w;
  if (in.row_push) {
    w.seg.phase = Phase(uint8_t(in.row.seg.phase) & ((1u << PhaseW) - 1));
    w.seg.clocks = in.row.seg.clocks;
    w.seg.jerk = wrap_signed64(in.row.seg.jerk, JerkW);
    w.seg.acc0 = wrap_signed64(in.row.seg.acc0, AccW);
    w.seg.vel0 = wrap_signed(in.row.seg.vel0, VelW);
    w.flags = uint8_t(in.row.flags & ((1u << RowFlagW) - 1));
  }
  held_stop_jerk_ = in.stop_jerk;
  held_stop_acc_ = in.stop_acc;
  held_guard_ = in.guard;
  held_soft_ = in.soft;
  // The stop generator's clock; idle and not started, it holds its state.
  if (stop_start || stop_.active()) {
    StopGen::Inputs si;
    si.start = stop_start;
    si.vel = vel_end;
    si.acc = acc_end;
    si.stop_jerk = in.stop_jerk;
    si.stop_acc = in.stop_acc;
    stop_.step(si);
  }
  const bool flush_all = flush || in.fifo_flush || was_stopping;
  // Retarget: row retarget_row not loaded (not even now), at most one place
  // behind the queued rows, the kept rows and it fit.
  const bool replace_req = in.row_push && in.row_replace;
  const uint32_t rt_off = in.retarget_row - rows_now;
  const bool replace_ok = replace_req && was_running && !was_stopping && !in.abort && !flush_all &&
                          !(flags_now & kRowStreamEnd) && rt_off >= uint32_t(load) && rt_off <= fifo_.level() &&
                          rt_off - uint32_t(load) < uint32_t(RowFifoDepth);
  const uint8_t ends_mask = uint8_t((1u << RowLevelW) - 1);
  const size_t keep = rt_off & ends_mask;
  // MOVE_END rows up to the written one (behind the kept rows for a replace).
  const uint8_t base = replace_req ? (keep == 0 ? q_.ends_out : fifo_.peek((keep - 1) & (RowFifoDepth - 1)).ends)
                                   : q_.ends_in;
  const uint8_t w_ends = uint8_t((base + ((w.flags & kRowMoveEnd) ? 1 : 0)) & ends_mask);
  const bool push_ok = in.row_push && !in.row_replace && !fifo_.full() && !flush_all;
  if (flush_all) {
    q_.ends_in = 0;
    q_.ends_out = 0;
  } else {
    if (push_ok || replace_ok) q_.ends_in = w_ends;
    if (load) q_.ends_out = hd_ends;
  }
  if (!was_running && in.start) {
    q_.rows = load ? 1 : 0;
  } else if (load) {
    q_.rows = rows_now + 1;
  }
  q_.refused = replace_req && !replace_ok;
  // The look-ahead's checker: the first row without a known reach; a row
  // that leaves the queue (popped, replaced, flushed) drops its evaluation.
  const bool rc_abort = flush_all || (load && chk_now == 0) || (replace_ok && keep <= chk_now);
  const bool rc_busy = shared_reach_ ? port_.busy : reach_.busy();
  const bool rc_done = shared_reach_ ? port_.done : reach_.done();
  const bool rc_start = in.soft.en && !rc_busy && chk_now < fifo_.level() && !rc_abort;
  const bool rc_write = rc_done && !rc_abort;
  if (rc_write) {
    side_[(fifo_.rd() + chk_now) & (RowFifoDepth - 1)] =
        shared_reach_ ? std::array<int64_t, 2>{port_.fwd, port_.rev}
                      : std::array<int64_t, 2>{reach_.reach_fwd(), reach_.reach_rev()};
  }
  const size_t chk_inc = chk_now + (rc_write ? 1 : 0);
  const size_t chk_keep = (replace_ok && keep < chk_inc) ? keep : chk_inc;
  q_.chk = uint8_t(flush_all ? 0 : (load && chk_keep != 0) ? chk_keep - 1 : chk_keep);
  {
    const Segment& at = fifo_.peek(chk_now & (RowFifoDepth - 1)).row.seg;
    RowReach::Inputs& ri = req_;
    ri.start = rc_start;
    ri.abort = rc_abort;
    ri.clocks = at.clocks;
    ri.jerk = at.jerk;
    ri.acc0 = at.acc0;
    ri.vel0 = at.vel0;
    if (!shared_reach_) reach_.step(ri);
  }
  fifo_.step(flush_all, in.row_push && !in.row_replace, Queued{w, w_ends}, load, replace_ok, keep);
}

// A jump is exact when, over the rest of the segment, velocity keeps one
// sign (so the position is monotone and "next carry" is a binary search)
// and nothing would wrap.
bool ProfileExec::jump_safe() const {
  if (!q_.run || q_.stop || q_.left < 2) return false;
  const uint64_t k = q_.left - 1;  // integrations left in this segment
  const i128 a_end = acc_after(q_.acc, q_.jerk, k);
  const i128 amax = (i128(1) << (AccW - 1)) - 1;
  if (a_end > amax || a_end < -amax) return false;
  const i128 vmax = (i128(1) << (VelW - 1)) - 1;
  const i128 v_end = vel_after(q_.vel, q_.acc, q_.jerk, k);
  if (v_end > vmax || v_end < -vmax) return false;
  // v_k is quadratic in k; check the ends and the vertex for a sign change.
  const bool pos0 = q_.vel >= 0;
  if ((v_end >= 0) != pos0) return false;
  if (q_.jerk != 0) {
    // dv/dk = a0 + (k - 1/2) j = 0  ->  k* = 1/2 - a0/j
    const double ks = 0.5 - double(q_.acc) / double(q_.jerk);
    if (ks > 0 && ks < double(k)) {
      for (int64_t c = int64_t(ks) - 1; c <= int64_t(ks) + 2; ++c) {
        if (c < 0 || uint64_t(c) > k) continue;
        const i128 vc = vel_after(q_.vel, q_.acc, q_.jerk, uint64_t(c));
        if ((vc >= 0) != pos0 || vc > vmax || vc < -vmax) return false;
      }
    }
  }
  return true;
}

// Clocks a hold covers in one closed-form jump (no input ends a hold within
// fast_forward(); the bound keeps v * k far inside 128 bits).
constexpr uint64_t kHoldSpan = uint64_t(1) << 30;

uint64_t ProfileExec::clocks_to_next_event() const {
  if (!reach_idle()) return 0;  // the look-ahead's checker runs clock by clock
  const bool hold = holding();
  if (!hold && !jump_safe()) return 0;
  const uint64_t left = hold ? kHoldSpan : q_.left;  // clock `left` reloads or finishes
  const bool fwd = q_.vel >= 0;
  // Smallest m in [1, left] whose clock emits a step:
  // fwd: frac + sum_{i<m} v_i >= 2^F ; back: frac + sum_{i<m} v_i < 0.
  auto emits_by = [&](uint64_t m) {
    const i128 p = i128(q_.frac) + pos_gain(q_.vel, q_.acc, q_.jerk, m);
    return fwd ? p >= i128(kOne) : p < 0;
  };
  if (!emits_by(left)) return left;
  uint64_t lo = 0, hi = left;  // emits_by(lo) false, emits_by(hi) true
  while (hi - lo > 1) {
    const uint64_t mid = lo + (hi - lo) / 2;
    if (emits_by(mid)) hi = mid; else lo = mid;
  }
  return hi;
}

uint64_t ProfileExec::closed_form_span() const {
  if (!reach_idle()) return 0;
  if (holding()) return kHoldSpan;
  return jump_safe() ? q_.left - 1 : 0;
}

void ProfileExec::advance(uint64_t k) {
  if (k == 0) return;
  const i128 one = i128(kOne);
  auto floor_div = [one](i128 x) { return x >= 0 ? x / one : -((-x + one - 1) / one); };
  const i128 p = i128(q_.frac) + pos_gain(q_.vel, q_.acc, q_.jerk, k);
  const i128 p_prev = i128(q_.frac) + pos_gain(q_.vel, q_.acc, q_.jerk, k - 1);
  const i128 steps = floor_div(p);
  if (steps != 0) q_.step_fwd = steps > 0;  // velocity keeps one sign here
  q_.step_req = floor_div(p_prev) != steps;
  q_.pint = add_wrap32(q_.pint, int32_t(int64_t(steps)));
  q_.frac = u128(p - steps * one);
  q_.vel = vel_after(q_.vel, q_.acc, q_.jerk, k);
  q_.acc = int64_t(acc_after(q_.acc, q_.jerk, k));
  if (!holding()) q_.left -= uint32_t(k);  // a hold repeats its last clock
  q_.move_done = false;
}

int64_t ProfileExec::fast_forward(uint64_t n) {
  // advance() never covers a reload clock, so the FIFO only moves in step().
  Inputs quiet{};
  quiet.stop_jerk = held_stop_jerk_;
  quiet.stop_acc = held_stop_acc_;
  quiet.guard = held_guard_;
  quiet.soft = held_soft_;
  const int32_t p0 = q_.pint;
  while (n > 0) {
    const uint64_t span = std::min(closed_form_span(), n);
    if (span > 0) {
      advance(span);
      n -= span;
      if (n == 0) break;
    }
    if (!q_.run && !q_.step_req && reach_idle()) {  // idle: nothing changes any more
      idle_clocks();
      break;
    }
    step(quiet);
    --n;
  }
  return int64_t(add_wrap32(q_.pint, -p0));
}

}  // namespace sc
