// RTL (Verilated sc_axis_core) and the bit-exact model in lockstep, every
// clock: random planned moves, random raw tables that reverse direction and
// overrun the step queue, controlled stops at random times on every engine,
// the paper's four groups, and proof that the checker reports an injected
// difference.
#include <fmt/format.h>
#include <gtest/gtest.h>

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
// high/low/setup/hold, and no step is lost.
TEST(Lockstep, RandomRawTablesWithReversalsAndOverrunsMatch) {
  std::mt19937_64 g(99);
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
    PinMonitor pins(t);
    CoreInputs in;
    in.enable = true;
    in.cfg = t;
    uint64_t clock = 0;
    auto tick = [&](const CoreInputs& ci) {
      rtl.step(ci);
      model.step(ci);
      const CoreOutputs o = rtl.outputs();
      chk.compare(clock, o, model.outputs());
      pins.on_clock(clock, o);
      ++clock;
    };
    for (const CoreInputs& ci : load_sequence(table, (u128(g()) << 16) & (kOne - 1), in)) {
      tick(ci);
      in = ci;
    }
    in.start = false;
    bool last_dir = model.outputs().dir;
    while (clock < 400000 && !chk.should_stop()) {
      tick(in);
      if (model.outputs().dir != last_dir) ++reversals;
      last_dir = model.outputs().dir;
      if (model.outputs().done && clock > 100) break;
    }
    ASSERT_TRUE(chk.errors().empty()) << chk.finish();
    // A table faster than the pulse timing trips the step-rate guard: the
    // executor stops at once (phase ABORT) and the queued steps drain.
    const bool rate_stop = model.outputs().fault_overrun;
    const std::string drain = "STEP pulse while phase " + std::to_string(int(Phase::PhAbort));
    for (const std::string& e : pins.errors()) {
      // Only the timing rules apply to raw tables (no duty-phase contract).
      if (!(rate_stop && e.find(drain) != std::string::npos))
        ASSERT_EQ(e.find("STEP pulse while phase"), std::string::npos) << e;
      ASSERT_TRUE(e.find("high") == std::string::npos && e.find("low") == std::string::npos &&
                  e.find("setup") == std::string::npos && e.find("hold") == std::string::npos)
          << "trial " << trial << ": " << e;
    }
    // No step lost or invented, overrun or not: at rest the pins' count is
    // the reference position's integer part.
    const CoreOutputs end = model.outputs();
    if (end.done) EXPECT_EQ(end.pulse_count, end.ref_pos_int) << "trial " << trial;
    if (end.fault_overrun) ++overruns;
  }
  EXPECT_GT(overruns, 0) << "the campaign must trip the step-rate guard at least once";
  EXPECT_GT(reversals, 10) << "the campaign must reverse direction";
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
