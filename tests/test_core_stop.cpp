// Controlled stops through the whole open-loop core (sc_axis_core with its
// executor, FIFO and stop generator): a planned move is interrupted at a
// random clock by STOP, by an underrun (only part of its rows pushed) or by
// a discontinuity (a row that does not continue the motion), with random
// stop limits. RTL and model in lockstep every clock; the pin monitor checks
// every pulse against the reference position; the stop itself is checked
// from the outputs by the stop monitor (the property checker of the stop
// generator's tests, which knows nothing of the algorithm) and against
// the continuous closed-form stopping distance (tb/stop_check.h).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <random>

#include "lockstep.h"
#include "pin_monitor.h"
#include "planner.h"
#include "rtl_core.h"
#include "loaded_core.h"
#include "sim_run.h"
#include "stop_harness.h"

using namespace sc;
using stoptest::ld;

namespace {

enum class Trigger { Stop, Underrun, Discontinuity };

const char* trigger_name(Trigger t) {
  switch (t) {
    case Trigger::Stop: return "STOP";
    case Trigger::Underrun: return "underrun";
    case Trigger::Discontinuity: return "discontinuity";
  }
  return "?";
}

ld log_uniform(std::mt19937_64& g, ld lo, ld hi) {
  std::uniform_real_distribution<double> u(std::log(double(lo)), std::log(double(hi)));
  return std::exp(ld(u(g)));
}

// Physical limits in executor LSBs at the model's clock.
using stoptest::acc_lsb;
using stoptest::jerk_lsb;

struct CampaignStats {
  int stops = 0, infeasible = 0, by_trigger[3] = {0, 0, 0};
  uint64_t clocks = 0;
  ld worst_excess = -1e30;  // stopping distance - closed form, pulses (feasible stops)
};

// One move interrupted once. Returns false after a failure.
bool run_case(std::mt19937_64& g, CampaignStats& st, int index) {
  // A move short enough to simulate quickly, in either direction.
  MoveRequest req;
  PulseTiming t;
  t.high = uint16_t(2 + g() % 10);
  t.low = uint16_t(2 + g() % 10);
  t.setup = uint16_t(g() % 40);
  t.hold = uint16_t(g() % 40);
  Plan plan;
  for (;;) {
    req.distance = int64_t(50 + g() % 20000) * ((g() & 1) ? 1 : -1);
    req.v_cruise = double(log_uniform(g, 2e3, 1.5e5));
    req.a_max = double(log_uniform(g, 1e4, 2e6));
    req.j_max = double(log_uniform(g, 1e5, 5e9));
    req.kind = g() % 5 == 0 ? ProfileKind::Trapezoid : ProfileKind::SCurve;
    PlanResult r = plan_move(req, t);
    if (auto* p = std::get_if<Plan>(&r); p && p->total_clocks < 400'000 && p->segments.size() >= 2) {
      plan = *p;
      break;
    }
  }
  const Trigger trig = Trigger(g() % 3);
  // Stop limits around the plan's own (below them a stop may not avoid a
  // reversal: the overshoot case).
  const ld J = log_uniform(g, 0.3, 5) * ld(req.kind == ProfileKind::Trapezoid ? 1e9 : req.j_max);
  const ld D = log_uniform(g, 0.3, 5) * ld(req.a_max);
  CoreInputs in;
  in.enable = true;
  in.cfg = t;
  in.pos_frac0 = plan.pos_frac0;
  in.stop_jerk = std::max<uint64_t>(1, jerk_lsb(J));
  in.stop_acc = std::max<uint64_t>(1, acc_lsb(D));

  std::vector<Row> rows = move_rows(plan.segments);
  // Underrun: only the first k rows; discontinuity: row k off by one LSB.
  const size_t k = 1 + g() % (rows.size() - 1);
  if (trig == Trigger::Underrun) rows.resize(k);
  if (trig == Trigger::Discontinuity) rows[k].seg.vel0 += (g() & 1) ? 1 : -1;

  RtlCore rtl;
  rtl.reset();
  AxisCore model;
  LockstepChecker chk;
  PinRules rules{t};
  rules.profile_phases = false;  // the stop follows no planned phase
  rules.accounting = StepAccounting::ReferencePosition;
  PinMonitor pins(rules);
  uint64_t clock = 0;
  const CoreOutputs* cur = nullptr;  // the RTL's outputs of the last clock (a lockstep ring slot)
  // held: the inputs of the previous clock again, no row pushed.
  auto tick = [&](const CoreInputs& ci, bool held = false) {
    if (held) {
      rtl.tick();
      model.tick();
    } else {
      rtl.step(ci);
      model.step(ci);
    }
    CoreOutputs& o = chk.slot(clock);
    rtl.read_outputs(o);
    chk.check(clock, model);
    pins.on_clock(clock, o);
    cur = &o;
    ++clock;
  };
  for (const CoreInputs& ci : load_sequence(rows, plan.pos_frac0, in)) tick(ci);
  const uint64_t stop_at = clock + t.setup + 3 + g() % std::max<uint64_t>(1, plan.total_clocks - 2);

  const std::string what = fmt::format("case {}: {} of a {}-pulse move at clock {}, J {:.3g}, D {:.3g}", index,
                                       trigger_name(trig), req.distance, stop_at, double(J), double(D));
  stopcheck::StopMonitor stop(in.stop_jerk, in.stop_acc);
  const uint64_t limit = clock + plan.total_clocks + 20'000'000;
  bool held = false;
  while (clock < limit && !chk.should_stop()) {
    if (trig == Trigger::Stop && clock == stop_at) {
      CoreInputs ci = in;
      ci.stop = true;
      tick(ci);
      held = false;
    } else {
      tick(in, held);
      held = true;
    }
    const CoreOutputs& o = *cur;
    const bool first = o.stopping && !stop.seen();
    stop.on_clock(o);
    if (first) {
      EXPECT_EQ(o.underrun, trig == Trigger::Underrun) << what;
      EXPECT_EQ(o.discont, trig == Trigger::Discontinuity) << what;
    }
    if (stop.ended()) {
      if (stop.feasible()) {
        st.worst_excess = std::max(st.worst_excess, stop.excess());
      } else {
        ++st.infeasible;
      }
      break;
    }
    if (!stop.seen() && !o.busy && clock > stop_at + 4) break;  // the move ended first
  }
  // Nothing moves after the stop (or after the move, when it ended first).
  const int32_t pos_end = cur->ref_pos_int;
  for (int i = 0; i < 3000; ++i) {
    tick(in, held);
    held = true;
    EXPECT_FALSE(cur->step) << what << ": a step after rest";
    EXPECT_FALSE(cur->busy) << what;
  }
  EXPECT_EQ(rtl.outputs().ref_pos_int, pos_end) << what;
  pins.finish(clock);
  EXPECT_TRUE(chk.errors().empty()) << what << "\n" << chk.finish();
  for (const std::string& e : pins.errors()) ADD_FAILURE() << what << ": " << e;
  EXPECT_EQ(pins.net_steps(), int64_t(rtl.outputs().ref_pos_int)) << what << ": every reference step on the pins";
  for (const std::string& e : stop.errors()) ADD_FAILURE() << what << ": " << e;
  // A STOP after the move's end, or an underrun/discontinuity that the move
  // did not reach, stops nothing; every trigger that came while moving did.
  if (stop.seen()) {
    EXPECT_TRUE(stop.ended()) << what << ": the stop did not end";
    ++st.stops;
    ++st.by_trigger[int(trig)];
  } else {
    EXPECT_TRUE(trig == Trigger::Stop) << what << ": an underrun or discontinuity must stop";
  }
  st.clocks += clock;
  return !::testing::Test::HasFailure();
}

void stop_campaign(int cases, uint64_t seed) {
  std::mt19937_64 g(seed);
  CampaignStats st;
  for (int i = 0; i < cases; ++i) {
    if (!run_case(g, st, i)) return;
  }
  EXPECT_GT(st.by_trigger[0], cases / 5);
  EXPECT_GT(st.by_trigger[1], cases / 5);
  EXPECT_GT(st.by_trigger[2], cases / 5);
  ::testing::Test::RecordProperty("stops", std::to_string(st.stops));
  ::testing::Test::RecordProperty("clocks", std::to_string(st.clocks));
  std::printf("[stop] %d stops (STOP %d, underrun %d, discontinuity %d; %d not stoppable without reversal), "
              "%llu clocks in lockstep, worst distance - closed form %+.4f pulse\n",
              st.stops, st.by_trigger[0], st.by_trigger[1], st.by_trigger[2], st.infeasible,
              (unsigned long long)st.clocks, double(st.worst_excess));
}

// The core with rows loaded (3000 pulses at 4e5 pulses/s^2, 4e7 pulses/s^3).
struct RunningCore : stoptest::LoadedCore {
  RunningCore() : LoadedCore(3000, 4e5, 4e7) {}
};

}  // namespace

TEST(CoreStop, RandomStopsUnderrunsAndDiscontinuitiesStopUnderControl) { stop_campaign(48, 5); }

TEST(CoreStopLong, ThousandRandomStopsStopUnderControl) { stop_campaign(1000, 6); }

TEST(CoreStop, StopWhileIdleChangesNothing) {
  RunningCore c;  // rows loaded, not started
  CoreInputs s = c.in;
  s.stop = true;
  c.tick(s);
  for (int i = 0; i < 20; ++i) c.tick();
  const CoreOutputs o = c.out();
  EXPECT_FALSE(o.busy);
  EXPECT_FALSE(o.stopping);
  EXPECT_EQ(o.phase, uint8_t(Phase::PhIdle));
  EXPECT_EQ(o.fifo_level, c.plan.segments.size()) << "the queued rows stay";
  EXPECT_FALSE(o.underrun || o.discont || o.fault_table);
  EXPECT_TRUE(c.chk.errors().empty()) << c.chk.finish();
}

TEST(CoreStop, StopWhileArmingDropsTheStart) {
  RunningCore c;
  c.in.cfg.setup = 200;  // a long arming
  for (int i = 0; i < 4; ++i) c.tick();
  CoreInputs s = c.in;
  s.start = true;
  c.tick(s);
  for (int i = 0; i < 20; ++i) c.tick();
  EXPECT_TRUE(c.out().busy) << "arming";
  s = c.in;
  s.stop = true;
  c.tick(s);
  for (int i = 0; i < 400; ++i) {
    c.tick();
    ASSERT_FALSE(c.out().step);
  }
  const CoreOutputs o = c.out();
  EXPECT_FALSE(o.busy);
  EXPECT_EQ(o.ref_pos_int, 0);
  EXPECT_EQ(o.phase, uint8_t(Phase::PhIdle)) << "the executor never started";
  EXPECT_TRUE(c.chk.errors().empty()) << c.chk.finish();
}

TEST(CoreStop, AbortDuringAStopIsImmediate) {
  RunningCore c;
  CoreInputs s = c.in;
  s.start = true;
  c.tick(s);
  while (c.out().ref_vel < c.plan.segments[1].vel0 && c.clock < 1'000'000) c.tick();
  s = c.in;
  s.stop = true;
  c.tick(s);
  for (int i = 0; i < 40; ++i) c.tick();
  ASSERT_TRUE(c.out().stopping);
  ASSERT_NE(c.out().ref_vel, 0);
  s = c.in;
  s.abort = true;
  c.tick(s);
  c.tick();
  c.tick();
  const CoreOutputs o = c.out();
  EXPECT_FALSE(o.stopping);
  EXPECT_EQ(o.ref_vel, 0);
  EXPECT_EQ(o.ref_acc, 0);
  EXPECT_EQ(o.ref_jerk, 0);
  EXPECT_EQ(o.phase, uint8_t(Phase::PhAbort));
  EXPECT_TRUE(c.chk.errors().empty()) << c.chk.finish();
}

TEST(CoreStop, RowsPushedWhileStoppingAreRefusedAndAFreshStreamRunsAfter) {
  RunningCore c;
  CoreInputs s = c.in;
  s.start = true;
  c.tick(s);
  for (int i = 0; i < 2000; ++i) c.tick();
  s = c.in;
  s.stop = true;
  c.tick(s);
  c.tick();
  ASSERT_TRUE(c.out().stopping);
  const std::vector<Row> rows = move_rows(c.plan.segments);
  CoreInputs w = c.in;
  w.row_push = true;
  w.row = rows[0];
  c.tick(w);
  EXPECT_EQ(c.out().fifo_level, 0) << "a push while stopping is not taken";
  EXPECT_TRUE(c.out().fifo_full) << "and the FIFO says so";
  while (c.out().busy && c.clock < 2'000'000) c.tick();
  ASSERT_FALSE(c.out().busy);
  EXPECT_FALSE(c.out().fifo_full);
  // The same move again, from where the stop left the axis: exact.
  const int32_t p0 = c.out().ref_pos_int;
  for (const Row& r : rows) {
    w.row = r;
    c.tick(w);
  }
  s = c.in;
  s.start = true;
  c.tick(s);
  while ((c.out().busy || !c.out().done) && c.clock < 4'000'000) c.tick();
  EXPECT_TRUE(c.out().done);
  EXPECT_EQ(c.out().ref_pos_int - p0, c.plan.distance);
  EXPECT_TRUE(c.chk.errors().empty()) << c.chk.finish();
}

// Stop limits ten times below the plan's, from a row boundary in its
// acceleration: the stop first ramps the acceleration down (it starts above
// the stop's deceleration limit), then brakes.
TEST(CoreStop, LowLimitsStopAMoveFromItsAccelerationUnderControl) {
  RtlCore rtl;
  rtl.reset();
  AxisCore model;
  LockstepChecker chk;
  MoveRequest req;
  req.distance = 6000;
  req.v_cruise = 30000;
  req.a_max = 4e5;
  req.j_max = 4e8;
  const Plan plan = std::get<Plan>(plan_move(req, PulseTiming{}));
  ASSERT_GE(plan.segments.size(), 3u);
  std::vector<Row> rows = move_rows(plan.segments);
  rows[2].seg.vel0 += 1;
  CoreInputs in;
  in.enable = true;
  in.pos_frac0 = plan.pos_frac0;
  in.stop_jerk = jerk_lsb(4e7);
  in.stop_acc = acc_lsb(2e5);
  uint64_t clock = 0;
  auto tick = [&](const CoreInputs& ci) {
    rtl.step(ci);
    model.step(ci);
    chk.compare(clock++, rtl.outputs(), model.outputs());
  };
  for (const CoreInputs& ci : load_sequence(rows, in.pos_frac0, in)) tick(ci);
  bool stopped = false;
  while (clock < 40'000'000 && !chk.should_stop()) {
    tick(in);
    stopped = stopped || rtl.outputs().stopping;
    if (stopped && !rtl.outputs().busy) break;
  }
  EXPECT_TRUE(stopped);
  EXPECT_FALSE(rtl.outputs().busy);
  EXPECT_TRUE(rtl.outputs().discont);
  EXPECT_EQ(rtl.outputs().ref_vel, 0);
  EXPECT_TRUE(chk.errors().empty()) << chk.finish();
}
