// Streamed moves with look-ahead: consecutive moves run back to back from
// one row stream, at nonzero junction speeds where the path allows.
//
//   scurve::StreamPlanner sp{scurve::Clock{}, scurve::PulseTiming{}, {500, 2500, 3000}};
//   if (auto e = sp.append({1000, 3000, 3000})) ...   // e->message names the bound
//   for (scurve::StreamedMove& m : sp.take_ready()) send(m.segments);
//   sp.flush();                                        // the tail to rest
//
// Each move is planned from the previous move's exact end state (velocity in
// LSB, acceleration 0, the position fraction carried over), so the rows form
// one continuous execution and the position after every move is exactly the
// running sum of the distances (see Planner::plan_from for the end window).
//
// Look-ahead: the junction speed into a move is the highest speed
//   <= min(v_junction_max, the cruise speeds of both neighbours)
// from which every queued move after it can still stop within the queued
// distance (backward pass, using the planner's own transitions), and which
// the previous move can reach from its own entry speed (forward pass). It is
// 0 at a direction change and at the end of the queue. A junction is final
// once the backward pass no longer limits it (appending only raises that
// bound); moves between final junctions are planned and handed out by
// take_ready() and never change.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <variant>
#include <vector>

#include "scurve/planner.h"

namespace scurve {

// Limits of the whole stream (S-curve, symmetric jerk).
struct StreamLimits {
  // {a_max, j_max, v_max}: the three limits, the window left out (a
  // constructor, so that form stays free of missing-initializer warnings).
  StreamLimits() = default;
  StreamLimits(double a, double j, double v) : a_max(a), j_max(j), v_max(v) {}
  double a_max = 0;  // pulses/s^2
  double j_max = 0;  // pulses/s^3
  double v_max = 0;  // pulses/s, <= the step-rate limit
  // The travel window (optional) and the position the stream starts at,
  // pulses. append() refuses a move whose end, start_position plus the
  // running sum of the distances, leaves the window, by the rule of
  // MoveRequest::soft_limits (moves never reverse inside themselves, so
  // the ends are the extremes; from a start beyond a limit, moves back
  // toward the window are accepted), naming the move index:
  //   "axis x: move 3: target position 1200 is beyond soft limit max=1000
  //    pulses (start 200, distance +1000)"
  // The positions the stream reports (position(), end_position) count from
  // the start as the hardware's reference position does: start_position is
  // not added to them.
  std::optional<SoftLimits> soft_limits;
  int64_t start_position = 0;
};

struct StreamMove {
  int64_t distance = 0;         // pulses, the sign is the direction
  double v_cruise = 0;          // pulses/s, (0, v_max]
  double v_junction_max = 0;    // pulses/s, [0, v_max]: limit at the junction into this move
};

struct StreamedMove {
  uint64_t index = 0;              // 0, 1, ... in append order
  int64_t distance = 0;
  std::vector<Segment> segments;   // continue the previous move's rows exactly
  double v_in = 0, v_out = 0;      // junction speeds, pulses/s
  JunctionState start, end;        // exact executor states
  uint64_t start_clock = 0, end_clock = 0;  // offsets from the stream's start
  int64_t end_position = 0;        // pulses: the running sum of the distances (from the start)
};

class StreamPlanner {
 public:
  // Default lookahead: queued moves beyond it are planned with their current
  // (always stoppable) junction speeds, which bounds the work per append.
  static constexpr size_t kDefaultLookahead = 64;

  // start_frac: the position fraction the stream starts at (default mid-pulse,
  // as a move from rest starts).
  StreamPlanner(Clock clock, PulseTiming timing, StreamLimits limits, u128 start_frac = kOne / 2,
                size_t lookahead = kDefaultLookahead);

  // Queues a move and re-plans the junctions it changes. An error (invalid
  // move or stream limits, a move that leaves the window) leaves the stream
  // unchanged.
  std::optional<Error> append(const StreamMove& move);
  // Planned moves whose rows can no longer change, in order (moved out).
  std::vector<StreamedMove> take_ready();
  // Ends the stream: plans every queued move, the last one to rest.
  std::optional<Error> flush();

  // Look-ahead junction speeds (pulses/s) into each queued move, then the
  // exit of the last one (0).
  std::vector<double> queued_junctions() const;
  size_t queued() const { return queue_.size(); }
  const JunctionState& state() const { return state_; }  // end of the last planned move
  int64_t position() const { return position_; }
  uint64_t clock_offset() const { return clock_offset_; }

 private:
  struct Queued {
    StreamMove move;
    int dir = 1;
    i128 cruise = 0;          // LSB
    i128 cap_in = 0;          // junction cap: v_junction_max, both cruises; 0 at a reversal
    i128 back_in = 0;         // min(cap_in, highest stoppable entry speed)
    bool cap_reached = false; // back_in == cap_in: appends cannot raise it
    i128 v_in = 0;            // planned junction speed
    bool final_in = false;
  };

  std::optional<Error> check_move(const StreamMove& move) const;
  i128 travel(i128 v_from, i128 v_to) const;
  static i128 grid(i128 top);
  i128 max_entry(int64_t distance, i128 v_exit, i128 top) const;
  i128 max_exit(i128 v_entry, int64_t distance, i128 top) const;
  bool backward_pass();
  bool forward_pass(size_t from);
  std::optional<Error> plan_front(i128 v_out);
  std::optional<Error> release_ready();

  Clock clock_;
  PulseTiming timing_;
  StreamLimits limits_;
  size_t lookahead_;
  std::optional<Error> config_error_;
  struct Solver;  // the planner's limits in LSB
  std::shared_ptr<const Solver> solver_;
  std::deque<Queued> queue_;
  std::vector<Queued> saved_;  // the queue before an append, to restore
  std::vector<StreamedMove> ready_;
  JunctionState state_;
  int64_t position_ = 0;
  uint64_t clock_offset_ = 0;
  uint64_t next_index_ = 0;
  i128 appended_end_ = 0;  // start_position + the distances appended so far
  // travel() of recent speed pairs: the junction passes ask for many again.
  struct TravelMemo {
    i128 from = -1, to = -1, gain = 0;
  };
  mutable std::array<TravelMemo, 256> travel_memo_{};
};

// A whole stream at once: every move appended, then flushed. The planned
// moves in order, or the first Error, its message prefixed with the move's
// place ("moves[3]: ...").
std::variant<std::vector<StreamedMove>, Error> plan_whole_stream(Clock clock, PulseTiming timing,
                                                                 const StreamLimits& limits,
                                                                 const std::vector<StreamMove>& moves);

}  // namespace scurve
