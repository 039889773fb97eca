// The row reach evaluator (sc_row_reach / RowReach): RTL and model in
// lockstep every clock, and the reach checked against references that do
// not share its algorithm: the executor's recurrence run clock by clock
// (short rows) and the position at the real roots of the velocity polynomial
// (rows of any length).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>

#include "profile_exec.h"
#include "row_reach.h"
#include "rtl_row_reach.h"

using namespace sc;

namespace {

// A row's segment as the executor queues it (the evaluator reads all but its phase).
Segment row(uint32_t clocks, int64_t jerk, int64_t acc0, i128 vel0) {
  return {Phase::PhIdle, clocks, jerk, acc0, vel0};
}

std::string describe(const Segment& r) {
  return "clocks " + std::to_string(r.clocks) + " jerk " + std::to_string(r.jerk) + " acc0 " +
         std::to_string(r.acc0) + " vel0 " + to_string_i128(r.vel0);
}

constexpr i128 kVelLim = i128(1) << (VelW - 1);
constexpr i128 kAccLim = i128(1) << (AccW - 1);
constexpr int kUnitSh = FracBits - ReachFrac;

i128 floor_div_pow2(i128 x, int sh) { return x >> sh; }  // arithmetic: floor
i128 ceil_div_pow2(i128 x, int sh) { return -((-x) >> sh); }

struct Reach {
  int64_t fwd = 0, rev = 0;
  bool operator==(const Reach&) const = default;
};
const Reach kSaturated{RowReach::kReachMax, RowReach::kReachMin};

// The executor's recurrence, clock by clock: pos += v; v += a; a += j.
Reach reach_by_recurrence(const Segment& r) {
  i128 p = 0, v = r.vel0, a = r.acc0, lo = 0, hi = 0;
  for (uint32_t n = 0; n < r.clocks; ++n) {
    if (v < -kVelLim || v >= kVelLim) return kSaturated;
    if (n + 1 < r.clocks && (a < -kAccLim || a >= kAccLim)) return kSaturated;
    p += v;
    v += a;
    a += r.jerk;
    lo = std::min(lo, p);
    hi = std::max(hi, p);
  }
  return {int64_t(ceil_div_pow2(hi, kUnitSh)), int64_t(floor_div_pow2(lo, kUnitSh))};
}

// Any length: S(n) exactly (the planner's closed form) at the ends and at the
// integers around the real roots of v(x) = v0 + x a0 + x (x - 1) / 2 j; the
// range checks at the ends and at the vertex of v.
Reach reach_by_roots(const Segment& r) {
  const uint32_t N = r.clocks;
  if (N == 0) return {};
  auto vel = [&](uint64_t n) { return vel_after(r.vel0, r.acc0, r.jerk, n); };
  auto in_vel = [&](uint64_t n) { const i128 v = vel(n); return v >= -kVelLim && v < kVelLim; };
  const long double v0 = (long double)r.vel0, a0 = (long double)r.acc0, j = (long double)r.jerk;
  std::vector<long double> xs;
  if (r.jerk != 0) {
    // j/2 x^2 + (a0 - j/2) x + v0 = 0; the vertex at (j/2 - a0) / j
    const long double A = j / 2, B = a0 - j / 2, C = v0;
    xs.push_back(-B / (2 * A));
    const long double disc = B * B - 4 * A * C;
    if (disc >= 0) {
      xs.push_back((-B + std::sqrt(disc)) / (2 * A));
      xs.push_back((-B - std::sqrt(disc)) / (2 * A));
    }
  } else if (r.acc0 != 0) {
    xs.push_back(-v0 / a0);
  }
  std::vector<uint64_t> ns = {0, 1, N - 1, N};
  for (long double x : xs) {
    if (!(x > -4 && x < N + 4.0L)) continue;
    const int64_t c = int64_t(std::floor(x));
    for (int64_t d = -2; d <= 3; ++d) {
      if (c + d >= 0 && c + d <= int64_t(N)) ns.push_back(uint64_t(c + d));
    }
  }
  // velocity range: at the ends and around the vertex (v monotone between)
  for (uint64_t n : ns) {
    if (n < N && !in_vel(n)) return kSaturated;
  }
  if (N >= 2) {
    const i128 a_last = acc_after(r.acc0, r.jerk, N - 2);
    if (a_last < -kAccLim || a_last >= kAccLim) return kSaturated;
  }
  i128 lo = 0, hi = 0;
  for (uint64_t n : ns) {
    const i128 s = pos_gain(r.vel0, r.acc0, r.jerk, n);
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  }
  return {int64_t(ceil_div_pow2(hi, kUnitSh)), int64_t(floor_div_pow2(lo, kUnitSh))};
}

// A row of `clocks` clocks that stays in range with a sign change of v
// inside as often as not: v0, a0 and j drawn so that the row's velocity
// changes by up to about its start velocity.
Segment random_row(std::mt19937_64& rng, uint32_t max_clocks) {
  std::uniform_int_distribution<uint32_t> nd(1, max_clocks);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Segment r;
  r.clocks = nd(rng);
  const long double N = r.clocks;
  const long double vmax = std::ldexp(1.0L, VelW - 2) * std::pow(2.0L, -20.0L * std::fabs(u(rng)));
  r.vel0 = i128(vmax * u(rng));
  const long double amax = std::min<long double>(vmax / N * 2, std::ldexp(1.0L, AccW - 2));
  r.acc0 = int64_t(amax * u(rng));
  const long double jmax = std::min<long double>(vmax / (N * N) * 4, std::ldexp(1.0L, JerkW - 2));
  const int kind = int(rng() % 6);
  r.jerk = kind == 0 ? 0 : int64_t(jmax * u(rng));
  if (kind == 1) r.acc0 = 0;
  if (kind == 2) r.vel0 = 0;
  if (rng() % 40 == 0) {
    // near the velocity limit and accelerating on: leaves the velocity range
    const int sign = rng() % 2 ? 1 : -1;
    r.vel0 = sign * (kVelLim - kVelLim / 65536);
    r.acc0 = sign * int64_t(std::min<long double>(std::ldexp(1.0L, AccW - 2), std::ldexp(1.0L, VelW - 4) / N));
    r.jerk = 0;
  }
  return r;
}

struct Evaluation {
  Reach reach;
  uint64_t clocks = 0;
  uint64_t mismatches = 0;
};

// One evaluation from idle; with `rtl`, both every clock.
Evaluation evaluate(const Segment& r, RowReach& model, RtlRowReach* rtl) {
  Evaluation run;
  RowReach::Inputs in;
  in.start = true;
  in.clocks = r.clocks;
  in.jerk = r.jerk;
  in.acc0 = r.acc0;
  in.vel0 = r.vel0;
  for (;;) {
    if (rtl && !(rtl->outputs() == outputs_of(model))) ++run.mismatches;
    if (model.done()) {
      run.reach = {model.reach_fwd(), model.reach_rev()};
      break;
    }
    model.step(in);
    if (rtl) rtl->step(in);
    in.start = false;
    ++run.clocks;
    if (run.clocks > 100000) break;
  }
  model.step(in);  // back to idle
  if (rtl) rtl->step(in);
  return run;
}

}  // namespace

TEST(RowReachLockstep, RtlMatchesModelEveryClockOnRandomRows) {
  RtlRowReach rtl;
  rtl.reset();
  RowReach model;
  std::mt19937_64 rng(11);
  uint64_t clocks = 0, mismatches = 0, longest = 0;
  int rows = 0;
  for (; rows < 400; ++rows) {
    const Segment r = random_row(rng, rows % 2 ? 5000 : 0xffffffffu);
    const Evaluation run = evaluate(r, model, &rtl);
    ASSERT_LT(run.clocks, 100000u) << describe(r);
    clocks += run.clocks;
    longest = std::max(longest, run.clocks);
    mismatches += run.mismatches;
    ASSERT_EQ(run.mismatches, 0u) << describe(r);
  }
  // An abort in the middle of an evaluation: both idle, the next row right.
  RowReach::Inputs in;
  in.start = true;
  in.clocks = 1000;
  in.vel0 = i128(1) << 70;
  in.acc0 = -(int64_t(1) << 61);
  for (int c = 0; c < 300; ++c) {
    EXPECT_EQ(rtl.outputs(), outputs_of(model));
    in.abort = c == 200;
    model.step(in);
    rtl.step(in);
    in.start = false;
  }
  EXPECT_FALSE(model.busy());
  EXPECT_EQ(rtl.outputs(), outputs_of(model));
  std::printf("row reach lockstep: %d rows, %llu clocks (longest %llu), %llu mismatches\n", rows,
              (unsigned long long)clocks, (unsigned long long)longest, (unsigned long long)mismatches);
}

TEST(RowReachReference, ShortRowsMatchTheExecutorRecurrence) {
  RowReach model;
  std::mt19937_64 rng(12);
  int reversing = 0, saturated = 0;
  for (int i = 0; i < 3000; ++i) {
    const Segment r = random_row(rng, 3000);
    const Reach want = reach_by_recurrence(r);
    const Evaluation run = evaluate(r, model, nullptr);
    ASSERT_EQ(run.reach, want) << describe(r) << ": fwd " << run.reach.fwd << " rev " << run.reach.rev
                               << " want " << want.fwd << " / " << want.rev;
    if (want == kSaturated) ++saturated;
    else if (want.fwd > 0 && want.rev < 0) ++reversing;
  }
  std::printf("3000 short rows: %d reverse inside, %d leave the velocity range\n", reversing, saturated);
  EXPECT_GT(reversing, 300);
  EXPECT_GT(saturated, 10);
}

TEST(RowReachReference, RowsOfAnyLengthMatchTheRootsOfTheVelocity) {
  RowReach model;
  std::mt19937_64 rng(13);
  uint64_t longest = 0;
  for (int i = 0; i < 3000; ++i) {
    const Segment r = random_row(rng, 0xffffffffu);
    const Reach want = reach_by_roots(r);
    const Evaluation run = evaluate(r, model, nullptr);
    ASSERT_EQ(run.reach, want) << describe(r);
    longest = std::max(longest, run.clocks);
  }
  std::printf("3000 rows up to 2^32 clocks: longest evaluation %llu clocks\n", (unsigned long long)longest);
}

TEST(RowReachEdges, DirectedRows) {
  RowReach model;
  auto reach = [&](Segment r) { return evaluate(r, model, nullptr).reach; };
  const int64_t one = int64_t(1) << ReachFrac;  // one pulse
  // No clocks: nothing moves.
  EXPECT_EQ(reach(row(0, 0, 0, 0)), (Reach{0, 0}));
  // One clock at half a pulse per clock: half a pulse forward.
  EXPECT_EQ(reach(row(1, 0, 0, kOne / 2)), (Reach{one / 2, 0}));
  // Cruise backward, 1000 clocks at -1/4 pulse per clock: -250 pulses.
  EXPECT_EQ(reach(row(1000, 0, 0, -kOne / 4)), (Reach{0, -250 * one}));
  // Decelerate through zero: v0 = 1/2, a = -1/1000 per clock: peak past
  // the start, end behind it; both against the recurrence.
  const Segment rev = row(300000, 0, -(int64_t(1) << 62), kOne / 2);  // a = -2^-18 pulses/clock^2
  EXPECT_EQ(reach(rev), reach_by_recurrence(rev));
  EXPECT_EQ(reach(rev), reach_by_roots(rev));
  EXPECT_GT(reach(rev).fwd, 30000 * one);
  EXPECT_LT(reach(rev).rev, 0);
  // The largest velocity for 2^32 - 1 clocks: under 2^32 pulses, in range.
  const Segment far = row(0xffffffffu, 0, 0, kVelLim - 1);
  EXPECT_EQ(reach(far), reach_by_roots(far));
  EXPECT_LT(reach(far).fwd, RowReach::kReachMax);
  // An acceleration that wraps the velocity inside the row: unbounded.
  EXPECT_EQ(reach(row(1000000, 0, int64_t(1) << 62, 0)), kSaturated);
}
