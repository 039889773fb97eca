// Limit switches through the whole register-level axis (sc_axi_axis: the
// switch filter, the register file and the core), RTL and model in lockstep
// every clock, against a switch model in the plant: a switch at a position
// on the pins' own count (the pin monitor, not the core's counters), with
// contact bounce of random length on every change of state.
//
// What is checked does not come from the RTL's algorithm: the stop happens
// past the switch by at most what the latency (bounce, debounce,
// synchroniser) and the closed-form stopping distance allow; the pins,
// PULSE_COUNT and REF_POS agree to the pulse; the flags and interrupts are
// set; a START further into the limit emits nothing; a move back off it
// runs to its exact end and the switch releases.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "axi_bench.h"
#include "board_regs.h"
#include "planner.h"
#include "random_moves.h"
#include "stop_check.h"
#include "switch_filter.h"
#include "switch_plant.h"

using namespace sc;
using namespace sc::board_test;

namespace {

using stopcheck::kF;
using stopcheck::kLsb;
using stopcheck::ld;

using scurve::test::log_uniform;

struct LimitCase {
  bool hard = false;
  bool invert = false;
  int debounce = 0;
  int bounce = 0;
  int dir = 1;
  int64_t distance = 0;
  int64_t at = 0;
  double stop_jerk = 0, stop_acc = 0;
  MoveRequest req;
};

// Runs the bench with the plant driving the pins until `done` or `limit` clocks.
template <class Done>
void run_with_plant(AxiBench& b, SwitchPlant& plant, int sw_bit, uint64_t limit, Done done) {
  const uint64_t t0 = b.clock();
  while (b.clock() - t0 < limit && !b.failed() && !done()) {
    b.side().sw_pins = uint8_t(plant.pin(b.net_steps()) ? 1u << sw_bit : 0u);
    b.tick();
  }
}

void run_limit_case(const LimitCase& c, uint32_t seed) {
  const std::string what = "distance " + std::to_string(c.distance) + ", switch at " + std::to_string(c.at) +
                           (c.hard ? ", hard" : ", controlled") + ", debounce " + std::to_string(c.debounce) +
                           ", bounce " + std::to_string(c.bounce) + (c.invert ? ", active low" : "");
  SCOPED_TRACE(what);
  const PulseTiming t{};
  const Plan p = plan_or_die(c.req, t);
  const int sw_bit = c.dir > 0 ? SwLimPos : SwLimNeg;
  const std::string err_flag = c.dir > 0 ? "LIMIT_POS" : "LIMIT_NEG";

  AxiBench b(true, seed);
  b.reset();
  SwitchPlant plant(c.at, c.dir, c.bounce, c.invert, seed);
  b.side().sw_pins = uint8_t(c.invert ? 1u << sw_bit : 0u);  // inactive at the start
  b.idle(4);
  const uint32_t sw_cfg = (c.invert ? uint32_t(1) << (SwInvertLsb + sw_bit) : 0) | field_mask("SW_CFG", "LIM_EN") |
                          (c.hard ? field_mask("SW_CFG", "LIM_HARD") : 0) |
                          (uint32_t(c.debounce) << SwDebounceLsb);
  ASSERT_EQ(b.write(reg_addr("SW_CFG"), sw_cfg), kOkay);
  ASSERT_EQ(b.write(reg_addr("CTRL"), field_mask("CTRL", "ENABLE")), kOkay);
  set_stop_limits(b, c.stop_jerk, c.stop_acc);
  // The inverted pin has settled through the filter (and raised SWITCH on
  // the way): start from clean flags.
  b.idle(uint64_t(c.debounce) + 8);
  ASSERT_EQ(b.write(reg_addr("IRQ_STATUS"), 0xffffffffu), kOkay);
  ASSERT_EQ(b.read(reg_addr("STATUS")).first & field_mask("STATUS", "SW_LEVEL"), 0u);
  load(b, p, t);
  ASSERT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);

  // Until the axis is at rest again.
  bool moved = false;
  run_with_plant(b, plant, sw_bit, p.total_clocks + 2'000'000, [&] {
    moved = moved || b.out().busy;
    return moved && !b.out().busy;
  });
  ASSERT_FALSE(b.failed()) << b.error();
  ASSERT_TRUE(moved);
  ASSERT_GE(plant.activations(), 1) << "the move never reached the switch";
  // Let the contact settle (the plant only runs in this loop, not during
  // the register reads below).
  run_with_plant(b, plant, sw_bit, uint64_t(c.bounce + c.debounce) + 10, [] { return false; });

  const int64_t end = b.net_steps();
  const int64_t overtravel = (end - c.at) * c.dir;
  // Latency from the switch position to the stop's first clock: the bounce,
  // the debounce, two synchroniser flops, the filter, the core's input
  // register and the executor's reaction.
  const ld latency = ld(c.bounce + c.debounce + 8);
  const ld v_peak = ld(p.peak_velocity), a_peak = ld(p.peak_acceleration);
  ld bound = v_peak * latency / kF + 2;
  if (!c.hard) {
    const stopcheck::ClosedForm cf = stopcheck::closed_form(
        v_peak * kLsb / kF, a_peak * kLsb / (kF * kF), ld(c.stop_jerk) * kLsb / (kF * kF * kF),
        ld(c.stop_acc) * kLsb / (kF * kF));
    bound += cf.dist / kLsb;
  }
  std::printf("[limit] %s: overtravel %lld pulses (bound %.1f)\n", what.c_str(), (long long)overtravel,
              double(bound));
  EXPECT_GE(overtravel, 0) << "stopped before the switch at " << end;
  EXPECT_LE(ld(overtravel), bound) << "stopped at " << end;
  EXPECT_LT(std::abs(end), std::abs(c.distance)) << "the limit did not stop the move";
  // Counts stay exact: the pins, the step counter and the reference agree.
  EXPECT_EQ(int32_t(b.read(reg_addr("PULSE_COUNT")).first), end);
  EXPECT_EQ(int32_t(b.read(reg_addr("REF_POS")).first), end);
  const uint32_t err = b.read(reg_addr("ERR")).first;
  EXPECT_EQ(err, field_mask("ERR", err_flag));
  const uint32_t status = b.read(reg_addr("STATUS")).first;
  EXPECT_EQ(status & field_mask("STATUS", "SW_LEVEL"), uint32_t(1) << (StatusSwLevelLsb + sw_bit));
  EXPECT_TRUE(status & field_mask("STATUS", "ERR"));
  EXPECT_FALSE(status & field_mask("STATUS", "DONE")) << "a stopped move is not done";
  const uint32_t irq = b.read(reg_addr("IRQ_STATUS")).first;
  EXPECT_TRUE(irq & field_mask("IRQ_STATUS", "FAULT"));
  EXPECT_TRUE(irq & field_mask("IRQ_STATUS", "SWITCH"));

  // Further into the limit: the START is taken by the register file and
  // refused by the core; nothing moves and the flag is set again.
  ASSERT_EQ(b.write(reg_addr("ERR"), 0xffffffffu), kOkay);
  ASSERT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "FLUSH")), kOkay);
  const Plan further = plan_or_die(scurve::test::move_request(100 * c.dir, 0, 5000, 0, 1e5, 1e7), t);
  load(b, further, t);
  ASSERT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
  run_with_plant(b, plant, sw_bit, 5000, [] { return false; });
  EXPECT_EQ(b.net_steps(), end) << "a move further into the limit ran";
  EXPECT_FALSE(b.out().busy);
  EXPECT_EQ(b.read(reg_addr("ERR")).first, field_mask("ERR", err_flag));

  // Back off the limit, past the switch: allowed, exact to the pulse, and
  // the switch releases.
  ASSERT_EQ(b.write(reg_addr("ERR"), 0xffffffffu), kOkay);
  ASSERT_EQ(b.write(reg_addr("IRQ_STATUS"), 0xffffffffu), kOkay);
  ASSERT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "FLUSH")), kOkay);
  const int64_t back = -(overtravel + 50) * c.dir;
  const Plan away = plan_or_die(scurve::test::move_request(back, 0, 20000, 0, 4e5, 4e7), t);
  load(b, away, t);
  ASSERT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
  moved = false;
  run_with_plant(b, plant, sw_bit, away.total_clocks + 200'000, [&] {
    moved = moved || b.out().busy;
    return moved && !b.out().busy;
  });
  run_with_plant(b, plant, sw_bit, uint64_t(c.bounce + c.debounce) + 10, [] { return false; });
  EXPECT_FALSE(b.failed()) << b.error();
  EXPECT_EQ(b.net_steps(), end + back);
  EXPECT_EQ(int32_t(b.read(reg_addr("PULSE_COUNT")).first), back) << "PULSE_COUNT restarts at START";
  EXPECT_EQ(b.read(reg_addr("ERR")).first, 0u);
  EXPECT_EQ(b.read(reg_addr("STATUS")).first & field_mask("STATUS", "SW_LEVEL"), 0u);
  EXPECT_TRUE(b.read(reg_addr("IRQ_STATUS")).first & field_mask("IRQ_STATUS", "SWITCH"));
  EXPECT_TRUE(b.read(reg_addr("STATUS")).first & field_mask("STATUS", "DONE"));
}

LimitCase random_case(std::mt19937_64& g, int i) {
  LimitCase c;
  c.dir = (i & 1) ? -1 : 1;
  c.hard = (i & 2) != 0;
  c.invert = g() % 3 == 0;
  c.debounce = int(g() % 3 == 0 ? 0 : g() % 400);
  c.bounce = int(g() % 4 == 0 ? 0 : g() % 300);
  for (;;) {
    const int64_t d = int64_t(2000 + g() % 18000);
    c.req = scurve::test::move_request(d * c.dir, 0, log_uniform(g, 5e3, 1.5e5), 0, log_uniform(g, 1e5, 2e6),
                                       log_uniform(g, 1e7, 2e9));
    const PlanResult r = plan_move(c.req, PulseTiming{});
    if (const Plan* p = std::get_if<Plan>(&r); p && p->total_clocks < 1'500'000) {
      c.distance = d * c.dir;
      break;
    }
  }
  // The switch inside the move, far enough from its end for the stop.
  c.at = c.distance / 10 + int64_t(g() % uint64_t(std::abs(c.distance) / 3)) * c.dir;
  c.stop_jerk = c.req.j_max * log_uniform(g, 1, 4);
  c.stop_acc = c.req.a_max * log_uniform(g, 1, 4);
  return c;
}

}  // namespace

TEST(LimitSwitch, RandomMovesIntoALimitStopPastTheSwitchWithinTheStopDistanceAndBackOffExactly) {
  std::mt19937_64 g(41);
  for (int i = 0; i < 8 && !::testing::Test::HasFatalFailure(); ++i) run_limit_case(random_case(g, i), uint32_t(100 + i));
}

// The filter model against its specification (the RTL is tied to the model
// by the lockstep tests above): a new level is taken after it held for
// debounce + 1 clocks past the synchroniser; a shorter pulse is ignored.
TEST(SwitchFilter, ALevelIsTakenAfterHoldingForTheDebouncePlusOneAndShorterPulsesAreIgnored) {
  for (uint32_t deb : {0u, 1u, 7u, 100u}) {
    SwitchFilter f;
    for (int i = 0; i < 5; ++i) f.step(0, 0, deb);
    // A pulse of deb clocks (and one of deb + 1) on bit 1.
    for (uint32_t width : {deb, deb + 1}) {
      if (width == 0) continue;
      uint32_t seen = 0;
      for (uint32_t k = 0; k < width + deb + 10; ++k) {
        f.step(k < width ? 2u : 0u, 0, deb);
        seen |= f.level();
      }
      EXPECT_EQ(seen != 0, width == deb + 1) << "debounce " << deb << ", pulse " << width;
      EXPECT_EQ(f.level(), 0u);
    }
    // A held level arrives debounce + 3 clocks after the pin (2 sync + 1 filter).
    int clocks = 0;
    while (f.level() == 0 && clocks < 1000) {
      f.step(4u, 0, deb);
      ++clocks;
    }
    EXPECT_EQ(clocks, int(deb) + 3) << "debounce " << deb;
    f.step(4u, 0, deb);
    EXPECT_EQ(f.level(), 4u);
    // Inverted: the pin high reads inactive.
    for (uint32_t k = 0; k < deb + 5; ++k) f.step(4u, 4u, deb);
    EXPECT_EQ(f.level(), 0u) << "debounce " << deb;
  }
}

namespace {

// One move over the latch's switch (clean contact) with the other latch
// input (home when the probe captures, the probe when home does) switching
// at a decoy position on the way: the pins' counts after every clock of the
// move and the clock the latch's pin first changed (-1: never).
struct LatchRun {
  std::vector<int64_t> count;  // pins' net steps after clock i of the run
  std::vector<int32_t> enc;    // the encoder input during clock i
  int64_t first_change = -1;
};

LatchRun run_over_switch(AxiBench& b, SwitchPlant& plant, SwitchPlant& decoy, int src_bit, int decoy_bit,
                         const Plan& p, bool want_active) {
  LatchRun r;
  load(b, p, PulseTiming{});
  EXPECT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
  bool moved = false, last_pin = !want_active;
  for (uint64_t i = 0; i < p.total_clocks + 400'000 && !b.failed(); ++i) {
    const int64_t pos = b.net_steps();
    const bool pin = plant.pin(pos);
    b.side().sw_pins = uint8_t((pin ? 1u << src_bit : 0u) | (decoy.pin(pos) ? 1u << decoy_bit : 0u));
    // An encoder input that changes every clock (3 counts per pulse plus a
    // clock stamp), so a capture one clock off reads a different value.
    const int32_t enc = int32_t(3 * pos + 7 * int64_t(r.count.size()) + 11);
    b.side().enc_pos = enc;
    r.enc.push_back(enc);
    if (pin != last_pin && r.first_change < 0) r.first_change = int64_t(r.count.size());
    last_pin = pin;
    b.tick();
    r.count.push_back(b.net_steps());
    moved = moved || b.out().busy;
    if (moved && !b.out().busy && i > 1000) break;
  }
  return r;
}

// The latch against the plant: with a clean contact the capture holds the
// counts of the clock the filtered level first shows the new state, which
// the filter's rule puts DEBOUNCE + 2 clocks after the first clock the pin
// shows it (two synchroniser flops, one of filtering; the register file
// takes it the next clock, with the encoder input of that next clock).
// The encoder input changes every clock, so a capture a clock early or late
// fails; the other input switches before it on the way out and after it on
// the way back, so a capture from the wrong input fails too.
void check_latch_on_both_edges(bool probe, uint64_t seed) {
  std::mt19937_64 g(seed);
  const int src_bit = probe ? SwProbe : SwHome, decoy_bit = probe ? SwHome : SwProbe;
  const uint32_t src = uint32_t(probe ? LatchSrcProbe : LatchSrcHome) << LatchSrcLsb;
  for (int i = 0; i < 4 && !::testing::Test::HasFatalFailure(); ++i) {
    const int dir = (i & 1) ? -1 : 1;
    const int debounce = int(g() % 3 == 0 ? 0 : g() % 500);
    const int64_t d = int64_t(1000 + g() % 3000) * dir;
    const int64_t at = d / 4 + int64_t(g() % uint64_t(std::abs(d) / 2)) * dir;
    const int64_t decoy_at = at / 2;  // crossed before the latch's switch out, after it back
    SCOPED_TRACE(std::string(probe ? "probe" : "home") + ": distance " + std::to_string(d) + ", switch at " +
                 std::to_string(at) + ", debounce " + std::to_string(debounce));
    AxiBench b(true, uint32_t(200 + i + (probe ? 10 : 0)));
    b.reset();
    SwitchPlant plant(at, dir, 0, false, uint64_t(i));
    SwitchPlant decoy(decoy_at, dir, 0, false, uint64_t(i + 100));
    ASSERT_EQ(b.write(reg_addr("SW_CFG"), field_mask("SW_CFG", "LIM_EN") | (uint32_t(debounce) << SwDebounceLsb)),
              kOkay);
    ASSERT_EQ(b.write(reg_addr("CTRL"), field_mask("CTRL", "ENABLE")), kOkay);
    ASSERT_EQ(b.write(reg_addr("LATCH_CFG"), field_mask("LATCH_CFG", "RISE") | src), kOkay);
    ASSERT_EQ(b.read(reg_addr("LATCH_CFG")).first, field_mask("LATCH_CFG", "RISE") | src);
    ASSERT_EQ(b.write(reg_addr("IRQ_STATUS"), 0xffffffffu), kOkay);
    const Plan out = plan_or_die(scurve::test::move_request(d, 0, log_uniform(g, 3e4, 1.5e5), 0, 1e6, 1e8));
    const LatchRun r1 = run_over_switch(b, plant, decoy, src_bit, decoy_bit, out, true);
    ASSERT_FALSE(b.failed()) << b.error();
    ASSERT_GE(r1.first_change, 0) << "the move never reached the switch";
    const size_t at1 = size_t(r1.first_change + debounce + 2);
    ASSERT_LT(at1, r1.count.size());
    EXPECT_TRUE(b.read(reg_addr("STATUS")).first & field_mask("STATUS", "LATCHED"));
    EXPECT_TRUE(b.read(reg_addr("IRQ_STATUS")).first & field_mask("IRQ_STATUS", "LATCH"));
    EXPECT_EQ(b.read(reg_addr("STATUS")).first & field_mask("STATUS", "SW_LEVEL"),
              (1u << (StatusSwLevelLsb + src_bit)) | (1u << (StatusSwLevelLsb + decoy_bit)))
        << "both inputs active at the end of the move";
    EXPECT_EQ(int32_t(b.read(reg_addr("LATCH_PULSE")).first), r1.count[at1]) << "rising edge";
    ASSERT_LT(at1 + 1, r1.enc.size());
    EXPECT_EQ(int32_t(b.read(reg_addr("LATCH_ENC")).first), r1.enc[at1 + 1]) << "rising edge";
    EXPECT_EQ(b.net_steps(), d);

    // Back over it: the release, after a re-arm on the falling edge.
    ASSERT_EQ(b.write(reg_addr("LATCH_CFG"), field_mask("LATCH_CFG", "FALL") | src), kOkay);
    EXPECT_FALSE(b.read(reg_addr("STATUS")).first & field_mask("STATUS", "LATCHED")) << "a write re-arms";
    const int64_t start2 = b.net_steps();
    const Plan back = plan_or_die(scurve::test::move_request(-d, 0, log_uniform(g, 3e4, 1.5e5), 0, 1e6, 1e8));
    const LatchRun r2 = run_over_switch(b, plant, decoy, src_bit, decoy_bit, back, false);
    ASSERT_FALSE(b.failed()) << b.error();
    ASSERT_GE(r2.first_change, 0);
    const size_t at2 = size_t(r2.first_change + debounce + 2);
    ASSERT_LT(at2, r2.count.size());
    EXPECT_EQ(int32_t(b.read(reg_addr("LATCH_PULSE")).first), r2.count[at2] - start2)
        << "falling edge (PULSE_COUNT restarts at START)";
    ASSERT_LT(at2 + 1, r2.enc.size());
    EXPECT_EQ(int32_t(b.read(reg_addr("LATCH_ENC")).first), r2.enc[at2 + 1]) << "falling edge";
    EXPECT_EQ(b.net_steps(), 0);
    std::printf("[latch] %s at %lld, debounce %d: rise latched at %lld, release at %lld\n", probe ? "probe" : "home",
                (long long)at, debounce, (long long)r1.count[at1], (long long)r2.count[at2]);
  }
}

}  // namespace

TEST(HomeLatch, CapturesTheCountsOfTheClockTheFilteredHomeEdgeArrivesOnBothEdges) {
  check_latch_on_both_edges(false, 7);
}

TEST(HomeLatch, WithProbeSelectedCapturesTheProbeEdgeNotHomes) { check_latch_on_both_edges(true, 8); }

// The open-loop axis takes the index as a level in step with its encoder
// input (enc_index_i, filtered outside, like enc_pos_i): with the encoder
// input changing every clock, a capture on Z rising holds the encoder value
// of the first clock Z is high, on Z falling of the first clock it is low;
// the home switch toggling at other clocks is not the source.
TEST(IndexLatch, OpenLoopAxisCapturesTheEncoderValueOfTheClockTheIndexLevelChanges) {
  std::mt19937_64 g(9);
  AxiBench b(true, 77);
  b.reset();
  ASSERT_EQ(b.write(reg_addr("SW_CFG"), field_mask("SW_CFG", "LIM_EN")), kOkay);  // DEBOUNCE 0
  uint64_t clk = 0;
  auto enc_of = [](uint64_t c) { return int32_t(7 * int64_t(c) + 11); };
  for (const bool rise : {true, false}) {
    const uint32_t cfg = field_mask("LATCH_CFG", rise ? "RISE" : "FALL") | (uint32_t(LatchSrcIndex) << LatchSrcLsb);
    ASSERT_EQ(b.write(reg_addr("LATCH_CFG"), cfg), kOkay);
    const uint64_t home_at = 50 + g() % 100, z_at = home_at + 20 + g() % 100;
    int32_t want = 0;
    for (uint64_t i = 0; i < z_at + 50; ++i, ++clk) {
      b.side().enc_pos = enc_of(clk);
      b.side().enc_z = (i >= z_at) == rise;
      b.side().sw_pins = uint8_t((i >= home_at) == rise ? 1u << SwHome : 0u);
      if (i == z_at) want = enc_of(clk);
      b.tick();
    }
    EXPECT_TRUE(b.read(reg_addr("STATUS")).first & field_mask("STATUS", "LATCHED"));
    EXPECT_EQ(int32_t(b.read(reg_addr("LATCH_ENC")).first), want) << (rise ? "Z rising" : "Z falling");
  }
  EXPECT_FALSE(b.failed()) << b.error();
}
