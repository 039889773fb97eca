// The controlled stop (sc_stop_gen / StopGen): RTL and model in lockstep
// every clock, and the stop's properties checked from the motion alone
// (stop_harness.h): no reversal, |da| <= J, |a| <= D once reached, exact rest,
// nothing after rest, distance within one pulse of the continuous minimum.
#include <gtest/gtest.h>

#include <cstdio>

#include "stop_harness.h"

using namespace sc;
using namespace sc::stoptest;

namespace {

struct Campaign {
  int cases = 0;
  int feasible = 0;
  uint64_t clocks = 0;
  uint64_t mismatches = 0;
  ld worst_err = 0;    // pulses, signed (distance - closed form)
  ld worst_extra = 0;  // clocks beyond the closed-form time
  ld worst_rel_extra = 0;
};

void check_case(const StopCase& c, const StopResult& r, Campaign& k) {
  ++k.cases;
  k.clocks += r.clocks;
  k.mismatches += r.mismatches;
  EXPECT_EQ(r.mismatches, 0u) << describe(c) << " first: " << r.first_mismatch;
  EXPECT_TRUE(r.errors.empty()) << describe(c) << ": " << (r.errors.empty() ? "" : r.errors.front());
  if (r.feasible) {
    ++k.feasible;
    EXPECT_FALSE(r.overshoot) << describe(c);
    ASSERT_TRUE(r.cf_feasible) << describe(c);
    const ld err = r.distance - r.cf_distance;
    EXPECT_LE(std::fabs(err), 1.0L) << describe(c) << " distance " << double(r.distance) << " closed form "
                                    << double(r.cf_distance);
    if (std::fabs(err) > std::fabs(k.worst_err)) k.worst_err = err;
    const ld extra = ld(r.clocks) - r.cf_time;
    k.worst_extra = std::max(k.worst_extra, extra);
    if (r.cf_time > 1000) k.worst_rel_extra = std::max(k.worst_rel_extra, extra / r.cf_time);
  } else {
    EXPECT_TRUE(r.overshoot) << "a start that cannot stop without reversal is flagged: " << describe(c);
  }
}

void report(const char* name, const Campaign& k) {
  std::printf("%s: %d stops (%d stoppable without reversal), %llu clocks, %llu mismatches, worst distance - "
              "closed form %+.6Lf pulses, worst time beyond closed form %.1Lf clocks (%.2Lg relative)\n",
              name, k.cases, k.feasible, (unsigned long long)k.clocks, (unsigned long long)k.mismatches,
              k.worst_err, k.worst_extra, k.worst_rel_extra);
}

StopResult run(const StopCase& c, RtlStopGen* rtl = nullptr) { return run_stop(c, rtl, 100'000'000); }

}  // namespace

TEST(StopGenLockstep, RtlMatchesModelEveryClockFromRandomStates) {
  RtlStopGen rtl;
  rtl.reset();
  CaseGen gen(11);
  Campaign k;
  for (int i = 0; i < 1200; ++i) {
    const StopCase c = gen.next(20000);
    check_case(c, run_stop(c, &rtl, 10'000'000), k);
    if (HasFailure()) break;
  }
  report("lockstep", k);
  EXPECT_EQ(k.mismatches, 0u);
}

TEST(StopGenLockstep, ComparisonCatchesAnInjectedDifference) {
  RtlStopGen rtl;
  rtl.reset();
  StopGen m;
  const StopGen::Inputs start{true, i128(1) << 70, -(int64_t(1) << 40), uint64_t(1) << 30, uint64_t(1) << 44};
  m.step(start);
  rtl.step(start);
  const StopGen::Inputs quiet{};
  int first = -1;
  for (int clk = 0; clk < 100 && first < 0; ++clk) {
    if (clk == 20) m.mutable_state().j += 1;  // the model's stop jerk off by one LSB
    if (!(rtl.outputs() == outputs_of(m))) first = clk;
    m.step(quiet);
    rtl.step(quiet);
  }
  EXPECT_EQ(first, 20);
}

TEST(StopGenProperties, RandomStatesStopWithinOnePulseOfClosedForm) {
  CaseGen gen(23);
  Campaign k;
  for (int i = 0; i < 1000; ++i) {
    const StopCase c = gen.next(200000);
    check_case(c, run(c), k);
    if (HasFailure()) break;
  }
  report("model", k);
}

TEST(StopGenEdges, AtRestIsDoneAtOnce) {
  StopGen m;
  m.step({true, 0, 0, 1000, 1000});
  EXPECT_FALSE(m.active());
  EXPECT_TRUE(m.done());
  EXPECT_EQ(m.jerk(), 0);
}

TEST(StopGenEdges, ZeroVelocityWithAccelerationEndsAtRestWithoutReversal) {
  for (int64_t a : {int64_t(1), int64_t(-1), int64_t(999), int64_t(1000), int64_t(-123456789), int64_t(1) << 50,
                    -(int64_t(1) << 50)}) {
    const uint64_t mag = uint64_t(a < 0 ? -a : a);
    for (uint64_t j : {std::max<uint64_t>(1, mag / 1000), std::max<uint64_t>(1, mag / 7), std::min<uint64_t>(2 * mag + 1, (uint64_t(1) << 47) - 1)}) {
      const StopCase c{0, a, j, uint64_t(1) << 45};
      const StopResult r = run(c);
      EXPECT_TRUE(r.errors.empty()) << describe(c) << ": " << (r.errors.empty() ? "" : r.errors.front());
      EXPECT_TRUE(r.feasible && !r.overshoot) << describe(c);
      EXPECT_GE(r.distance, 0) << describe(c);
    }
  }
}

TEST(StopGenEdges, TinyVelocitiesEndExactly) {
  for (int v = -5; v <= 5; ++v) {
    for (int64_t a : {int64_t(0), int64_t(1), int64_t(-1), int64_t(3), int64_t(-3)}) {
      const StopCase c{v, a, 2, 7};
      const StopResult r = run(c);
      EXPECT_TRUE(r.errors.empty()) << describe(c) << ": " << (r.errors.empty() ? "" : r.errors.front());
      EXPECT_LT(r.clocks, 20u) << describe(c);
    }
  }
}

TEST(StopGenEdges, AccelerationAboveTheLimitRampsIntoItAtStopJerk) {
  // a = 8 D against the motion, plenty of velocity: |a| falls by J each clock
  // until it is within D, then never leaves it (checked by StopChecker).
  const uint64_t J = uint64_t(1) << 40, D = uint64_t(1) << 50;
  const StopCase c{i128(1) << 72, -int64_t(8 * D), J, D};
  StopGen m;
  m.step({true, c.v, c.a, c.j, c.d});
  for (int i = 0; i < 100; ++i) {
    EXPECT_EQ(m.jerk(), int64_t(J)) << "clock " << i;
    m.step({});
  }
  const StopResult r = run(c);
  EXPECT_TRUE(r.errors.empty()) << (r.errors.empty() ? "" : r.errors.front());
  EXPECT_LE(std::fabs(r.distance - r.cf_distance), 1.0L);
}

TEST(StopGenEdges, MirroredStartsAreMirroredStops) {
  CaseGen gen(5);
  for (int i = 0; i < 200; ++i) {
    StopCase c = gen.next(20000);
    StopCase n = c;
    n.v = -c.v;
    n.a = -c.a;
    const StopResult rp = run(c), rn = run(n);
    EXPECT_EQ(rp.clocks, rn.clocks) << describe(c);
    EXPECT_LE(std::fabs(rp.distance - rn.distance), 1e-6L) << describe(c);
  }
}

TEST(StopGenEdges, StartThatCannotStopWithoutReversalIsFlaggedAndStillEndsAtRest) {
  // Braking at 2^40 LSB with almost no velocity left and J = 2^20: ramping a
  // to 0 takes 2^20 clocks, far more than the velocity lasts.
  const StopCase c{i128(1) << 30, -(int64_t(1) << 40), uint64_t(1) << 20, uint64_t(1) << 44};
  ASSERT_FALSE(discrete_feasible(c));
  const StopResult r = run(c);
  EXPECT_TRUE(r.overshoot);
  EXPECT_TRUE(r.errors.empty()) << (r.errors.empty() ? "" : r.errors.front());
}

TEST(StopGenEdges, ExtremeWidthsAndLimits) {
  const i128 vmax = (i128(1) << (VelW - 1)) - 1;
  const int64_t amax = std::numeric_limits<int64_t>::max();
  RtlStopGen rtl;
  rtl.reset();
  // J and D at their largest, zero limits (taken as 1), |a| at full scale.
  const StopCase cases[] = {
      {vmax, 0, ~uint64_t(0), ~uint64_t(0)},
      {-vmax, 0, ~uint64_t(0), ~uint64_t(0)},
      {vmax / 4, -amax / 1024, uint64_t(1) << 46, ~uint64_t(0)},
      {vmax, -amax, (uint64_t(1) << 47) - 1, ~uint64_t(0)},
      {5, 3, 0, 0},
      {1000, std::numeric_limits<int64_t>::min(), (uint64_t(1) << 47) - 1, ~uint64_t(0)},
  };
  for (const StopCase& c : cases) {
    const StopResult r = run_stop(c, &rtl, 50'000'000);
    EXPECT_EQ(r.mismatches, 0u) << describe(c) << " " << r.first_mismatch;
    EXPECT_TRUE(r.errors.empty()) << describe(c) << ": " << (r.errors.empty() ? "" : r.errors.front());
  }
}

TEST(StopGenEdges, StartWhileStoppingRestartsFromTheGivenState) {
  StopGen m;
  m.step({true, i128(1) << 72, 0, uint64_t(1) << 30, uint64_t(1) << 42});
  for (int i = 0; i < 1000; ++i) m.step({});
  ASSERT_TRUE(m.active());
  m.step({true, -(i128(1) << 60), int64_t(1) << 35, uint64_t(1) << 30, uint64_t(1) << 42});
  EXPECT_TRUE(m.state().neg);
  EXPECT_EQ(m.state().v, i128(1) << 60);
}

// constant_span()/advance() jump through phases of constant jerk; the state
// after each jump equals per-clock stepping.
TEST(StopGenFastForward, ConstantSpanAdvanceMatchesStep) {
  CaseGen gen(31);
  uint64_t jumped = 0, clocks = 0;
  for (int i = 0; i < 200; ++i) {
    const StopCase c = gen.next(i % 4 == 0 ? 2'000'000 : 100'000);
    StopGen fast, ref;
    const StopGen::Inputs start{true, c.v, c.a, c.j, c.d};
    fast.step(start);
    ref.step(start);
    while (fast.active()) {
      const uint64_t n = fast.constant_span();
      ASSERT_GE(n, 1u);
      const int64_t j = fast.jerk();
      for (uint64_t t = 0; t < n; ++t) {
        ASSERT_EQ(ref.jerk(), j) << describe(c) << " clock " << clocks + t << " of span " << n;
        ref.step({});
      }
      if (n > 1) {
        fast.advance(n);
        jumped += n;
      } else {
        fast.step({});
      }
      clocks += n;
      ASSERT_TRUE(fast.state() == ref.state()) << describe(c) << " after clock " << clocks;
    }
  }
  std::printf("fast-forward: %llu of %llu clocks in closed-form jumps\n", (unsigned long long)jumped,
              (unsigned long long)clocks);
  EXPECT_GT(jumped, clocks / 2);
}

// Nightly size: more and longer stops, RTL in lockstep.
TEST(StopGenLong, RtlMatchesModelAndPropertiesHoldOnLongStops) {
  RtlStopGen rtl;
  rtl.reset();
  CaseGen gen(97);
  Campaign k;
  for (int i = 0; i < 5000; ++i) {
    const StopCase c = gen.next(i % 10 == 0 ? 2'000'000 : 100'000);
    check_case(c, run_stop(c, &rtl, 100'000'000), k);
    if (HasFailure()) break;
  }
  report("long lockstep", k);
}
