#include "scurve/planner.h"

#include <fmt/format.h>

#include "solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace scurve {

using hw::MaxSegs;
using hw::SegClkW;

namespace detail {

// Closed-form S-curve (or trapezoid) travel while the speed changes between
// x and y (LSB, clocks): the mean speed times the duration. Estimates only.
double closed_form_travel(double x, double y, double a, double j) {
  const double dv = std::abs(y - x);
  const double t = j <= 0 ? dv / a : dv >= a * a / j ? dv / a + a / j : 2.0 * std::sqrt(dv / j);
  return 0.5 * (x + y) * t;
}

namespace {

constexpr uint64_t kMaxRowClocks = (uint64_t(1) << SegClkW) - 1;
// Transitions whose estimated length exceeds this are treated as infeasible
// before any exact arithmetic, which keeps every closed form far from the
// 128-bit range (1e12 pulses * 2^80 < 2^127).
constexpr double kFarPulses = 1e12;

i128 row_gain(const Row& r) { return pos_gain(r.vel0, r.acc0, r.jerk, r.clocks); }

// floor(num / den) for num >= 0, den > 0: the quotient in double, corrected
// by one step either way (an integer division of 64 or 128 bits costs
// several times as much); a division where the quotient is too large for
// that.
template <class T>
T quotient(T num, int64_t den) {
  // (128-bit conversions are library calls: through 64 bits where they fit)
  const double qd = (num < T(INT64_MAX) ? double(int64_t(num)) : double(num)) / double(den);
  if (!(qd < 0x1p50)) return num / den;
  T q = T(int64_t(qd));
  T rest = num - q * den;
  if (rest < 0) {
    --q;
    rest += den;
  } else if (rest >= den) {
    ++q;
  }
  return q;
}

// Removes the last `rest` LSBs of a velocity change exactly, with acceleration
// 0 at both ends, in at most three pulses (jerk <= j_lim, |a| <= a_max):
//   k clocks at jerk x, k at -x          : x*k^2   (the bulk, k ~ sqrt(rest/j))
//   1 clock at y, m-1 holding y, 1 at -y : y*m     (what is left, < (2k+1)*j)
//   1 clock at z, 1 at -z                : z       (what is left, < m)
// The integer type T holds rest and every product below (int64_t when rest
// < 2^62: the tail is shorter than one clock at the peak acceleration, so
// always in practice; __int128 otherwise): the same values either way.
template <class T>
void append_exact_tail_in(RowList& rows, T rest, int s, int64_t j_lim, int64_t a_max, Phase ph_up,
                          Phase ph_down) {
  const T x_max = std::min<T>(j_lim, a_max);
  constexpr bool kSmall = std::is_same_v<T, int64_t>;  // every divisor below fits 64 bits
  for (int iter = 0; iter < 64 && rest > 0; ++iter) {
    if (rest <= x_max) {
      rows.push_back({ph_up, 1, int64_t(s * rest), 0, 0});
      rows.push_back({ph_down, 1, int64_t(-s * rest), 0, 0});
      return;
    }
    const int64_t k = std::max<int64_t>(1, int64_t(std::sqrt(double(rest) / double(x_max))));
    if (k >= 3 && i128(k) * x_max <= a_max) {
      const T x = std::min<T>(x_max, kSmall ? quotient<T>(rest, k * k) : rest / (T(k) * k));
      rows.push_back({ph_up, uint64_t(k), int64_t(s * x), 0, 0});
      rows.push_back({ph_down, uint64_t(k), int64_t(-s * x), 0, 0});
      rest -= x * k * k;
      continue;
    }
    const T m = kSmall ? quotient<T>(rest + x_max - 1, int64_t(x_max)) : (rest + x_max - 1) / x_max;
    const T y = kSmall ? quotient<T>(rest, int64_t(m)) : rest / m;
    rows.push_back({ph_up, 1, int64_t(s * y), 0, 0});
    if (m > 1) rows.push_back({ph_up == Phase::PhAccJerkUp ? Phase::PhAccConst : Phase::PhDecConst,
                               uint64_t(m - 1), 0, int64_t(s * y), 0});
    rows.push_back({ph_down, 1, int64_t(-s * y), 0, 0});
    rest -= y * m;
  }
}

}  // namespace

void append_exact_tail(RowList& rows, i128 rest, int s, int64_t j_lim, int64_t a_max, Phase ph_up,
                       Phase ph_down) {
  if (rest < (i128(1) << 62)) {
    append_exact_tail_in<int64_t>(rows, int64_t(rest), s, j_lim, a_max, ph_up, ph_down);
  } else {
    append_exact_tail_in<i128>(rows, rest, s, j_lim, a_max, ph_up, ph_down);
  }
}

namespace {

// Holds the acceleration s * a1 (> 0) for `hold` clocks, then ramps it to
// exactly 0 at jerk <= j: ceil(a1 / j) ramp clocks, the first (a1 mod clocks)
// one LSB steeper. With `extra` in (0, a1) the velocity change (magnitude)
// is that plus extra, exactly: one clock more at a1, and a1 - extra of the
// ramp's steps taken one clock earlier (whole steps, then part of one).
// |a| never rises, so only j bounds it: one clock instead of an exact
// tail's pulses, which rise at the smaller of the two jerks.
void push_hold_and_ramp_down(RowList& rows, int64_t a1, uint64_t hold, int64_t extra, int s, int64_t j,
                             Phase ph_hold, Phase ph_down) {
  const int64_t n = a1 / j + (a1 % j != 0);
  const int64_t jd = a1 / n;
  const int64_t r = a1 - n * jd;  // steps 1..r are jd + 1, the rest jd
  if (hold > 0) rows.push_back({ph_hold, hold, 0, s * a1, 0});
  // Ramp rows from step `from` (1-based) to `to`, from acceleration magnitude a.
  int64_t a = a1;
  const auto steps = [&](int64_t from, int64_t to) {
    const int64_t steep_end = std::min(to, r);
    if (steep_end >= from) {
      rows.push_back({ph_down, uint64_t(steep_end - from + 1), -s * (jd + 1), s * a, 0});
      a -= (steep_end - from + 1) * (jd + 1);
    }
    const int64_t flat_from = std::max(from, r + 1);
    if (to >= flat_from) {
      rows.push_back({ph_down, uint64_t(to - flat_from + 1), -s * jd, s * a, 0});
      a -= (to - flat_from + 1) * jd;
    }
  };
  if (extra <= 0) {
    steps(1, n);
    return;
  }
  // The first m steps and p of step m + 1 come one clock earlier: m steps,
  // then one clock stepping p, one stepping the rest of step m + 1.
  const int64_t early = a1 - extra;
  const int64_t m = early < r * (jd + 1) ? early / (jd + 1) : r + (early - r * (jd + 1)) / jd;
  const int64_t before = m <= r ? m * (jd + 1) : r * (jd + 1) + (m - r) * jd;
  const int64_t p = early - before;
  const int64_t step_m1 = m + 1 <= r ? jd + 1 : jd;
  steps(1, m);
  rows.push_back({ph_down, 1, -s * p, s * a, 0});
  a -= p;
  rows.push_back({ph_down, 1, -s * (step_m1 - p), s * a, 0});
  a -= step_m1 - p;
  steps(m + 2, n);
}

// Fastest change of velocity from v_a by at most dv (>= 0, magnitude) in
// direction s, starting and ending at zero acceleration. Jerk j_in while
// |a| rises, j_out while it falls; trapezoid: constant acceleration only.
// The realised change never exceeds dv and falls short by less than one
// clock at the peak acceleration; with `exact` it is exactly dv.
// Built into t, a fresh Transition (a candidate's own: no copy of the rows).
void make_transition(Transition& t, i128 v_a, i128 dv, int s, int64_t j_in, int64_t j_out, int64_t a_max,
                     bool trapezoid, bool exact, const Units& u) {
  t.v_end = v_a;
  if (dv <= 0) return;
  const Phase ph_up = s > 0 ? Phase::PhAccJerkUp : Phase::PhDecJerkUp;
  const Phase ph_const = s > 0 ? Phase::PhAccConst : Phase::PhDecConst;
  const Phase ph_down = s > 0 ? Phase::PhAccJerkDown : Phase::PhDecJerkDown;
  const double dvd = double(dv);
  const double v_hi = std::max(double(v_a), double(v_a) + s * dvd) / u.vel;

  if (trapezoid) {
    const double secs = dvd / double(a_max) / u.f;
    if (secs * v_hi > kFarPulses) {
      t.too_far = true;
      return;
    }
    // Fewest clocks at <= a_max; a change below one clock of a_max still
    // takes one clock (at a lower acceleration), it is never dropped.
    const i128 n = (dv + a_max - 1) / a_max;
    const int64_t a = int64_t(dv / n);
    if (exact) {
      // The first dv mod n clocks one LSB higher: exactly dv, still <= a_max.
      const i128 n_high = dv - n * a;
      if (n_high > 0) t.rows.push_back({ph_const, uint64_t(n_high), 0, int64_t(s) * (a + 1), v_a});
      t.rows.push_back({ph_const, uint64_t(n - n_high), 0, int64_t(s) * a, v_a});
    } else {
      t.rows.push_back({ph_const, uint64_t(n), 0, int64_t(s) * a, v_a});
      t.shortfall_bound = n;  // dv - n*floor(dv/n) < n
    }
  } else {
    const double a_full = double(a_max);
    const double thresh = a_full * a_full * (0.5 / double(j_in) + 0.5 / double(j_out));
    const double a_peak =
        dvd >= thresh ? a_full : std::sqrt(2.0 * dvd / (1.0 / double(j_in) + 1.0 / double(j_out)));
    const double secs = (a_peak / double(j_in) + a_peak / double(j_out) +
                         std::max(0.0, dvd - thresh) / a_full) / u.f;
    if (secs * v_hi > kFarPulses) {
      t.too_far = true;
      return;
    }
    // Peak acceleration a (<= a_max): the ramps take ceil(a / j) clocks at
    // jerk floor(a / clocks) <= j, so a ramp shorter than one clock still
    // takes one clock. If the jerk phases alone overshoot dv, shrink a.
    int64_t a = std::clamp<int64_t>(int64_t(a_peak), 1, a_max);
    i128 dv_done = 0;  // velocity change of the rows kept
    for (int iter = 0; iter < 400; ++iter) {
      // Ramp clocks: floor(a/j) keeps the jerk at exactly j (long ramps),
      // ceil(a/j) at a slightly lower jerk reaches nearer to a (ramps of a
      // few clocks); take whichever peaks higher.
      const int64_t q = quotient(a, j_in);
      const int64_t n_floor = std::max<int64_t>(1, q);
      const int64_t n_ceil = q + (a != q * j_in);  // (a + j_in - 1) / j_in
      const int64_t a_by_floor = quotient(a, n_floor);
      const int64_t a_by_ceil = n_ceil == n_floor ? a_by_floor : quotient(a, n_ceil);
      const int64_t a_floor = n_floor * std::min(j_in, a_by_floor);
      const int64_t a_ceil = n_ceil * a_by_ceil;
      const int64_t n1 = a_floor >= a_ceil ? n_floor : n_ceil;
      const int64_t j1 = std::min(j_in, a_floor >= a_ceil ? a_by_floor : a_by_ceil);
      const int64_t a1 = n1 * j1;  // realised peak, <= a
      const int64_t q3 = quotient(a1, j_out);
      const int64_t n3 = q3 + (a1 != q3 * j_out);  // (a1 + j_out - 1) / j_out
      const int64_t j3 = quotient(a1, n3);
      const int64_t r = a1 - n3 * j3;  // first r clocks at j3+1: a ends at exactly 0
      Row rows[4];
      int n_rows = 0;
      rows[n_rows++] = {ph_up, uint64_t(n1), s * j1, 0, 0};
      rows[n_rows++] = {ph_const, 0, 0, s * a1, 0};
      if (r > 0) rows[n_rows++] = {ph_down, uint64_t(r), -s * (j3 + 1), 0, 0};
      rows[n_rows++] = {ph_down, uint64_t(n3 - r), -s * j3, 0, 0};
      // Velocity gained by the jerk rows alone (the constant row adds n2*a1),
      // in magnitude: up n1 clocks from 0 to a1, down r clocks at j3+1 to
      // a2, then n3-r clocks at j3 to 0 (the executor's sums, modulo 2^128).
      const uint64_t m3 = uint64_t(n3 - r);
      const u128 a2 = u128(i128(a1 - r * (j3 + 1)));
      const i128 dv_jerk = i128(choose2(uint64_t(n1)) * u128(j1) + u128(r) * u128(a1) -
                                choose2(uint64_t(r)) * u128(j3 + 1) + u128(m3) * a2 - choose2(m3) * u128(j3));
      if (dv_jerk > dv) {
        if (a == 1) break;  // dv below one LSB of velocity change: nothing to do
        const double shrink = std::sqrt(double(dv) / double(dv_jerk));
        a = std::clamp<int64_t>(int64_t(double(a) * shrink * 0.999), 1, a - 1);
        continue;
      }
      rows[1].clocks = uint64_t(quotient(dv - dv_jerk, a1));
      t.shortfall_bound = a1;  // less than one more clock at the peak
      dv_done = dv_jerk + i128(rows[1].clocks) * a1;
      if (exact && dv_done < dv) {  // the rest (< a1) in the hold and the ramp down
        t.rows.push_back(rows[0]);
        push_hold_and_ramp_down(t.rows, a1, rows[1].clocks, int64_t(dv - dv_done), s, j_out, ph_const, ph_down);
        t.shortfall_bound = 0;
        dv_done = dv;
        break;
      }
      for (int i = 0; i < n_rows; ++i) {
        if (rows[i].clocks > 0) t.rows.push_back(rows[i]);
      }
      break;
    }
    if (exact && dv_done < dv) {  // below one LSB of peak acceleration: no ramp at all
      append_exact_tail(t.rows, dv - dv_done, s, std::min(j_in, j_out), a_max, ph_up, ph_down);
      t.shortfall_bound = 0;
    }
  }
  // Chain exact starting values through the rows.
  i128 v = v_a;
  int64_t a = 0;
  for (Row& row : t.rows) {
    row.vel0 = v;
    if (row.jerk != 0 || row.phase == ph_up) row.acc0 = a;
    if (row.clocks == 1) {  // the closed forms at k = 1 (most exact-tail rows)
      t.gain += v;
      v = i128(u128(v) + u128(i128(row.acc0)));
      a = row.acc0 + row.jerk;
      continue;
    }
    t.gain += row_gain(row);
    v = vel_after(row.vel0, row.acc0, row.jerk, row.clocks);
    a = int64_t(acc_after(row.acc0, row.jerk, row.clocks));
  }
  t.v_end = v;
}

struct Candidate {
  Transition t1, t2;
  i128 gain = 0;  // travel of the two transitions
  bool feasible = false;
  bool too_far = false;
  bool partial = false;  // probe stopped after t1: gain is t1's only
};

// Plateau v1 (LSB) between the transitions vs -> v1 -> ve. Feasible when a
// cruise of n >= 0 clocks at the plateau puts the travel in the window:
// gain < hi, and with no plateau speed the gain itself must be >= lo.
// probe: the caller keeps only feasible candidates, so an infeasible one may
// stop early, without t2 or gain, once the first transition alone is too
// far or covers the window (the second one's gain is >= 0): then gain is the
// first transition's alone (partial).
void evaluate(Candidate& c, i128 vs, i128 v1_lsb, i128 ve, const TravelWindow& w, const Limits& lim,
              bool probe = false) {
  c.t1.clear();
  c.t2.clear();
  c.gain = 0;
  c.feasible = c.too_far = c.partial = false;
  transition_to(c.t1, vs, v1_lsb, lim);
  if (probe && (c.t1.too_far || c.t1.gain >= w.hi)) {
    c.too_far = c.t1.too_far;
    c.gain = c.t1.gain;  // (a lower bound)
    c.partial = true;
    return;
  }
  transition_to(c.t2, c.t1.v_end, ve, lim);
  c.too_far = c.t1.too_far || c.t2.too_far;
  if (c.too_far) return;
  c.gain = c.t1.gain + c.t2.gain;
  const i128 plateau = c.t1.v_end;
  c.feasible = c.gain < w.hi && (plateau > 0 || c.gain >= w.lo);
}

Candidate evaluate(i128 vs, i128 v1_lsb, i128 ve, const TravelWindow& w, const Limits& lim, bool probe = false) {
  Candidate c;
  evaluate(c, vs, v1_lsb, ve, w, lim, probe);
  return c;
}

// The ramps of a transition: with the same ramps, its realised changes of
// velocity lie one shortfall bound (a clock at the peak) apart.
struct Shape {
  uint64_t clocks = 0;
  int64_t jerk = 0, peak = 0;
  bool operator==(const Shape& o) const { return clocks == o.clocks && jerk == o.jerk && peak == o.peak; }
};
Shape shape_of(const Transition& t) {
  if (t.rows.empty()) return {};
  const Row& r = *t.rows.begin();
  return {r.clocks, r.jerk, int64_t(t.shortfall_bound)};
}

// The cruise that places the travel in the window: the largest travel <= aim
// (or the smallest >= lo if that is below lo).
uint64_t cruise_clocks(i128 gain, i128 plateau, const TravelWindow& w) {
  if (plateau > 0 && w.aim > gain) {
    i128 n = (w.aim - gain) / plateau;
    if (gain + n * plateau < w.lo) ++n;  // (plateau < 1 pulse: still < hi)
    return uint64_t(n);
  }
  if (plateau > 0 && gain < w.lo) return uint64_t((w.lo - gain + plateau - 1) / plateau);
  return 0;
}

// The duration of a feasible candidate, its cruise included.
uint64_t candidate_clocks(const Candidate& c, const TravelWindow& w) {
  uint64_t n = cruise_clocks(c.gain, c.t1.v_end, w);
  for (const Row& r : c.t1.rows) n += r.clocks;
  for (const Row& r : c.t2.rows) n += r.clocks;
  return n;
}

// The continuous travel vs -> p -> ve (LSB) as a function of the plateau p
// (LSB per clock), with its slope: the estimate the exact plateau search
// starts from and corrects. The integer ramps and floored jerks of the exact
// transitions make it an estimate only.
class TravelModel {
 public:
  TravelModel(i128 vs, i128 ve, const Limits& lim)
      : x_(double(vs)), y_(double(ve)), a_(double(lim.a_max)), inv_a_(1.0 / a_), trapezoid_(lim.trapezoid),
        acc_(lim.trapezoid ? Jerks{} : Jerks(lim.j_acc_in, lim.j_acc_out, a_)),
        dec_(lim.trapezoid ? Jerks{} : Jerks(lim.j_dec_in, lim.j_dec_out, a_)) {}

  // Travel of vs -> p (first) and p -> ve (second), and the slope of their
  // sum (or of the first alone) in p.
  double travel(double p, double* first = nullptr, double* slope = nullptr, double* first_slope = nullptr) const {
    double d1, d2;
    const double t1 = p >= x_ ? from_fixed(x_, shape(p - x_, acc_), +1, d1)
                              : from_fixed(x_, shape(x_ - p, dec_), -1, d1);
    const double t2 = p >= y_ ? from_plateau(p, shape(p - y_, dec_), -1, d2)
                              : from_plateau(p, shape(y_ - p, acc_), +1, d2);
    if (first) *first = t1;
    if (slope) *slope = d1 + d2;
    if (first_slope) *first_slope = d1;
    return t1 + t2;
  }

  // The u in [0, u_max] whose plateau least + sign * u travels `target` (u_max
  // if even that travels less): safeguarded Newton. first_only: the travel
  // of vs -> p alone (a single transition to the end speed p).
  double solve(double target, double least, double sign, double u_max, bool first_only = false,
               double start = -1) const {
    const auto f_of = [&](double u, double& slope) {
      double first, d, d1;
      const double all = travel(least + sign * u, &first, &d, &d1);
      slope = sign * (first_only ? d1 : d);
      return (first_only ? first : all) - target;
    };
    double lo = 0, hi = u_max, slope, u = start;
    if (!(start > 0 && start < u_max)) {  // cold start
      double s_hi;
      const double f_hi = f_of(hi, s_hi);
      if (f_hi <= 0) return hi;
      const double f_0 = f_of(0, slope);
      if (f_0 >= 0) return 0;
      // The quadratic through f(0), f(hi) and f'(hi): exact while a_max is
      // reached throughout (the travel is then quadratic in the plateau).
      const double c = (s_hi * hi - (f_hi - f_0)) / (hi * hi), b = s_hi - 2 * c * hi;
      const double disc = b * b - 4 * c * f_0;
      u = c > 0 && disc >= 0 ? -2 * f_0 / (b + std::sqrt(disc)) : -1;
      if (!(u > 0 && u < hi)) u = hi * std::sqrt(-f_0 / (f_hi - f_0));  // (growth as u^2)
    }
    for (int i = 0; i < 40; ++i) {
      const double f = f_of(u, slope);
      if (f == 0) return u;
      (f > 0 ? hi : lo) = u;
      double next = slope > 0 ? u - f / slope : lo;
      if (std::abs(next - u) <= 1e-11 * std::abs(least + sign * u) + 0.5) return std::clamp(next, lo, hi);
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      u = next;
    }
    return lo;
  }

 private:
  // One direction's constants (a = a_max; k = 1/j_in + 1/j_out).
  struct Jerks {
    double thresh = 0;           // the velocity change that first reaches a
    double half_ak = 0;          // a k / 2: T = dv / a + a k / 2 once a is reached
    double t_b = 0, dv1 = 0;     // falling ramp time; the rising ramp's change
    double rel0 = 0;             // the ramps' own travel terms once a is reached
    double two_over_k = 0, k = 0, c3 = 0, c3_3_over_k = 0;  // below a: rel = A^3 c3
    Jerks() = default;
    Jerks(int64_t in, int64_t out, double a) {
      const double j_in = double(in), j_out = double(out);
      k = 1.0 / j_in + 1.0 / j_out;
      thresh = 0.5 * a * a * k;
      half_ak = 0.5 * a * k;
      const double t_a = a / j_in;
      t_b = a / j_out;
      dv1 = 0.5 * a * t_a;
      rel0 = a * t_a * t_a / 6 + a * t_b * t_b / 3;
      two_over_k = 2.0 / k;
      c3 = 1.0 / (6 * j_in * j_in) + 1.0 / (2 * j_in * j_out) + 1.0 / (3 * j_out * j_out);
      c3_3_over_k = 3.0 * c3 / k;
    }
  };
  // A speed change by dv >= 0 starting at rest: its duration T, its travel
  // rel, and their slopes in dv.
  struct Shape {
    double T, rel, dT, drel;
  };
  Shape shape(double dv, const Jerks& j) const {
    if (trapezoid_) return {dv * inv_a_, 0.5 * dv * dv * inv_a_, inv_a_, dv * inv_a_};
    if (dv >= j.thresh) {  // a_max reached: rising, constant, falling
      const double t_c = dv * inv_a_ - j.half_ak;
      const double dv2 = j.dv1 + a_ * t_c;
      const double rel = j.rel0 + j.dv1 * t_c + 0.5 * a_ * t_c * t_c + dv2 * j.t_b;
      return {dv * inv_a_ + j.half_ak, rel, inv_a_, dv2 * inv_a_ + j.t_b};
    }
    const double A = std::sqrt(dv * j.two_over_k);
    return {A * j.k, A * A * A * j.c3, A > 0 ? 1.0 / A : 0.0, A * j.c3_3_over_k};
  }
  // Travel from the fixed speed s toward the plateau (s = vs; dir +1 speeding
  // up) and its slope in the plateau.
  static double from_fixed(double s, const Shape& sh, int dir, double& slope) {
    slope = dir * (s * sh.dT + dir * sh.drel);
    return s * sh.T + dir * sh.rel;
  }
  // Travel from the plateau p toward the fixed end speed, and its slope in p.
  static double from_plateau(double p, const Shape& sh, int dir, double& slope) {
    slope = sh.T - dir * (p * sh.dT + dir * sh.drel);
    return p * sh.T + dir * sh.rel;
  }

  double x_, y_, a_, inv_a_;
  bool trapezoid_;
  Jerks acc_, dec_;
};

}  // namespace

void transition_to(Transition& t, i128 v_from, i128 v_to, const Limits& lim) {
  if (v_to >= v_from) {
    make_transition(t, v_from, v_to - v_from, +1, lim.j_acc_in, lim.j_acc_out, lim.a_max, lim.trapezoid,
                    lim.exact_transitions, lim.units);
  } else {
    make_transition(t, v_from, v_from - v_to, -1, lim.j_dec_in, lim.j_dec_out, lim.a_max, lim.trapezoid,
                    lim.exact_transitions, lim.units);
  }
}

Transition transition_to(i128 v_from, i128 v_to, const Limits& lim) {
  Transition t;
  transition_to(t, v_from, v_to, lim);
  return t;
}

Limits make_limits(const MoveRequest& req, const PulseTiming& timing, Clock clock) {
  const Units u(clock);
  Limits lim{0, 0, 0, 0, 0, 0, false, u};
  lim.v_rate = i128(kOne) / (i128(timing.high) + timing.low);
  lim.a_max = int64_t(std::floor(req.a_max * u.acc));
  lim.trapezoid = req.kind == ProfileKind::Trapezoid;
  if (!lim.trapezoid) {
    std::array<double, 4> j = req.jerks.value_or(std::array<double, 4>{req.j_max, req.j_max,
                                                                       req.j_max, req.j_max});
    lim.j_acc_in = int64_t(std::floor(j[0] * u.jerk));
    lim.j_acc_out = int64_t(std::floor(j[1] * u.jerk));
    lim.j_dec_in = int64_t(std::floor(j[2] * u.jerk));
    lim.j_dec_out = int64_t(std::floor(j[3] * u.jerk));
  }
  return lim;
}

// The plateau search stops once its bracket is this narrow (relative, as a
// power of two): the duration is flat in the plateau there.
constexpr int kBracketBits = 24;
// At most this many exact candidates in the search (a bracket that narrows
// more slowly ends with the best one found).
constexpr int kSearchProbes = 12;

std::variant<Solved, Unsolvable> solve_profile(i128 vs, double v_cruise, i128 ve, const TravelWindow& w,
                                               const Limits& lim) {
  const auto to_lsb = [&](double v) { return std::min(i128(std::floor(v * lim.units.vel)), lim.v_rate); };
  // ---- choose the plateau velocity ---------------------------------------
  // The plateau is the cruise speed if the distance allows it; otherwise a
  // plateau between v_cruise and max(vs, ve) (the plateau that needs the
  // least travel) whose transitions cover about the aimed travel: the cruise
  // covers the rest, and a higher plateau only travels further. The search
  // runs along u >= 0, the distance of the plateau from the least-travel one
  // toward v_cruise; the travel grows with u.
  const i128 p_least = std::max(vs, ve);
  const i128 p_cruise = to_lsb(v_cruise);
  const bool up = p_cruise >= p_least;
  const i128 u_cruise = up ? p_cruise - p_least : p_least - p_cruise;
  const auto plateau_at = [&](i128 u) { return up ? p_least + u : p_least - u; };
  const TravelModel model(vs, ve, lim);
  const double least = double(p_least), sign = up ? 1.0 : -1.0;
  // Exact minus modelled travel of a candidate (of t1 alone if that is all the probe built).
  const auto model_error = [&](const Candidate& t, double u) {
    double first;
    const double all = model.travel(least + sign * u, &first);
    return double(t.gain) - (t.partial ? first : all);
  };
  // The travel the plateau's transitions aim for: the aimed travel (the
  // move's own fastest plan), or for streamed moves the window's end. The
  // model aims half a clock of the plateau speed short of it.
  const i128 reach = lim.reach_window_end ? w.hi - 1 : w.aim;
  const auto aim_at = [&](double u) { return double(reach) - 0.5 * std::max(1.0, least + sign * u); };

  Candidate c;
  // Moves from an exact state (plan_from, streams) whose start or end speed is
  // above the cruise speed keep the least-travel plateau unless the cruise
  // speed fits: no search.
  const bool least_or_cruise = lim.least_above_cruise && !up;
  // The exact cruise candidate first when the model says it (nearly) fits.
  const double aim_cruise = aim_at(double(u_cruise));
  const bool cruise_likely = model.travel(double(p_cruise)) <= aim_cruise * (1.0 + 1.0 / 64);
  double u_model = cruise_likely ? double(u_cruise) : model.solve(aim_cruise, least, sign, double(u_cruise));
  bool cruise_tried = false;
  if (least_or_cruise || cruise_likely || u_model >= double(u_cruise) * (1.0 - 1.0 / 64)) {
    c = evaluate(vs, p_cruise, ve, w, lim, /*probe=*/true);
    cruise_tried = true;
  }
  if (!c.feasible) {
    // Exact candidates from the model's plateau: each one corrects the model
    // by the exact travel it found, bracketed by the highest plateau that
    // covers at most the aim (good) and the lowest that covers more (bad).
    i128 good = -1, bad = u_cruise, floor_u = -1;  // floor_u: too small to move
    // The realised plateaus of good and bad (-1: unknown), good's shortfall bound.
    i128 good_plateau = 0, good_step = 0, bad_plateau = -1;
    Shape good_shape{}, bad_shape{};
    Candidate slots[2];  // the best candidate so far and the next probe (no copy of rows)
    int best_i = -1, cur = 0;
    uint64_t best_clocks = 0;
    bool bad_seen = false;
    if (cruise_likely) u_model = model.solve(aim_cruise, least, sign, double(u_cruise));
    i128 u = i128(u_model);
    for (int it = 0; it < kSearchProbes && !least_or_cruise; ++it) {
      const i128 lo_u = std::max(good, floor_u);
      // Done when the bracket is narrow (the duration is flat in the plateau
      // there; only the integer rounding varies), or when no other candidate
      // lies between (transitions that fall short of their target: one step
      // of the good candidate's realised plateaus).
      if (bad - lo_u <= std::max<i128>(1, plateau_at(bad) >> kBracketBits)) break;
      if (good >= 0 && bad_plateau >= 0 && good_shape == bad_shape) {
        const i128 gap = bad_plateau - good_plateau;
        if ((gap < 0 ? -gap : gap) <= good_step) break;
      }
      if (u <= lo_u || u >= bad) u = lo_u + (bad - lo_u) / 2;
      Candidate& t = slots[cur];
      evaluate(t, vs, plateau_at(u), ve, w, lim, /*probe=*/true);
      const i128 gain = t.gain;
      const bool feasible = t.feasible, known = !t.too_far;
      const i128 plateau = t.t1.v_end, step = t.t1.shortfall_bound;
      // Near enough: the cruise would be shorter than a clock (streamed
      // moves: within 1/64 pulse of the window's end).
      const i128 near = lim.reach_window_end ? std::max(plateau, i128(kOne) >> 6) : plateau;
      const Shape shape = shape_of(t.t1);
      const double off = known ? model_error(t, double(u)) : 0.0;
      if (feasible) {
        const uint64_t clocks = candidate_clocks(t, w);
        // Kept: the fastest; a streamed move's plateau that covers the most,
        // a plateau below both ends the one closest to the cruise speed.
        const bool by_reach = lim.reach_window_end || !up;
        if (best_i < 0 || (by_reach ? gain <= reach && u > good : clocks < best_clocks)) {
          best_i = cur;
          cur ^= 1;
          best_clocks = clocks;
        }
      }
      if (feasible && gain <= reach) {
        good = u;
        good_plateau = plateau;
        good_step = step;
        good_shape = shape;
        if (reach - gain <= near) break;
      } else if (known && gain > reach) {
        bad = u;
        bad_plateau = plateau;
        bad_shape = shape;
        bad_seen = true;
      } else if (known) {
        floor_u = u;  // (gain < lo with plateau 0)
        u = -1;
        continue;
      } else {
        bad = u;
        bad_plateau = -1;
        bad_seen = true;
        u = -1;
        continue;
      }
      u = i128(model.solve(aim_at(double(u)) - off, least, sign, double(u_cruise), false, double(u)));
      if (u == good) ++u;
    }
    Candidate best;
    if (best_i >= 0) best = std::move(slots[best_i]);
    // A stop (vs = ve = 0) has no least-travel fallback, but a small enough
    // plateau always fits: descend (bisect above a plateau too small to move).
    for (int k = 0; k < 64 && !best.feasible && p_least == 0 && bad - std::max<i128>(floor_u, 0) > 1; ++k) {
      const i128 u = floor_u >= 0 ? floor_u + (bad - floor_u) / 2 : bad / 8;
      if (u <= 0) break;
      Candidate t = evaluate(vs, plateau_at(u), ve, w, lim, /*probe=*/true);
      if (t.feasible) {
        best = std::move(t);
      } else if (!t.too_far && t.gain < w.lo) {
        floor_u = u;
      } else {
        bad = u;
      }
    }
    if (!cruise_tried && (!bad_seen || !best.feasible)) {
      Candidate t = evaluate(vs, p_cruise, ve, w, lim, /*probe=*/true);
      if (t.feasible) best = std::move(t);
    }
    if (!best.feasible) {
      if (p_least == 0) return Unsolvable{};  // vs = ve = 0: no least-travel fallback
      Candidate far = evaluate(vs, p_least, ve, w, lim);
      if (!far.feasible) {
        Unsolvable why;
        why.end_unreachable = true;
        why.too_far = far.too_far;
        why.least_gain = far.gain;
        return why;
      }
      best = std::move(far);
    }
    c = std::move(best);
  }

  // ---- fill: the cruise clocks place the travel in the window ------------
  Solved out;
  out.plateau = c.t1.v_end;
  const uint64_t n_cruise = cruise_clocks(c.gain, out.plateau, w);
  out.travel = c.gain + i128(n_cruise) * out.plateau;
  out.rows.reserve(c.t1.rows.size() + 1 + c.t2.rows.size());
  out.rows.assign(c.t1.rows.begin(), c.t1.rows.end());
  if (n_cruise > 0) out.rows.push_back({Phase::PhCruise, n_cruise, 0, 0, out.plateau});
  out.rows.insert(out.rows.end(), c.t2.rows.begin(), c.t2.rows.end());
  out.v_end = c.t2.rows.empty() ? out.plateau : c.t2.v_end;
  out.end_shortfall_bound = c.t2.shortfall_bound;
  if (out.rows.empty()) return Unsolvable{};
  return out;
}

std::optional<i128> reachable_end_speed(i128 vs, i128 ve, i128 p_cruise, const TravelWindow& w,
                                        const Limits& lim) {
  // End speed e = vs +- u. Its plan exists when the plateau max(vs, e) or the
  // cruise speed fits (a move speeding up ends with a shortfall's tiny
  // transition at the plateau max(vs, e), which the cruise plateau avoids);
  // the lesser travel of the two grows with u, and u = |ve - vs| fits neither. The boundary is searched to the
  // resolution of a double end speed: the plan's duration can depend
  // strongly on the end speed there (a plateau below both ends).
  const bool up = ve >= vs;
  const i128 u_max = up ? ve - vs : vs - ve;
  const auto end_at = [&](i128 u) { return up ? vs + u : vs - u; };
  const TravelModel model(vs, vs, lim);
  const double sign = up ? 1.0 : -1.0, from = double(vs), aim = double(w.hi - 1);
  i128 good = -1, bad = u_max, g_good = 0, g_bad = 0;
  bool bracketed = false;  // g_good and g_bad are exact travels
  i128 u = i128(model.solve(aim, from, sign, double(u_max), /*first_only=*/true));
  for (int it = 0; it < 48; ++it) {
    const i128 tol = std::max<i128>(1, std::max(end_at(std::max<i128>(good, 0)), end_at(bad)) >> 50);
    if (bad - good <= tol) break;
    if (bracketed && good >= 0) {  // regula falsi, kept a sixteenth inside the bracket
      const double f = (double(w.hi) - 0.5 - double(g_good)) / double(g_bad - g_good);
      const i128 span = bad - good;
      u = good + std::clamp(i128(double(span) * f), span / 16, span - span / 16);
    }
    if (u <= good || u >= bad) u = good + (bad - good) / 2;
    const i128 e = end_at(u);
    Candidate c = evaluate(vs, std::max(vs, e), e, w, lim);
    if (!c.feasible && p_cruise != std::max(vs, e)) {
      Candidate via_cruise = evaluate(vs, p_cruise, e, w, lim);
      if (via_cruise.feasible || (!via_cruise.too_far && (c.too_far || via_cruise.gain < c.gain))) {
        c = std::move(via_cruise);
      }
    }
    if (c.feasible) {
      good = u;
      g_good = c.gain;
    } else {
      bad = u;
      g_bad = c.too_far ? 0 : c.gain;
    }
    bracketed = good >= 0 && !c.too_far && g_bad > g_good;
    if (!bracketed && !c.too_far) {  // the model of the single transition, corrected by this exact travel
      double first;
      model.travel(double(e), &first);
      u = i128(model.solve(aim - (double(c.gain) - first), from, sign, double(u_max), true));
      if (u == good) ++u;
    } else if (!bracketed) {
      u = -1;
    }
  }
  if (good < 0) return std::nullopt;
  return end_at(good);
}

std::vector<Segment> to_segments(const std::vector<Row>& rows, int dir) {
  std::vector<Segment> segs;
  segs.reserve(rows.size() + 2);
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
      segs.push_back(s);
      r.clocks -= n;
      if (r.clocks == 0) break;
      r.vel0 = vel_after(r.vel0, r.acc0, r.jerk, n);
      r.acc0 = int64_t(acc_after(r.acc0, r.jerk, n));
    }
  }
  return segs;
}

// Shortest text that reads back as the same double: the value as the user gave it.
std::string num(double v) { return fmt::format("{}", v); }

uint64_t rows_needed(const std::vector<Row>& rows) {
  uint64_t n = 0;
  for (const Row& r : rows) n += (r.clocks + kMaxRowClocks - 1) / kMaxRowClocks;
  return n;
}

}  // namespace detail

namespace {

using namespace detail;

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

// Smallest distance (pulses) that leaves transitions covering `gain` a
// remainder >= 1 LSB: distance * 2^F + 2^(F-1) - gain >= 1.
int64_t needed_distance(i128 gain) {
  const i128 num = gain + 1 - (i128(kOne) >> 1);
  return int64_t(num <= 0 ? 0 : (num + i128(kOne) - 1) / i128(kOne));
}

// Refine: on an unreachable end speed, check the shortest distance the
// planner accepts near the estimate from the least-travel candidate, so the
// message names the true minimum. The check itself plans without it.
// Probe: for the searches over end speed and distance, which only ask
// whether a plan exists: errors carry the parameter but no message (the
// message formatting costs more than an unreachable end speed's solve).
enum class Detail { Refine, Message, Probe };
PlanResult plan_magnitude(const MoveRequest& req, const PulseTiming& timing, double v_end, Clock clock,
                          Detail detail = Detail::Refine);

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
    case Phase::PhStop: return "stop";
  }
  return "?";
}

namespace detail {

namespace {

bool axis_name_ok(const std::string& name) {
  if (name.empty() || name.size() > SoftLimits::kMaxAxisName) return false;
  for (const char c : name) {
    const bool ok = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
                    c == '-' || c == '.';
    if (!ok) return false;
  }
  return true;
}

// A name as given, control and non-ASCII bytes as \xNN (the message stays one line).
std::string shown_name(const std::string& name) {
  std::string out;
  for (const char c : name.substr(0, 64)) {
    const auto u = static_cast<unsigned char>(c);
    out += (u < 0x20 || u >= 0x7f) ? fmt::format("\\x{:02x}", u) : std::string(1, c);
  }
  return name.size() > 64 ? out + "..." : out;
}

std::optional<Error> check_position(const char* name, int64_t v) {
  if (v >= -PlannerLimits::kMaxPosition && v <= PlannerLimits::kMaxPosition) return std::nullopt;
  return Error{name, fmt::format("{}={}: exceeds the limit +-{} pulses", name, v, PlannerLimits::kMaxPosition)};
}

}  // namespace

std::optional<Error> check_window_fields(const std::optional<SoftLimits>& window, int64_t start_position) {
  if (auto e = check_position("start_position", start_position)) return e;
  if (!window) return std::nullopt;
  const SoftLimits& w = *window;
  if (!axis_name_ok(w.axis)) {
    return Error{"soft_limits.axis",
                 fmt::format("soft_limits.axis='{}': must be 1 to {} characters of A-Z a-z 0-9 _ - .",
                             shown_name(w.axis), SoftLimits::kMaxAxisName)};
  }
  if (w.min_pos) {
    if (auto e = check_position("soft_limits.min_pos", *w.min_pos)) return e;
  }
  if (w.max_pos) {
    if (auto e = check_position("soft_limits.max_pos", *w.max_pos)) return e;
  }
  if (w.min_pos && w.max_pos && *w.min_pos > *w.max_pos) {
    return Error{"soft_limits.min_pos",
                 fmt::format("axis {}: soft limit min={} is above max={} pulses: needs min <= max", w.axis,
                             *w.min_pos, *w.max_pos)};
  }
  return std::nullopt;
}

std::optional<Error> check_window(const SoftLimits& w, i128 start, int64_t distance, std::string_view label) {
  const i128 target = start + distance;
  const bool above = w.max_pos && target > *w.max_pos;
  const bool below = w.min_pos && target < *w.min_pos;
  if (!above && !below) return std::nullopt;
  const char* side = above ? "max" : "min";
  const int64_t limit = above ? *w.max_pos : *w.min_pos;
  // From a start beyond the same limit, a move back toward the window is
  // accepted; one further out is refused naming the start.
  const bool start_beyond = above ? start > limit : start < limit;
  if (start_beyond) {
    const bool closer = above ? target < start : target > start;
    if (closer) return std::nullopt;
    return Error{"start_position",
                 fmt::format("axis {}: {}start position {} is already beyond soft limit {}={} pulses and target "
                             "position {} is further out (distance {:+}): from there only moves back toward the "
                             "window are accepted",
                             w.axis, label, to_string_i128(start), side, limit, to_string_i128(target), distance)};
  }
  return Error{above ? "soft_limits.max_pos" : "soft_limits.min_pos",
               fmt::format("axis {}: {}target position {} is beyond soft limit {}={} pulses (start {}, distance {:+})",
                           w.axis, label, to_string_i128(target), side, limit, to_string_i128(start), distance)};
}

}  // namespace detail

namespace {

// Limits checked before solving (clock, timing, distance, speeds, a_max,
// jerks, the soft limits).
std::optional<PlanError> check_request(const MoveRequest& req, const PulseTiming& timing, Clock clock) {
  if (std::string e = check_clock(clock); !e.empty()) return PlanError{"clock_hz", e};
  if (timing.high < 1) return PlanError{"pulse_high", "pulse_high=0: must be >= 1 clock"};
  if (timing.low < 1) return PlanError{"pulse_low", "pulse_low=0: must be >= 1 clock"};
  if (req.distance == 0) return PlanError{"distance", "distance=0: must be non-zero"};
  if (req.distance > PlannerLimits::kMaxDistance || req.distance < -PlannerLimits::kMaxDistance) {
    return PlanError{"distance", fmt::format("distance={}: exceeds the limit +-{} pulses",
                                             req.distance, PlannerLimits::kMaxDistance)};
  }
  const double v_lim = step_rate_limit(timing, clock);
  // The unit text names the step-rate limit; formatted only for an error.
  const auto check_speed = [&](const char* name, double v, double lo) -> std::optional<PlanError> {
    if (std::isfinite(v) && v >= lo && v <= v_lim) return std::nullopt;
    const std::string rate_note = fmt::format(
        " pulses/s (step-rate limit: pulse high {} + low {} clocks at {} MHz)", timing.high,
        timing.low, clock.hz / 1e6);
    return check_range(name, v, lo, v_lim, rate_note.c_str());
  };
  const LimitRange acc_ok = accel_range(clock), jerk_ok = jerk_range(clock);
  if (auto e = check_speed("v_start", req.v_start, 0)) return *e;
  if (auto e = check_speed("v_cruise", req.v_cruise, PlannerLimits::kMinCruise)) return *e;
  if (auto e = check_speed("v_end", req.v_end, 0)) return *e;
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
  if (auto e = check_window_fields(req.soft_limits, req.start_position)) return *e;
  if (req.soft_limits) return check_window(*req.soft_limits, req.start_position, req.distance);
  return std::nullopt;
}

}  // namespace

// An adjusted end speed whose plan fails (a realised end speed off the
// double grid, the row limit) is retried this much nearer v_start: u >> shift.
constexpr int kRetryShift[4] = {40, 20, 10, 1};

PlanResult Planner::plan(const MoveRequest& req, const PulseTiming& timing) const {
  const Clock clock = clock_;
  if (auto e = check_request(req, timing, clock)) return *e;
  // The minimum-distance search runs only for an error the user will see.
  PlanResult r = plan_magnitude(req, timing, req.v_end, clock, req.adjust_end_speed ? Detail::Message : Detail::Refine);
  if (std::holds_alternative<PlanError>(r) && req.adjust_end_speed &&
      std::get<PlanError>(r).parameter == "v_end" && req.v_end != req.v_start) {
    // The nearest reachable end speed (LSB), then the end speed in pulses/s
    // that floors to it (or, on the double grid, next to it toward v_start).
    const Limits lim = make_limits(req, timing, clock);
    const double vel = lim.units.vel;
    const i128 vs = std::min(i128(std::floor(req.v_start * vel)), lim.v_rate);
    const i128 ve = std::min(i128(std::floor(req.v_end * vel)), lim.v_rate);
    const i128 target = pulses_to_lsb(req.distance < 0 ? -req.distance : req.distance) + (i128(kOne) >> 1);
    const TravelWindow window{target - i128(kOne) + 1, target, target - 1};
    const bool up = ve >= vs;
    std::optional<Plan> best;
    const i128 p_cruise = std::min(i128(std::floor(req.v_cruise * vel)), lim.v_rate);
    if (const std::optional<i128> e = reachable_end_speed(vs, ve, p_cruise, window, lim)) {
      // A few tries nearer v_start should the realised end speed not fit.
      i128 u = up ? *e - vs : vs - *e;
      for (int k = 0; k < 4 && !best; u -= std::max<i128>(1, u >> kRetryShift[k++])) {
        if (u <= 0) break;
        const i128 e_k = up ? vs + u : vs - u;
        double v = double(e_k) / vel;
        while (up ? i128(std::floor(v * vel)) > e_k : i128(std::floor(v * vel)) < e_k) {
          v = std::nextafter(v, up ? 0.0 : HUGE_VAL);
        }
        PlanResult m = plan_magnitude(req, timing, v, clock, Detail::Probe);
        if (auto* p = std::get_if<Plan>(&m)) best = std::move(*p);
      }
    }
    if (!best) {
      PlanResult m = plan_magnitude(req, timing, req.v_start, clock, Detail::Probe);
      if (std::holds_alternative<Plan>(m)) best = std::get<Plan>(m);
    }
    if (best) {
      best->end_speed_adjusted = true;
      return *best;
    }
    return plan_magnitude(req, timing, req.v_end, clock, Detail::Refine);
  }
  return r;
}

namespace {

// Re-checks a table by executing it (Ruckig style) and fills the figures
// measured from it. `v_cap`: the largest speed the request allows (LSB).
std::optional<PlanError> check_table(Plan& plan, const Limits& lim, i128 v_cap, int dir, const Solved& sol,
                                     i128 ve) {
  const TableReport rep = run_table(plan.segments, plan.pos_frac0, dir);
  // Transitions fall short of their target by less than one clock at the
  // peak acceleration; anything more is a planner bug (a dropped transition).
  const i128 end_miss = sol.v_end > ve ? sol.v_end - ve : ve - sol.v_end;
  const int64_t j_cap =
      lim.trapezoid ? 0 : std::max({lim.j_acc_in, lim.j_acc_out, lim.j_dec_in, lim.j_dec_out});
  // The executor's step rule: a step each time floor(position / 2^F)
  // changes, so the end must lie in [distance, distance + 1) pulses
  // relative to the integer part of the start position.
  const i128 window_lo = i128(plan.distance) * i128(kOne);
  std::string why;
  if (!rep.ok) why = rep.error;
  else if (rep.steps != plan.distance) why = fmt::format("steps {} != distance", rep.steps);
  else if (rep.end_pos < window_lo || rep.end_pos >= window_lo + i128(kOne)) why = "end outside the window";
  else if (rep.min_signed_vel < 0) why = "velocity reverses";
  else if (rep.peak_vel > v_cap || rep.peak_vel > lim.v_rate) why = "velocity limit exceeded";
  else if (rep.peak_acc > lim.a_max) why = "acceleration limit exceeded";
  else if (!lim.trapezoid && rep.peak_jerk > j_cap) why = "jerk limit exceeded";
  else if (end_miss > sol.end_shortfall_bound) why = "end speed missed";
  if (!why.empty()) {
    return PlanError{"internal", fmt::format("internal planner error ({}); please report the request", why)};
  }
  const double f = lim.units.f;
  plan.total_clocks = rep.clocks;
  plan.duration_s = double(rep.clocks) / f;
  plan.peak_velocity = vel_to_phys(rep.peak_vel, plan.clock);
  plan.peak_acceleration = acc_to_phys(rep.peak_acc, plan.clock);
  plan.peak_jerk = jerk_to_phys(rep.peak_jerk, plan.clock);
  plan.end_state.velocity = dir * sol.v_end;
  plan.end_state.frac = u128(rep.end_pos - window_lo);
  return std::nullopt;
}

PlanResult plan_magnitude(const MoveRequest& req, const PulseTiming& timing, double v_end, Clock clock,
                          Detail detail) {
  const int dir = req.distance < 0 ? -1 : 1;
  const int64_t dist = req.distance * dir;
  const Limits lim = make_limits(req, timing, clock);
  const Units& u = lim.units;
  const i128 vs = std::min(i128(std::floor(req.v_start * u.vel)), lim.v_rate);
  const i128 ve = std::min(i128(std::floor(v_end * u.vel)), lim.v_rate);
  const i128 target = pulses_to_lsb(dist) + (i128(kOne) >> 1);  // end mid-pulse
  // From rest the start fraction p0 in [1, 2^F) is free: travel = target - p0,
  // placed so p0 is smallest (the first step comes after almost one pulse).
  const TravelWindow window{target - i128(kOne) + 1, target, target - 1};

  auto solved = solve_profile(vs, req.v_cruise, ve, window, lim);
  if (const auto* why = std::get_if<Unsolvable>(&solved)) {
    if (detail == Detail::Probe) return PlanError{why->end_unreachable ? "v_end" : "distance", {}};
    if (!why->end_unreachable) {
      return PlanError{"distance", fmt::format("distance={}: too short for any motion with these limits", dist)};
    }
    const char* hint = req.adjust_end_speed ? "" : " (or allow --adjust-end-speed)";
    std::string need = "more than 1e12";
    if (!why->too_far) {
      int64_t min_dist = needed_distance(why->least_gain);
      if (detail == Detail::Refine) {
        const auto accepts = [&](int64_t d) {
          MoveRequest r = req;
          r.distance = d * dir;
          return d <= PlannerLimits::kMaxDistance &&
                 std::holds_alternative<Plan>(plan_magnitude(r, timing, v_end, clock, Detail::Probe));
        };
        // Local check of the exact estimate: the result is accepted and one
        // pulse less is not (a few steps at most).
        for (int k = 0; k < 4 && min_dist > 1 && accepts(min_dist - 1); ++k) --min_dist;
        for (int k = 0; k < 4 && !accepts(min_dist); ++k) ++min_dist;
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
  const Solved& sol = std::get<Solved>(solved);
  const i128 p0 = target - sol.travel;

  // ---- split rows to the 32-bit clock field, mirror for direction ---------
  if (const uint64_t n = rows_needed(sol.rows); n > uint64_t(MaxSegs)) {
    return PlanError{"distance", fmt::format("distance={}: the move needs {} table rows, the executor holds {} "
                                             "(a row lasts at most {:.1f} s); raise v_cruise or split the move",
                                             dist, n, MaxSegs, double((uint64_t(1) << SegClkW) - 1) / u.f)};
  }
  Plan plan;
  plan.clock = clock;
  plan.segments = to_segments(sol.rows, dir);
  plan.pos_frac0 = dir > 0 ? u128(p0) : kOne - u128(p0);
  plan.distance = req.distance;
  plan.v_plateau = vel_to_phys(sol.plateau, clock);
  plan.v_end_used = v_end;
  plan.v_end_actual = vel_to_phys(sol.v_end, clock);

  const i128 v_cap = std::min(i128(std::floor(std::max({req.v_cruise, req.v_start, v_end}) * u.vel)),
                              lim.v_rate);
  if (auto e = check_table(plan, lim, v_cap, dir, sol, ve)) return *e;
  return plan;
}

}  // namespace

namespace detail {

TravelWindow continuation_window(u128 frac, int64_t distance) {
  const int dir = distance < 0 ? -1 : 1;
  const int64_t dist = distance * dir;
  const i128 f = i128(frac);
  const i128 one = i128(kOne);
  // Aimed mid-pulse, as a move from rest ends, so a following reversal has
  // half a pulse before its first step.
  if (dir > 0) return {dist * one - f, (dist + 1) * one - f, dist * one + one / 2 - f};
  // End in (f - (dist+1), f - dist] below ... mirrored, integers.
  return {(dist - 1) * one + f + 1, dist * one + f + 1, dist * one - one / 2 + f};
}

PlanResult plan_continuation(const JunctionState& start, int64_t distance, double v_cruise, i128 ve,
                             const Limits& lim, Clock clock, bool messages) {
  return plan_continuation(start, {}, distance, v_cruise, ve, lim, clock, messages);
}

PlanResult plan_continuation(const JunctionState& start, const std::vector<Row>& prefix, int64_t distance,
                             double v_cruise, i128 ve, const Limits& lim, Clock clock, bool messages) {
  const int dir = distance < 0 ? -1 : 1;
  i128 vs = dir * start.velocity;
  // Travel (magnitude) that ends the move in [distance, distance + 1) pulses
  // from the start's integer part, less what the prefix covers.
  TravelWindow window = continuation_window(start.frac, distance);
  i128 prefix_peak = vs;
  for (const Row& r : prefix) {
    const i128 gain = row_gain(r);
    window.lo -= gain;
    window.hi -= gain;
    window.aim -= gain;
    vs = vel_after(r.vel0, r.acc0, r.jerk, r.clocks);
    prefix_peak = std::max({prefix_peak, r.vel0, vs});
  }
  const double v_start = vel_to_phys(vs, clock);
  const double v_end = vel_to_phys(ve, clock);
  auto solved = solve_profile(vs, v_cruise, ve, window, lim);
  if (!prefix.empty() && std::holds_alternative<Unsolvable>(solved) && vs == ve && window.lo <= 0 && window.hi > 0) {
    solved = Solved{{}, 0, vs, vs, 0};  // the prefix alone ends in the window at the end speed
  }
  if (const auto* why = std::get_if<Unsolvable>(&solved)) {
    if (!messages) return PlanError{why->end_unreachable ? "v_end" : "distance", {}};
    if (!why->end_unreachable) {
      return PlanError{"distance", fmt::format("distance={}: too short for any motion with these limits", distance)};
    }
    return PlanError{"v_end", fmt::format("v_end={} unreachable from the start speed {} pulses/s within "
                                          "distance={}",
                                          num(v_end), num(v_start), distance)};
  }
  Solved& sol = std::get<Solved>(solved);
  if (!prefix.empty()) sol.rows.insert(sol.rows.begin(), prefix.begin(), prefix.end());
  Plan plan;
  plan.clock = clock;
  plan.segments = to_segments(sol.rows, dir);
  plan.pos_frac0 = start.frac;
  plan.distance = distance;
  plan.v_plateau = vel_to_phys(sol.plateau, clock);
  plan.v_end_used = v_end;
  plan.v_end_actual = vel_to_phys(sol.v_end, clock);
  const i128 v_cap = std::max({std::min(i128(std::floor(v_cruise * lim.units.vel)), lim.v_rate), prefix_peak, ve});
  if (auto e = check_table(plan, lim, v_cap, dir, sol, ve)) return *e;
  return plan;
}

}  // namespace detail

VelocityResult Planner::plan_velocity(i128 v_from, const VelocityRequest& req, const PulseTiming& timing) const {
  // The clock, the timing, a_max and j_max are checked as for a move.
  MoveRequest as_move;
  as_move.distance = 1;
  as_move.v_cruise = PlannerLimits::kMinCruise;
  as_move.a_max = req.a_max;
  as_move.j_max = req.j_max;
  if (auto e = check_request(as_move, timing, clock_)) return *e;
  const double v_lim = step_rate_limit(timing, clock_);
  if (auto e = check_range("v_target", req.v_target, -v_lim, v_lim,
                           "pulses/s (the step-rate limit, either direction)")) {
    return *e;
  }
  Limits lim = make_limits(as_move, timing, clock_);
  lim.exact_transitions = true;
  const i128 speed_from = v_from < 0 ? -v_from : v_from;
  if (speed_from > lim.v_rate) {
    return PlanError{"v_from", fmt::format("v_from={} LSB: exceeds the step-rate limit {} LSB",
                                           to_string_i128(v_from), to_string_i128(lim.v_rate))};
  }
  const int dir_to = req.v_target < 0 ? -1 : 1;
  const i128 speed_to = std::min(i128(std::floor(std::fabs(req.v_target) * lim.units.vel)), lim.v_rate);
  const int dir_from = v_from < 0 ? -1 : 1;

  VelocityPlan out;
  // One transition of the speed (magnitude) in one direction.
  const auto ramp = [&](i128 from, i128 to, int dir) {
    if (from == to) return;
    const Transition t = transition_to(from, to, lim);
    const std::vector<Row> rows(t.rows.begin(), t.rows.end());
    for (const Row& r : rows) out.ramp_clocks += r.clocks;
    out.ramp_gain += dir * t.gain;
    for (const Segment& s : to_segments(rows, dir)) out.segments.push_back(s);
  };
  if (speed_from != 0 && speed_to != 0 && dir_from != dir_to) {
    ramp(speed_from, 0, dir_from);  // a direction change passes through rest
    ramp(0, speed_to, dir_to);
  } else {
    ramp(speed_from, speed_to, speed_from != 0 ? dir_from : dir_to);
  }
  out.v_end = dir_to * speed_to;
  out.hold = speed_to != 0;
  if (out.hold) {
    Segment h;
    h.phase = Phase::PhCruise;
    h.clocks = 1;
    h.vel0 = out.v_end;
    out.segments.push_back(h);
  }
  return out;
}

namespace {

// The start fraction and velocity of a move from an exact state.
std::optional<PlanError> check_start(const JunctionState& start, int dir, const Limits& lim) {
  if (start.frac >= kOne) {
    return PlanError{"start_frac", fmt::format("start_frac={}: must be < 2^{} (one pulse)",
                                               to_hex_u128(start.frac, 128), hw::FracBits)};
  }
  const i128 speed = start.velocity < 0 ? -start.velocity : start.velocity;
  if (speed > lim.v_rate) {
    return PlanError{"start_velocity", fmt::format("start_velocity={} LSB: exceeds the step-rate limit {} LSB",
                                                   to_string_i128(start.velocity), to_string_i128(lim.v_rate))};
  }
  if (start.velocity != 0 && (start.velocity < 0) != (dir < 0)) {
    return PlanError{"start_velocity",
                     fmt::format("start_velocity={} LSB: a direction change needs junction speed 0",
                                 to_string_i128(start.velocity))};
  }
  return std::nullopt;
}

}  // namespace

PlanResult Planner::plan_from(const JunctionState& start, const MoveRequest& req, const PulseTiming& timing) const {
  // The start speed is the exact state; validate the rest as plan() does.
  MoveRequest checked = req;
  checked.v_start = 0;
  if (auto e = check_request(checked, timing, clock_)) return *e;
  const Limits lim = [&] {
    Limits l = make_limits(req, timing, clock_);
    l.exact_transitions = true;
    l.least_above_cruise = true;
    return l;
  }();
  const int dir = req.distance < 0 ? -1 : 1;
  if (auto e = check_start(start, dir, lim)) return *e;
  const i128 speed = start.velocity < 0 ? -start.velocity : start.velocity;
  const i128 ve = std::min(i128(std::floor(req.v_end * lim.units.vel)), lim.v_rate);
  PlanResult r = plan_continuation(start, req.distance, req.v_cruise, ve, lim, clock_);
  if (std::holds_alternative<PlanError>(r) && req.adjust_end_speed && std::get<PlanError>(r).parameter == "v_end") {
    // The nearest reachable end speed (a cruise at the start speed always is).
    const TravelWindow window = continuation_window(start.frac, req.distance);
    std::optional<Plan> best;
    const i128 p_cruise = std::min(i128(std::floor(req.v_cruise * lim.units.vel)), lim.v_rate);
    if (const std::optional<i128> e = reachable_end_speed(speed, ve, p_cruise, window, lim)) {
      const bool up = ve >= speed;
      i128 u = up ? *e - speed : speed - *e;
      for (int k = 0; k < 4 && !best; u -= std::max<i128>(1, u >> kRetryShift[k++])) {
        if (u <= 0) break;
        PlanResult m = plan_continuation(start, req.distance, req.v_cruise, up ? speed + u : speed - u, lim, clock_,
                                         /*messages=*/false);
        if (auto* p = std::get_if<Plan>(&m)) best = std::move(*p);
      }
    }
    if (!best) {
      PlanResult m = plan_continuation(start, req.distance, req.v_cruise, speed, lim, clock_, /*messages=*/false);
      if (auto* p = std::get_if<Plan>(&m)) best = std::move(*p);
    }
    if (best) {
      best->end_speed_adjusted = true;
      return *best;
    }
  }
  return r;
}

namespace {

// The rows of a retargeted move's opening are built in magnitude form
// (direction +1) from the start state (v0, a0), a0 != 0, s = sign(a0).
struct RampPhases {
  Phase up, hold, down;
};
RampPhases ramp_phases(int s) {
  if (s > 0) return {Phase::PhAccJerkUp, Phase::PhAccConst, Phase::PhAccJerkDown};
  return {Phase::PhDecJerkUp, Phase::PhDecConst, Phase::PhDecJerkDown};
}
int64_t jerk_in(int s, const Limits& lim) { return s > 0 ? lim.j_acc_in : lim.j_dec_in; }
int64_t jerk_out(int s, const Limits& lim) { return s > 0 ? lim.j_acc_out : lim.j_dec_out; }

// Ramps the acceleration s * a_mag to exactly 0 at jerk <= j: ceil(a_mag / j)
// clocks, the first (a_mag mod clocks) one LSB steeper, as make_transition
// ends its ramps.
void push_ramp_down(RowList& rows, int64_t a_mag, int s, int64_t j, Phase phase) {
  if (a_mag <= 0) return;
  const int64_t n = a_mag / j + (a_mag % j != 0);
  const int64_t jd = a_mag / n;
  const int64_t r = a_mag - n * jd;
  if (r > 0) rows.push_back({phase, uint64_t(r), -s * (jd + 1), 0, 0});
  rows.push_back({phase, uint64_t(n - r), -s * jd, 0, 0});
}

// Fills the exact starting values of the rows from (v, a); returns the end
// state and the travel.
struct RowsEnd {
  i128 v = 0;
  int64_t a = 0;
  i128 gain = 0;
};
RowsEnd chain_rows(Row* begin, Row* end, i128 v, int64_t a) {
  RowsEnd out{v, a, 0};
  for (Row* r = begin; r != end; ++r) {
    r->vel0 = out.v;
    r->acc0 = out.a;
    out.gain += row_gain(*r);
    out.v = vel_after(r->vel0, r->acc0, r->jerk, r->clocks);
    out.a = int64_t(acc_after(r->acc0, r->jerk, r->clocks));
  }
  return out;
}

// The start acceleration s * a0m carries on: jerk up to a peak (<= a_max),
// hold, jerk down to exactly 0, changing the speed by exactly dv (> 0, in
// direction s): make_transition's shape entered mid-ramp, and its exact tail.
bool push_continued_ramp(RowList& rows, int64_t a0m, i128 dv, int s, const Limits& lim) {
  const int64_t j_up = jerk_in(s, lim), j_down = jerk_out(s, lim);
  const RampPhases ph = ramp_phases(s);
  // Continuous peak: (ap^2 - a0^2) / (2 j_up) + ap^2 / (2 j_down) = dv.
  const double a0d = double(a0m);
  const double ap =
      std::sqrt((double(dv) + a0d * a0d * 0.5 / double(j_up)) / (0.5 / double(j_up) + 0.5 / double(j_down)));
  int64_t a = std::clamp<int64_t>(int64_t(std::min(ap, double(lim.a_max))), a0m, lim.a_max);
  for (int iter = 0; iter < 400; ++iter) {
    RowList ramp;
    const int64_t rise = a - a0m;
    const int64_t n1 = rise / j_up + (rise % j_up != 0);
    const int64_t j1 = n1 > 0 ? rise / n1 : 0;
    const int64_t a1 = a0m + n1 * j1;
    if (n1 > 0) ramp.push_back({ph.up, uint64_t(n1), s * j1, 0, 0});
    push_ramp_down(ramp, a1, s, j_down, ph.down);
    const i128 dv_jerk = s * chain_rows(ramp.begin(), ramp.end(), 0, s * a0m).v;
    if (dv_jerk > dv) {
      if (a == a0m) return false;  // ending the start acceleration alone overshoots dv
      // The change beyond ending a0 grows with ap^2 - a0^2: scale that.
      const double dv0 = a0d * a0d * 0.5 / double(j_down);
      const double ratio = std::max(0.0, (double(dv) - dv0) / (double(dv_jerk) - dv0));
      const double ad = double(a);
      const double next = std::sqrt(a0d * a0d + (ad * ad - a0d * a0d) * ratio * 0.999);
      a = std::clamp<int64_t>(iter < 8 ? int64_t(next) : a0m + (a - a0m) / 2, a0m, a - 1);
      continue;
    }
    const i128 n2 = (dv - dv_jerk) / a1;
    for (const Row& r : ramp) {
      if (r.phase != ph.down) rows.push_back(r);
    }
    push_hold_and_ramp_down(rows, a1, uint64_t(n2), int64_t(dv - dv_jerk - n2 * a1), s, j_down, ph.hold, ph.down);
    return true;
  }
  return false;
}

// A retargeted move's start, magnitude form: (v0, a0) with a0 != 0, and the
// speed where ramping a0 to 0 at full jerk ends (the settle speed).
struct StartRamp {
  i128 v0 = 0;
  int64_t a0 = 0;
  int s = 1;
  i128 v_settle = 0;
};

// The opening from the start state to speed v at acceleration 0, in `out`:
// beyond the settle speed in a0's direction the ramp carries on; otherwise
// a0 settles and a transition (through the same full jerk) goes on to v.
// Returns the travel, or nothing if the rows cannot end at exactly v.
std::optional<i128> build_opening(std::vector<Row>& out, const StartRamp& st, i128 v, const Limits& lim) {
  RowList rows;
  const int64_t a0m = st.s * st.a0;
  if (st.s * (v - st.v_settle) > 0) {
    if (!push_continued_ramp(rows, a0m, st.s * (v - st.v0), st.s, lim)) return std::nullopt;
  } else {
    push_ramp_down(rows, a0m, st.s, jerk_out(st.s, lim), ramp_phases(st.s).down);
    Transition t;
    transition_to(t, st.v_settle, v, lim);
    if (t.too_far) return std::nullopt;
    for (const Row& r : t.rows) rows.push_back(r);
  }
  const RowsEnd end = chain_rows(rows.begin(), rows.end(), st.v0, st.a0);
  if (end.a != 0 || end.v != v) return std::nullopt;
  out.assign(rows.begin(), rows.end());
  return end.gain;
}

}  // namespace

PlanResult Planner::plan_from_state(const ExactState& start, const MoveRequest& req, const PulseTiming& timing) const {
  const JunctionState junction{start.velocity, start.frac};
  if (start.acceleration == 0) return plan_from(junction, req, timing);
  MoveRequest checked = req;
  checked.v_start = 0;
  if (auto e = check_request(checked, timing, clock_)) return *e;
  Limits lim = make_limits(req, timing, clock_);
  lim.exact_transitions = true;
  lim.least_above_cruise = true;
  const int dir = req.distance < 0 ? -1 : 1;
  if (auto e = check_start(junction, dir, lim)) return *e;
  const i128 a_mag = start.acceleration < 0 ? -i128(start.acceleration) : i128(start.acceleration);
  if (a_mag > lim.a_max) {
    return PlanError{"start_acceleration", fmt::format("start_acceleration={} LSB: exceeds a_max {} LSB",
                                                       start.acceleration, lim.a_max)};
  }
  // Trapezoid rows step the acceleration anyway: plan as from a = 0.
  if (lim.trapezoid) return plan_from(junction, req, timing);

  StartRamp st;
  st.v0 = dir * start.velocity;
  st.a0 = dir * start.acceleration;
  st.s = st.a0 > 0 ? 1 : -1;
  const auto refuse_ramp = [&](const char* why, const std::string& bound) {
    return PlanError{"start_acceleration",
                     fmt::format("start_acceleration={} LSB at start_velocity={} LSB: {} {}", start.acceleration,
                                 to_string_i128(start.velocity), why, bound)};
  };
  if (st.v0 == 0 && st.a0 < 0) {
    return refuse_ramp("points against the move from rest (a reversal needs rest first): needs", "0 or the move's "
                       "direction");
  }
  // The settle speed: first in double (a far estimate would overflow the exact sums), then exactly.
  const int64_t j_settle = jerk_out(st.s, lim);
  const double settle_est = double(st.v0) + st.s * double(a_mag) * double(a_mag) * 0.5 / double(j_settle);
  const std::string rate_bound = fmt::format("the step-rate limit {} LSB", to_string_i128(lim.v_rate));
  if (settle_est > 1.01 * double(lim.v_rate) + 2.0 * double(a_mag)) {
    return refuse_ramp("ending it at the jerk limit passes", rate_bound);
  }
  if (settle_est < -2.0 * double(a_mag)) {
    return refuse_ramp("ending it at the jerk limit reverses the velocity: needs a speed of at least",
                       fmt::format("{} LSB", num(-settle_est + double(st.v0))));
  }
  std::vector<Row> settle_rows;
  {
    RowList rows;
    push_ramp_down(rows, st.s * st.a0, st.s, j_settle, ramp_phases(st.s).down);
    settle_rows.assign(rows.begin(), rows.end());
    st.v_settle = chain_rows(settle_rows.data(), settle_rows.data() + settle_rows.size(), st.v0, st.a0).v;
  }
  if (st.v_settle > lim.v_rate) return refuse_ramp("ending it at the jerk limit passes", rate_bound);
  if (st.v_settle < 0) {
    return refuse_ramp("ending it at the jerk limit reverses the velocity: needs a speed of at least",
                       fmt::format("{} LSB", to_string_i128(st.v0 - st.v_settle)));
  }

  const double vel = lim.units.vel;
  const auto to_lsb = [&](double v) { return std::min(i128(std::floor(v * vel)), lim.v_rate); };
  const TravelWindow window = continuation_window(start.frac, req.distance);
  // The largest double whose speed is <= v (LSB), or the smallest one >= v.
  const auto phys_at_most = [&](i128 v) {
    double x = vel_to_phys(v, clock_);
    for (int k = 0; k < 64 && to_lsb(x) > v; ++k) x = std::nextafter(x, 0.0);
    return x;
  };
  const auto phys_at_least = [&](i128 v) {
    double x = vel_to_phys(v, clock_);
    for (int k = 0; k < 64 && to_lsb(x) < v; ++k) x = std::nextafter(x, HUGE_VAL);
    return x;
  };

  // The move to end speed v_end (pulses/s): the faster of
  //   * settle, then plan_from's solver from the settle speed;
  //   * the opening straight to the highest plateau whose opening and final
  //     transition fit the window, then a cruise at it (the continued ramp,
  //     or a plateau on the settle speed's far side when settling first
  //     would leave the start speed above the cruise speed).
  std::vector<Row> opening;
  const auto plan_to = [&](double v_end) -> PlanResult {
    const i128 ve = to_lsb(v_end);
    PlanResult best = plan_continuation(junction, settle_rows, req.distance, req.v_cruise, ve, lim, clock_, false);
    // Braking on below the settle speed only pays if settling leaves the
    // speed above the cruise speed, or nothing else fits.
    if (st.s < 0 && st.v_settle <= to_lsb(req.v_cruise) && std::holds_alternative<Plan>(best)) return best;
    // The plateau's range on the continued ramp's side of the settle speed.
    const double top_phys = std::max(req.v_cruise, v_end);
    double lo = 0, hi = 0;
    if (st.s > 0) {
      lo = std::max(phys_at_least(st.v_settle + 1), v_end);
      hi = top_phys;
    } else {
      lo = v_end;
      hi = to_lsb(top_phys) < st.v_settle ? top_phys : phys_at_most(st.v_settle - 1);
    }
    if (!(lo <= hi) || to_lsb(lo) > to_lsb(hi) || (st.s > 0 && to_lsb(lo) <= st.v_settle) ||
        (st.s < 0 && to_lsb(hi) >= st.v_settle)) {
      return best;
    }
    // The highest plateau whose travel stays within the aim (mid-pulse, as
    // the solver aims), else the lowest one if it still ends in the window.
    const auto fits = [&](double v, i128 bound) {
      const i128 p = to_lsb(v);
      const std::optional<i128> gain = build_opening(opening, st, p, lim);
      if (!gain) return false;
      const Transition last = transition_to(p, ve, lim);
      return !last.too_far && *gain + last.gain <= bound;
    };
    if (!fits(hi, window.aim)) {
      if (fits(lo, window.aim)) {
        for (int it = 0; it < 48; ++it) {  // hi does not fit, lo does
          const i128 gap = to_lsb(hi) - to_lsb(lo);
          if (gap <= std::max<i128>(1, to_lsb(hi) >> kBracketBits)) break;
          const double mid = 0.5 * (lo + hi);
          if (mid <= lo || mid >= hi) break;
          (fits(mid, window.aim) ? lo : hi) = mid;
        }
      } else if (!fits(lo, window.hi - 1)) {
        return best;
      }
      hi = lo;
      if (!fits(hi, window.hi - 1)) return best;  // (rebuilds the opening at hi)
    }
    // A plateau of 0 (a stop short of the target) lets the solver creep on.
    PlanResult ramp = plan_continuation(junction, opening, req.distance, to_lsb(hi) > 0 ? hi : req.v_cruise, ve,
                                        lim, clock_, false);
    const Plan* a = std::get_if<Plan>(&best);
    const Plan* b = std::get_if<Plan>(&ramp);
    if (b && (!a || b->total_clocks < a->total_clocks)) return ramp;
    return best;
  };

  PlanResult r = plan_to(req.v_end);
  if (auto* p = std::get_if<Plan>(&r)) {
    p->v_end_used = req.v_end;
    return r;
  }
  const i128 ve = to_lsb(req.v_end);
  const auto least_travel = [&](i128 v) -> std::optional<i128> { return build_opening(opening, st, v, lim); };
  if (req.adjust_end_speed && ve != st.v_settle) {
    // The reachable end speeds lie around the settle speed (the opening to
    // them travels least there); the one nearest v_end, a few tries nearer.
    double good = phys_at_most(st.v_settle), bad = req.v_end;
    const auto reachable = [&](double v) {
      const std::optional<i128> g = least_travel(to_lsb(v));
      return g && *g < window.hi;
    };
    if (reachable(good)) {
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (good + bad);
        if (mid == good || mid == bad || to_lsb(good) == to_lsb(bad)) break;
        (reachable(mid) ? good : bad) = mid;
      }
      for (int k = 0; k < 6; ++k) {
        PlanResult m = plan_to(good);
        if (auto* p = std::get_if<Plan>(&m)) {
          p->end_speed_adjusted = true;
          p->v_end_used = good;
          return m;
        }
        good += (phys_at_most(st.v_settle) - good) * 0.25;
      }
    }
  }
  // Nothing fits: the opening straight to the end speed travels least.
  const std::optional<i128> least = least_travel(ve);
  std::string need = "more than 1e12";
  if (least) {
    const i128 one = i128(kOne);
    const i128 c = window.hi - i128(req.distance * dir) * one;  // hi = distance * one + c
    const i128 over = *least - c;
    need = fmt::format("{}", to_string_i128(over < 0 ? 1 : std::max<i128>(1, over / one + 1)));
  }
  const std::string from = fmt::format("from the start state (velocity {} LSB, acceleration {} LSB)",
                                       to_string_i128(start.velocity), start.acceleration);
  if (ve == 0) {
    return PlanError{"distance", fmt::format("distance={}: too short to stop {}: needs distance >= {} pulses",
                                             req.distance, from, need)};
  }
  return PlanError{"v_end", fmt::format("v_end={} unreachable {}: needs distance >= {} pulses, got {}{}",
                                        num(req.v_end), from, need, req.distance * dir,
                                        req.adjust_end_speed ? "" : " (or allow --adjust-end-speed)")};
}

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
    const i128 v_last = vel_after(s.vel0, s.acc0, s.jerk, last);
    upd_v(s.vel0);
    upd_v(v_last);
    // v_{c+1} - v_c = a_c: while the acceleration keeps one sign over the
    // row, v is monotone and its extremes are the two ends above.
    const i128 a_last = acc_after(s.acc0, s.jerk, last);
    const i128 a_before_last = last > 0 ? a_last - s.jerk : a_last;
    const bool monotone = (s.acc0 >= 0 && a_before_last >= 0) || (s.acc0 <= 0 && a_before_last <= 0);
    if (s.jerk != 0 && !monotone) {
      const double ks = 0.5 - double(s.acc0) / double(s.jerk);
      for (int64_t c = int64_t(std::floor(ks)) - 1; c <= int64_t(std::floor(ks)) + 2; ++c) {
        if (c >= 0 && uint64_t(c) <= last) upd_v(vel_after(s.vel0, s.acc0, s.jerk, uint64_t(c)));
      }
    }
    upd_a(s.acc0);
    upd_a(a_last);
    upd_j(s.jerk);
    if (have_prev) {  // per-clock differences across the reload
      upd_a(s.vel0 - prev_v);
      upd_j(i128(s.acc0) - prev_a);
    }
    pos += pos_gain(s.vel0, s.acc0, s.jerk, n);
    rep.clocks += n;
    prev_v = v_last;
    prev_a = int64_t(a_last);
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
