#include "stop_gen.h"

#include <algorithm>

namespace sc {

namespace {

constexpr i128 kJMax = (i128(1) << (JerkW - 1)) - 1;
constexpr i128 kDMax = (i128(1) << (AccW - 1)) - 1;
constexpr u128 kDMask = (u128(1) << StopGen::kDW) - 1;

// Closed forms for i clocks of one move with level step delta.
struct Phase3 {
  i128 v, b, u;
};
Phase3 after(const StopGen::State& q, StopGen::Move m, uint64_t i) {
  const i128 ii = i128(i);
  const i128 c2 = i128(choose2(i));
  const i128 j = i128(q.j);
  switch (m) {
    case StopGen::Move::Up:
      return {q.v - ii * q.b - j * c2, q.b + ii * j, q.u + ii * q.b + j * (c2 + ii)};
    case StopGen::Move::Down:
      return {q.v - ii * q.b + j * c2, q.b - ii * j, q.u - ii * q.b + j * c2};
    default:
      return {q.v - ii * q.b, q.b, q.u};
  }
}

}  // namespace

StopGen::Next StopGen::decide() const {
  Next n;
  const i128 j = i128(q_.j);
  const i128 d = i128(q_.d);
  const i128 b = q_.b;
  n.v1 = q_.v - b;  // exact (the RTL compares in 90 bits)
  // Up: brake harder by J, clamped at D (off the grid: remember the grid level).
  const i128 bsum = b + j;
  const bool clamp_up = bsum > d;
  const i128 bu = clamp_up ? d : bsum;
  const i128 uu = b <= 0 ? std::max<i128>(bu, 0) : q_.u + bu;
  const bool up_ok = b < d && !q_.uinf && n.v1 >= uu;
  // Land: a level equal to the remaining velocity (<= J) ends the stop next clock.
  const bool land_ok = n.v1 >= 0 && n.v1 <= j && n.v1 <= d && n.v1 <= b + j && n.v1 >= b - j;
  const bool hold_ok = b <= d && !q_.uinf && n.v1 >= q_.u;
  if (up_ok) {
    n.move = Move::Up;
    n.b1 = bu;
    n.u1 = uu;
    n.clamp1 = clamp_up;
  } else if (land_ok) {
    n.move = Move::Land;
    n.b1 = n.v1;
    n.u1 = n.v1;
  } else if (hold_ok) {
    n.move = Move::Hold;
    n.b1 = b;
    n.u1 = q_.u;
    n.clamp1 = q_.clamp;
  } else {
    n.move = Move::Down;
    n.b1 = b > j ? (q_.clamp ? q_.g : b - j) : (b > 0 ? i128(0) : b);
    n.u1 = n.b1 <= j ? std::max<i128>(n.b1, 0) : q_.u - b;
  }
  return n;
}

int64_t StopGen::jerk() const {
  if (!q_.active) return 0;
  const i128 delta = decide().b1 - q_.b;
  return int64_t(q_.neg ? delta : -delta);
}

void StopGen::step(const Inputs& in) {
  if (in.start) {
    State s;
    const uint64_t jin = in.stop_jerk & ((uint64_t(1) << JerkW) - 1);
    s.j = uint64_t(std::clamp<i128>(i128(jin), 1, kJMax));
    s.d = uint64_t(std::clamp<i128>(i128(in.stop_acc), 1, kDMax));
    const i128 vel = wrap_signed(in.vel, VelW);
    const i128 acc = in.acc;
    s.neg = vel < 0 || (vel == 0 && acc < 0);
    s.v = s.neg ? -vel : vel;
    s.b = s.neg ? acc : -acc;
    if (s.v == 0 && s.b == 0) {
      s.done = true;
    } else {
      s.active = true;
      if (s.b <= i128(s.j)) {
        s.u = std::max<i128>(s.b, 0);
      } else {
        const int eb = msb_u128(u128(s.b));
        const int ej = msb_u128(u128(s.j));
        if (2 * eb - ej >= kInfExp) {
          s.uinf = true;
        } else {
          // One shifter: b0 << k0 now, J << k0 and J << 2k0 in the next two clocks.
          s.div = true;
          s.prep = 1;
          s.k = uint8_t(eb - ej);
          s.rem = u128(s.b);
          s.remk = (u128(s.b) << s.k) & kDMask;
          s.u = i128(s.remk << 1);
        }
      }
    }
    q_ = s;
    return;
  }
  if (!q_.active) return;

  const Next n = decide();
  State s = q_;
  s.v = wrap_signed(n.v1, kVW);
  s.b = wrap_signed(n.b1, kBW);
  s.u = wrap_signed(n.u1, kUW);
  s.clamp = n.clamp1;
  if (n.move == Move::Up && n.clamp1) s.g = q_.b;
  if (n.b1 <= i128(q_.j)) {
    // At or below one jerk step the bound is exact (R(b) = b): resync.
    s.div = false;
    s.uinf = false;
  } else if (q_.div && q_.prep == 1) {
    s.jk = (u128(q_.j) << q_.k) & kDMask;
    s.prep = 2;
  } else if (q_.div && q_.prep == 2) {
    s.j2k = (q_.jk << q_.k) & kDMask;
    s.prep = 0;
  } else if (q_.div) {
    // One bit of floor(b0 / J); the bound tightens by d (see docs/stop.md).
    const bool take = q_.rem >= q_.jk;
    const u128 dec = take ? (3 * q_.j2k - q_.jk) >> 1 : q_.remk;
    s.u = wrap_signed(n.u1 - i128(dec), kUW);
    if (take) {
      s.rem = q_.rem - q_.jk;
      s.remk = q_.remk - q_.j2k;
    }
    if (q_.k == 0) {
      s.div = false;
    } else {
      s.k = uint8_t(q_.k - 1);
      s.jk = q_.jk >> 1;
      s.j2k = q_.j2k >> 2;
      s.remk = s.remk >> 1;
    }
  }
  if (n.v1 < 0) {
    // Only reachable from a start state that no stop within J can bring to
    // rest without reversing: finish |a| -> 0, then stop the other way.
    s.overshoot = true;
    if (n.b1 == 0) {
      s.neg = !q_.neg;
      s.v = wrap_signed(-n.v1, kVW);
    }
  }
  if (n.v1 == 0 && n.b1 == 0) {
    s.active = false;
    s.done = true;
    s.div = false;
    s.clamp = false;
  }
  q_ = s;
}

uint64_t StopGen::constant_span() const {
  if (!q_.active) return 0;
  if (q_.div || q_.uinf || q_.b <= 2 * i128(q_.j) || q_.v <= 0) return 1;
  const Move m = decide().move;
  // Land ends the stop; the first step down from the clamp goes to g.
  if (m == Move::Land || (m == Move::Down && q_.clamp)) return 1;
  const i128 j = i128(q_.j);
  const i128 d = i128(q_.d);
  // Is clock i (0-based) still the same move with the same level step?
  auto same = [&](uint64_t i) {
    const Phase3 p = after(q_, m, i);
    const i128 v1 = p.v - p.b;
    if (v1 <= j) return false;  // landing possible: leave it to step()
    switch (m) {
      case Move::Up:
        return p.b + j <= d && v1 >= p.u + p.b + j;
      case Move::Hold:
        return v1 >= p.u;
      default:
        return p.b > 2 * j && v1 < p.u;
    }
  };
  if (!same(0)) return 1;
  uint64_t lo = 1, hi = 2;  // same(lo - 1) holds
  constexpr uint64_t kMax = uint64_t(1) << 38;
  while (hi < kMax && same(hi - 1)) {
    lo = hi;
    hi *= 2;
  }
  if (hi >= kMax) return lo;
  while (hi - lo > 1) {
    const uint64_t mid = lo + (hi - lo) / 2;
    if (same(mid - 1)) lo = mid; else hi = mid;
  }
  return lo;
}

void StopGen::advance(uint64_t n) {
  if (n == 0) return;
  const Move m = decide().move;
  const Phase3 p = after(q_, m, n);
  q_.v = p.v;
  q_.b = p.b;
  q_.u = p.u;
}

}  // namespace sc
