// RTL (Verilated sc_axis_core) and the bit-exact model in lockstep, every
// clock: random planned moves, random raw tables that reverse direction and
// overrun the step queue, controlled stops at random times on every engine,
// a row FIFO filled to its depth, the step queue's depth and the exact
// STEP/DIR timing at reversals against the package and the timing rules
// (not against the model), the paper's four groups, and proof that the
// checker reports an injected difference.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>

#include "lockstep.h"
#include "pin_monitor.h"
#include "planner.h"
#include "rtl_core.h"
#include "scenarios.h"
#include "scurve/reg_encode.h"
#include "sim_run.h"

using namespace sc;

namespace {

Limits4Check limits_of(const MoveRequest& r, const Plan& p) {
  Limits4Check l;
  l.v_max = std::max({r.v_cruise, r.v_start, p.v_end_used});
  l.a_max = r.a_max;
  if (r.kind == ProfileKind::SCurve) l.j_max = r.j_max;
  return l;
}

// The step generator's timing rules as a predicate on the pins and the queue
// (step_pending_o), written from its specification, not from the model:
//  * STEP rises on the first clock on which a step is owed in DIR's
//    direction, STEP has been low `low` clocks and DIR has held `setup`
//    clocks: never later, never earlier;
//  * while a step is owed against DIR, DIR turns on the first clock on which
//    STEP is low and `hold` clocks have passed since the last rising edge.
// (Clock c sees the pins after its edge; a rule on clock c reads the state
// of clock c-1, so a rise comes at least one clock after a DIR turn.)
// It counts the rises whose clock the setup time decided, the owed turns
// whose clock the hold time decided, and the requests that arrived against
// steps still owed in the other direction.
class ExactStepDirTiming {
 public:
  explicit ExactStepDirTiming(const PulseTiming& t) : t_(t) {}

  void on_clock(uint64_t c, const CoreOutputs& o) {
    const int pend = o.step_pending;
    if (have_prev_) check(c, o.step, o.dir, pend);
    if (o.step && !prev_step_) {
      last_rise_ = c;
      any_rise_ = true;
    }
    if (!o.step && prev_step_) {
      last_fall_ = c;
      any_fall_ = true;
    }
    if (have_prev_ && o.dir != prev_dir_) {
      last_dir_ = c;
      any_dir_ = true;
    }
    pp_step_ = prev_step_;
    pp_pend_ = prev_pend_;
    prev_step_ = o.step;
    prev_dir_ = o.dir;
    prev_pend_ = pend;
    have_prev_ = true;
  }
  const std::vector<std::string>& errors() const { return errors_; }
  uint64_t rises() const { return rises_; }
  uint64_t setup_decided() const { return setup_decided_; }
  uint64_t owed_turns() const { return owed_turns_; }
  uint64_t hold_decided() const { return hold_decided_; }
  uint64_t requests_against_owed() const { return against_owed_; }

 private:
  bool low_ok(uint64_t c) const { return !any_fall_ || c - last_fall_ >= t_.low; }
  bool setup_ok(uint64_t c) const { return !any_dir_ || c - last_dir_ >= t_.setup; }
  bool hold_ok(uint64_t c) const { return !any_rise_ || c - last_rise_ >= t_.hold; }
  static bool owed_toward(int pend, bool dir) { return pend != 0 && (pend > 0) == dir; }

  void check(uint64_t c, bool step, bool dir, int pend) {
    const bool owed = prev_pend_ != 0;
    const bool want_fwd = prev_pend_ > 0;
    const bool rise = step && !prev_step_;
    const bool rise_due = owed && prev_dir_ == want_fwd && !prev_step_ && low_ok(c) && setup_ok(c);
    if (rise != rise_due) {
      error(fmt::format("clock {}: STEP {} (owed {}, DIR {}, {} clocks since the fall, {} since the DIR turn)", c,
                        rise ? "rose early" : "did not rise when due", prev_pend_, int(prev_dir_),
                        any_fall_ ? int64_t(c - last_fall_) : -1, any_dir_ ? int64_t(c - last_dir_) : -1));
    }
    if (rise) {
      ++rises_;
      // The setup time decided the clock: the rise comes max(setup, 1)
      // clocks after the turn, and a clock earlier the step was already
      // owed that way and STEP low long enough (only the setup was missing;
      // with setup <= 1: the step was owed on the clock of the turn).
      const uint64_t need = std::max<uint64_t>(t_.setup, 1);
      const int owed_before = need >= 2 ? pp_pend_ : prev_pend_;
      if (any_dir_ && c - last_dir_ == need && low_ok(c - 1) && owed_toward(owed_before, prev_dir_)) ++setup_decided_;
    }
    const bool owed_against = owed && prev_dir_ != want_fwd;
    const bool turn = dir != prev_dir_;
    if (owed_against) {
      const bool turn_due = !prev_step_ && hold_ok(c);
      if (turn != turn_due) {
        error(fmt::format("clock {}: DIR {} ({} owed against it, STEP {}, {} clocks since the rise)", c,
                          turn ? "turned early" : "did not turn when due", prev_pend_, int(prev_step_),
                          any_rise_ ? int64_t(c - last_rise_) : -1));
      }
      if (turn) {
        ++owed_turns_;
        // The hold time decided the clock: `hold` clocks after the rise,
        // and a clock earlier the step was already owed against DIR and
        // STEP low (only the hold was missing).
        if (any_rise_ && c - last_rise_ == t_.hold && pp_pend_ != 0 && !owed_toward(pp_pend_, prev_dir_) && !pp_step_) {
          ++hold_decided_;
        }
      }
    }
    // A request of the other sign while steps are owed: the queue moves
    // toward zero by more than the rise (if any) accounts for.
    const int by_rise = rise ? (prev_dir_ ? -1 : 1) : 0;
    const int request = pend - prev_pend_ - by_rise;
    if (request < -1 || request > 1) error(fmt::format("clock {}: the queue moved by {}", c, pend - prev_pend_));
    if (owed && request != 0 && (request > 0) != want_fwd) ++against_owed_;
  }
  void error(std::string s) {
    if (errors_.size() < 10) errors_.push_back(std::move(s));
  }

  PulseTiming t_;
  bool have_prev_ = false, prev_step_ = false, prev_dir_ = true;
  int prev_pend_ = 0;
  uint64_t last_rise_ = 0, last_fall_ = 0, last_dir_ = 0;
  bool any_rise_ = false, any_fall_ = false, any_dir_ = false;
  bool pp_step_ = false;  // clock c-2
  int pp_pend_ = 0;
  uint64_t rises_ = 0, setup_decided_ = 0, owed_turns_ = 0, hold_decided_ = 0, against_owed_ = 0;
  std::vector<std::string> errors_;
};

}  // namespace

TEST(Lockstep, SixtyRandomPlannedMovesMatchEveryClockAndEmitExactlyL) {
  std::mt19937_64 g(2024);
  int run = 0;
  uint64_t clocks = 0;
  while (run < 60) {
    MoveRequest r;
    r.distance = int64_t(1 + g() % 4000) * ((g() % 4 == 0) ? -1 : 1);
    r.v_start = (g() % 3 == 0) ? 0.0 : double(g() % 30000);
    r.v_cruise = 500 + double(g() % 150000);
    r.v_end = (g() % 3 == 0) ? 0.0 : double(g() % 30000);
    r.a_max = 2e4 + double(g() % 5000000);
    r.j_max = 1e6 + double(g() % 2000000000);
    r.kind = (g() % 5 == 0) ? ProfileKind::Trapezoid : ProfileKind::SCurve;
    PulseTiming t;
    t.high = uint16_t(2 + g() % 60);
    t.low = uint16_t(2 + g() % 60);
    t.setup = uint16_t(g() % 200);
    t.hold = uint16_t(g() % 200);
    const PlanResult pr = plan_move(r, t);
    if (!std::holds_alternative<Plan>(pr)) continue;  // e.g. end speed unreachable
    const Plan& p = std::get<Plan>(pr);
    if (p.total_clocks > 4'000'000) continue;  // keep the default suite short
    const SimResult s = run_move(p, t, limits_of(r, p), SimOptions{});
    ASSERT_TRUE(s.pass()) << "move " << run << " (distance " << r.distance << " vs " << r.v_start << " vc "
                          << r.v_cruise << " ve " << r.v_end << " a " << r.a_max << " j " << r.j_max << " kind "
                          << int(r.kind) << " high/low/setup/hold " << t.high << "/" << t.low << "/" << t.setup
                          << "/" << t.hold << "): " << s.failure_lines();
    EXPECT_EQ(s.mismatches, 0u);
    EXPECT_EQ(s.pulses, r.distance);
    clocks += s.total_clocks;
    ++run;
  }
  RecordProperty("clocks", std::to_string(clocks));
}

// The run of `scurve sim --stop-at`: random planned moves stopped at a random
// time with the move's own limits (the tools' default) or random ones. Every
// engine passes its checks (the stop monitor: rest, no reversal, limits,
// distance within a pulse of the closed form; every reference step on the
// pins) and all four end at the same position, not beyond the target when
// the stop limits are the move's own.
TEST(Lockstep, StopAtRandomTimesEndsAtRestOnEveryEngine) {
  std::mt19937_64 g(77);
  int stops = 0, own_limits = 0, overshoots = 0;
  for (int trial = 0; stops < 24; ++trial) {
    ASSERT_LT(trial, 200) << "too few plannable moves";
    MoveRequest r;
    r.distance = int64_t(200 + g() % 6000) * ((g() & 1) ? -1 : 1);
    r.v_cruise = 2000 + double(g() % 120000);
    r.a_max = 5e4 + double(g() % 3000000);
    r.j_max = 1e7 + double(g() % 2000000000);
    r.kind = (g() % 5 == 0) ? ProfileKind::Trapezoid : ProfileKind::SCurve;
    PulseTiming t;
    t.high = uint16_t(2 + g() % 20);
    t.low = uint16_t(2 + g() % 20);
    t.setup = uint16_t(g() % 50);
    t.hold = uint16_t(g() % 50);
    const PlanResult pr = plan_move(r, t);
    if (!std::holds_alternative<Plan>(pr)) continue;
    const Plan& p = std::get<Plan>(pr);
    if (p.total_clocks > 1'500'000 || p.total_clocks < 100) continue;
    scurve::StopLimits lim = scurve::move_stop_limits(r);
    const bool own = g() % 3 != 0;
    if (!own) {
      lim.jerk *= 0.2 + double(g() % 1000) / 200;
      lim.acc *= 0.2 + double(g() % 1000) / 200;
    }
    const auto codes = scurve::stop_limit_codes(lim.jerk, lim.acc);
    ASSERT_TRUE(std::holds_alternative<scurve::StopLimitCodes>(codes));
    SimOptions opt;
    opt.stop_at = t.setup + 3 + g() % (p.total_clocks - t.setup - 4);
    opt.stop_jerk = std::get<scurve::StopLimitCodes>(codes).jerk;
    opt.stop_acc = std::get<scurve::StopLimitCodes>(codes).acc;
    const std::string what = fmt::format("move {} ({} pulses, {} clocks), stop at clock {}, J {:.4g}, D {:.4g}", trial,
                                         r.distance, p.total_clocks, *opt.stop_at, lim.jerk, lim.acc);
    std::optional<int64_t> end;
    for (SimEngine e : {SimEngine::Lockstep, SimEngine::RtlOnly, SimEngine::ModelOnly, SimEngine::ModelFast}) {
      opt.engine = e;
      const SimResult s = run_move(p, t, limits_of(r, p), opt);
      ASSERT_TRUE(s.pass()) << what << " on " << engine_name(e) << ": " << s.failure_lines();
      ASSERT_TRUE(s.stop.taken) << what << " on " << engine_name(e);
      EXPECT_EQ(s.pulses, s.stop.end_position) << what << " on " << engine_name(e);
      if (end) EXPECT_EQ(s.stop.end_position, *end) << what << " on " << engine_name(e);
      end = s.stop.end_position;
      if (e == SimEngine::Lockstep) {
        overshoots += s.stop.overshoot;
        // With the move's own limits the stop brakes at least as hard as the
        // rest of the plan: the axis ends short of the target, give or take
        // the stop's pulse of discretisation.
        if (own) EXPECT_LE(std::abs(s.stop.end_position), std::abs(r.distance) + 1) << what;
      }
    }
    ++stops;
    own_limits += own;
  }
  EXPECT_GT(own_limits, 8);
  EXPECT_LT(own_limits, 24);
  RecordProperty("overshoots", std::to_string(overshoots));
}

// Raw tables (not from the planner): velocity crossing zero, speeds far
// above the step-rate limit, random pulse timing. RTL and model must agree
// on every output every clock, including DIR changes and the step-rate
// guard (STATUS.FAULT_OVERRUN), the pins must still honour
// high/low/setup/hold and every rise and owed DIR turn comes on the first
// clock the rules allow (ExactStepDirTiming), and no step is lost (the pins
// against the reference position at every change and at rest, also after a
// guard stop). Several
// seeds: each campaign must trip the guard and reverse on its own.
class RawTableSeed : public ::testing::TestWithParam<uint64_t> {};

TEST_P(RawTableSeed, RandomRawTablesWithReversalsAndOverrunsMatch) {
  std::mt19937_64 g(GetParam());
  int overruns = 0, reversals = 0;
  for (int trial = 0; trial < 40; ++trial) {
    PulseTiming t;
    t.high = uint16_t(1 + g() % 20);
    t.low = uint16_t(1 + g() % 20);
    t.setup = uint16_t(g() % 40);
    t.hold = uint16_t(g() % 40);
    const int rows = 1 + int(g() % MaxSegs);
    std::vector<Segment> table;
    for (int i = 0; i < rows; ++i) {
      Segment s;
      s.phase = Phase(1 + g() % 7);
      s.clocks = uint32_t(1 + g() % 20000);
      const i128 v = i128(g() % (uint64_t(1) << 40)) << 38;  // up to ~0.25 pulse/clock
      s.vel0 = (g() & 1) ? v : -v;
      const int64_t a = int64_t(g() % (uint64_t(1) << 62)) >> (16 + g() % 20);
      s.acc0 = (g() & 1) ? a : -a;
      const int64_t j = int64_t(g() % (uint64_t(1) << 47)) >> (g() % 30);
      s.jerk = (g() & 1) ? j : -j;
      table.push_back(s);
    }
    continue_velocities(table);
    RtlCore rtl;
    rtl.reset();
    AxisCore model;
    LockstepChecker chk;
    PinMonitor pins(PinRules{t, false, StepAccounting::ReferencePosition});
    CoreInputs in;
    in.enable = true;
    in.cfg = t;
    uint64_t clock = 0;
    ExactStepDirTiming exact(t);
    auto tick = [&](const CoreInputs& ci) {
      rtl.step(ci);
      model.step(ci);
      const CoreOutputs o = rtl.outputs();
      chk.compare(clock, o, model.outputs());
      pins.on_clock(clock, o);
      exact.on_clock(clock, o);
      ++clock;
    };
    for (const CoreInputs& ci : load_sequence(table, (u128(g()) << 16) & (kOne - 1), in)) {
      tick(ci);
      in = ci;
    }
    in.start = false;
    bool last_dir = model.outputs().dir;
    // Until done, or at rest after the step-rate guard stopped the executor
    // (phase ABORT) and the queued steps drained.
    while (clock < 400000 && !chk.should_stop()) {
      tick(in);
      if (model.outputs().dir != last_dir) ++reversals;
      last_dir = model.outputs().dir;
      if (!model.outputs().busy && clock > 100) break;
    }
    pins.finish(clock);
    ASSERT_TRUE(chk.errors().empty()) << chk.finish();
    // Only the timing rules and the step accounting apply to raw tables (no
    // duty-phase contract): no step lost or invented at any change.
    for (const std::string& e : pins.errors()) ADD_FAILURE() << "trial " << trial << ": " << e;
    for (const std::string& e : exact.errors()) ADD_FAILURE() << "trial " << trial << ": " << e;
    // At rest, done or stopped by the guard, the pins' count is the
    // reference position's integer part.
    const CoreOutputs end = model.outputs();
    EXPECT_FALSE(end.busy) << "trial " << trial;
    EXPECT_EQ(end.pulse_count, end.ref_pos_int) << "trial " << trial;
    if (end.fault_overrun) ++overruns;
  }
  EXPECT_GT(overruns, 0) << "the campaign must trip the step-rate guard at least once";
  EXPECT_GT(reversals, 10) << "the campaign must reverse direction";
}

// Seed 99 is the campaign's original one.
INSTANTIATE_TEST_SUITE_P(Lockstep, RawTableSeed, ::testing::Values(99, 1, 2, 3, 4, 5, 6, 7),
                         [](const ::testing::TestParamInfo<uint64_t>& i) { return "Seed" + std::to_string(i.param); });

namespace {

// The step queue's limits from the package (rtl/sc_pkg.sv through
// sc_params.h), not from the model's code: a signed PendW-bit counter.
constexpr int kPkgPendMax = (1 << (PendW - 1)) - 1;
constexpr int kPkgPendMin = -(1 << (PendW - 1));

// Cuts rows until there are `n`: the longest row is split in two, the
// second part starting from the first part's exact end state, so the rows
// still continue each other as the executor checks.
std::vector<Segment> split_rows(std::vector<Segment> rows, size_t n) {
  while (rows.size() < n) {
    auto it = std::max_element(rows.begin(), rows.end(),
                               [](const Segment& a, const Segment& b) { return a.clocks < b.clocks; });
    Segment first = *it;
    first.clocks = it->clocks / 2;
    it->clocks -= first.clocks;
    it->vel0 = wrap_signed(vel_after(first.vel0, first.acc0, first.jerk, first.clocks), VelW);
    it->acc0 = wrap_signed64(int64_t(acc_after(first.acc0, first.jerk, first.clocks)), AccW);
    rows.insert(it, first);
  }
  return rows;
}

// A planned move of 7 rows, cut into exactly the FIFO's depth of rows.
MoveRequest fifo_move() {
  MoveRequest r;
  r.distance = 2500;
  r.v_cruise = 60000;
  r.a_max = 2e6;
  r.j_max = 2e8;
  return r;
}

}  // namespace

// A START with the row FIFO holding exactly its depth (sc_pkg RowFifoDepth)
// of rows that continue each other: every row runs and the move ends on
// exactly L pulses, on the model alone (its pins against the planner's
// endpoint) and with the RTL in lockstep.
TEST(Lockstep, FullFifoOfRowsRunsToTheExactEnd) {
  const MoveRequest r = fifo_move();
  const PulseTiming t{5, 5, 20, 20};
  Plan p = std::get<Plan>(plan_move(r, t));
  ASSERT_LT(p.segments.size(), size_t(RowFifoDepth));
  p.segments = split_rows(p.segments, RowFifoDepth);
  ASSERT_EQ(p.segments.size(), size_t(RowFifoDepth));
  for (SimEngine e : {SimEngine::ModelOnly, SimEngine::Lockstep}) {
    SimOptions opt;
    opt.engine = e;
    const SimResult s = run_move(p, t, limits_of(r, p), opt);
    EXPECT_TRUE(s.pass()) << engine_name(e) << ": " << s.failure_lines();
    EXPECT_EQ(s.pulses, r.distance) << engine_name(e);
  }
}

// One row more than the FIFO holds is refused at the core (fifo_full_o set,
// the level stays at the depth) and changes nothing: the full FIFO runs to
// the exact end and is empty after it. Model alone and RTL in lockstep.
TEST(Lockstep, RowPastAFullFifoIsRefusedAndTheFullFifoRunsExact) {
  const MoveRequest r = fifo_move();
  const PulseTiming t{5, 5, 20, 20};
  Plan p = std::get<Plan>(plan_move(r, t));
  p.segments = split_rows(p.segments, RowFifoDepth);
  std::vector<Row> rows = move_rows(p.segments);
  rows.push_back(rows.front());  // would start the move over again
  for (SimEngine e : {SimEngine::ModelOnly, SimEngine::Lockstep}) {
    CoreDriver drv(e, PinRules{t, true, StepAccounting::ReferencePosition});
    CoreInputs in;
    in.enable = true;
    in.cfg = t;
    const std::vector<CoreInputs> seq = load_sequence(rows, p.pos_frac0, in);
    for (size_t i = 0; i + 1 < seq.size(); ++i) {
      drv.tick(seq[i]);
      const size_t want = std::min(i + 1, size_t(RowFifoDepth));
      ASSERT_EQ(drv.out().fifo_level, want) << engine_name(e) << ": push " << i;
      ASSERT_EQ(drv.out().fifo_full, want == size_t(RowFifoDepth)) << engine_name(e) << ": push " << i;
    }
    drv.tick(seq.back());
    in = seq.back();
    in.start = false;
    const uint64_t limit = drv.clock() + p.total_clocks + 10000;
    while (!drv.out().done && drv.clock() < limit && !drv.stopped()) drv.tick(in);
    for (int i = 0; i < 2000 && !drv.stopped(); ++i) drv.tick(in);
    drv.pins().finish(drv.clock());
    const std::string what = engine_name(e);
    EXPECT_TRUE(drv.checker().errors().empty()) << what << ": " << drv.checker().finish();
    EXPECT_TRUE(drv.out().done) << what;
    EXPECT_EQ(drv.pins().net_steps(), r.distance) << what;
    EXPECT_EQ(drv.out().pulse_count, r.distance) << what;
    EXPECT_EQ(drv.out().fifo_level, 0u) << what << ": the refused row is not queued behind the move";
    for (const std::string& err : drv.pins().errors()) ADD_FAILURE() << what << ": " << err;
  }
}

// The step generator's queue alone (model, no Verilator), against the
// package's PendW: with the pulse held back by a long DIR setup, exactly
// PendMax forward (and -PendMin backward) requests are queued, the next one
// sets the sticky overrun and is not queued, and the queued ones all leave
// on the pins afterwards.
TEST(StepQueue, HoldsExactlyThePackageDepthOfOwedStepsAndTheNextRequestOverruns) {
  for (const bool fwd : {true, false}) {
    const char* what = fwd ? "forward" : "backward";
    StepGen sg;
    StepGen::Inputs in;
    in.cfg = PulseTiming{3, 3, 60000, 0};
    in.dir_hint_valid = true;  // no step owed: DIR turns away from the burst's direction
    in.dir_hint = !fwd;
    for (int i = 0; i < 3; ++i) sg.step(in);
    ASSERT_EQ(sg.state().dir, !fwd) << what;
    in.dir_hint_valid = false;
    in.step_req = true;
    in.step_fwd = fwd;
    const int depth = fwd ? kPkgPendMax : -kPkgPendMin;
    const int sign = fwd ? 1 : -1;
    for (int k = 1; k <= depth; ++k) {
      sg.step(in);
      ASSERT_EQ(sg.state().pend, sign * k) << what << ": request " << k;
      ASSERT_FALSE(sg.state().overrun) << what << ": request " << k << " of " << depth;
      ASSERT_FALSE(sg.state().step) << what << ": the setup time holds the pulse back";
    }
    sg.step(in);
    EXPECT_TRUE(sg.state().overrun) << what << ": request " << depth + 1 << " must overrun";
    EXPECT_EQ(sg.state().pend, sign * depth) << what;
    in.step_req = false;
    int rises = 0;
    bool prev = false;
    for (int c = 0; c < 70000; ++c) {
      sg.step(in);
      rises += sg.state().step && !prev;
      prev = sg.state().step;
    }
    EXPECT_EQ(rises, depth) << what;
    EXPECT_EQ(sg.state().count, sign * depth) << what;
    EXPECT_EQ(sg.state().pend, 0) << what;
    EXPECT_TRUE(sg.state().overrun) << what << ": sticky";
  }
}

// The same depth through the whole core, on the RTL as on the model: a raw
// row at one step per clock against a 40-clock pulse fills the queue until
// the step-rate guard stops the executor (from three short of full, the
// clock after, with two more requests in flight), so the queue peaks at
// exactly the package's PendMax, never beyond, and no step is lost (the
// pins against the reference position at every change and at rest).
TEST(Lockstep, StepQueuePeaksAtThePackageDepthWhenTheRateGuardStopsAndLosesNoStep) {
  const PulseTiming t{20, 20, 10, 10};
  for (const int sign : {1, -1}) {
    Segment s;
    s.phase = Phase::PhCruise;
    s.clocks = 400;
    s.vel0 = sign * i128(kOne - 1);  // the largest speed: a carry every clock
    for (SimEngine e : {SimEngine::ModelOnly, SimEngine::Lockstep}) {
      const std::string what = fmt::format("{} {}", sign > 0 ? "forward" : "backward", engine_name(e));
      CoreDriver drv(e, PinRules{t, false, StepAccounting::ReferencePosition});
      CoreInputs in;
      in.enable = true;
      in.cfg = t;
      for (const CoreInputs& ci : load_sequence(std::vector<Segment>{s}, kOne / 2, in)) {
        drv.tick(ci);
        in = ci;
      }
      in.start = false;
      int peak = 0;
      for (int c = 0; c < 2000 && !drv.stopped(); ++c) {
        drv.tick(in);
        const int pend = drv.out().step_pending;
        if (std::abs(pend) > std::abs(peak)) peak = pend;
      }
      drv.pins().finish(drv.clock());
      EXPECT_TRUE(drv.checker().errors().empty()) << what << ": " << drv.checker().finish();
      EXPECT_EQ(peak, sign * kPkgPendMax) << what;
      EXPECT_TRUE(drv.out().fault_overrun) << what << ": the step-rate guard stopped the executor";
      EXPECT_FALSE(drv.out().busy) << what;
      EXPECT_EQ(drv.out().pulse_count, drv.out().ref_pos_int) << what << ": a step lost";
      EXPECT_EQ(drv.pins().net_steps(), drv.out().ref_pos_int) << what;
      EXPECT_GT(std::abs(drv.out().ref_pos_int), kPkgPendMax) << what;
      for (const std::string& err : drv.pins().errors()) ADD_FAILURE() << what << ": " << err;
    }
  }
}

namespace {

// A raw table from rest to rest that turns `turns` times: up to +v at
// acceleration a, down through zero to -v, back up, ..., down to rest. The
// velocity crosses zero at the full acceleration, so near a turn the
// position often carries and then borrows back within a few clocks.
std::vector<Segment> reversing_table(int64_t a, uint32_t n, int turns) {
  std::vector<Segment> rows;
  Segment s;
  s.phase = Phase::PhAccConst;
  s.clocks = n;
  s.acc0 = a;
  rows.push_back(s);
  for (int i = 0; i < turns; ++i) {
    s.phase = i % 2 == 0 ? Phase::PhDecConst : Phase::PhAccConst;
    s.clocks = 2 * n;
    s.acc0 = i % 2 == 0 ? -a : a;
    rows.push_back(s);
  }
  s.phase = turns % 2 == 0 ? Phase::PhDecConst : Phase::PhAccConst;
  s.clocks = n;
  s.acc0 = turns % 2 == 0 ? -a : a;
  rows.push_back(s);
  continue_velocities(rows);
  return rows;
}

struct ReversalStats {
  uint64_t rises = 0, setup_decided = 0, owed_turns = 0, hold_decided = 0, against_owed = 0, guard_stops = 0;
};

// Runs reversing tables with timing `t` on `engine`: the exact-timing
// predicate, the pin monitor (widths, setup/hold minima, the pins against
// the reference position at every change and at rest) and, in lockstep,
// every output against the model. Failures are reported; the counts returned.
struct TableShape {
  double acc_lo, acc_hi;  // pulses/clock^2 at the turns (log-uniform; the largest the executor holds is 2^-17)
  double exc_lo, exc_hi;  // pulses between the turns (log-uniform)
};

ReversalStats run_reversals(const PulseTiming& t, SimEngine engine, std::mt19937_64& g, int tables,
                            const TableShape& shape) {
  ReversalStats st;
  auto log_uniform = [&](double lo, double hi) { return lo * std::pow(hi / lo, double(g() % 1000) / 1000); };
  for (int k = 0; k < tables; ++k) {
    const double acc = log_uniform(shape.acc_lo, shape.acc_hi);
    const double excursion = log_uniform(shape.exc_lo, shape.exc_hi);
    const double v = std::sqrt(2 * acc * excursion);
    const uint32_t n = std::max<uint32_t>(1, uint32_t(v / acc));
    const int64_t a = int64_t(acc * double(kOne));
    const std::vector<Segment> rows = reversing_table(a, n, 2 + int(g() % 5));
    const std::string what = fmt::format("{} table {} (timing {}/{}/{}/{}, a {:.3g}, {} clocks a row)",
                                         engine_name(engine), k, t.high, t.low, t.setup, t.hold, acc, n);
    CoreDriver drv(engine, PinRules{t, false, StepAccounting::ReferencePosition});
    ExactStepDirTiming exact(t);
    CoreInputs in;
    in.enable = true;
    in.cfg = t;
    auto tick = [&](const CoreInputs& ci) {
      drv.tick(ci);
      exact.on_clock(drv.clock() - 1, drv.out());
    };
    for (const CoreInputs& ci : load_sequence(rows, (u128(g()) << 16) & (kOne - 1), in)) {
      tick(ci);
      in = ci;
    }
    in.start = false;
    uint64_t total = 0;
    for (const Segment& s : rows) total += s.clocks;
    const uint64_t limit = drv.clock() + total + 20ull * (t.high + t.low + t.setup + t.hold) + 2000;
    while (drv.clock() < limit && !drv.stopped() && (drv.out().busy || drv.clock() < 10)) tick(in);
    for (int i = 0; i < 4 * (t.high + t.low + t.setup + t.hold) + 100 && !drv.stopped(); ++i) tick(in);
    drv.pins().finish(drv.clock());
    EXPECT_TRUE(drv.checker().errors().empty()) << what << ": " << drv.checker().finish();
    EXPECT_FALSE(drv.out().busy) << what;
    EXPECT_EQ(drv.pins().net_steps(), drv.out().ref_pos_int) << what;
    for (const std::string& e : drv.pins().errors()) ADD_FAILURE() << what << ": " << e;
    for (const std::string& e : exact.errors()) ADD_FAILURE() << what << ": " << e;
    st.rises += exact.rises();
    st.setup_decided += exact.setup_decided();
    st.owed_turns += exact.owed_turns();
    st.hold_decided += exact.hold_decided();
    st.against_owed += exact.requests_against_owed();
    st.guard_stops += drv.out().fault_overrun;
  }
  return st;
}

}  // namespace

// Reversals right after a pulse, where DIR setup and hold decide the clock,
// for setup/hold 0, 1 and random values: a rise after a DIR turn with the
// step owed comes exactly max(setup, 1) clocks after the turn, an owed turn
// exactly `hold` clocks after the last rising edge (once STEP is low: hold >
// high), and every other rise and owed turn on the first clock the rules
// allow (ExactStepDirTiming); model alone and RTL in lockstep, with the pin
// monitor's widths and the pins against the reference position.
TEST(Lockstep, DirSetupAndHoldAreExactWhenAReversalFollowsAPulse) {
  std::mt19937_64 g(31);
  // high, low, setup, hold. Setup and hold 0 and 1, each with the other one
  // long; then random ones. A hold up to `high` never decides (STEP is still
  // high then); a turn owed within a long hold makes the setup decide even
  // when it is 0 or 1 (the rise the clock after the turn).
  std::vector<PulseTiming> timings = {{200, 300, 0, 1500}, {100, 150, 1, 1200}, {120, 80, 1500, 0}, {90, 60, 1200, 1}};
  for (int i = 0; i < 4; ++i) {
    PulseTiming t;
    t.high = uint16_t(20 + g() % 280);
    t.low = uint16_t(20 + g() % 280);
    t.setup = uint16_t(200 + g() % 1800);
    t.hold = uint16_t(i % 2 ? g() % (t.high + 1) : 1000 + g() % 2000);
    timings.push_back(t);
  }
  // Turns at up to the largest acceleration, 0.5..20 pulses apart: a step
  // owed against DIR within a hold of ~1000 clocks after the last rise, or
  // within the setup after a turn.
  const TableShape shape{1e-7, 7e-6, 0.5, 20};
  for (const PulseTiming& t : timings) {
    for (SimEngine e : {SimEngine::ModelOnly, SimEngine::Lockstep}) {
      const ReversalStats st = run_reversals(t, e, g, 10, shape);
      const std::string what = fmt::format("timing {}/{}/{}/{} on {}", t.high, t.low, t.setup, t.hold, engine_name(e));
      std::printf("%s: %llu rises, %llu decided by setup, %llu owed turns, %llu decided by hold, %llu against owed, "
                  "%llu guard stops\n",
                  what.c_str(), (unsigned long long)st.rises, (unsigned long long)st.setup_decided,
                  (unsigned long long)st.owed_turns, (unsigned long long)st.hold_decided,
                  (unsigned long long)st.against_owed, (unsigned long long)st.guard_stops);
      EXPECT_GT(st.setup_decided, 0u) << what << ": no rise where the setup time was the bound";
      if (t.hold > t.high) EXPECT_GT(st.hold_decided, 0u) << what << ": no turn where the hold time was the bound";
    }
  }
}

// Reversals with steps still owed in the old direction (a pulse slower than
// the steps before the turn, the turn at up to the largest acceleration):
// requests of the other sign arrive while the queue is nonzero and net out
// against the owed steps. No step lost or invented (the pins against the
// reference position at every change and at rest), DIR never turns while a
// step is owed its way, every rise and owed turn on time (ExactStepDirTiming);
// model alone and RTL in lockstep.
TEST(Lockstep, ReversalWithStepsStillOwedLosesNoStep) {
  std::mt19937_64 g(32);
  const std::vector<PulseTiming> timings = {{300, 300, 0, 0}, {250, 400, 60, 20}, {500, 200, 5, 900}};
  const TableShape shape{1e-6, 7e-6, 0.5, 4};
  for (const PulseTiming& t : timings) {
    for (SimEngine e : {SimEngine::ModelOnly, SimEngine::Lockstep}) {
      const ReversalStats st = run_reversals(t, e, g, 10, shape);
      const std::string what = fmt::format("timing {}/{}/{}/{} on {}", t.high, t.low, t.setup, t.hold, engine_name(e));
      std::printf("%s: %llu requests against owed steps, %llu rises, %llu guard stops\n", what.c_str(),
                  (unsigned long long)st.against_owed, (unsigned long long)st.rises,
                  (unsigned long long)st.guard_stops);
      EXPECT_GE(st.against_owed, 5u) << what << ": too few reversals with a step owed";
    }
  }
}

TEST(LockstepChecker, ReportsAnInjectedStateDifferenceAtTheRightClock) {
  const Plan p = std::get<Plan>(plan_move(paper_group(1), {}));
  RtlCore rtl;
  rtl.reset();
  AxisCore model;
  LockstepChecker chk;
  CoreInputs in;
  in.enable = true;
  for (const CoreInputs& ci : load_sequence(p.segments, p.pos_frac0, in)) {
    rtl.step(ci);
    model.step(ci);
    in = ci;
  }
  in.start = false;
  const uint64_t inject_at = 5000;
  for (uint64_t clock = 0; clock < 6000; ++clock) {
    rtl.step(in);
    model.step(in);
    if (clock == inject_at) model.exec().mutable_state().frac ^= u128(1) << 3;  // one LSB-ish bit
    chk.compare(clock, rtl.outputs(), model.outputs());
    if (chk.should_stop()) break;
  }
  ASSERT_EQ(chk.errors().size(), 1u);
  const Mismatch& m = chk.errors().front();
  EXPECT_EQ(m.clock, inject_at);
  EXPECT_EQ(m.signal, "ref_pos_frac_o");
  EXPECT_NE(m.rtl, m.model);
  EXPECT_NE(m.context.find("clock"), std::string::npos) << "context of earlier clocks";
  EXPECT_NE(chk.finish().find("clock 5000 signal ref_pos_frac_o"), std::string::npos) << chk.finish();
}

TEST(LockstepChecker, ReportsAPinDifferenceFromADifferentPulseWidth) {
  MoveRequest r = paper_group(1);
  r.distance = 200;
  r.v_end = 0;
  r.v_start = 1500;
  r.v_cruise = 1500;
  r.adjust_end_speed = true;
  const Plan p = std::get<Plan>(plan_move(r, {}));
  RtlCore rtl;
  rtl.reset();
  AxisCore model;
  LockstepChecker chk;
  CoreInputs in;
  in.enable = true;
  CoreInputs model_in;
  for (CoreInputs ci : load_sequence(p.segments, p.pos_frac0, in)) {
    rtl.step(ci);
    in = ci;
    ci.cfg.high = uint16_t(ci.cfg.high + 1);  // the model believes in a wider pulse
    model.step(ci);
    model_in = ci;
  }
  in.start = model_in.start = false;
  uint64_t clock = 0;
  while (clock < 2'000'000 && !chk.should_stop()) {
    rtl.step(in);
    model.step(model_in);
    chk.compare(clock++, rtl.outputs(), model.outputs());
  }
  ASSERT_FALSE(chk.errors().empty());
  EXPECT_EQ(chk.errors().front().signal, "step_o");
  EXPECT_EQ(chk.errors().front().rtl, "0x0");
  EXPECT_EQ(chk.errors().front().model, "0x1");
}

// The comparer is one template for every bench: any struct of outputs with
// operator== and a render function.
struct TwoPorts {
  uint32_t a = 0;
  int16_t b = 0;
  bool operator==(const TwoPorts&) const = default;
};
SignalValues render_two(const TwoPorts& p) { return {{"a_o", hex_bits(uint64_t(p.a), 32)}, {"b_o", hex_bits(int64_t(p.b), 12)}}; }

TEST(Lockstep, ReportsTheFirstDifferingSignalInHexWithTheLastClocksAndStops) {
  Lockstep<TwoPorts> chk(&render_two);
  uint64_t clock = 0;
  for (; clock < 100 && !chk.should_stop(); ++clock) {
    const TwoPorts rtl{uint32_t(clock), int16_t(-1)};
    TwoPorts model = rtl;
    if (clock == 42) model.b = 1;
    chk.compare(clock, rtl, model);
  }
  EXPECT_EQ(clock, 43u) << "stops at the first mismatch by default";
  ASSERT_EQ(chk.errors().size(), 1u);
  EXPECT_EQ(chk.errors().front().to_string().substr(0, 40), "clock 42 signal b_o: rtl=0xfff model=0x0");
  EXPECT_EQ(chk.matched(), 42u);
  EXPECT_EQ(chk.mismatches(), 1u);
  const std::string& ctx = chk.errors().front().context;
  EXPECT_NE(ctx.find("clock         34 (match) b_o=0xfff"), std::string::npos) << ctx;
  EXPECT_NE(ctx.find("clock         41 (match) b_o=0xfff"), std::string::npos) << ctx;
  EXPECT_EQ(ctx.find("clock         33"), std::string::npos) << "only the last " << Lockstep<TwoPorts>::kContext;
  EXPECT_NE(chk.finish().find("42 clocks matched, 1 mismatching clocks"), std::string::npos) << chk.finish();
}

TEST(Lockstep, FinishFlagsARunThatComparedNothing) {
  Lockstep<TwoPorts> chk(&render_two);
  EXPECT_TRUE(chk.compared_nothing());
  EXPECT_EQ(chk.finish(), "lockstep: nothing compared");
  chk.compare(0, TwoPorts{}, TwoPorts{});
  EXPECT_EQ(chk.finish(), "lockstep: 1 clocks matched, 0 mismatches");
}

// ---- pin monitor: step accounting catches what RTL and model share ----------------
// A synthetic open-loop run: the executor's position moves at clock
// 400k+10, its request enters the queue one clock later, the pulse leaves
// the queue at 400k+200. `drop_request` loses one request (a step-queue
// overrun RTL and model would agree on).
std::vector<std::string> run_reference_accounting(int steps, int drop_request) {
  PulseTiming t{10, 10, 5, 5};  // high, low, setup, hold
  PinMonitor pins(PinRules{t, false, StepAccounting::ReferencePosition});
  int32_t ref = 1000;  // the executor does not start at 0
  int32_t queued = 0;
  bool step = false;
  int high_left = 0;
  const uint64_t end = uint64_t(steps) * 400 + 1000;
  for (uint64_t clock = 0; clock < end; ++clock) {
    const uint64_t k = clock / 400, at = clock % 400;
    if (high_left > 0 && --high_left == 0) step = false;
    if (k < uint64_t(steps) && at == 10) ++ref;
    if (k < uint64_t(steps) && at == 11 && k != uint64_t(drop_request)) ++queued;
    if (at == 200 && queued > 0) {
      step = true;
      high_left = t.high;
      --queued;
    }
    pins.on_clock(clock, step, true, false, 0, ref, queued);
  }
  pins.finish(end);
  return pins.errors();
}

TEST(PinMonitor, ReferenceAccountingPassesAnExactRun) {
  const auto errors = run_reference_accounting(20, -1);
  EXPECT_TRUE(errors.empty()) << errors.front();
}

TEST(PinMonitor, ReferenceAccountingReportsADroppedRequestAtTheNextPositionChange) {
  const auto errors = run_reference_accounting(20, 7);
  ASSERT_FALSE(errors.empty());
  // request 7 is lost at clock 7*400+11; the position moves next at 8*400+10
  EXPECT_EQ(errors.front().rfind("clock 3210: step accounting: 7 net STEP edges + 0 queued != 8 pulses", 0), 0u)
      << errors.front();
}

TEST(PinMonitor, ReferenceAccountingReportsALostLastRequestAtTheEnd) {
  const auto errors = run_reference_accounting(20, 19);
  ASSERT_EQ(errors.size(), 1u) << errors.front();
  EXPECT_EQ(errors.front().rfind("clock 9000: step accounting at the end: 19 net STEP edges + 0 queued != 20 pulses", 0),
            0u)
      << errors.front();
}

TEST(PinMonitor, PulseCounterAccountingReportsAPulseTheCounterMissedAndFollowsItsClear) {
  PulseTiming t{4, 4, 0, 0};  // high, low, setup, hold
  PinMonitor pins(PinRules{t, false, StepAccounting::PulseCounter});
  int32_t count = 0;
  uint64_t clock = 0;
  auto pulse = [&](bool counted) {
    if (counted) ++count;
    for (int i = 0; i < 8; ++i, ++clock) pins.on_clock(clock, i < 4, true, false, 0, count);
  };
  pulse(true);
  pulse(true);
  count = 0;  // a new move clears the counter
  pins.on_clock(clock++, false, true, false, 0, count);
  pulse(true);
  EXPECT_TRUE(pins.errors().empty()) << pins.errors().front();
  pulse(false);  // a STEP edge the counter does not see
  ASSERT_FALSE(pins.errors().empty());
  EXPECT_EQ(pins.errors().front(), fmt::format("clock {}: step accounting: 2 net STEP edges != pulse counter 1", clock - 8));
}

TEST(PinMonitor, ClosedLoopRulesKeepTimingChecksWithoutProfilePhases) {
  PulseTiming t{4, 4, 10, 0};  // high, low, setup, hold
  PinMonitor pins(PinRules{t, false, StepAccounting::None});
  // pulses while the reported phase is "done" are fine in closed loop ...
  const uint8_t done = uint8_t(Phase::PhDone);
  uint64_t clock = 0;
  for (int i = 0; i < 8; ++i, ++clock) pins.on_clock(clock, i < 4, true, true, done);
  // ... but a DIR change 3 clocks before the rising edge is not
  pins.on_clock(clock++, false, false, true, done);
  for (int i = 0; i < 2; ++i) pins.on_clock(clock++, false, false, true, done);
  pins.on_clock(clock, true, false, true, done);
  pins.finish(clock + 1);
  ASSERT_EQ(pins.errors().size(), 1u) << pins.errors().front();
  EXPECT_EQ(pins.errors().front(), fmt::format("clock {}: DIR setup 3 < 10 clocks", clock));
}

// The paper's four groups (L = 30,000, a = 500, j = 2500), full length at
// 20 MHz: 278-400 M clocks each, every clock compared.
class PaperGroup : public ::testing::TestWithParam<int> {};

TEST_P(PaperGroup, FullLengthLockstepIsExactAndInPhase) {
  const int g = GetParam();
  const MoveRequest r = paper_group(g);
  const Plan p = std::get<Plan>(plan_move(r, {}));
  const SimResult s = run_move(p, {}, limits_of(r, p), SimOptions{});
  EXPECT_TRUE(s.pass()) << s.failure_lines();
  EXPECT_EQ(s.mismatches, 0u);
  EXPECT_EQ(s.pulses, 30000);
  EXPECT_EQ(s.final_error, 0);
  EXPECT_EQ(s.trends, s.expected_trends) << "duty phases in the planned order";
  EXPECT_GT(s.matched_clocks, 278'000'000u);
  EXPECT_LE(s.peak_velocity, std::max({r.v_start, r.v_cruise, r.v_end}) + 1e-9);
  EXPECT_LE(s.peak_acceleration, r.a_max + 1e-9);
  EXPECT_LE(s.peak_jerk, r.j_max + 1e-9);
  RecordProperty("clocks_per_s", std::to_string(s.clocks_per_s));
  std::printf("group %d: %llu clocks, %.1f M clocks/s (%.2fx real time)\n", g,
              static_cast<unsigned long long>(s.total_clocks), s.clocks_per_s / 1e6, s.clocks_per_s / ClkHz);
}

INSTANTIATE_TEST_SUITE_P(Paper000Table2, PaperGroup, ::testing::Values(1, 2, 3, 4),
                         [](const ::testing::TestParamInfo<int>& i) { return "Group" + std::to_string(i.param); });
