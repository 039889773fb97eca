// Register-level tests of the closed-loop axis behind the AXI4-Lite slave
// (sc_axi_servo = sc_axi_regs with the controller-settings words +
// sc_servo_axis), RTL and model (AxiServo) compared every clock:
// controller settings written and read back (reset = the closed-loop
// runner's defaults, reserved bits, access types, locked while busy) and a
// short closed-loop move loaded over AXI with the stepper/encoder plant.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "axi_bench.h"
#include "board_regs.h"
#include "closed_loop_run.h"
#include "planner.h"
#include "reg_encode.h"
#include "sc_regmap.h"

using namespace sc;
using namespace sc::board_test;

namespace {

// The controller-settings registers, in cfg-word order.
std::vector<const regmap::Reg*> settings() {
  std::vector<const regmap::Reg*> v;
  for (const regmap::Reg& r : regmap::kRegs)
    if (r.servo && r.access == regmap::Access::RW) v.push_back(&r);
  return v;
}

MoveRequest cl_move(int64_t distance) { return scurve::test::move_request(distance, 0, 4000, 0, 100000, 4e6); }

}  // namespace

// Reset values are the closed-loop runner's defaults (ControllerParams{},
// PlantConfig{}, PulseTiming{}), every register answers OKAY with its
// reserved bits 0, RW registers hold exactly their implemented bits, RO
// ones refuse writes, and the unmapped addresses answer DECERR.
TEST(AxiServo, ControllerSettingsResetReadBackAndAccessTypes) {
  AxiServoBench b(true, 31);
  b.set_jitter(true);
  const auto words = settings();
  ASSERT_EQ(int(words.size()), ClCfgWords);
  for (size_t i = 0; i < words.size(); ++i) EXPECT_EQ(words[i]->addr, uint32_t(RegClFirst + 4 * int(i)));

  ServoConfig want;
  ASSERT_EQ(to_servo_config(ControllerParams{}, PlantConfig{}, PulseTiming{}, want), "");
  const ServoConfig have = AxiServo::decode_config(true, true, PulseTiming{}, b.model().regs().state().cl);
  EXPECT_TRUE(have == want) << "register reset values differ from the closed-loop runner's defaults";

  for (const regmap::Reg& r : regmap::kRegs) {
    expect_reset_read(b, r);
  }
  for (const regmap::Reg& r : regmap::kRegs) {
    if (!r.servo) continue;
    if (r.access == regmap::Access::RW) {
      EXPECT_EQ(b.write(r.addr, 0xffffffffu), kOkay) << r.name;
      EXPECT_EQ(b.read(r.addr).first, r.mask) << r.name;
      EXPECT_EQ(b.write(r.addr, 0x5a5a5a5au), kOkay) << r.name;
      EXPECT_EQ(b.read(r.addr).first, 0x5a5a5a5au & r.mask) << r.name;
      EXPECT_EQ(b.write(r.addr, r.reset), kOkay) << r.name;
    } else {
      EXPECT_EQ(b.write(r.addr, 0xffffffffu), kSlvErr) << r.name << ": write to a read-only register";
      EXPECT_TRUE(b.read(reg_addr("ERR")).first & field_mask("ERR", "BAD_ACCESS"));
      EXPECT_EQ(b.write(reg_addr("ERR"), field_mask("ERR", "BAD_ACCESS")), kOkay);
    }
  }
  // byte strobes on a settings word
  EXPECT_EQ(b.write(reg_addr("K_P"), 0x00112233u), kOkay);
  EXPECT_EQ(b.write(reg_addr("K_P"), 0xffaabbccu, 0x2), kOkay);
  EXPECT_EQ(b.read(reg_addr("K_P")).first, 0x0011bb33u);
  // CTRL.CLOSED_LOOP
  EXPECT_EQ(b.write(reg_addr("CTRL"), field_mask("CTRL", "ENABLE") | field_mask("CTRL", "CLOSED_LOOP")), kOkay);
  EXPECT_EQ(b.read(reg_addr("CTRL")).first, 3u);
  // everything else in the 1 KiB window answers DECERR (nothing above
  // 0x0FC aliases the map below it)
  int illegal = 0;
  for (uint32_t a = 0; a < (1u << RegAddrW); ++a) {
    bool mapped = false;
    for (const regmap::Reg& r : regmap::kRegs) mapped = mapped || r.addr == a;
    if (mapped) continue;
    ++illegal;
    EXPECT_EQ(b.read(a).second, kDecErr) << std::hex << a;
    EXPECT_EQ(b.write(a, 0xffffffffu), kDecErr) << std::hex << a;
  }
  EXPECT_EQ(illegal, (1 << RegAddrW) - regmap::kNumRegs);
  EXPECT_FALSE(b.failed()) << b.error();
  EXPECT_GT(b.matched(), 1000u);
}

// A closed-loop move loaded over AXI: controller settings written (the
// runner's defaults), CTRL.CLOSED_LOOP, the table,
// START; ENC_POS / FOLLOW_ERR / CTL_* read while it runs; writes to the
// settings and a CLOSED_LOOP change while busy refused and flagged; done
// in position with final error 0.
TEST(AxiServo, ClosedLoopMoveOverAxiWithPlant) {
  const int64_t L = 400;
  const Plan p = plan_or_die(cl_move(L));
  AxiServoBench b(true, 32);
  b.set_jitter(true);
  b.attach_plant(PlantConfig{});
  // settings through the bus (as a host would): the runner's defaults. (With
  // a 2 ms in-position hold this move can hunt +-2 counts around L after the
  // reference is done, depending on START's clock: see the report.)
  ServoConfig cfg;
  const ControllerParams cp;
  ASSERT_EQ(to_servo_config(cp, PlantConfig{}, PulseTiming{}, cfg), "");
  for (const RegWrite& w : encode_servo_config(cfg)) ASSERT_EQ(b.write(w.addr, w.data), kOkay) << reg_name(w.addr);
  EXPECT_EQ(b.read(reg_addr("CL_PERIOD")).first >> ClInposHoldLsb, uint32_t(cfg.ctl.inpos_hold));
  EXPECT_TRUE(AxiServo::decode_config(true, true, PulseTiming{}, b.model().regs().state().cl) == cfg)
      << "encode_servo_config / decode_config round trip";
  for (const RegWrite& w : encode_move(p, PulseTiming{}, false)) ASSERT_EQ(b.write(w.addr, w.data), kOkay) << reg_name(w.addr);
  const uint32_t ctrl = field_mask("CTRL", "ENABLE") | field_mask("CTRL", "CLOSED_LOOP");
  ASSERT_EQ(b.write(reg_addr("CTRL"), ctrl), kOkay);
  ASSERT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
  b.idle(20000);
  ASSERT_TRUE(b.out().busy);

  // refused while busy: settings, the loop mode; CTRL keeping the mode is fine
  for (const char* n : {"K_P", "CL_CFG", "CL_PERIOD", "W_V2_MAX", "SETTLE_RATE"}) {
    const uint32_t before = b.read(reg_addr(n)).first;
    EXPECT_EQ(b.write(reg_addr(n), 0), kSlvErr) << n << " written while busy";
    EXPECT_EQ(b.read(reg_addr(n)).first, before) << n;
    EXPECT_TRUE(b.read(reg_addr("ERR")).first & field_mask("ERR", "REJECT")) << n;
    EXPECT_EQ(b.write(reg_addr("ERR"), field_mask("ERR", "REJECT")), kOkay);
  }
  EXPECT_EQ(b.write(reg_addr("CTRL"), field_mask("CTRL", "ENABLE")), kSlvErr) << "CLOSED_LOOP changed while busy";
  EXPECT_EQ(b.read(reg_addr("CTRL")).first, ctrl);
  EXPECT_EQ(b.write(reg_addr("ERR"), field_mask("ERR", "REJECT")), kOkay);
  EXPECT_EQ(b.write(reg_addr("CTRL"), ctrl), kOkay);

  // observe the loop while it moves
  int32_t max_ferr = 0, last_enc = 0;
  bool saw_u = false, saw_active = false, done = false;
  const uint64_t t0 = b.clock();
  while (!done && b.clock() - t0 < p.total_clocks + 2 * uint64_t(ClkHz) && !b.failed()) {
    const int32_t enc = int32_t(b.read(reg_addr("ENC_POS")).first);
    const int32_t ferr = int32_t(b.read(reg_addr("FOLLOW_ERR")).first);
    const int32_t ref = int32_t(b.read(reg_addr("REF_POS")).first);
    EXPECT_LE(std::abs(ref - enc - ferr), 40) << "FOLLOW_ERR far from REF_POS - ENC_POS";
    max_ferr = std::max(max_ferr, std::abs(ferr));
    EXPECT_GE(enc, last_enc - 2) << "encoder ran backwards";
    last_enc = enc;
    saw_u = saw_u || b.read(reg_addr("CTL_U")).first != 0;
    const uint32_t cs = b.read(reg_addr("CL_STATUS")).first;
    saw_active = saw_active || (cs & field_mask("CL_STATUS", "CTL_ACTIVE"));
    EXPECT_FALSE(cs & field_mask("CL_STATUS", "FAULT_FERR"));
    done = b.read(reg_addr("STATUS")).first & field_mask("STATUS", "DONE");
    b.idle(5000);
  }
  ASSERT_TRUE(done) << "no DONE (in position): ENC_POS " << int32_t(b.read(reg_addr("ENC_POS")).first) << " FOLLOW_ERR "
                    << int32_t(b.read(reg_addr("FOLLOW_ERR")).first) << " STATUS 0x" << std::hex
                    << b.read(reg_addr("STATUS")).first << " CL_STATUS 0x" << b.read(reg_addr("CL_STATUS")).first
                    << " ERR 0x" << b.read(reg_addr("ERR")).first << " max_ferr " << std::dec << max_ferr
                    << " plant count " << b.plant()->count() << " commanded " << b.plant()->commanded();
  EXPECT_TRUE(saw_u);
  EXPECT_TRUE(saw_active);
  EXPECT_GT(max_ferr, 0);
  EXPECT_LT(max_ferr, 30) << "following error";
  const uint32_t st = b.read(reg_addr("STATUS")).first;
  EXPECT_TRUE(st & field_mask("STATUS", "IN_POS"));
  EXPECT_FALSE(st & field_mask("STATUS", "FAULT_FERR"));
  EXPECT_EQ(st & field_mask("STATUS", "PHASE"), uint32_t(Phase::PhDone));
  EXPECT_EQ(int32_t(b.read(reg_addr("ENC_POS")).first), L);
  EXPECT_EQ(int32_t(b.read(reg_addr("FOLLOW_ERR")).first), 0);
  EXPECT_EQ(int32_t(b.read(reg_addr("REF_POS")).first), L);
  EXPECT_EQ(b.read(reg_addr("CL_STATUS")).first & field_mask("CL_STATUS", "IN_POS"), field_mask("CL_STATUS", "IN_POS"));
  EXPECT_EQ(b.read(reg_addr("CL_STATUS")).first & field_mask("CL_STATUS", "ENC_ILLEGAL"), 0u);
  EXPECT_GT(int32_t(b.read(reg_addr("CTL_W_P1")).first), 0) << "w_p1 learns up from 0";
  EXPECT_EQ(b.read(reg_addr("ERR")).first, 0u);
  EXPECT_EQ(b.plant()->count(), L);
  EXPECT_EQ(b.net_steps(), b.plant()->commanded());
  // settings writable again once idle
  EXPECT_EQ(b.write(reg_addr("K_P"), 1234), kOkay);
  EXPECT_EQ(b.read(reg_addr("K_P")).first, 1234u);
  EXPECT_FALSE(b.failed()) << b.error();
  EXPECT_GT(b.matched(), p.total_clocks);
  std::printf("closed loop over AXI: L=%lld, %llu clocks matched, max |FOLLOW_ERR| %d\n", (long long)L,
              (unsigned long long)b.matched(), max_ferr);
}

// A following-error fault over the registers (FERR_LIM below what the loop
// lags on this move, CL_CFG.FERR_STOP): the reference stops under control,
// the counts are kept (pins = PULSE_COUNT, the plant's count = ENC_POS),
// STATUS.FAULT_FERR, CL_STATUS.FAULT_FERR and IRQ_STATUS.FAULT are set;
// the documented recovery - a wider limit, the move to the target again,
// START (which clears the fault) - ends in position on the target.
TEST(AxiServo, FollowingErrorFaultStopsUnderControlKeepsTheCountsAndRecoversAtTheNextStart) {
  const int64_t L = 600;
  const PulseTiming t{};
  AxiServoBench b(true, 33);
  b.attach_plant(PlantConfig{});
  ControllerParams cp;
  cp.ferr_lim = 1.0;
  cp.ferr_stop = true;
  ServoConfig cfg;
  ASSERT_EQ(to_servo_config(cp, PlantConfig{}, t, cfg), "");
  for (const RegWrite& w : encode_servo_config(cfg)) ASSERT_EQ(b.write(w.addr, w.data), kOkay) << reg_name(w.addr);
  set_stop_limits(b, 4e6, 1e5);
  load(b, plan_or_die(cl_move(L)), t);
  const uint32_t ctrl = field_mask("CTRL", "ENABLE") | field_mask("CTRL", "CLOSED_LOOP");
  ASSERT_EQ(b.write(reg_addr("CTRL"), ctrl), kOkay);
  ASSERT_EQ(b.write(reg_addr("IRQ_STATUS"), 0xffffffffu), kOkay);
  ASSERT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
  bool fault = false;
  for (int i = 0; i < 400 && !b.failed() && !fault; ++i) {
    b.idle(5000);
    fault = b.read(reg_addr("STATUS")).first & field_mask("STATUS", "FAULT_FERR");
  }
  ASSERT_TRUE(fault) << "no following-error fault with FERR_LIM = 1 count";
  EXPECT_TRUE(b.read(reg_addr("CL_STATUS")).first & field_mask("CL_STATUS", "FAULT_FERR"));
  EXPECT_TRUE(b.read(reg_addr("IRQ_STATUS")).first & field_mask("IRQ_STATUS", "FAULT"));
  // The controlled stop, then the loop settles where the reference rested.
  for (int i = 0; i < 400 && !b.failed() && b.out().busy; ++i) b.idle(5000);
  ASSERT_FALSE(b.out().busy);
  b.idle(20000);
  const int32_t ref = int32_t(b.read(reg_addr("REF_POS")).first);
  EXPECT_GT(ref, 0);
  EXPECT_LT(ref, L) << "the fault did not stop the reference";
  EXPECT_EQ(int32_t(b.read(reg_addr("PULSE_COUNT")).first), b.net_steps()) << "a step lost or invented";
  EXPECT_EQ(int32_t(b.read(reg_addr("ENC_POS")).first), b.plant()->count());
  EXPECT_EQ(b.net_steps(), b.plant()->commanded());
  EXPECT_FALSE(b.read(reg_addr("STATUS")).first & field_mask("STATUS", "DONE")) << "a faulted move is not done";

  // Recovery: the default limit, the rest of the way, START.
  cp.ferr_lim = ControllerParams{}.ferr_lim;
  ASSERT_EQ(to_servo_config(cp, PlantConfig{}, t, cfg), "");
  for (const RegWrite& w : encode_servo_config(cfg)) ASSERT_EQ(b.write(w.addr, w.data), kOkay) << reg_name(w.addr);
  ASSERT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "FLUSH")), kOkay);
  const Plan rest = plan_or_die(cl_move(L - ref));
  load(b, rest, t);
  ASSERT_EQ(b.write(reg_addr("CTRL"), ctrl), kOkay);
  ASSERT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
  b.idle(1000);  // past the DIR setup: the loop restarts with the reference
  EXPECT_FALSE(b.read(reg_addr("STATUS")).first & field_mask("STATUS", "FAULT_FERR")) << "START clears the fault";
  bool done = false;
  const uint64_t t0 = b.clock();
  while (!done && !b.failed() && b.clock() - t0 < rest.total_clocks + 2 * uint64_t(ClkHz)) {
    b.idle(5000);
    done = b.read(reg_addr("STATUS")).first & field_mask("STATUS", "DONE");
  }
  ASSERT_TRUE(done) << "no DONE after the recovery";
  EXPECT_EQ(int32_t(b.read(reg_addr("REF_POS")).first), L);
  EXPECT_EQ(int32_t(b.read(reg_addr("ENC_POS")).first), L);
  EXPECT_EQ(b.plant()->count(), L);
  EXPECT_FALSE(b.failed()) << b.error();
}

// The position latch on the encoder index, open and closed loop, both
// directions: the plant's encoder has an index (Z high in one quadrature
// state every 97 counts, at a random place). Armed on Z rising, the latch
// holds the count the plant's encoder showed when Z rose (the first rising
// edge on the pins after arming, found from the plant, not the RTL), which
// is an index state; PULSE_COUNT is taken in the clock the decoder shows Z
// (two synchroniser flops and CL_CFG.ENC_FILT + 1 filter clocks after the
// pin). Armed on Z falling, a move back latches the count Z left.
TEST(AxiServo, IndexLatchHoldsTheEncoderCountOfTheIndexStateInBothDirectionsAndModes) {
  constexpr int64_t kPeriod = 97;
  const PulseTiming t{};
  std::mt19937_64 g(23);
  for (int c = 0; c < 4; ++c) {
    const bool closed = c >= 2;
    const int dir = (c & 1) ? -1 : 1;
    PlantConfig pc;
    pc.index_period = kPeriod;
    pc.index_at = int64_t(g() % kPeriod);
    const int64_t d = dir * int64_t(150 + g() % 150);
    SCOPED_TRACE(std::string(closed ? "closed" : "open") + " loop, distance " + std::to_string(d) + ", index at " +
                 std::to_string(pc.index_at));
    AxiServoBench b(true, uint32_t(40 + c));
    b.attach_plant(pc);
    uint32_t ctrl = field_mask("CTRL", "ENABLE");
    int filt = RstEncFilt;
    if (closed) {
      ServoConfig cfg;
      ASSERT_EQ(to_servo_config(ControllerParams{}, pc, t, cfg), "");
      for (const RegWrite& w : encode_servo_config(cfg)) ASSERT_EQ(b.write(w.addr, w.data), kOkay) << reg_name(w.addr);
      ctrl |= field_mask("CTRL", "CLOSED_LOOP");
      filt = int(cfg.ctl.enc_filt);
    }
    for (int leg = 0; leg < 2; ++leg) {
      const bool rise = leg == 0;
      const uint32_t cfg_word = field_mask("LATCH_CFG", rise ? "RISE" : "FALL") |
                                (uint32_t(LatchSrcIndex) << LatchSrcLsb);
      ASSERT_EQ(b.write(reg_addr("LATCH_CFG"), cfg_word), kOkay);
      ASSERT_EQ(b.read(reg_addr("LATCH_CFG")).first, cfg_word);
      const int32_t pulse0 = int32_t(b.net_steps());
      load(b, plan_or_die(cl_move(rise ? d : -d)), t);
      ASSERT_EQ(b.write(reg_addr("CTRL"), ctrl), kOkay);
      ASSERT_EQ(b.write(reg_addr("CMD"), field_mask("CMD", "START")), kOkay);
      // clock by clock: the pins' Z and count, the steps after each clock
      std::vector<int64_t> net;
      int64_t edge_clock = -1, edge_count = 0;
      bool last_z = b.plant()->enc_z(), moved = false;
      for (uint64_t i = 0; i < 4'000'000 && !b.failed(); ++i) {
        const bool z = b.plant()->enc_z();
        if (edge_clock < 0 && z != last_z && z == rise) {
          edge_clock = int64_t(net.size());
          edge_count = b.plant()->count();
        }
        last_z = z;
        b.tick();
        net.push_back(b.net_steps());
        moved = moved || b.out().busy;
        if (moved && !b.out().busy && edge_clock >= 0 && net.size() > size_t(edge_clock) + 100) break;
      }
      ASSERT_FALSE(b.failed()) << b.error();
      ASSERT_GE(edge_clock, 0) << "the move crossed no index";
      // rising: the index state itself; falling: one count off it (either side: the rotor rings)
      const int64_t off = ((edge_count - pc.index_at) % kPeriod + kPeriod) % kPeriod;
      if (rise) {
        EXPECT_EQ(off, 0) << "Z rose at " << edge_count;
      } else {
        EXPECT_TRUE(off == 1 || off == kPeriod - 1) << "Z fell at " << edge_count;
      }
      EXPECT_TRUE(b.read(reg_addr("STATUS")).first & field_mask("STATUS", "LATCHED"));
      EXPECT_EQ(int32_t(b.read(reg_addr("LATCH_ENC")).first), edge_count) << (rise ? "rising" : "falling") << " edge";
      const size_t at = size_t(edge_clock + 2 + filt);
      ASSERT_LT(at, net.size());
      EXPECT_EQ(int32_t(b.read(reg_addr("LATCH_PULSE")).first), int32_t(net[at]) - pulse0)
          << "PULSE_COUNT of the clock the decoder shows Z (it restarts at START)";
      std::printf("[index] %s loop: Z %s at count %lld, PULSE_COUNT %d\n", closed ? "closed" : "open",
                  rise ? "rose" : "fell", (long long)edge_count, int32_t(net[at]) - pulse0);
    }
  }
}

// Open loop through the same wrapper (CTRL.CLOSED_LOOP = 0): exact pulses.
TEST(AxiServo, OpenLoopModeEmitsExactPulses) {
  const Plan p = plan_or_die(cl_move(300));
  AxiServoBench b(true, 33);
  b.attach_plant(PlantConfig{});
  for (const RegWrite& w : encode_move(p, PulseTiming{}, true)) ASSERT_EQ(b.write(w.addr, w.data), kOkay);
  const uint64_t t0 = b.clock();
  while (!b.out().done && b.clock() - t0 < p.total_clocks + 200000 && !b.failed()) b.idle(1000);
  EXPECT_TRUE(b.out().done);
  EXPECT_EQ(b.net_steps(), 300);
  EXPECT_EQ(int32_t(b.read(reg_addr("PULSE_COUNT")).first), 300);
  EXPECT_FALSE(b.read(reg_addr("STATUS")).first & field_mask("STATUS", "IN_POS"));
  EXPECT_FALSE(b.failed()) << b.error();
}

// The checker must be able to fail: one flipped encoder sample in the model.
TEST(AxiServo, CheckerCatchesAnInjectedDifference) {
  AxiServoBench b(true, 34);
  b.idle(100);
  EXPECT_FALSE(b.failed());
  b.inject_model_fault();
  b.idle(20);
  b.read(reg_addr("ENC_POS"));
  ASSERT_TRUE(b.failed());
  EXPECT_EQ(b.error().rfind("clock ", 0), 0u) << b.error();
  EXPECT_NE(b.error().find(" signal enc_pos_o: rtl=0x"), std::string::npos) << b.error();
}
