#include "scurve/stream_planner.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "solver.h"

namespace scurve {

using detail::Limits;

struct StreamPlanner::Solver {
  Limits lim;
};

namespace {

std::optional<Error> check_speed(const char* name, double v, double lo, double hi, const char* hi_name,
                                 bool lo_open = false) {
  if (!std::isfinite(v)) return Error{name, fmt::format("{}={}: must be a finite number", name, v)};
  if (lo_open ? v <= lo : v < lo) {
    return Error{name, fmt::format("{}={}: must be {} {} pulses/s", name, detail::num(v), lo_open ? ">" : ">=",
                                   detail::num(lo))};
  }
  if (v > hi) {
    return Error{name, fmt::format("{}={}: exceeds the limit {}={} pulses/s", name, detail::num(v), hi_name,
                                   detail::num(hi))};
  }
  return std::nullopt;
}

std::optional<Error> check_stream_config(Clock clock, const PulseTiming& timing, const StreamLimits& l) {
  if (std::string e = check_clock(clock); !e.empty()) return Error{"clock_hz", e};
  if (timing.high < 1) return Error{"pulse_high", "pulse_high=0: must be >= 1 clock"};
  if (timing.low < 1) return Error{"pulse_low", "pulse_low=0: must be >= 1 clock"};
  const auto range = [](const char* name, double v, LimitRange r, const char* unit) -> std::optional<Error> {
    if (!std::isfinite(v)) return Error{name, fmt::format("{}={}: must be a finite number", name, v)};
    if (v < r.lo) return Error{name, fmt::format("{}={}: must be >= {} {}", name, detail::num(v), detail::num(r.lo), unit)};
    if (v > r.hi) {
      return Error{name, fmt::format("{}={}: exceeds the limit {} {}", name, detail::num(v), detail::num(r.hi), unit)};
    }
    return std::nullopt;
  };
  if (auto e = range("a_max", l.a_max, accel_range(clock), "pulses/s^2")) return e;
  if (auto e = range("j_max", l.j_max, jerk_range(clock), "pulses/s^3")) return e;
  if (auto e = check_speed("v_max", l.v_max, PlannerLimits::kMinCruise, step_rate_limit(timing, clock),
                           "step-rate limit")) {
    return e;
  }
  return detail::check_window_fields(l.soft_limits, l.start_position);
}

// Largest dv in [0, dv_max] whose closed-form travel from speed v is <= budget
// (to 1e-6: the guess of an exact search on a grid 2^-12 of the speed).
double closed_form_dv(double v, double budget, double dv_max, double a, double j) {
  double lo = 0, hi = dv_max;
  if (detail::closed_form_travel(v, v + hi, a, j) <= budget) return hi;
  for (int i = 0; i < 100 && hi - lo > 1e-6 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (detail::closed_form_travel(v, v + mid, a, j) <= budget ? lo : hi) = mid;
  }
  return lo;
}

// Largest speed on the grid {lo_ok} + {k * grid} within [lo_ok, top] that
// `ok` accepts (lo_ok must be accepted), searched outward from `guess`. The
// grid makes the answer independent of the guess, so a junction only moves
// when its constraints do.
template <class Ok>
i128 largest_accepted(i128 lo_ok, i128 top, i128 grid, i128 guess, const Ok& ok) {
  const auto snap = [&](i128 v) { return std::clamp(v / grid * grid, lo_ok, top); };
  if (ok(top)) return top;
  i128 lo = lo_ok, hi = top;  // ok(lo), !ok(hi); inner points on the grid
  guess = snap(guess);
  i128 step = grid;
  if (guess > lo && guess < hi) {
    if (ok(guess)) {
      lo = guess;
      for (i128 c = snap(lo + step); c > lo && c < hi; step *= 4, c = snap(lo + step)) {
        if (!ok(c)) {
          hi = c;
          break;
        }
        lo = c;
      }
    } else {
      hi = guess;
      for (i128 c = snap(hi - step); c > lo && c < hi; step *= 4, c = snap(hi - step)) {
        if (ok(c)) {
          lo = c;
          break;
        }
        hi = c;
      }
    }
  }
  for (;;) {
    const i128 mid = snap(lo + (hi - lo) / 2);
    if (mid <= lo || mid >= hi) break;
    (ok(mid) ? lo : hi) = mid;
  }
  return lo;
}

i128 speed_lsb(double v, const Limits& lim) { return std::min(i128(std::floor(v * lim.units.vel)), lim.v_rate); }

}  // namespace

StreamPlanner::StreamPlanner(Clock clock, PulseTiming timing, StreamLimits limits, u128 start_frac,
                             size_t lookahead)
    : clock_(clock), timing_(timing), limits_(limits), lookahead_(std::max<size_t>(2, lookahead)) {
  config_error_ = check_stream_config(clock, timing, limits);
  if (!config_error_ && start_frac >= kOne) {
    config_error_ = Error{"start_frac", fmt::format("start_frac={}: must be < 2^{} (one pulse)",
                                                    to_hex_u128(start_frac, 128), hw::FracBits)};
  }
  state_.frac = start_frac;
  appended_end_ = limits.start_position;
  if (config_error_) return;
  MoveRequest req;
  req.a_max = limits.a_max;
  req.j_max = limits.j_max;
  auto solver = std::make_shared<Solver>(Solver{detail::make_limits(req, timing, clock)});
  solver->lim.exact_transitions = true;  // junction speeds are met exactly
  solver->lim.least_above_cruise = true;
  solver->lim.reach_window_end = true;
  solver_ = std::move(solver);
}

std::optional<Error> StreamPlanner::check_move(const StreamMove& m) const {
  if (config_error_) return config_error_;
  if (m.distance == 0) return Error{"distance", "distance=0: must be non-zero"};
  if (m.distance > PlannerLimits::kMaxDistance || m.distance < -PlannerLimits::kMaxDistance) {
    return Error{"distance",
                 fmt::format("distance={}: exceeds the limit +-{} pulses", m.distance, PlannerLimits::kMaxDistance)};
  }
  if (auto e = check_speed("v_cruise", m.v_cruise, PlannerLimits::kMinCruise, limits_.v_max, "v_max")) return e;
  if (auto e = check_speed("v_junction_max", m.v_junction_max, 0, limits_.v_max, "v_max")) return e;
  if (!limits_.soft_limits) return std::nullopt;
  const uint64_t index = next_index_ + queue_.size();  // the index this move gets
  return detail::check_window(*limits_.soft_limits, appended_end_, m.distance, fmt::format("move {}: ", index));
}

// Junction speeds found by search below `top` are multiples of this: the
// power of two at or below top / 2^12 (about 0.01% to 0.02% of top).
i128 StreamPlanner::grid(i128 top) {
  if (top < (i128(1) << 13)) return 1;
  const u128 t = u128(top);
  const int bits = t >> 64 ? 128 - __builtin_clzll(uint64_t(t >> 64)) : 64 - __builtin_clzll(uint64_t(t));
  return i128(1) << (bits - 13);  // the least power of two with g * 2^13 > top
}

// Position LSBs covered while changing speed (the planner's own transition).
i128 StreamPlanner::travel(i128 v_from, i128 v_to) const {
  const u128 h = (u128(v_from) * 0x9E3779B97F4A7C15ull) ^ u128(v_to);
  TravelMemo& m = travel_memo_[size_t(uint64_t(h ^ (h >> 64)) * 0x9E3779B97F4A7C15ull >> 56)];
  if (m.from == v_from && m.to == v_to) return m.gain;
  const detail::Transition t = detail::transition_to(v_from, v_to, solver_->lim);
  m = {v_from, v_to, t.too_far ? std::numeric_limits<i128>::max() : t.gain};
  return m.gain;
}

// Highest entry speed that still reaches v_exit within `distance` pulses.
// distance * 2^F is the least travel window any start fraction allows (the
// window's upper end is at least distance * 2^F + 1), so the move is
// plannable whatever fraction it starts from.
i128 StreamPlanner::max_entry(int64_t distance, i128 v_exit, i128 top) const {
  const Limits& lim = solver_->lim;
  const i128 budget = i128(distance) * i128(kOne);
  const double dv = closed_form_dv(double(v_exit), double(budget), double(top - v_exit), double(lim.a_max),
                                   double(lim.j_dec_in));
  return largest_accepted(v_exit, top, grid(top), v_exit + i128(dv),
                          [&](i128 v) { return travel(v, v_exit) <= budget; });
}

// Highest exit speed reachable from v_entry within `distance` pulses.
i128 StreamPlanner::max_exit(i128 v_entry, int64_t distance, i128 top) const {
  const Limits& lim = solver_->lim;
  const i128 budget = i128(distance) * i128(kOne);
  const double dv = closed_form_dv(double(v_entry), double(budget), double(top - v_entry), double(lim.a_max),
                                   double(lim.j_acc_in));
  return largest_accepted(v_entry, top, grid(top), v_entry + i128(dv),
                          [&](i128 v) { return travel(v_entry, v) <= budget; });
}

// Junction k (into queue_[k], k >= 1): the highest entry speed from which the
// rest of the queue can stop, capped. Stops where a junction is unchanged:
// the ones before it depend only on it.
bool StreamPlanner::backward_pass() {
  i128 v_exit = 0;  // the end of the queue: rest
  size_t first_changed = queue_.size();
  for (size_t k = queue_.size() - 1; k >= 1; --k) {
    Queued& q = queue_[k];
    const int64_t dist = q.move.distance < 0 ? -q.move.distance : q.move.distance;
    i128 back;
    bool reached;
    if (travel(q.cap_in, v_exit) <= i128(dist) * i128(kOne)) {
      back = q.cap_in;
      reached = true;
    } else {
      back = q.cap_in > v_exit ? max_entry(dist, v_exit, q.cap_in) : q.cap_in;
      reached = false;
    }
    const bool same = back == q.back_in && reached == q.cap_reached;
    if (same && k + 1 < queue_.size()) break;
    q.back_in = back;
    q.cap_reached = reached;
    first_changed = k;
    v_exit = back;
  }
  return forward_pass(std::min(first_changed, queue_.size() - 1));
}

// Junctions from `from` on: also reachable from the previous junction.
// False if a move cannot get from its (frozen) entry speed to any exit the
// rest of the queue allows within its distance.
bool StreamPlanner::forward_pass(size_t from) {
  Queued& front = queue_.front();
  front.v_in = state_.velocity < 0 ? -state_.velocity : state_.velocity;
  front.final_in = true;
  for (size_t k = std::max<size_t>(from, 1); k < queue_.size(); ++k) {
    const Queued& prev = queue_[k - 1];
    Queued& q = queue_[k];
    const int64_t dist = prev.move.distance < 0 ? -prev.move.distance : prev.move.distance;
    const i128 budget = i128(dist) * i128(kOne);
    bool forward_limited = false, lowered_to_brake = false;
    q.v_in = q.back_in;
    if (q.back_in > prev.v_in && travel(prev.v_in, q.back_in) > budget) {
      q.v_in = max_exit(prev.v_in, dist, q.back_in);
      forward_limited = true;
    } else if (q.back_in < prev.v_in && travel(prev.v_in, q.back_in) > budget) {
      // A short jerk-limited braking covers less distance to rest than to a
      // third of its start speed, so a higher exit can need more room than
      // the backward pass (computed for a lower one) gave. Brake further:
      // any lower exit keeps the rest of the queue stoppable.
      if (travel(prev.v_in, 0) > budget) return false;
      q.v_in = largest_accepted(0, q.back_in, grid(q.back_in), 0,
                                [&](i128 e) { return travel(prev.v_in, e) <= budget; });
      lowered_to_brake = true;
    }
    // Appends raise back_in in general; a junction held by its cap or by
    // what the previous move can reach keeps its value.
    q.final_in = prev.final_in && !lowered_to_brake && (q.cap_reached || forward_limited);
  }
  return true;
}

std::optional<Error> StreamPlanner::append(const StreamMove& move) {
  if (auto e = check_move(move)) return e;
  appended_end_ += move.distance;
  const Limits& lim = solver_->lim;
  Queued q;
  q.move = move;
  q.dir = move.distance < 0 ? -1 : 1;
  q.cruise = speed_lsb(move.v_cruise, lim);
  if (!queue_.empty()) {
    const Queued& prev = queue_.back();
    q.cap_in = prev.dir != q.dir ? 0 : std::min({speed_lsb(move.v_junction_max, lim), prev.cruise, q.cruise});
  }
  if (queue_.empty()) {
    queue_.push_back(q);
    forward_pass(0);
    return std::nullopt;
  }
  saved_.assign(queue_.begin(), queue_.end());  // reuses its capacity
  queue_.push_back(q);
  if (!backward_pass()) {
    // The new junctions do not fit the frozen entry speed: keep the queue as
    // it was (valid, ending at rest) and enter the new move from rest.
    queue_.assign(saved_.begin(), saved_.end());
    q.v_in = q.back_in = 0;
    q.cap_reached = q.final_in = false;
    queue_.push_back(q);
  }
  return release_ready();
}

std::optional<Error> StreamPlanner::plan_front(i128 v_out) {
  const Queued q = queue_.front();
  PlanResult r = detail::plan_continuation(state_, q.move.distance, q.move.v_cruise, v_out, solver_->lim, clock_);
  if (auto* e = std::get_if<Error>(&r)) return *e;
  Plan& p = std::get<Plan>(r);
  StreamedMove m;
  m.index = next_index_++;
  m.distance = q.move.distance;
  m.segments = std::move(p.segments);
  m.start = state_;
  m.end = p.end_state;
  m.v_in = vel_to_phys(q.v_in, clock_);
  m.v_out = vel_to_phys(v_out, clock_);
  m.start_clock = clock_offset_;
  m.end_clock = clock_offset_ + p.total_clocks;
  position_ += q.move.distance;
  m.end_position = position_;
  state_ = p.end_state;
  clock_offset_ = m.end_clock;
  ready_.push_back(std::move(m));
  queue_.pop_front();
  if (!queue_.empty()) {  // the new front starts from the exact state just planned
    queue_.front().v_in = v_out;
    queue_.front().final_in = true;
  }
  return std::nullopt;
}

// Plans the moves between final junctions, and the oldest ones beyond the
// lookahead (their junctions always allow stopping within the queue).
std::optional<Error> StreamPlanner::release_ready() {
  while (queue_.size() >= 2 && (queue_[1].final_in || queue_.size() > lookahead_)) {
    if (auto e = plan_front(queue_[1].v_in)) return e;
  }
  return std::nullopt;
}

std::optional<Error> StreamPlanner::flush() {
  if (config_error_) return config_error_;
  while (!queue_.empty()) {
    if (auto e = plan_front(queue_.size() >= 2 ? queue_[1].v_in : 0)) return e;
  }
  return std::nullopt;
}

std::vector<StreamedMove> StreamPlanner::take_ready() {
  std::vector<StreamedMove> out;
  out.swap(ready_);
  return out;
}

std::vector<double> StreamPlanner::queued_junctions() const {
  std::vector<double> v;
  for (const Queued& q : queue_) v.push_back(vel_to_phys(q.v_in, clock_));
  if (!queue_.empty()) v.push_back(0.0);
  return v;
}

std::variant<std::vector<StreamedMove>, Error> plan_whole_stream(Clock clock, PulseTiming timing,
                                                                 const StreamLimits& limits,
                                                                 const std::vector<StreamMove>& moves) {
  StreamPlanner sp(clock, timing, limits);
  std::vector<StreamedMove> planned;
  for (size_t i = 0; i < moves.size(); ++i) {
    if (auto e = sp.append(moves[i])) return Error{e->parameter, fmt::format("moves[{}]: {}", i, e->message)};
    for (StreamedMove& m : sp.take_ready()) planned.push_back(std::move(m));
  }
  if (auto e = sp.flush()) return *e;
  for (StreamedMove& m : sp.take_ready()) planned.push_back(std::move(m));
  return planned;
}

}  // namespace scurve
