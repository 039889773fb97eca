// Bit-exact model of rtl/sc_profile_exec.sv (with its sc_row_fifo and
// sc_stop_gen): same
// state, same update order, same wrap. step() is one clock; fast_forward() jumps many clocks in closed
// form and is tested equal to step().
#pragma once

#include <array>
#include <cstdint>

#include "fixed_point.h"
#include "row_fifo.h"
#include "row_reach.h"
#include "stop_gen.h"

namespace sc {

struct Segment {
  Phase phase = Phase::PhIdle;
  uint32_t clocks = 0;
  int64_t jerk = 0;  // JerkW bits, sign-extended
  int64_t acc0 = 0;  // AccW bits
  i128 vel0 = 0;     // VelW bits, sign-extended
  bool operator==(const Segment&) const = default;
};

// One word of the row FIFO: a segment and its RowFlag* bits.
struct Row {
  Segment seg{};
  uint8_t flags = 0;
  bool operator==(const Row&) const = default;
};

// The executor's row guards (guard_*_i): the largest |vel0|, |acc0| and
// |jerk| a loaded row may carry, unsigned VelW / AccW / JerkW bits;
// 0 = no limit.
struct GuardLimits {
  u128 vel = 0;
  uint64_t acc = 0;
  uint64_t jerk = 0;
  bool operator==(const GuardLimits&) const = default;
  // The same limits with every field cut to its port width.
  GuardLimits masked() const;
  // The row is over one of the limits.
  bool exceeded_by(const Segment& s) const;
};

// The soft-limit window of the look-ahead (soft_en_i, soft_min_i,
// soft_max_i): the lowest and highest positions inside.
struct SoftWindow {
  bool en = false;
  int32_t min = 0;
  int32_t max = 0;
  bool operator==(const SoftWindow&) const = default;
};

inline constexpr uint8_t kRowMoveEnd = uint8_t(1u << RowFlagMoveEnd);
inline constexpr uint8_t kRowStreamEnd = uint8_t(1u << RowFlagStreamEnd);
inline constexpr uint8_t kRowAccStep = uint8_t(1u << RowFlagAccStep);
inline constexpr uint8_t kRowHold = uint8_t(1u << RowFlagHold);

class ProfileExec {
 public:
  struct Inputs {
    bool row_push = false;
    bool row_replace = false;    // with row_push: the row replaces from retarget_row on
    uint32_t retarget_row = 0;
    Row row{};
    bool fifo_flush = false;
    u128 pos_frac0 = 0;
    bool start = false;
    bool abort = false;
    bool stop = false;                    // controlled stop
    uint64_t stop_jerk = StopJerkReset;   // JerkW bits (default: the register's reset value)
    uint64_t stop_acc = StopAccReset;     // AccW bits
    GuardLimits guard{};                  // row guards (0 = none)
    SoftWindow soft{};                    // soft-limit look-ahead
    bool reach_veto = false;              // another executor refuses its head row (multi-axis rows)
  };
  struct State {
    bool run = false;
    bool finished = false;
    bool fault = false;
    bool underrun = false;
    bool discont = false;
    bool guard = false;  // a row broke a guard limit (until START)
    bool reach = false;  // the look-ahead refused a row (until START)
    uint8_t chk = 0;     // rows at the head of the FIFO whose reach is known
    bool stop = false;  // controlled stop running
    uint8_t idx = 0;
    uint8_t flags = 0;
    uint32_t left = 0;
    int64_t jerk = 0;
    int64_t acc = 0;
    i128 vel = 0;
    u128 frac = 0;
    int32_t pint = 0;
    Phase phase = Phase::PhIdle;
    bool step_req = false;
    bool step_fwd = true;
    uint32_t move_idx = 0;
    int32_t bpos = 0;
    bool move_done = false;
    // MOVE_END rows pushed and popped since the last flush (RowLevelW bits):
    // their difference is the number queued.
    uint8_t ends_in = 0, ends_out = 0;
    uint32_t rows = 0;      // rows loaded since START (row_count_o)
    bool refused = false;   // retarget_refused_o
    bool operator==(const State&) const = default;
  };

  // The row reach evaluator's state as an executor outside it sees it
  // (sc_profile_exec #(.OwnReach(0)): rc_busy_i, rc_done_i, rc_fwd_i,
  // rc_rev_i).
  struct ReachPort {
    bool busy = false;  // busy with any executor's row
    bool done = false;  // done with this executor's row
    int64_t fwd = 0, rev = 0;
  };

  ProfileExec() { reset(); }
  void reset();
  // Use an evaluator outside (shared): step() then reads reach_port() and
  // leaves its request in reach_request() instead of stepping its own.
  void share_reach() { shared_reach_ = true; }
  ReachPort& reach_port() { return port_; }
  const RowReach::Inputs& reach_request() const { return req_; }
  void step(const Inputs& in);

  // Clocks until the next clock that emits a step or ends the segment
  // (1 = the coming clock), assuming no inputs; 0 if the executor is idle
  // or a closed-form jump is not safe (velocity changes sign, would wrap).
  uint64_t clocks_to_next_event() const;
  // Clocks that advance() may cover in closed form: the rest of the current
  // segment except its last (reload) clock, or a stretch of a hold
  // (velocity mode); 0 when not safe.
  uint64_t closed_form_span() const;
  // Advance k quiet clocks (k <= closed_form_span()) in closed form,
  // including the steps they emit; bit-exact with k calls of step().
  void advance(uint64_t k);
  // Quiet clocks while idle (not running, no step request): only the
  // one-clock move_done pulse ends. Equal to that many calls of step().
  void idle_clocks() { q_.move_done = false; }
  // Advance up to n quiet clocks (no start/abort/push/flush): a whole segment
  // per advance(), step() for the reload clocks. Returns net steps emitted.
  // Equal to n calls of step() (stops early once idle).
  int64_t fast_forward(uint64_t n);

  const State& state() const { return q_; }
  State& mutable_state() { return q_; }  // for fault-injection tests only
  size_t fifo_level() const { return fifo_.level(); }
  // fifo_full_o: no row is taken (full, or a controlled stop runs).
  bool fifo_full() const { return fifo_.full() || q_.stop; }
  // jerk_o: the jerk applied this clock (the stop's while stopping).
  int64_t jerk() const { return q_.stop ? stop_.jerk() : q_.jerk; }
  bool stopping() const { return q_.stop; }
  // Velocity mode: a HOLD row at constant velocity waits for a whole move
  // (with no inputs, it waits as long as no row is pushed).
  bool holding() const;
  bool overshoot() const { return stop_.overshoot(); }
  const StopGen& stop_gen() const { return stop_; }
  // head_fwd_o: direction of the head row (velocity's sign, else the
  // acceleration's, else the jerk's).
  bool head_forward() const;
  // start_ready_o: a START may load the head now (its reach is known, or
  // the look-ahead is off).
  bool start_ready(bool soft_en) const { return !soft_en || fifo_.empty() || q_.chk != 0; }
  // reach_bad_o: with the window on, the head row's reach is not known yet
  // or leaves the window from where the row would start (after this clock's
  // integration while running, at pos_frac0 at a START).
  bool reach_bad(u128 pos_frac0, const SoftWindow& soft) const;
  // The look-ahead has nothing left to evaluate (fast-forward may jump):
  // the evaluator idle, and every queued row checked or the window off.
  bool reach_idle() const {
    return !(shared_reach_ ? port_.busy : reach_.busy()) && (q_.chk == fifo_.level() || !held_soft_.en);
  }
  const RowReach& row_reach() const { return reach_; }

 private:
  bool jump_safe() const;
  State q_;
  // One FIFO word: the row and the MOVE_END rows pushed up to it.
  struct Queued {
    Row row{};
    uint8_t ends = 0;
  };
  RowFifo<Queued, RowFifoDepth> fifo_;
  StopGen stop_;
  RowReach reach_;
  bool shared_reach_ = false;
  ReachPort port_{};
  RowReach::Inputs req_{};
  // The reach of each FIFO entry (sc_row_fifo's side array): forward, backward.
  std::array<std::array<int64_t, 2>, RowFifoDepth> side_{};
  // The stop limits of the last step() (inputs the RTL sees held while
  // fast_forward() runs without inputs).
  uint64_t held_stop_jerk_ = StopJerkReset, held_stop_acc_ = StopAccReset;
  GuardLimits held_guard_{};
  SoftWindow held_soft_{};
};

}  // namespace sc
