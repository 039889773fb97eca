// Internal pieces of the planner shared by Planner (planner.cpp) and
// StreamPlanner (stream_planner.cpp): the transition builder, the plateau
// search and the row finishing. Not installed; not part of the API.
#pragma once

#include <algorithm>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "scurve/planner.h"

namespace scurve::detail {

// The clock rate and the LSB scales derived from it.
struct Units {
  double f;     // clock, Hz
  double vel;   // LSB per pulse/s
  double acc;   // LSB per pulse/s^2
  double jerk;  // LSB per pulse/s^3
  explicit Units(Clock c)
      : f(c.hz), vel(vel_lsb_per_unit(c)), acc(acc_lsb_per_unit(c)), jerk(jerk_lsb_per_unit(c)) {}
};

// A row before splitting to the hardware's 32-bit clock field.
struct Row {
  Phase phase;
  uint64_t clocks;
  int64_t jerk;
  int64_t acc0;
  i128 vel0;
};

// The rows of one transition: at most 4, or a few more with an exact tail.
// Held inline (a transition is built for every candidate plateau the
// searches try, so a heap allocation each time would dominate); more than
// kInline rows spill to the heap.
class RowList {
 public:
  static constexpr size_t kInline = 20;
  RowList() = default;
  RowList(const RowList& o) { *this = o; }
  RowList& operator=(const RowList& o) {
    if (this == &o) return *this;
    n_ = o.n_;
    heap_ = o.heap_;
    std::copy(o.inline_, o.inline_ + std::min(n_, kInline), inline_);
    return *this;
  }
  void push_back(const Row& r) {
    if (n_ < kInline) [[likely]] {  // (n_ < kInline: never spilled)
      inline_[n_++] = r;
      return;
    }
    spill(r);
  }
  size_t size() const { return n_; }
  void clear() {
    n_ = 0;
    heap_.clear();
  }
  bool empty() const { return n_ == 0; }
  Row* begin() { return heap_.empty() ? inline_ : heap_.data(); }
  Row* end() { return begin() + n_; }
  const Row* begin() const { return heap_.empty() ? inline_ : heap_.data(); }
  const Row* end() const { return begin() + n_; }

 private:
  // The first row past kInline moves all rows to the heap.
  [[gnu::noinline]] void spill(const Row& r) {
    if (heap_.empty()) heap_.assign(inline_, inline_ + n_);
    heap_.push_back(r);
    ++n_;
  }

  Row inline_[kInline];
  size_t n_ = 0;
  std::vector<Row> heap_;  // all rows once spilled
};

struct Transition {
  RowList rows;
  i128 v_end = 0;
  i128 gain = 0;             // position LSBs covered
  i128 shortfall_bound = 0;  // the realised change falls short of dv by <= this
  bool too_far = false;
  void clear() {
    rows.clear();
    v_end = gain = shortfall_bound = 0;
    too_far = false;
  }
};

struct Limits {
  i128 v_rate;  // step-rate limit in LSB (exact: 2^F / (high + low))
  int64_t a_max;
  int64_t j_acc_in, j_acc_out, j_dec_in, j_dec_out;
  bool trapezoid;
  Units units;
  // Streamed moves: every transition ends at exactly its target velocity
  // (a short jerk-limited tail absorbs the sub-clock shortfall), so the next
  // move starts from the speed the look-ahead planned.
  bool exact_transitions = false;
  // Moves from an exact state (plan_from, streams): a start or end speed
  // above the cruise speed keeps the least-travel plateau unless the cruise
  // speed fits.
  bool least_above_cruise = false;
  // Streamed moves: the plateau's transitions cover as much of the final
  // pulse window as they can (the next move then has that much less to
  // cover) instead of the move's own fastest plan.
  bool reach_window_end = false;
};

// The request's limits in LSBs (a_max, jerks, the step-rate limit).
Limits make_limits(const MoveRequest& req, const PulseTiming& timing, Clock clock);

// Fastest change of velocity from v_from to v_to starting and ending at zero
// acceleration (see make_transition in planner.cpp).
// A velocity change of exactly `rest` LSB (> 0) in direction s from
// acceleration 0 back to 0, in at most three jerk-limited pulses (jerk <=
// j_lim, |a| <= a_max), appended to rows (their acc0 chained from 0).
void append_exact_tail(RowList& rows, i128 rest, int s, int64_t j_lim, int64_t a_max, Phase ph_up, Phase ph_down);

Transition transition_to(i128 v_from, i128 v_to, const Limits& lim);
void transition_to(Transition& out, i128 v_from, i128 v_to, const Limits& lim);  // into a fresh one

// Position LSBs a move must cover: any travel in [lo, hi) is accepted; the
// cruise length places the travel at the largest value <= aim (or the
// smallest one >= lo if that is below lo).
struct TravelWindow {
  i128 lo = 0, hi = 0, aim = 0;
};

// The solved profile of one move in magnitude (direction +1) form.
struct Solved {
  std::vector<Row> rows;
  i128 travel = 0;   // position LSBs covered, inside the window
  i128 plateau = 0;  // velocity between the two transitions
  i128 v_end = 0;    // realised end velocity
  i128 end_shortfall_bound = 0;
};

// Why no profile fits: the end speed cannot be reached within the window
// (far: the candidate that needs the least travel), or no motion fits at all.
struct Unsolvable {
  bool end_unreachable = false;
  bool too_far = false;  // even the least-travel candidate exceeds 1e12 pulses
  i128 least_gain = 0;   // travel of the least-travel candidate
};

// Chooses the plateau (v_cruise if the window allows it, else the plateau
// between v_cruise and max(vs, ve) whose transitions cover about the aimed
// travel: from the closed-form model, corrected by a few exact candidates)
// and the cruise length that places the travel in the window.
std::variant<Solved, Unsolvable> solve_profile(i128 vs, double v_cruise, i128 ve, const TravelWindow& w,
                                               const Limits& lim);

// Adjusted end speed (MoveRequest::adjust_end_speed): the end speed nearest
// to ve (LSB) between vs and ve that a move within the window reaches, found
// from the closed form and a few exact single transitions; none if only vs
// itself remains (vs = 0: a move from rest to rest is planned instead).
std::optional<i128> reachable_end_speed(i128 vs, i128 ve, i128 p_cruise, const TravelWindow& w,
                                        const Limits& lim);

// Splits rows to the hardware's clock field and mirrors them for direction.
std::vector<Segment> to_segments(const std::vector<Row>& rows, int dir);

std::string num(double v);

}  // namespace scurve::detail

namespace scurve::detail {

uint64_t rows_needed(const std::vector<Row>& rows);

// Closed-form travel (LSB) while the speed changes between x and y (LSB per
// clock) at peak acceleration a and jerk j (j <= 0: trapezoid): the mean
// speed times the duration. A starting point for exact searches only.
double closed_form_travel(double x, double y, double a, double j);

// A move from an exact start state to end speed ve (LSB, magnitude): the
// core of Planner::plan_from (no request validation). messages = false: an
// error names the parameter only (for searches that discard it).
PlanResult plan_continuation(const JunctionState& start, int64_t distance, double v_cruise, i128 ve,
                             const Limits& lim, Clock clock, bool messages = true);

// plan_continuation after `prefix`: rows (magnitude form, chained from the
// start state) that end at acceleration 0; the solved move continues from
// their end speed, over the window less their travel. An empty prefix is
// plan_continuation itself.
PlanResult plan_continuation(const JunctionState& start, const std::vector<Row>& prefix, int64_t distance,
                             double v_cruise, i128 ve, const Limits& lim, Clock clock, bool messages = true);

// The travel (magnitude, LSB) that ends a move of `distance` pulses from the
// position fraction `frac` in [distance, distance + 1) pulses from the
// start's integer part, aimed mid-pulse.
TravelWindow continuation_window(u128 frac, int64_t distance);

// The fields of a window (axis name, bounds within +-kMaxPosition, min <=
// max) and a start position, before any move is checked against them.
std::optional<Error> check_window_fields(const std::optional<SoftLimits>& window, int64_t start_position);
// The window rule of MoveRequest::soft_limits for a move of `distance`
// pulses from `start` (a move never reverses, so its target is its extreme
// position); `label` ("move 3: ") follows the axis in the message.
std::optional<Error> check_window(const SoftLimits& window, i128 start, int64_t distance, std::string_view label = {});

}  // namespace scurve::detail
