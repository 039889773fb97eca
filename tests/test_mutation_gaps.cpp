// Directed tests for what the mutation campaigns (scripts/mutation.py,
// docs/mutation.md) found the fast open-loop suite never drove:
//  - STOP held as a level (as the limit switches drive the executor's stop
//    input) instead of a one-clock pulse: the stop must not restart every clock;
//  - a limit switch on the side of the motion, each side and both modes, at the
//    core: motion (or an arming, or a START) into it stops or is refused,
//    motion away from it runs to the exact end.
//  - a STOP in the very clock a stream ends, a zero-length row met while
//    moving, the FIFO running dry at rest and at cruise speed, a START whose
//    head row is over a guard limit, the pins from reset;
//  - which flag a broken stream sets, the row index of a stream, pulse
//    times of zero with steps owed every clock.
// RTL and model run in lockstep every clock; besides, each test checks a
// property of its own (same rest as a pulsed STOP; the move stops short of
// its end, or reaches it exactly), so a change made in RTL and model alike
// fails it too.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <cstdlib>
#include <string>
#include <vector>

#include "loaded_core.h"
#include "pin_monitor.h"
#include "sim_run.h"

using namespace sc;
using stoptest::ld;

namespace {

using stoptest::acc_lsb;
using stoptest::jerk_lsb;
using stoptest::LoadedCore;

std::string fmt_case(int dir, bool hard, bool same_side) {
  return std::string(dir > 0 ? "forward" : "backward") + (hard ? ", hard limit" : ", controlled limit") +
         (same_side ? " ahead" : " behind");
}

struct Rest {
  uint64_t clock;
  int32_t pos;
  int32_t pulses;
};

// A move stopped `after` clocks from START; STOP held for `hold` clocks
// (hold 0: until the axis rests).
Rest stop_move(uint64_t after, uint64_t hold) {
  LoadedCore c(3000);
  c.start();
  for (uint64_t i = 0; i < after; ++i) c.tick();
  EXPECT_TRUE(c.out().busy);
  const uint64_t t0 = c.clock;
  c.in.stop = true;
  bool stopping_seen = false;
  while ((c.out().busy || c.clock < t0 + 4) && c.clock < t0 + 2'000'000) {
    if (hold != 0 && c.clock >= t0 + hold) c.in.stop = false;
    c.tick();
    stopping_seen = stopping_seen || c.out().stopping;
    if (!c.chk.errors().empty()) break;
  }
  c.in.stop = false;
  for (int i = 0; i < 200; ++i) c.tick();
  EXPECT_TRUE(stopping_seen) << "a controlled stop ran";
  EXPECT_FALSE(c.out().busy) << "the stop ended";
  EXPECT_EQ(c.out().ref_vel, 0);
  EXPECT_EQ(c.out().ref_acc, 0);
  EXPECT_TRUE(c.chk.errors().empty()) << c.chk.finish();
  return {c.clock - t0, c.out().ref_pos_int, c.out().pulse_count};
}

// Empties the FIFO (one clock) and pushes `rows`, one a clock.
void reload(LoadedCore& c, const std::vector<Row>& rows) {
  CoreInputs f = c.in;
  f.fifo_flush = true;
  c.tick(f);
  for (const Row& r : rows) {
    CoreInputs w = c.in;
    w.row_push = true;
    w.row = r;
    c.tick(w);
  }
}

}  // namespace

// A STOP held high until the axis rests stops exactly like a one-clock STOP:
// the same clock of rest, position and pulse count (from the acceleration,
// the cruise and the deceleration of the move).
TEST(MutationGaps, StopHeldAsALevelStopsLikeAOneClockStop) {
  for (uint64_t after : {20'000u, 120'000u, 400'000u}) {
    const Rest pulse = stop_move(after, 1);
    const Rest level = stop_move(after, 0);
    EXPECT_EQ(level.clock, pulse.clock) << "stop at " << after;
    EXPECT_EQ(level.pos, pulse.pos) << "stop at " << after;
    EXPECT_EQ(level.pulses, pulse.pulses) << "stop at " << after;
    EXPECT_GT(pulse.pos, 0) << "stop at " << after;
  }
}

// A limit that becomes active on the move's side while the core arms (DIR
// held for a long setup) drops the start: the executor never runs, nothing
// moves, the trip is reported on that side; with the limit on the other side
// the move starts.
TEST(MutationGaps, LimitActiveWhileArmingDropsTheStartTowardIt) {
  for (int dir : {1, -1}) {
    for (bool hard : {false, true}) {
      for (bool same_side : {true, false}) {
        const std::string what = fmt_case(dir, hard, same_side);
        LoadedCore c(3000 * dir);
        c.in.cfg.setup = 2000;
        c.in.lim_hard = hard;
        c.start();
        for (int i = 0; i < 200; ++i) c.tick();
        ASSERT_TRUE(c.out().busy) << what << ": arming";
        ASSERT_EQ(c.out().phase, uint8_t(Phase::PhIdle)) << what << ": still arming";
        const bool fwd_side = (dir > 0) == same_side;
        c.in.lim_fwd = fwd_side;
        c.in.lim_rev = !fwd_side;
        bool trip = false, moved = false;
        for (int i = 0; i < 6000; ++i) {
          c.tick();
          trip = trip || (fwd_side ? c.out().lim_trip_fwd : c.out().lim_trip_rev);
          moved = moved || c.out().ref_vel != 0 || c.out().phase != uint8_t(Phase::PhIdle);
        }
        EXPECT_TRUE(c.chk.errors().empty()) << what << c.chk.finish();
        if (same_side) {
          EXPECT_TRUE(trip) << what;
          EXPECT_FALSE(moved) << what << ": the executor must not start toward the limit";
          EXPECT_FALSE(c.out().busy) << what << ": the start is dropped";
          EXPECT_EQ(c.out().pulse_count, 0) << what;
        } else {
          EXPECT_FALSE(trip) << what;
          EXPECT_TRUE(moved) << what << ": the move away from the limit starts";
        }
      }
    }
  }
}

// A START toward a limit that is already active is refused in its own clock:
// the core never arms (busy stays low), the trip shows on that side only and
// nothing moves; the START away from the limit runs to the exact end.
TEST(MutationGaps, LimitAlreadyActiveRefusesTheStartTowardItWithoutArming) {
  for (int dir : {1, -1}) {
    for (bool hard : {false, true}) {
      for (bool same_side : {true, false}) {
        const std::string what = fmt_case(dir, hard, same_side);
        LoadedCore c(3000 * dir);
        c.in.lim_hard = hard;
        const bool fwd_side = (dir > 0) == same_side;
        c.in.lim_fwd = fwd_side;
        c.in.lim_rev = !fwd_side;
        for (int i = 0; i < 8; ++i) c.tick();  // through the limit inputs' registers
        CoreInputs s = c.in;
        s.start = true;
        c.tick(s);
        const bool trip_on_side = fwd_side ? c.out().lim_trip_fwd : c.out().lim_trip_rev;
        bool trip_other_side = fwd_side ? c.out().lim_trip_rev : c.out().lim_trip_fwd;
        bool trip = trip_on_side || trip_other_side, busy = false;
        while ((c.out().busy || !c.out().done) && c.clock < 3'000'000 && c.chk.errors().empty()) {
          c.tick();
          busy = busy || c.out().busy;
          trip = trip || c.out().lim_trip_fwd || c.out().lim_trip_rev;
          trip_other_side = trip_other_side || (fwd_side ? c.out().lim_trip_rev : c.out().lim_trip_fwd);
          if (same_side && c.clock > 4000) break;
        }
        EXPECT_TRUE(c.chk.errors().empty()) << what << c.chk.finish();
        if (same_side) {
          EXPECT_TRUE(trip_on_side) << what << ": the refused START trips its side in its own clock";
          EXPECT_FALSE(trip_other_side) << what << ": and only its side";
          EXPECT_FALSE(busy) << what << ": a refused START never arms";
          EXPECT_EQ(c.out().ref_pos_int, 0) << what;
          EXPECT_EQ(c.out().pulse_count, 0) << what;
        } else {
          EXPECT_FALSE(trip) << what << ": a START away from a limit runs";
          EXPECT_TRUE(c.out().done) << what;
          EXPECT_EQ(c.out().ref_pos_int, 3000 * dir) << what << ": the move ends exactly";
          EXPECT_EQ(c.out().pulse_count, 3000 * dir) << what;
        }
      }
    }
  }
}

// A limit active on the side the move heads to stops it short of its end
// (controlled or, with lim_hard, at once) and reports the trip on that side
// only; the limit on the other side changes nothing: the move ends exactly.
TEST(MutationGaps, LimitOnTheSideOfTheMotionStopsItAndTheOtherSideDoesNot) {
  for (int dir : {1, -1}) {
    for (bool hard : {false, true}) {
      for (bool same_side : {true, false}) {
        LoadedCore c(3000 * dir);
        c.in.lim_hard = hard;
        c.start();
        for (int i = 0; i < 60'000; ++i) c.tick();
        ASSERT_TRUE(c.out().busy);
        const bool fwd_side = (dir > 0) == same_side;
        c.in.lim_fwd = fwd_side;
        c.in.lim_rev = !fwd_side;
        bool trip_fwd = false, trip_rev = false;
        while ((c.out().busy || !c.out().done) && c.clock < 3'000'000 && c.chk.errors().empty()) {
          c.tick();
          trip_fwd = trip_fwd || c.out().lim_trip_fwd;
          trip_rev = trip_rev || c.out().lim_trip_rev;
          if (same_side && !c.out().busy) break;
        }
        const std::string what = fmt_case(dir, hard, same_side);
        EXPECT_TRUE(c.chk.errors().empty()) << what << c.chk.finish();
        EXPECT_FALSE(c.out().busy) << what;
        if (same_side) {
          EXPECT_EQ(fwd_side ? trip_fwd : trip_rev, true) << what << ": the trip on the side of the motion";
          EXPECT_EQ(fwd_side ? trip_rev : trip_fwd, false) << what << ": no trip on the other side";
          EXPECT_LT(std::abs(c.out().ref_pos_int), 3000) << what << ": stopped short of the end";
          EXPECT_EQ(c.out().pulse_count, c.out().ref_pos_int) << what << ": every step on the pins";
        } else {
          EXPECT_FALSE(trip_fwd || trip_rev) << what << ": motion away from a limit runs";
          EXPECT_TRUE(c.out().done) << what;
          EXPECT_EQ(c.out().ref_pos_int, 3000 * dir) << what << ": the move ends exactly";
          EXPECT_EQ(c.out().pulse_count, 3000 * dir) << what;
        }
      }
    }
  }
}

// A STOP that reaches the executor in the clock the stream ends as planned
// changes nothing (sc_profile_exec): whichever clock around the end STOP
// comes in, the axis rests on the move's end, no stop is left running, and the
// FIFO takes the next move, which runs exactly.
TEST(MutationGaps, StopAroundTheClockTheStreamEndsLeavesTheAxisReady) {
  // the clock the executor's jerk goes to zero at the end (its last boundary)
  uint64_t end_clock = 0;
  {
    LoadedCore c(200);
    c.start();
    bool jerk_seen = false;
    while ((c.out().busy || !c.out().done) && c.clock < 2'000'000) {
      c.tick();
      if (c.out().ref_jerk != 0) jerk_seen = true;
      if (jerk_seen && c.out().ref_jerk == 0 && c.out().ref_vel == 0 && end_clock == 0) end_clock = c.clock;
    }
    ASSERT_GT(end_clock, 0u);
  }
  for (uint64_t k = end_clock - 6; k <= end_clock + 2; ++k) {
    LoadedCore c(200);
    c.start();
    while (c.clock < k) c.tick();
    CoreInputs s = c.in;
    s.stop = true;
    c.tick(s);
    while ((c.out().busy || c.out().stopping) && c.clock < k + 2'000'000) c.tick();
    for (int i = 0; i < 50; ++i) c.tick();
    const std::string at = "STOP at clock " + std::to_string(k) + " (stream end " + std::to_string(end_clock) + ")";
    EXPECT_FALSE(c.out().stopping) << at << ": no stop left running";
    EXPECT_FALSE(c.out().fifo_full) << at << ": the FIFO takes rows";
    EXPECT_EQ(c.out().ref_vel, 0) << at;
    const int32_t p0 = c.out().ref_pos_int;
    EXPECT_EQ(c.out().pulse_count, p0) << at;
    // the next move, from where the axis rests
    for (const Row& r : move_rows(c.plan.segments)) {
      CoreInputs w = c.in;
      w.row_push = true;
      w.row = r;
      c.tick(w);
    }
    c.start();
    while ((c.out().busy || !c.out().done) && c.clock < k + 4'000'000) c.tick();
    EXPECT_TRUE(c.out().done) << at;
    EXPECT_EQ(c.out().ref_pos_int - p0, 200) << at << ": the next move is exact";
    EXPECT_TRUE(c.chk.errors().empty()) << at << c.chk.finish();
  }
}

// A zero-length row met at a row boundary while moving is malformed: the axis
// stops under control (no velocity step) and reports the table fault.
TEST(MutationGaps, ZeroLengthRowMidMoveStopsUnderControl) {
  LoadedCore probe(3000);
  const std::vector<Row> rows = move_rows(probe.plan.segments);
  ASSERT_GE(rows.size(), 4u);
  for (size_t bad = 1; bad + 1 < rows.size(); ++bad) {
    LoadedCore c(3000);
    // reload the FIFO with row `bad` cut to zero clocks
    std::vector<Row> cut = rows;
    cut[bad].seg.clocks = 0;
    reload(c, cut);
    c.start();
    bool stopping = false;
    i128 worst_dv = 0, last_v = 0;
    while ((c.out().busy || c.clock < 10) && c.clock < 4'000'000) {
      c.tick();
      stopping = stopping || c.out().stopping;
      const i128 dv = c.out().ref_vel - last_v;
      worst_dv = std::max(worst_dv, dv < 0 ? -dv : dv);
      last_v = c.out().ref_vel;
    }
    const std::string what = "zero-length row " + std::to_string(bad);
    EXPECT_TRUE(c.chk.errors().empty()) << what << c.chk.finish();
    EXPECT_TRUE(c.out().fault_table) << what;
    EXPECT_EQ(c.out().ref_vel, 0) << what;
    // moving when the row came: a controlled stop, velocity continuous (per clock
    // by at most the larger of the plan's and the stop's acceleration)
    if (rows[bad].seg.vel0 != 0) {
      EXPECT_TRUE(stopping) << what << ": a controlled stop";
      EXPECT_LE(worst_dv, i128(acc_lsb(4e6)) * 2) << what << ": no velocity step";
    }
  }
}

// The FIFO running dry at the end of a row is decided by the end state alone:
// at rest (v = a = 0) the stream ends as planned, also without the
// STREAM_END flag (no stop, no underrun, the move exact); still moving, also
// at constant speed (a = 0, the end of a cruise row), it is an underrun: a
// controlled stop without a velocity step, every step on the pins.
TEST(MutationGaps, FifoRunningDryEndsTheStreamOnlyAtRest) {
  for (int dir : {1, -1}) {
    const std::string way = dir > 0 ? "forward" : "backward";
    {
      LoadedCore c(3000 * dir);
      reload(c, move_rows(c.plan.segments, /*stream_end=*/false));
      c.start();
      bool stopping = false;
      while ((c.out().busy || !c.out().done) && c.clock < 3'000'000) {
        c.tick();
        stopping = stopping || c.out().stopping;
      }
      EXPECT_TRUE(c.chk.errors().empty()) << way << c.chk.finish();
      EXPECT_TRUE(c.out().done) << way << ": the rows end at rest: the stream ends";
      EXPECT_FALSE(stopping || c.out().underrun) << way << ": no stop, no underrun";
      EXPECT_EQ(c.out().ref_pos_int, 3000 * dir) << way;
      EXPECT_EQ(c.out().pulse_count, 3000 * dir) << way;
    }
    {
      LoadedCore c(3000 * dir);
      std::vector<Row> rows = move_rows(c.plan.segments, /*stream_end=*/false);
      const auto cruise = std::find_if(rows.begin(), rows.end(), [](const Row& r) {
        return r.seg.jerk == 0 && r.seg.acc0 == 0 && r.seg.vel0 != 0;
      });
      ASSERT_NE(cruise, rows.end()) << way << ": the move has a cruise row";
      rows.erase(cruise + 1, rows.end());
      reload(c, rows);
      c.start();
      bool stopping = false;
      i128 worst_dv = 0, last_v = 0;
      while ((c.out().busy || !c.out().done) && c.clock < 3'000'000) {
        c.tick();
        stopping = stopping || c.out().stopping;
        const i128 dv = c.out().ref_vel - last_v;
        worst_dv = std::max(worst_dv, dv < 0 ? -dv : dv);
        last_v = c.out().ref_vel;
        if (!c.out().busy && c.out().ref_vel == 0 && c.clock > 100) break;
      }
      EXPECT_TRUE(c.chk.errors().empty()) << way << c.chk.finish();
      EXPECT_TRUE(c.out().underrun) << way << ": dry at cruise speed is an underrun";
      EXPECT_TRUE(stopping) << way << ": a controlled stop";
      EXPECT_LE(worst_dv, i128(acc_lsb(4e6)) * 2) << way << ": no velocity step";
      EXPECT_EQ(c.out().ref_vel, 0) << way;
      EXPECT_EQ(c.out().pulse_count, c.out().ref_pos_int) << way << ": every step on the pins";
      EXPECT_GT(c.out().ref_pos_int * dir, 0) << way;
    }
  }
}

// From reset STEP is low, DIR is high (forward) and EN (the driver enable
// pin) is low until enable_i is set; EN then follows enable_i one clock
// later. RTL and model are checked against these levels, not against each
// other, so a wrong reset value in both fails it too.
TEST(MutationGaps, PinsFromResetAreStepLowDirForwardEnLowAndEnFollowsItsInput) {
  RtlCore rtl;
  AxisCore model;
  rtl.reset();
  CoreInputs in;
  in.cfg = PulseTiming{};
  bool prev_enable = false;
  for (int clk = 0; clk < 64; ++clk) {
    for (const auto& [who, o] : {std::pair{"RTL", rtl.outputs()}, std::pair{"model", model.outputs()}}) {
      EXPECT_EQ(o.en, prev_enable) << who << ", clock " << clk;
      EXPECT_FALSE(o.step) << who << ", clock " << clk;
      EXPECT_TRUE(o.dir) << who << ", clock " << clk << ": DIR idles forward (no move commanded)";
    }
    in.enable = clk >= 8 && clk < 40 && clk != 20;  // low after reset, on, one clock off, on, off
    rtl.step(in);
    model.step(in);
    prev_enable = in.enable;
  }
}

// A START whose head row is over a guard limit is refused: nothing moves, the
// guard flag is set and the rows are flushed.
TEST(MutationGaps, StartWithTheHeadRowOverAGuardLimitIsRefused) {
  LoadedCore c(3000);
  const Row head = move_rows(c.plan.segments).front();
  ASSERT_GT(head.seg.jerk, 1);
  c.in.guard.jerk = uint64_t(head.seg.jerk / 2);
  for (int i = 0; i < 4; ++i) c.tick();
  c.start();
  bool moved = false;
  for (int i = 0; i < 4000; ++i) {
    c.tick();
    moved = moved || c.out().ref_vel != 0 || c.out().step;
  }
  EXPECT_TRUE(c.chk.errors().empty()) << c.chk.finish();
  EXPECT_FALSE(moved) << "a head row over the jerk guard must not run";
  EXPECT_TRUE(c.out().guard);
  EXPECT_EQ(c.out().fifo_level, 0) << "what was queued behind it is flushed";
  EXPECT_FALSE(c.out().busy);
}

// A stream that breaks sets the one flag of its cause and no other: the FIFO
// running dry while moving (UNDERRUN), a row that does not continue the
// motion (DISCONTINUITY), a row over a guard limit (GUARD); each ends in a
// controlled stop at rest with every step on the pins.
TEST(MutationGaps, EachStreamBreakSetsTheFlagOfItsCauseOnly) {
  enum Cause { Underrun, Discontinuity, Guard };
  for (const Cause cause : {Underrun, Discontinuity, Guard}) {
    const char* name = cause == Underrun ? "underrun" : cause == Discontinuity ? "discontinuity" : "guard";
    LoadedCore c(3000);
    std::vector<Row> rows = move_rows(c.plan.segments);
    const auto cruise = std::find_if(rows.begin(), rows.end(), [](const Row& r) {
      return r.seg.jerk == 0 && r.seg.acc0 == 0 && r.seg.vel0 != 0;
    });
    ASSERT_NE(cruise, rows.end()) << name << ": the move has a cruise row";
    if (cause == Underrun) {
      rows.erase(cruise + 1, rows.end());  // dry at the end of the cruise
    } else if (cause == Discontinuity) {
      (cruise + 1)->seg.vel0 -= 1;  // one LSB off the cruise row's end speed
    } else {
      const i128 v = cruise->seg.vel0;  // the cruise row starts above the velocity guard
      c.in.guard.vel = u128(v - 1);
    }
    reload(c, rows);
    c.start();
    bool stopping = false;
    while ((c.out().busy || !c.out().done) && c.clock < 3'000'000) {
      c.tick();
      stopping = stopping || c.out().stopping;
      if (!c.out().busy && c.out().ref_vel == 0 && c.clock > 100) break;
    }
    EXPECT_TRUE(c.chk.errors().empty()) << name << c.chk.finish();
    EXPECT_TRUE(stopping) << name << ": a controlled stop";
    EXPECT_EQ(c.out().underrun, cause == Underrun) << name;
    EXPECT_EQ(c.out().discont, cause == Discontinuity) << name;
    EXPECT_EQ(c.out().guard, cause == Guard) << name;
    EXPECT_FALSE(c.out().fault_table) << name;
    EXPECT_EQ(c.out().ref_vel, 0) << name;
    EXPECT_EQ(c.out().pulse_count, c.out().ref_pos_int) << name << ": every step on the pins";
    EXPECT_GT(c.out().ref_pos_int, 0) << name;
  }
}

// The row index (STATUS.SEG_IDX) counts the rows of the running move from 0
// and starts again at 0 with the next move of the stream: each index is
// shown for exactly its row's clocks (from the row lengths, not the model).
TEST(MutationGaps, RowIndexCountsTheRowsOfEachMoveForTheirClocks) {
  LoadedCore c(3000);
  std::vector<Row> rows = move_rows(c.plan.segments, /*stream_end=*/false);
  const std::vector<Row> second = move_rows(c.plan.segments);
  rows.insert(rows.end(), second.begin(), second.end());
  ASSERT_LE(rows.size(), size_t(32)) << "both moves fit the FIFO";
  reload(c, rows);
  c.start();
  // (index, clocks shown) runs while the stream runs
  std::vector<std::pair<int, uint64_t>> runs;
  while ((c.out().busy || !c.out().done) && c.clock < 4'000'000) {
    c.tick();
    if (!c.out().busy) break;
    const int idx = c.out().seg_idx;
    if (runs.empty() || runs.back().first != idx) runs.emplace_back(idx, 0);
    ++runs.back().second;
  }
  EXPECT_TRUE(c.chk.errors().empty()) << c.chk.finish();
  EXPECT_EQ(c.out().ref_pos_int, 6000) << "both moves ran to their end";
  const size_t n = second.size();
  ASSERT_EQ(runs.size(), 2 * n) << "one run of the index per row";
  for (size_t k = 0; k < runs.size(); ++k) {
    EXPECT_EQ(runs[k].first, int(k % n)) << "row " << k;
    // the first run also shows the clocks between START and the first row
    if (k > 0) {
      EXPECT_EQ(runs[k].second, rows[k].seg.clocks) << "row " << k;
    }
  }
}

// PULSE_TIME HIGH = LOW = 0 act as one clock: with steps owed faster than the
// pins can take them (one a clock; the step-rate guard stops the executor)
// every pulse is high exactly one clock and low at least one, and the pins'
// rising edges are the reference position at rest: no two steps merge.
TEST(MutationGaps, ZeroPulseTimesActAsOneClockAndMergeNoSteps) {
  for (const int sign : {1, -1}) {
    const std::string what = sign > 0 ? "forward" : "backward";
    RtlCore rtl;
    rtl.reset();
    AxisCore model;
    LockstepChecker chk;
    const PulseTiming zero{0, 0, 0, 0};
    PinMonitor pins(PinRules{PulseTiming{1, 1, 0, 0}, false, StepAccounting::ReferencePosition});
    Segment s;
    s.phase = Phase::PhCruise;
    s.clocks = 400;
    s.vel0 = sign * i128(kOne - 1);  // a carry every clock
    CoreInputs in;
    in.enable = true;
    in.cfg = zero;
    uint64_t clock = 0;
    auto tick = [&](const CoreInputs& ci) {
      rtl.step(ci);
      model.step(ci);
      chk.compare(clock, rtl.outputs(), model.outputs());
      pins.on_clock(clock, rtl.outputs());
      ++clock;
    };
    for (const CoreInputs& ci : load_sequence(std::vector<Segment>{s}, kOne / 2, in)) {
      tick(ci);
      in = ci;
    }
    in.start = false;
    for (int k = 0; k < 2000 && (rtl.outputs().busy || clock < 100); ++k) tick(in);
    pins.finish(clock);
    const CoreOutputs end = rtl.outputs();
    EXPECT_TRUE(chk.errors().empty()) << what << chk.finish();
    for (const std::string& e : pins.errors()) ADD_FAILURE() << what << ": " << e;
    EXPECT_FALSE(end.busy) << what;
    EXPECT_TRUE(end.fault_overrun) << what << ": the step-rate guard stopped the executor";
    EXPECT_GT(std::abs(end.ref_pos_int), 2) << what;
    EXPECT_EQ(pins.net_steps(), end.ref_pos_int) << what << ": a step merged or lost";
    EXPECT_EQ(end.pulse_count, end.ref_pos_int) << what;
  }
}
