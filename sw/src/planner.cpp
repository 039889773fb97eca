#include "scurve/planner.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace scurve {

using hw::MaxSegs;
using hw::SegClkW;

namespace {

// The clock rate and the LSB scales derived from it.
struct Units {
  double f;     // clock, Hz
  double vel;   // LSB per pulse/s
  double acc;   // LSB per pulse/s^2
  double jerk;  // LSB per pulse/s^3
  explicit Units(Clock c)
      : f(c.hz), vel(vel_lsb_per_unit(c)), acc(acc_lsb_per_unit(c)), jerk(jerk_lsb_per_unit(c)) {}
};
constexpr uint64_t kMaxRowClocks = (uint64_t(1) << SegClkW) - 1;
// Transitions whose estimated length exceeds this are treated as infeasible
// before any exact arithmetic, which keeps every closed form far from the
// 128-bit range (1e12 pulses * 2^80 < 2^127).
constexpr double kFarPulses = 1e12;

// A row before splitting to the hardware's 32-bit clock field.
struct Row {
  Phase phase;
  uint64_t clocks;
  int64_t jerk;
  int64_t acc0;
  i128 vel0;
};

struct Transition {
  std::vector<Row> rows;
  i128 v_end = 0;
  i128 gain = 0;       // position LSBs covered
  i128 shortfall_bound = 0;  // the realised change falls short of dv by <= this
  bool too_far = false;
};

i128 row_gain(const Row& r) { return pos_gain(r.vel0, r.acc0, r.jerk, r.clocks); }

// Fastest change of velocity from v_a by at most dv (>= 0, magnitude) in
// direction s, starting and ending at zero acceleration. Jerk j_in while
// |a| rises, j_out while it falls; trapezoid: constant acceleration only.
// The realised change never exceeds dv and falls short by less than one
// clock at the peak acceleration.
Transition make_transition(i128 v_a, i128 dv, int s, int64_t j_in, int64_t j_out,
                           int64_t a_max, bool trapezoid, const Units& u) {
  Transition t;
  t.v_end = v_a;
  if (dv <= 0) return t;
  const Phase ph_up = s > 0 ? Phase::PhAccJerkUp : Phase::PhDecJerkUp;
  const Phase ph_const = s > 0 ? Phase::PhAccConst : Phase::PhDecConst;
  const Phase ph_down = s > 0 ? Phase::PhAccJerkDown : Phase::PhDecJerkDown;
  const double dvd = double(dv);
  const double v_hi = std::max(double(v_a), double(v_a) + s * dvd) / u.vel;

  if (trapezoid) {
    const double secs = dvd / double(a_max) / u.f;
    if (secs * v_hi > kFarPulses) {
      t.too_far = true;
      return t;
    }
    // Fewest clocks at <= a_max; a change below one clock of a_max still
    // takes one clock (at a lower acceleration), it is never dropped.
    const i128 n = (dv + a_max - 1) / a_max;
    const int64_t a = int64_t(dv / n);
    t.rows.push_back({ph_const, uint64_t(n), 0, int64_t(s) * a, v_a});
    t.shortfall_bound = n;  // dv - n*floor(dv/n) < n
  } else {
    const double a_full = double(a_max);
    const double thresh = a_full * a_full * (0.5 / double(j_in) + 0.5 / double(j_out));
    const double a_peak =
        dvd >= thresh ? a_full : std::sqrt(2.0 * dvd / (1.0 / double(j_in) + 1.0 / double(j_out)));
    const double secs = (a_peak / double(j_in) + a_peak / double(j_out) +
                         std::max(0.0, dvd - thresh) / a_full) / u.f;
    if (secs * v_hi > kFarPulses) {
      t.too_far = true;
      return t;
    }
    // Peak acceleration a (<= a_max): the ramps take ceil(a / j) clocks at
    // jerk floor(a / clocks) <= j, so a ramp shorter than one clock still
    // takes one clock. If the jerk phases alone overshoot dv, shrink a.
    int64_t a = std::clamp<int64_t>(int64_t(a_peak), 1, a_max);
    for (int iter = 0; iter < 400; ++iter) {
      // Ramp clocks: floor(a/j) keeps the jerk at exactly j (long ramps),
      // ceil(a/j) at a slightly lower jerk reaches nearer to a (ramps of a
      // few clocks); take whichever peaks higher.
      const int64_t n_floor = std::max<int64_t>(1, a / j_in);
      const int64_t n_ceil = (a + j_in - 1) / j_in;
      const int64_t a_floor = n_floor * std::min(j_in, a / n_floor);
      const int64_t a_ceil = n_ceil * (a / n_ceil);
      const int64_t n1 = a_floor >= a_ceil ? n_floor : n_ceil;
      const int64_t j1 = std::min(j_in, a / n1);
      const int64_t a1 = n1 * j1;  // realised peak, <= a
      const int64_t n3 = (a1 + j_out - 1) / j_out;
      const int64_t j3 = a1 / n3;
      const int64_t r = a1 - n3 * j3;  // first r clocks at j3+1: a ends at exactly 0
      std::vector<Row> rows;
      rows.push_back({ph_up, uint64_t(n1), s * j1, 0, 0});
      rows.push_back({ph_const, 0, 0, s * a1, 0});
      if (r > 0) rows.push_back({ph_down, uint64_t(r), -s * (j3 + 1), 0, 0});
      rows.push_back({ph_down, uint64_t(n3 - r), -s * j3, 0, 0});
      // Velocity gained by the jerk rows alone (the constant row adds n2*a1).
      i128 dv_jerk = 0;
      int64_t acc = 0;
      for (const Row& row : rows) {
        if (row.jerk == 0) continue;
        dv_jerk += vel_after(0, acc, row.jerk, row.clocks);
        acc = int64_t(acc_after(acc, row.jerk, row.clocks));
      }
      dv_jerk = s > 0 ? dv_jerk : -dv_jerk;
      if (dv_jerk > dv) {
        if (a == 1) break;  // dv below one LSB of velocity change: nothing to do
        const double shrink = std::sqrt(double(dv) / double(dv_jerk));
        a = std::clamp<int64_t>(int64_t(double(a) * shrink * 0.999), 1, a - 1);
        continue;
      }
      rows[1].clocks = uint64_t((dv - dv_jerk) / a1);
      t.shortfall_bound = a1;  // less than one more clock at the peak
      for (const Row& row : rows) {
        if (row.clocks > 0) t.rows.push_back(row);
      }
      break;
    }
  }
  // Chain exact starting values through the rows.
  i128 v = v_a;
  int64_t a = 0;
  for (Row& row : t.rows) {
    row.vel0 = v;
    if (row.jerk != 0 || row.phase == ph_up) row.acc0 = a;
    t.gain += row_gain(row);
    v = vel_after(row.vel0, row.acc0, row.jerk, row.clocks);
    a = int64_t(acc_after(row.acc0, row.jerk, row.clocks));
  }
  t.v_end = v;
  return t;
}

struct Limits {
  i128 v_rate;  // step-rate limit in LSB (exact: 2^F / (high + low))
  int64_t a_max;
  int64_t j_acc_in, j_acc_out, j_dec_in, j_dec_out;
  bool trapezoid;
  Units units;
};

Transition transition_to(i128 v_from, i128 v_to, const Limits& lim) {
  if (v_to >= v_from) {
    return make_transition(v_from, v_to - v_from, +1, lim.j_acc_in, lim.j_acc_out, lim.a_max,
                           lim.trapezoid, lim.units);
  }
  return make_transition(v_from, v_from - v_to, -1, lim.j_dec_in, lim.j_dec_out, lim.a_max,
                         lim.trapezoid, lim.units);
}

struct Candidate {
  Transition t1, t2;
  i128 remainder = 0;  // target - transition gain
  bool feasible = false;
  bool too_far = false;
};

Candidate evaluate(i128 vs, double v1, i128 ve, i128 target, const Limits& lim) {
  Candidate c;
  const i128 v1_lsb = std::min(i128(std::floor(v1 * lim.units.vel)), lim.v_rate);
  c.t1 = transition_to(vs, v1_lsb, lim);
  c.t2 = transition_to(c.t1.v_end, ve, lim);
  c.too_far = c.t1.too_far || c.t2.too_far;
  if (c.too_far) return c;
  c.remainder = target - c.t1.gain - c.t2.gain;
  const i128 plateau = c.t1.v_end;
  // The plateau row must absorb remainder - p0 with p0 in [1, plateau]:
  // possible for any remainder >= 1 if plateau > 0, else only a tiny one.
  c.feasible = c.remainder >= 1 && (plateau > 0 || c.remainder < i128(kOne));
  return c;
}

// Shortest text that reads back as the same double: the value as the user gave it.
std::string num(double v) { return fmt::format("{}", v); }

std::optional<PlanError> check_range(const char* name, double v, double lo, double hi,
                                     const char* unit, bool lo_open = false) {
  if (!std::isfinite(v)) return PlanError{name, fmt::format("{}={}: must be a finite number", name, v)};
  if (lo_open ? v <= lo : v < lo) {
    return PlanError{name, fmt::format("{}={}: must be {} {} {}", name, num(v), lo_open ? ">" : ">=",
                                       num(lo), unit)};
  }
  if (v > hi) {
    return PlanError{name, fmt::format("{}={}: exceeds the limit {} {}", name, num(v), num(hi), unit)};
  }
  return std::nullopt;
}

i128 pulses_to_lsb(int64_t p) { return i128(p) * i128(kOne); }

// Smallest distance (pulses) that leaves the candidate's transitions a
// remainder >= 1 LSB: distance * 2^F + 2^(F-1) - gain >= 1.
int64_t needed_distance(const Candidate& c, i128 target) {
  const i128 gain = target - c.remainder;  // position covered by the transitions
  const i128 num = gain + 1 - (i128(kOne) >> 1);
  return int64_t(num <= 0 ? 0 : (num + i128(kOne) - 1) / i128(kOne));
}

// refine_minimum: on an unreachable end speed, search the shortest distance
// the planner accepts, so the message names the true minimum (the closed-form
// estimate can be a pulse or two high). The search itself plans without it.
PlanResult plan_magnitude(const MoveRequest& req, const PulseTiming& timing, double v_end, Clock clock,
                          bool refine_minimum = true);

}  // namespace

double step_rate_limit(const PulseTiming& timing, Clock clock) {
  return clock.hz / (double(timing.high) + double(timing.low));
}

std::string check_clock(const Clock& clock) {
  if (!std::isfinite(clock.hz)) {
    return fmt::format("clock_hz={}: must be a finite number within {}..{} Hz", clock.hz, num(Clock::kMinHz),
                       num(Clock::kMaxHz));
  }
  if (!(clock.hz >= Clock::kMinHz && clock.hz <= Clock::kMaxHz)) {
    return fmt::format("clock_hz={}: outside the accepted range {}..{} Hz", num(clock.hz), num(Clock::kMinHz),
                       num(Clock::kMaxHz));
  }
  return {};
}

// One LSB at least, half the register range at most (room for the per-clock
// sums), within the PlannerLimits bounds.
LimitRange accel_range(Clock clock) {
  const double lsb = 1.0 / acc_lsb_per_unit(clock);
  const double top = std::ldexp(1.0, hw::AccW - 2) * lsb;
  return {std::max(PlannerLimits::kMinAccel, lsb), std::min(PlannerLimits::kMaxAccel, top)};
}

LimitRange jerk_range(Clock clock) {
  const double lsb = 1.0 / jerk_lsb_per_unit(clock);
  const double top = std::ldexp(1.0, hw::JerkW - 2) * lsb;
  return {std::max(PlannerLimits::kMinJerk, lsb), std::min(PlannerLimits::kMaxJerk, top)};
}

const char* phase_name(Phase p) {
  switch (p) {
    case Phase::PhIdle: return "idle";
    case Phase::PhAccJerkUp: return "acc-jerk-up";
    case Phase::PhAccConst: return "acc-const";
    case Phase::PhAccJerkDown: return "acc-jerk-down";
    case Phase::PhCruise: return "cruise";
    case Phase::PhDecJerkUp: return "dec-jerk-up";
    case Phase::PhDecConst: return "dec-const";
    case Phase::PhDecJerkDown: return "dec-jerk-down";
    case Phase::PhDone: return "done";
    case Phase::PhAbort: return "abort";
    case Phase::PhFault: return "fault";
  }
  return "?";
}

PlanResult Planner::plan(const MoveRequest& req, const PulseTiming& timing) const {
  const Clock clock = clock_;
  // ---- limits checked before solving ------------------------------------
  if (std::string e = check_clock(clock); !e.empty()) return PlanError{"clock_hz", e};
  if (timing.high < 1) return PlanError{"pulse_high", "pulse_high=0: must be >= 1 clock"};
  if (timing.low < 1) return PlanError{"pulse_low", "pulse_low=0: must be >= 1 clock"};
  if (req.distance == 0) return PlanError{"distance", "distance=0: must be non-zero"};
  if (req.distance > PlannerLimits::kMaxDistance || req.distance < -PlannerLimits::kMaxDistance) {
    return PlanError{"distance", fmt::format("distance={}: exceeds the limit +-{} pulses",
                                             req.distance, PlannerLimits::kMaxDistance)};
  }
  const double v_lim = step_rate_limit(timing, clock);
  const std::string rate_note = fmt::format(
      " pulses/s (step-rate limit: pulse high {} + low {} clocks at {} MHz)", timing.high,
      timing.low, clock.hz / 1e6);
  const LimitRange acc_ok = accel_range(clock), jerk_ok = jerk_range(clock);
  if (auto e = check_range("v_start", req.v_start, 0, v_lim, rate_note.c_str())) return *e;
  if (auto e = check_range("v_cruise", req.v_cruise, PlannerLimits::kMinCruise, v_lim, rate_note.c_str())) {
    return *e;
  }
  if (auto e = check_range("v_end", req.v_end, 0, v_lim, rate_note.c_str())) return *e;
  if (auto e = check_range("a_max", req.a_max, acc_ok.lo, acc_ok.hi,
                           "pulses/s^2")) {
    return *e;
  }
  if (req.kind == ProfileKind::SCurve) {
    if (req.jerks) {
      static const char* names[4] = {"jerk_ts1", "jerk_ts2", "jerk_te1", "jerk_te2"};
      for (int i = 0; i < 4; ++i) {
        if (auto e = check_range(names[i], (*req.jerks)[i], jerk_ok.lo, jerk_ok.hi,
                                 "pulses/s^3")) {
          return *e;
        }
      }
    } else if (auto e = check_range("j_max", req.j_max, jerk_ok.lo, jerk_ok.hi,
                                    "pulses/s^3")) {
      return *e;
    }
  }

  // The minimum-distance search runs only for an error the user will see.
  PlanResult r = plan_magnitude(req, timing, req.v_end, clock, !req.adjust_end_speed);
  if (std::holds_alternative<PlanError>(r) && req.adjust_end_speed &&
      std::get<PlanError>(r).parameter == "v_end" && req.v_end != req.v_start) {
    // Bisect the end speed between v_start (always reachable) and v_end.
    double ok = req.v_start, bad = req.v_end;
    std::optional<Plan> best;
    for (int it = 0; it < 64; ++it) {
      const double mid = 0.5 * (ok + bad);
      PlanResult m = plan_magnitude(req, timing, mid, clock, false);
      if (std::holds_alternative<Plan>(m)) {
        ok = mid;
        best = std::get<Plan>(m);
      } else {
        bad = mid;
      }
    }
    if (!best) {
      PlanResult m = plan_magnitude(req, timing, req.v_start, clock, false);
      if (std::holds_alternative<Plan>(m)) best = std::get<Plan>(m);
    }
    if (best) {
      best->end_speed_adjusted = true;
      return *best;
    }
    return plan_magnitude(req, timing, req.v_end, clock, true);
  }
  return r;
}

namespace {

PlanResult plan_magnitude(const MoveRequest& req, const PulseTiming& timing, double v_end, Clock clock,
                          bool refine_minimum) {
  const Units u(clock);
  const int dir = req.distance < 0 ? -1 : 1;
  const int64_t dist = req.distance * dir;
  const bool trap = req.kind == ProfileKind::Trapezoid;
  Limits lim{0, 0, 0, 0, 0, 0, false, u};
  lim.v_rate = i128(kOne) / (i128(timing.high) + timing.low);
  lim.a_max = int64_t(std::floor(req.a_max * u.acc));
  lim.trapezoid = trap;
  if (!trap) {
    std::array<double, 4> j = req.jerks.value_or(std::array<double, 4>{req.j_max, req.j_max,
                                                                       req.j_max, req.j_max});
    lim.j_acc_in = int64_t(std::floor(j[0] * u.jerk));
    lim.j_acc_out = int64_t(std::floor(j[1] * u.jerk));
    lim.j_dec_in = int64_t(std::floor(j[2] * u.jerk));
    lim.j_dec_out = int64_t(std::floor(j[3] * u.jerk));
  }
  const i128 vs = std::min(i128(std::floor(req.v_start * u.vel)), lim.v_rate);
  const i128 ve = std::min(i128(std::floor(v_end * u.vel)), lim.v_rate);
  const i128 target = pulses_to_lsb(dist) + (i128(kOne) >> 1);  // end mid-pulse

  // ---- choose the plateau velocity ---------------------------------------
  // The plateau is the cruise speed if the distance allows it; otherwise the
  // feasible plateau closest to v_cruise, searched toward max(v_start, v_end)
  // (the plateau that needs the least distance).
  Candidate c = evaluate(vs, req.v_cruise, ve, target, lim);
  if (!c.feasible) {
    const double v_far = std::max(req.v_start, v_end);
    const Candidate far = evaluate(vs, v_far, ve, target, lim);
    const bool far_is_stop = v_far == 0.0;  // vs = ve = 0: a tiny plateau always fits
    if (!far_is_stop && !far.feasible) {
      const char* hint = req.adjust_end_speed ? "" : " (or allow --adjust-end-speed)";
      std::string need = "more than 1e12";
      if (!far.too_far) {
        int64_t min_dist = needed_distance(far, target);
        if (refine_minimum) {
          const auto accepts = [&](int64_t d) {
            MoveRequest r = req;
            r.distance = d * dir;
            return d <= PlannerLimits::kMaxDistance &&
                   std::holds_alternative<Plan>(plan_magnitude(r, timing, v_end, clock, false));
          };
          // Local search from the estimate: the result is accepted and one
          // pulse less is not.
          for (int k = 0; k < 64 && min_dist > 1 && accepts(min_dist - 1); ++k) --min_dist;
          for (int k = 0; k < 64 && !accepts(min_dist); ++k) ++min_dist;
        }
        need = fmt::format("{}", min_dist);
      }
      if (v_end > req.v_start) {
        return PlanError{"v_end", fmt::format("v_end={} unreachable from v_start={}: needs distance >= {} "
                                              "pulses, got {}{}",
                                              num(v_end), num(req.v_start), need, dist, hint)};
      }
      return PlanError{"v_end", fmt::format("v_end={} unreachable: slowing from v_start={} needs distance "
                                            ">= {} pulses, got {}{}",
                                            num(v_end), num(req.v_start), need, dist, hint)};
    }
    // Walk geometrically from v_cruise toward v_far, then bisect.
    double bad = req.v_cruise, good = -1;
    Candidate good_c;
    for (int k = 1; k <= 2000; ++k) {
      const double v = v_far + (req.v_cruise - v_far) * std::pow(0.97, k);
      Candidate t = evaluate(vs, v, ve, target, lim);
      if (t.feasible) {
        good = v;
        good_c = t;
        break;
      }
      bad = v;
    }
    if (good < 0 && !far_is_stop) {
      good = v_far;
      good_c = far;
    }
    if (good < 0) {
      return PlanError{"distance", fmt::format("distance={}: too short for any motion with these limits", dist)};
    }
    for (int it = 0; it < 80; ++it) {
      const double mid = 0.5 * (bad + good);
      if (mid == bad || mid == good) break;
      Candidate t = evaluate(vs, mid, ve, target, lim);
      if (t.feasible) {
        good = mid;
        good_c = t;
      } else {
        bad = mid;
      }
    }
    c = good_c;
  }

  // ---- fill: plateau clocks and the initial fraction ---------------------
  const i128 plateau = c.t1.v_end;
  uint64_t n_cruise = 0;
  i128 p0 = c.remainder;
  if (plateau > 0) {
    const i128 n = (c.remainder - 1) / plateau;  // p0 = remainder - n*plateau in [1, plateau]
    n_cruise = uint64_t(n);
    p0 = c.remainder - n * plateau;
  }
  std::vector<Row> rows = c.t1.rows;
  if (n_cruise > 0) rows.push_back({Phase::PhCruise, n_cruise, 0, 0, plateau});
  rows.insert(rows.end(), c.t2.rows.begin(), c.t2.rows.end());
  if (rows.empty()) {
    return PlanError{"distance", fmt::format("distance={}: too short for any motion with these limits", dist)};
  }

  // ---- split rows to the 32-bit clock field, mirror for direction ---------
  uint64_t rows_needed = 0;
  for (const Row& r : rows) rows_needed += (r.clocks + kMaxRowClocks - 1) / kMaxRowClocks;
  if (rows_needed > uint64_t(MaxSegs)) {
    return PlanError{"distance", fmt::format("distance={}: the move needs {} table rows, the executor holds {} "
                                             "(a row lasts at most {:.1f} s); raise v_cruise or split the move",
                                             dist, rows_needed, MaxSegs, kMaxRowClocks / u.f)};
  }
  Plan plan;
  plan.clock = clock;
  for (const Row& r0 : rows) {
    Row r = r0;
    while (r.clocks > 0) {
      const uint64_t n = std::min(r.clocks, kMaxRowClocks);
      Segment s;
      s.phase = r.phase;
      s.clocks = uint32_t(n);
      s.jerk = dir * r.jerk;
      s.acc0 = dir * r.acc0;
      s.vel0 = dir * r.vel0;
      plan.segments.push_back(s);
      r.vel0 = vel_after(r.vel0, r.acc0, r.jerk, n);
      r.acc0 = int64_t(acc_after(r.acc0, r.jerk, n));
      r.clocks -= n;
    }
  }
  plan.pos_frac0 = dir > 0 ? u128(p0) : kOne - u128(p0);
  plan.distance = req.distance;
  plan.v_plateau = vel_to_phys(plateau, clock);
  plan.v_end_used = v_end;
  plan.v_end_actual = vel_to_phys(c.t2.rows.empty() ? plateau : c.t2.v_end, clock);

  // ---- re-check the result by executing it (Ruckig style) ----------------
  const TableReport rep = run_table(plan.segments, plan.pos_frac0, dir);
  // Transitions fall short of their target by less than one clock at the
  // peak acceleration; anything more is a planner bug (a dropped transition).
  const i128 v_end_real = c.t2.v_end;
  const i128 end_miss = v_end_real > ve ? v_end_real - ve : ve - v_end_real;
  const i128 v_cap = std::min(i128(std::floor(std::max({req.v_cruise, req.v_start, v_end}) * u.vel)),
                              lim.v_rate);
  const i128 v_rate = lim.v_rate;
  const int64_t j_cap = trap ? 0
                             : std::max({lim.j_acc_in, lim.j_acc_out, lim.j_dec_in, lim.j_dec_out});
  std::string why;
  if (!rep.ok) why = rep.error;
  else if (rep.steps != req.distance) why = fmt::format("steps {} != distance", rep.steps);
  else if (rep.min_signed_vel < 0) why = "velocity reverses";
  else if (rep.peak_vel > v_cap || rep.peak_vel > v_rate) why = "velocity limit exceeded";
  else if (rep.peak_acc > lim.a_max) why = "acceleration limit exceeded";
  else if (!trap && rep.peak_jerk > j_cap) why = "jerk limit exceeded";
  else if (end_miss > c.t2.shortfall_bound) why = "end speed missed";
  if (!why.empty()) {
    return PlanError{"internal", fmt::format("internal planner error ({}); please report the request", why)};
  }
  plan.total_clocks = rep.clocks;
  plan.duration_s = double(rep.clocks) / u.f;
  plan.peak_velocity = vel_to_phys(rep.peak_vel, clock);
  plan.peak_acceleration = acc_to_phys(rep.peak_acc, clock);
  plan.peak_jerk = jerk_to_phys(rep.peak_jerk, clock);
  return plan;
}

}  // namespace

TableReport run_table(const std::vector<Segment>& rows, u128 pos_frac0, int direction) {
  TableReport rep;
  i128 pos = i128(pos_frac0);
  const i128 start = pos;
  bool have_prev = false;
  i128 prev_v = 0;   // last velocity register value of the previous row
  int64_t prev_a = 0;
  auto upd_v = [&](i128 v) {
    const i128 av = v < 0 ? -v : v;
    rep.peak_vel = std::max(rep.peak_vel, av);
    rep.min_signed_vel = std::min(rep.min_signed_vel, direction >= 0 ? v : -v);
  };
  auto upd_a = [&](i128 a) {
    const i128 aa = a < 0 ? -a : a;
    rep.peak_acc = int64_t(std::max<i128>(rep.peak_acc, aa));
  };
  auto upd_j = [&](i128 j) {
    const i128 aj = j < 0 ? -j : j;
    rep.peak_jerk = int64_t(std::max<i128>(rep.peak_jerk, aj));
  };
  rep.min_signed_vel = std::numeric_limits<int64_t>::max();
  for (const Segment& s : rows) {
    if (s.clocks == 0) {
      rep.ok = false;
      rep.error = "zero-length row";
      return rep;
    }
    const uint64_t n = s.clocks;
    const uint64_t last = n - 1;  // register values v_0 .. v_{n-1}
    upd_v(s.vel0);
    upd_v(vel_after(s.vel0, s.acc0, s.jerk, last));
    if (s.jerk != 0) {
      const double ks = 0.5 - double(s.acc0) / double(s.jerk);
      for (int64_t c = int64_t(std::floor(ks)) - 1; c <= int64_t(std::floor(ks)) + 2; ++c) {
        if (c >= 0 && uint64_t(c) <= last) upd_v(vel_after(s.vel0, s.acc0, s.jerk, uint64_t(c)));
      }
    }
    upd_a(s.acc0);
    upd_a(acc_after(s.acc0, s.jerk, last));
    upd_j(s.jerk);
    if (have_prev) {  // per-clock differences across the reload
      upd_a(s.vel0 - prev_v);
      upd_j(i128(s.acc0) - prev_a);
    }
    pos += pos_gain(s.vel0, s.acc0, s.jerk, n);
    rep.clocks += n;
    prev_v = vel_after(s.vel0, s.acc0, s.jerk, last);
    prev_a = int64_t(acc_after(s.acc0, s.jerk, last));
    have_prev = true;
  }
  auto floor_div = [](i128 a) {
    const i128 one = i128(kOne);
    return a >= 0 ? a / one : -((-a + one - 1) / one);
  };
  rep.end_pos = pos;
  rep.steps = int64_t(floor_div(pos) - floor_div(start));
  return rep;
}

}  // namespace scurve
