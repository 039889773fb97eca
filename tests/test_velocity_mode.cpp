// Velocity mode (jog): the planner's velocity changes (exact targets,
// limits, fastest ramps by the closed form), the executor's HOLD rows (held
// until a whole command is queued, never an underrun), and random jog
// programs on the core in RTL/model lockstep with the pin monitor, ending at
// rest or with a controlled stop.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "jog_run.h"
#include "planner.h"
#include "scurve/reg_encode.h"

using namespace sc;

namespace {

const scurve::Clock kClock = model_clock();

scurve::VelocityPlan plan_or_fail(i128 v_from, double v_target, double a, double j) {
  const scurve::Planner planner{kClock};
  auto r = planner.plan_velocity(v_from, {v_target, a, j}, scurve::PulseTiming{});
  if (const scurve::Error* e = std::get_if<scurve::Error>(&r)) {
    ADD_FAILURE() << e->message;
    return {};
  }
  return std::get<scurve::VelocityPlan>(r);
}

// Fastest change of speed by dv >= 0 with |a| <= A and |j| <= J (seconds).
double closed_form_ramp_s(double dv, double A, double J) {
  return dv >= A * A / J ? dv / A + A / J : 2 * std::sqrt(dv / J);
}

}  // namespace

TEST(VelocityPlan, RampsReachTheTargetExactlyWithinTheLimitsAndAsFastAsTheClosedForm) {
  std::mt19937_64 g(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double v_max = 150000;
  int reversals = 0, checked = 0;
  double worst = 0;  // largest relative excess of a ramp over the closed form
  i128 v = 0;
  for (int i = 0; i < 400; ++i) {
    const double a = 1e4 * std::pow(10.0, 2 * u(g)), j = a * 10 * std::pow(10.0, 2 * u(g));
    const double target = (u(g) < 0.1) ? 0.0 : v_max * (2 * u(g) - 1);
    const scurve::VelocityPlan p = plan_or_fail(v, target, a, j);
    if (p.segments.empty()) {
      EXPECT_EQ(v, p.v_end);
      continue;
    }
    const std::string at = fmt::format("command {}: {} -> {} pulses/s", i,
                                       double(v) / scurve::vel_lsb_per_unit(kClock), target);
    // The target on the LSB grid, exactly: the hold row starts there.
    const i128 want = i128(std::floor(std::fabs(target) * scurve::vel_lsb_per_unit(kClock))) * (target < 0 ? -1 : 1);
    EXPECT_EQ(p.v_end, want) << at;
    EXPECT_EQ(p.hold, target != 0) << at;
    if (p.hold) {
      const scurve::Segment& h = p.segments.back();
      EXPECT_EQ(h.vel0, p.v_end) << at;
      EXPECT_EQ(h.acc0, 0) << at;
      EXPECT_EQ(h.jerk, 0) << at;
    }
    // The ramp run in closed form from v: continuous, ends at v_end with a = 0.
    i128 vel = v, pos = 0;
    int64_t acc = 0;
    int64_t peak_acc = 0, peak_jerk = 0;
    bool sign_flip = false;
    int last_sign = v > 0 ? 1 : v < 0 ? -1 : 0;
    const size_t ramp_rows = p.segments.size() - (p.hold ? 1 : 0);
    for (size_t k = 0; k < ramp_rows; ++k) {
      const scurve::Segment& s = p.segments[k];
      EXPECT_EQ(s.vel0, vel) << at << ", row " << k;
      EXPECT_EQ(s.acc0, acc) << at << ", row " << k;
      const int64_t acc_end = int64_t(scurve::acc_after(s.acc0, s.jerk, s.clocks));
      peak_acc = std::max({peak_acc, std::abs(s.acc0), std::abs(acc_end)});
      peak_jerk = std::max(peak_jerk, std::abs(s.jerk));
      const i128 v_next = scurve::vel_after(s.vel0, s.acc0, s.jerk, s.clocks);
      // (a reversal passes through exactly 0 at a row boundary)
      if (v_next != 0) {
        if (last_sign != 0 && (v_next > 0) != (last_sign > 0)) sign_flip = true;
        last_sign = v_next > 0 ? 1 : -1;
      }
      pos += scurve::pos_gain(s.vel0, s.acc0, s.jerk, s.clocks);
      vel = v_next;
      acc = int64_t(scurve::acc_after(s.acc0, s.jerk, s.clocks));
    }
    EXPECT_EQ(vel, p.v_end) << at;
    EXPECT_EQ(acc, 0) << at;
    EXPECT_EQ(pos, p.ramp_gain) << at;
    EXPECT_LE(peak_acc, int64_t(std::floor(a * scurve::acc_lsb_per_unit(kClock)))) << at;
    EXPECT_LE(peak_jerk, int64_t(std::floor(j * scurve::jerk_lsb_per_unit(kClock)))) << at;
    const bool reverses = (v > 0 && p.v_end < 0) || (v < 0 && p.v_end > 0);
    EXPECT_EQ(sign_flip, reverses) << at << ": the velocity changes sign only at a direction change";
    reversals += reverses;
    // Time-optimal: the closed form of the change (through rest at a
    // reversal) for the limits on the register grid (floored to an LSB),
    // within 0.5 % and a few clocks: the integer clock grid, and a peak
    // acceleration the transition builder lowers a little so that its jerk
    // ramps fit the change exactly; short ramps (no constant-acceleration
    // phase) lose the most (measured: up to about 0.2 %).
    const double aq = std::floor(a * scurve::acc_lsb_per_unit(kClock)) / scurve::acc_lsb_per_unit(kClock);
    const double jq = std::floor(j * scurve::jerk_lsb_per_unit(kClock)) / scurve::jerk_lsb_per_unit(kClock);
    const double vf = std::fabs(double(v)) / scurve::vel_lsb_per_unit(kClock), vt = std::fabs(target);
    const double t = reverses ? closed_form_ramp_s(vf, aq, jq) + closed_form_ramp_s(vt, aq, jq)
                              : closed_form_ramp_s(std::fabs(vt - vf), aq, jq);
    EXPECT_LE(double(p.ramp_clocks), t * kClock.hz * (1 + 5e-3) + 8) << at;
    EXPECT_GE(double(p.ramp_clocks), t * kClock.hz * (1 - 1e-4) - 8) << at;
    worst = std::max(worst, double(p.ramp_clocks) / (t * kClock.hz) - 1);
    ++checked;
    v = p.v_end;
  }
  EXPECT_GT(checked, 300);
  EXPECT_GT(reversals, 50);
  std::printf("velocity ramps: %d checked, %d reversals; slowest %.4f %% over the closed form\n", checked, reversals,
              100 * worst);
}

TEST(VelocityPlan, BadInputNamesTheParameterTheValueAndTheBound) {
  const scurve::Planner planner{kClock};
  const scurve::PulseTiming t{};
  const double v_lim = scurve::step_rate_limit(t, kClock);
  struct Case {
    i128 v_from;
    scurve::VelocityRequest req;
    std::string parameter, text;
  };
  const i128 lsb_lim = i128(kOne) / (t.high + t.low);
  const std::vector<Case> cases = {
      {0, {v_lim * 1.01, 1e5, 1e7}, "v_target", "exceeds the limit"},
      {0, {-v_lim * 1.01, 1e5, 1e7}, "v_target", "must be >="},
      {0, {std::nan(""), 1e5, 1e7}, "v_target", "finite"},
      {0, {1000, 0, 1e7}, "a_max", "a_max=0"},
      {0, {1000, 1e5, -1}, "j_max", "j_max=-1"},
      {lsb_lim + 1, {1000, 1e5, 1e7}, "v_from", "step-rate limit"},
  };
  for (const Case& c : cases) {
    auto r = planner.plan_velocity(c.v_from, c.req, t);
    ASSERT_TRUE(std::holds_alternative<scurve::Error>(r)) << c.parameter;
    const scurve::Error& e = std::get<scurve::Error>(r);
    EXPECT_EQ(e.parameter, c.parameter) << e.message;
    EXPECT_NE(e.message.find(c.text), std::string::npos) << e.message;
  }
  // A jog program whose last target is not rest and has no stop.
  JogRequest jr;
  jr.a_max = 1e5;
  jr.j_max = 1e7;
  jr.commands = {{1000, 0}};
  auto p = plan_jog(jr, PulseTiming{});
  ASSERT_TRUE(std::holds_alternative<scurve::Error>(p));
  EXPECT_EQ(std::get<scurve::Error>(p).parameter, "commands[0].v_target");
  jr.commands = {{1000, -1}, {0, 0}};
  p = plan_jog(jr, PulseTiming{});
  ASSERT_TRUE(std::holds_alternative<scurve::Error>(p));
  EXPECT_EQ(std::get<scurve::Error>(p).parameter, "commands[0].hold_s");
}

namespace {

void push(ProfileExec& ex, const Row& r) {
  ProfileExec::Inputs w;
  w.row_push = true;
  w.row = r;
  ex.step(w);
}

void run(ProfileExec& ex, uint64_t n) {
  for (uint64_t i = 0; i < n; ++i) ex.step({});
}

// The rows pushed, START, and the clocks of the ramp: the hold runs.
void start_and_ramp(ProfileExec& ex, const std::vector<Row>& rows, uint64_t ramp_clocks) {
  for (const Row& r : rows) push(ex, r);
  ProfileExec::Inputs st;
  st.start = true;
  st.pos_frac0 = kOne / 2;
  ex.step(st);
  run(ex, ramp_clocks + 2);
}

}  // namespace

TEST(VelocityModeExec, AHoldKeepsItsVelocityUntilAWholeCommandIsQueuedThenRampsFromIt) {
  ProfileExec ex;
  const scurve::VelocityPlan up = plan_or_fail(0, 40000, 2e6, 4e8);
  start_and_ramp(ex, velocity_rows(up), up.ramp_clocks);
  // Held far longer than any row: no underrun, v exact, a = j = 0.
  for (int k = 0; k < 5; ++k) {
    run(ex, 200000);
    ASSERT_TRUE(ex.state().run);
    ASSERT_TRUE(ex.holding());
    EXPECT_EQ(ex.state().vel, to_model(up.segments.back()).vel0);
    EXPECT_EQ(ex.state().acc, 0);
    EXPECT_FALSE(ex.state().underrun);
  }
  // The next command, all but its last row: still holding.
  const scurve::VelocityPlan down = plan_or_fail(up.v_end, -25000, 2e6, 4e8);
  const std::vector<Row> rows = velocity_rows(down);
  ASSERT_GE(rows.size(), 3u);
  for (size_t k = 0; k + 1 < rows.size(); ++k) push(ex, rows[k]);
  run(ex, 50000);
  EXPECT_TRUE(ex.holding()) << "a part of a command does not end the hold";
  EXPECT_EQ(ex.fifo_level(), rows.size() - 1);
  EXPECT_EQ(ex.state().vel, up.v_end);
  // The last row: the ramp starts in the next clocks and reaches -25000 exactly.
  push(ex, rows.back());
  run(ex, 2);
  EXPECT_FALSE(ex.holding());
  run(ex, down.ramp_clocks + 2);
  EXPECT_TRUE(ex.holding());
  EXPECT_EQ(ex.state().vel, down.v_end);
  EXPECT_EQ(ex.state().move_idx, 1u) << "the first command's move ends when its hold ends";
  // To rest: the stream ends, done, no fault.
  for (const Row& r : velocity_rows(plan_or_fail(down.v_end, 0, 2e6, 4e8))) push(ex, r);
  run(ex, 2000000);
  EXPECT_FALSE(ex.state().run);
  EXPECT_TRUE(ex.state().finished);
  EXPECT_FALSE(ex.state().underrun || ex.state().discont || ex.state().fault);
  EXPECT_EQ(ex.state().vel, 0);
}

TEST(VelocityModeExec, AHoldEndsWhenTheFifoFillsAndAHoldRowThatAcceleratesIsAnOrdinaryRow) {
  // Constant-velocity rows without MOVE_END fill the FIFO: the hold ends
  // (the host could push nothing more); they run, then the FIFO runs dry.
  ProfileExec ex;
  const scurve::VelocityPlan up = plan_or_fail(0, 30000, 2e6, 4e8);
  start_and_ramp(ex, velocity_rows(up), up.ramp_clocks);
  ASSERT_TRUE(ex.holding());
  Row cruise{to_model(up.segments.back()), 0};
  cruise.seg.clocks = 1000;
  for (size_t k = 0; k + 1 < RowFifoDepth; ++k) push(ex, cruise);
  EXPECT_TRUE(ex.holding());
  push(ex, cruise);
  EXPECT_FALSE(ex.holding()) << "a full FIFO ends the hold";
  run(ex, 1000 * RowFifoDepth + 10);
  EXPECT_TRUE(ex.state().underrun) << "after the queued rows the FIFO ran dry while moving";

  // A HOLD row with a != 0 ends as any row: here into an empty FIFO while
  // moving, an underrun and the controlled stop.
  ProfileExec ex2;
  std::vector<Row> rows = velocity_rows(up);
  rows.back().seg.clocks = 5;
  rows.back().seg.jerk = 1;
  start_and_ramp(ex2, rows, up.ramp_clocks + 18);
  EXPECT_FALSE(ex2.holding());
  EXPECT_TRUE(ex2.state().underrun);
  EXPECT_TRUE(ex2.stopping() || !ex2.state().run);
}

namespace {

JogRequest random_program(std::mt19937_64& g, bool long_holds) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  JogRequest r;
  r.a_max = 1e6 * std::pow(10.0, u(g));
  r.j_max = r.a_max * 50 * std::pow(10.0, u(g));
  const int n = 2 + int(g() % 5);
  for (int i = 0; i < n; ++i) {
    JogCommand c;
    c.v_target = (u(g) < 0.15 ? 0.0 : 120000 * (2 * u(g) - 1));
    c.hold_s = (long_holds ? 0.02 : 0.004) * u(g);
    r.commands.push_back(c);
  }
  r.stop_at_end = u(g) < 0.5;
  if (!r.stop_at_end) r.commands.push_back({0, 0});
  r.push_gap = (u(g) < 0.3) ? uint64_t(g() % 3000) : 0;
  return r;
}

JogRunResult run_program(const JogRequest& r, SimEngine engine) {
  auto planned = plan_jog(r, PulseTiming{});
  if (const scurve::Error* e = std::get_if<scurve::Error>(&planned)) {
    ADD_FAILURE() << e->message;
    return {};
  }
  const auto codes = scurve::stop_limit_codes(r.j_max, r.a_max);
  const auto& c = std::get<scurve::StopLimitCodes>(codes);
  return run_jog(r, std::get<std::vector<scurve::VelocityPlan>>(planned), PulseTiming{}, engine, c.jerk, c.acc);
}

}  // namespace

TEST(VelocityModeLockstep, RandomJogProgramsMatchEveryClockHoldExactlyAndEndAtRestOrStopUnderControl) {
  std::mt19937_64 g(41);
  int stops = 0, commands = 0;
  for (int i = 0; i < 10; ++i) {
    const JogRequest req = random_program(g, false);
    const JogRunResult r = run_program(req, SimEngine::Lockstep);
    EXPECT_TRUE(r.pass()) << "program " << i << ": " << (r.failures.empty() ? "" : r.failures.front());
    EXPECT_EQ(r.mismatches, 0u);
    EXPECT_GT(r.matched_clocks, 0u);
    EXPECT_EQ(r.commands.size(), req.commands.size());
    stops += r.stopped;
    commands += int(r.commands.size());
  }
  EXPECT_GT(stops, 2);
  EXPECT_GT(commands, 30);
}

TEST(VelocityModeModel, FastForwardThroughLongHoldsEqualsTheClockByClockModel) {
  std::mt19937_64 g(42);
  for (int i = 0; i < 8; ++i) {
    const JogRequest req = random_program(g, true);
    const JogRunResult slow = run_program(req, SimEngine::ModelOnly);
    const JogRunResult fast = run_program(req, SimEngine::ModelFast);
    EXPECT_TRUE(slow.pass()) << (slow.failures.empty() ? "" : slow.failures.front());
    EXPECT_TRUE(fast.pass()) << (fast.failures.empty() ? "" : fast.failures.front());
    EXPECT_EQ(slow.end_position, fast.end_position) << "program " << i;
    EXPECT_EQ(slow.pulses, fast.pulses) << "program " << i;
    EXPECT_EQ(slow.clocks, fast.clocks) << "program " << i;
  }
}
