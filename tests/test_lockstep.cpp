// RTL (Verilated sc_axis_core) and the bit-exact model in lockstep, every
// clock: random planned moves, random raw tables that reverse direction and
// overrun the step queue, the paper's four groups, and proof that the
// checker reports an injected difference.
#include <gtest/gtest.h>

#include <random>

#include "lockstep.h"
#include "pin_monitor.h"
#include "planner.h"
#include "rtl_core.h"
#include "scenarios.h"
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

std::string describe(const SimResult& r) {
  std::string s;
  for (const auto& f : r.failures) s += f + "\n";
  return s;
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
                          << "/" << t.hold << "): " << describe(s);
    EXPECT_EQ(s.mismatches, 0u);
    EXPECT_EQ(s.pulses, r.distance);
    clocks += s.total_clocks;
    ++run;
  }
  RecordProperty("clocks", std::to_string(clocks));
}

// Raw tables (not from the planner): velocity crossing zero, speeds far
// above the step-rate limit, random pulse timing. RTL and model must agree
// on every output every clock, including DIR changes and the overrun flag,
// and the pins must still honour high/low/setup/hold.
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
    for (const std::string& e : pins.errors()) {
      // Only the timing rules apply to raw tables (no duty-phase contract).
      ASSERT_EQ(e.find("STEP pulse while phase"), std::string::npos) << e;
      ASSERT_TRUE(e.find("high") == std::string::npos && e.find("low") == std::string::npos &&
                  e.find("setup") == std::string::npos && e.find("hold") == std::string::npos)
          << "trial " << trial << ": " << e;
    }
    if (model.outputs().fault_overrun) ++overruns;
  }
  EXPECT_GT(overruns, 0) << "the campaign must overrun the step queue at least once";
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
  EXPECT_EQ(chk.errors().front().rtl, "0");
  EXPECT_EQ(chk.errors().front().model, "1");
}

// The paper's four groups (L = 30,000, a = 500, j = 2500), full length at
// 20 MHz: 278-400 M clocks each, every clock compared.
class PaperGroup : public ::testing::TestWithParam<int> {};

TEST_P(PaperGroup, FullLengthLockstepIsExactAndInPhase) {
  const int g = GetParam();
  const MoveRequest r = paper_group(g);
  const Plan p = std::get<Plan>(plan_move(r, {}));
  const SimResult s = run_move(p, {}, limits_of(r, p), SimOptions{});
  EXPECT_TRUE(s.pass()) << describe(s);
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
