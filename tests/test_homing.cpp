// Homing (the host library's sequence, scurve::home) against the
// register-level axis with a home switch in the plant. What is checked does
// not come from the sequence: the zero against the plant's true release
// point of the switch, the pins against REF_POS, the lockstep comparer
// every clock.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <random>
#include <variant>
#include <vector>

#include "homing_run.h"
#include "random_moves.h"
#include "scurve/homing.h"
#include "scurve/hw/params.h"

using namespace sc;

namespace {

using scurve::test::log_uniform;

// A random homing: the switch 300 .. 1500 pulses from the start on a random
// side, a random seek speed, a latch speed within the exact bound.
HomingSimConfig random_homing(std::mt19937_64& g, int i, bool lockstep, uint32_t max_bounce) {
  HomingSimConfig c;
  c.lockstep = lockstep;
  c.seed = uint64_t(1000 + i);
  c.debounce = uint32_t(100 + g() % 400);
  c.bounce = max_bounce == 0 ? 0 : uint32_t(g() % (max_bounce + 1));
  scurve::HomingRequest& r = c.request;
  r.direction = (g() & 1) ? 1 : -1;
  r.seek_speed = log_uniform(g, 3e4, 1.5e5);
  r.latch_speed = std::min(r.seek_speed, scurve::exact_latch_speed(c.debounce, max_bounce) * 0.5);
  r.a_max = log_uniform(g, 5e6, 2e7);
  r.j_max = log_uniform(g, 5e9, 2e10);
  r.max_travel = 6000;
  r.max_backoff = 3000;
  r.offset = int64_t(g() % 2001) - 1000;
  r.poll_period = 1e-4;
  c.stop_jerk = r.j_max;
  c.stop_acc = r.a_max;
  c.switch_at = r.direction * int64_t(300 + g() % 1201);
  return c;
}

// A valid request with round numbers (for the checks and the scripted board).
scurve::HomingRequest plain_request() {
  scurve::HomingRequest r;
  r.seek_speed = 20000;
  r.latch_speed = 1000;
  r.a_max = 1e6;
  r.j_max = 1e9;
  r.max_travel = 10000;
  r.max_backoff = 1000;
  return r;
}

void expect_homed(const HomingSimResult& r) {
  EXPECT_TRUE(r.homed) << r.error;
  EXPECT_TRUE(r.error.empty()) << r.error;
  EXPECT_EQ(r.pins, r.ref_pos) << "pins and REF_POS disagree at rest";
}

std::vector<HomingSimResult> run_random(int n, bool lockstep, uint32_t max_bounce, uint64_t seed) {
  std::mt19937_64 g(seed);
  std::vector<HomingSimResult> runs;
  for (int i = 0; i < n && !::testing::Test::HasFailure(); ++i) {
    const HomingSimConfig c = random_homing(g, i, lockstep, max_bounce);
    runs.push_back(run_homing_sim(c));
    SCOPED_TRACE(::testing::Message() << "run " << i << ": switch at " << c.switch_at << ", seek "
                                      << c.request.seek_speed << " pulses/s, bounce " << c.bounce);
    expect_homed(runs.back());
  }
  return runs;
}

}  // namespace

TEST(Homing, HundredRandomHomingsOnTheModelLandOnTheSwitchReleaseExactly) {
  const auto runs = run_random(100, false, 0, 5);
  const HomingSummary s = summarize(runs);
  std::printf("%s", homing_table(runs).c_str());
  EXPECT_EQ(s.passed, 100u);
  // The zero is the plant's release point itself, every run: spread 0.
  EXPECT_EQ(s.zero_min, 0);
  EXPECT_EQ(s.zero_max, 0);
}

TEST(Homing, RandomHomingsInRtlLockstepLandOnTheSwitchReleaseExactly) {
  const auto runs = run_random(8, true, 0, 6);
  const HomingSummary s = summarize(runs);
  std::printf("%s", homing_table(runs).c_str());
  EXPECT_EQ(s.passed, runs.size());
  EXPECT_EQ(s.spread(), 0);
  EXPECT_EQ(s.zero_min, 0);
  for (const HomingSimResult& r : runs) EXPECT_EQ(r.matched_clocks, r.clocks);
}

TEST(Homing, ContactBounceShorterThanTheLatchSpeedAllowsKeepsTheZeroExact) {
  // Bounce up to 300 clocks on every change; the latch speed within the
  // exact bound for that bounce: still the release point, every run.
  const auto runs = run_random(30, false, 300, 7);
  const HomingSummary s = summarize(runs);
  std::printf("%s", homing_table(runs).c_str());
  EXPECT_EQ(s.passed, runs.size());
  EXPECT_EQ(s.spread(), 0);
  EXPECT_EQ(s.zero_min, 0);
}

TEST(Homing, NoiseGlitchesShorterThanTheDebounceAreReportedAsTheZerosSpread) {
  // Glitches restart the debounce count: the capture comes later and may
  // take a step more. The zero stays on the release side of the switch and
  // within the steps the latch speed makes in the delay.
  std::mt19937_64 g(8);
  std::vector<HomingSimResult> runs;
  for (int i = 0; i < 30 && !HasFailure(); ++i) {
    HomingSimConfig c = random_homing(g, i, false, 0);
    c.noise_rate = 2e-4;
    c.noise_clocks = 1 + uint32_t(g() % 20);
    runs.push_back(run_homing_sim(c));
    expect_homed(runs.back());
  }
  const HomingSummary s = summarize(runs);
  std::printf("%s", homing_table(runs).c_str());
  std::printf("[homing] with noise: zero error %lld .. %lld pulses, spread %lld\n", (long long)s.zero_min,
              (long long)s.zero_max, (long long)s.spread());
  uint64_t glitches = 0;
  for (const HomingSimResult& r : runs) glitches += r.glitches;
  EXPECT_GT(glitches, 0u) << "the noise never glitched";
  EXPECT_EQ(s.passed, runs.size());
  EXPECT_GE(s.zero_min, 0);
  EXPECT_LE(s.zero_max, 2);
}

TEST(Homing, StartingOnTheSwitchSkipsTheSeekAndFindsTheSameZero) {
  std::mt19937_64 g(9);
  HomingSimConfig c = random_homing(g, 0, true, 0);
  c.switch_at = c.request.direction * -200;  // the start is 200 pulses inside the switch
  const HomingSimResult r = run_homing_sim(c);
  expect_homed(r);
  EXPECT_TRUE(r.result.seek_skipped);
  EXPECT_EQ(r.zero_error, 0);
}

TEST(Homing, NoSwitchWithinMaxTravelIsAnErrorNamingItAndTheAxisIsAtRest) {
  std::mt19937_64 g(10);
  HomingSimConfig c = random_homing(g, 0, true, 0);
  c.request.max_travel = 200;
  c.switch_at = c.request.direction * 2000;
  const HomingSimResult r = run_homing_sim(c);
  EXPECT_FALSE(r.homed);
  EXPECT_NE(r.error.find("max_travel=200"), std::string::npos) << r.error;
  EXPECT_EQ(r.pins, int64_t(c.request.direction) * 200) << "the seek ran its full travel, exactly";
  EXPECT_EQ(r.matched_clocks, r.clocks);
}

TEST(Homing, BadRequestsAreRefusedNamingTheField) {
  const scurve::PulseTiming t{};
  const scurve::HomingRequest ok = plain_request();
  EXPECT_FALSE(scurve::check_homing_request(ok, t).has_value());
  struct Bad {
    const char* field;
    void (*mutate)(scurve::HomingRequest&);
  };
  const Bad bad[] = {
      {"direction", [](scurve::HomingRequest& r) { r.direction = 0; }},
      {"seek_speed", [](scurve::HomingRequest& r) { r.seek_speed = -1; }},
      {"seek_speed", [](scurve::HomingRequest& r) { r.seek_speed = 1e9; }},
      {"seek_speed", [](scurve::HomingRequest& r) { r.seek_speed = NAN; }},
      {"latch_speed", [](scurve::HomingRequest& r) { r.latch_speed = 30000; }},
      {"latch_speed", [](scurve::HomingRequest& r) { r.latch_speed = 0; }},
      {"max_travel", [](scurve::HomingRequest& r) { r.max_travel = 0; }},
      {"max_backoff", [](scurve::HomingRequest& r) { r.max_backoff = -5; }},
      {"max_index_travel", [](scurve::HomingRequest& r) { r.max_index_travel = -1; }},
      {"poll_period", [](scurve::HomingRequest& r) { r.poll_period = 0; }},
      {"offset", [](scurve::HomingRequest& r) { r.offset = INT64_MAX; }},
      {"a_max", [](scurve::HomingRequest& r) { r.a_max = -1; }},
      {"j_max", [](scurve::HomingRequest& r) { r.j_max = 0; }},
  };
  for (const Bad& b : bad) {
    scurve::HomingRequest r = ok;
    b.mutate(r);
    const auto e = scurve::check_homing_request(r, t);
    ASSERT_TRUE(e.has_value()) << b.field;
    EXPECT_EQ(e->parameter, b.field) << e->message;
    EXPECT_NE(e->message.find(b.field), std::string::npos) << e->message;
  }
}

// The sequence against a scripted board: the switch already active (no
// seek), the back-off latching at once. CTRL.CLOSED_LOOP, read at the start,
// is kept in every CTRL write (the closed-loop axis homes in its mode), and
// the zero is the back-off's start plus LATCH_PULSE.
TEST(Homing, KeepsTheClosedLoopModeAndTakesTheZeroFromTheLatchOnAScriptedBoard) {
  namespace hw = scurve::hw;
  struct ScriptedPort : scurve::RegisterPort {
    uint32_t ctrl = (1u << hw::CtrlEnableBit) | (1u << hw::CtrlClosedBit);
    std::vector<uint32_t> ctrl_writes;
    int polls_since_start = -1;  // -1: no move started
    std::optional<scurve::Error> write(uint32_t addr, uint32_t data) override {
      if (addr == uint32_t(hw::RegCtrl)) {
        ctrl = data;
        ctrl_writes.push_back(data);
      }
      if (addr == uint32_t(hw::RegCmd) && (data & (1u << hw::CmdStartBit))) polls_since_start = 0;
      return std::nullopt;
    }
    std::variant<uint32_t, scurve::Error> read(uint32_t addr) override {
      if (addr == uint32_t(hw::RegCtrl)) return ctrl;
      if (addr == uint32_t(hw::RegRefPos)) return 100u;
      if (addr == uint32_t(hw::RegLatchPulse)) return 7u;
      if (addr == uint32_t(hw::RegErr)) return 0u;
      uint32_t st = polls_since_start < 0 ? (1u << (hw::StatusSwLevelLsb + hw::SwHome)) : 0u;
      if (polls_since_start >= 0) {
        st |= 1u << hw::StatusLatchedBit;
        if (polls_since_start++ == 0) st |= 1u << hw::StatusBusyBit;
      }
      return st;
    }
    void wait(double) override {}
  } port;
  scurve::HomingRequest r = plain_request();
  r.offset = 50;
  const scurve::HomingOutcome o = scurve::home(port, r, scurve::PulseTiming{});
  ASSERT_TRUE(std::holds_alternative<scurve::HomingResult>(o)) << std::get<scurve::Error>(o).message;
  const scurve::HomingResult& h = std::get<scurve::HomingResult>(o);
  EXPECT_TRUE(h.seek_skipped);
  EXPECT_EQ(h.home_ref, 107);
  EXPECT_EQ(h.machine_position(107), 50);
  ASSERT_FALSE(port.ctrl_writes.empty());
  for (uint32_t c : port.ctrl_writes) EXPECT_TRUE(c & (1u << hw::CtrlClosedBit)) << "CTRL written without CLOSED_LOOP";
}

// Switch plus index: after the release, the axis creeps on to the encoder's
// index (one index every 2000 counts, fixed on the shaft). With the switch
// at random places (within a quarter revolution), contact bounce beyond the
// exact latch speed and noise, every run's zero is the same index count,
// exactly; LATCH_ENC is that count (checked by the bench against its own
// encoder). The same runs without the index show the switch's spread.
TEST(Homing, OnTheIndexEveryRunFindsTheSameIndexCountWhateverTheSwitchDoes) {
  constexpr int64_t kPeriod = 2000;
  std::mt19937_64 g(31);
  std::vector<HomingSimResult> on_index, on_switch;
  for (int i = 0; i < 16 && !::testing::Test::HasFailure(); ++i) {
    const bool lockstep = i < 2;
    HomingSimConfig c = random_homing(g, i, lockstep, 1500);
    c.request.direction = -1;
    c.switch_at = -int64_t(1000 + g() % 500);
    c.noise_rate = 2e-5;
    c.noise_clocks = 20;
    c.request.latch_speed = c.request.seek_speed / 4;  // beyond the exact bound: the switch alone wanders
    c.index_period = kPeriod;
    c.index_at = -1250 + kPeriod / 2;  // half a revolution past the switches' middle
    c.request.max_index_travel = kPeriod;
    SCOPED_TRACE(::testing::Message() << "run " << i << ": switch at " << c.switch_at << ", bounce " << c.bounce);
    on_index.push_back(run_homing_sim(c));
    expect_homed(on_index.back());
    EXPECT_TRUE(on_index.back().result.on_index);
    EXPECT_EQ(on_index.back().result.home_ref, *c.index_at) << "the zero is the index on the shaft";
    EXPECT_EQ(on_index.back().result.index_enc, *c.index_at);
    c.request.max_index_travel = 0;
    c.lockstep = false;
    on_switch.push_back(run_homing_sim(c));
  }
  const HomingSummary si = summarize(on_index), ss = summarize(on_switch);
  std::printf("%s", homing_table(on_index).c_str());
  std::printf("[homing] on the index: spread %lld pulses over %zu runs; on the switch alone: spread %lld\n",
              (long long)si.spread(), si.runs, (long long)ss.spread());
  EXPECT_EQ(si.passed, si.runs);
  EXPECT_EQ(si.zero_min, 0);
  EXPECT_EQ(si.zero_max, 0);
}

// An index farther than max_index_travel: an error naming it.
TEST(Homing, NoIndexWithinMaxIndexTravelIsAnErrorNamingIt) {
  std::mt19937_64 g(32);
  HomingSimConfig c = random_homing(g, 0, false, 0);
  c.index_period = 4000;  // the index half a revolution (2000 pulses) past the release
  c.request.max_index_travel = 500;
  const HomingSimResult r = run_homing_sim(c);
  EXPECT_FALSE(r.homed);
  EXPECT_NE(r.error.find("max_index_travel"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("no encoder index"), std::string::npos) << r.error;
}

TEST(HomingLong, HundredRandomHomingsInRtlLockstepLandOnTheSwitchReleaseExactly) {
  const auto runs = run_random(100, true, 0, 11);
  const HomingSummary s = summarize(runs);
  std::printf("%s", homing_table(runs).c_str());
  EXPECT_EQ(s.passed, 100u);
  EXPECT_EQ(s.spread(), 0);
  EXPECT_EQ(s.zero_min, 0);
}
