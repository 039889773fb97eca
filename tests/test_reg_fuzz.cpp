// Register fuzzing: random AXI4-Lite transaction sequences against the
// register-level axis (sc_axi_axis), and random byte streams into the UART
// bridge of the board top.
//
// The AXI sequences mix everything a host (or a bug in one) can do: writes
// to any address (documented registers, free words, unaligned and
// out-of-map addresses) with random data and strobes, random reads, random
// bus timing, valid moves with START, hostile rows (random staging values
// and flags), CMD.START / STOP / ESTOP / FLUSH at any time, random guard and
// stop limits, and switch inputs toggling. What must hold, checked every
// clock by the bench and not taken from the RTL's algorithm:
//   * every transaction gets its response (the master fails on a bus hang);
//   * the pins keep the pulse timing programmed for the move (pin monitor);
//   * no step is lost or invented: the pins' count follows the reference
//     position minus the steps still queued (pin monitor);
//   * RTL and model agree on every output (lockstep, in the RTL variant);
// and every 400 fuzz steps CMD.ESTOP must bring the axis to rest
// within the time the programmed pulse timing needs to finish the queued
// steps: the axis is never left moving without a way to stop it.
//
// The UART streams (the board top, RTL) mix valid frames to any word of the
// window with random data, frames with a flipped bit, truncated frames,
// unknown commands and garbage bytes. After every burst and a frame gap, a
// read of ID must come back right (the bridge never hangs or stays out of
// step), and every few bursts an ESTOP frame must bring the axis to rest.
// The pulse timing under random register writes is the AXI campaign's
// check (the bridge sits on the same register file).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <string>
#include <variant>
#include <vector>

#include "axi_bench.h"
#include "board_regs.h"
#include "planner.h"

using namespace sc;
using namespace sc::board_test;

namespace {

struct FuzzCounts {
  uint64_t steps = 0, writes = 0, reads = 0, okay = 0, slverr = 0, decerr = 0;
  uint64_t moves = 0, hostile_rows = 0, stop_checks = 0;
  // What the traffic reached (a flag seen rising between two fuzz steps).
  uint64_t overrun = 0, guard = 0, discont = 0, underrun = 0, limit = 0, stop = 0, table = 0;
};

class AxiFuzzer {
 public:
  AxiFuzzer(AxiBench& b, uint64_t seed) : b_(b), g_(seed) {
    for (const regmap::Reg& r : regmap::kRegs) addrs_.push_back(r.addr);
  }

  // One random transaction (or a quiet gap, or a switch change).
  void transaction() {
    const unsigned pick = unsigned(g_() % 100);
    if (pick < 30) {
      write(random_addr(), random_data(), (g_() % 5 == 0) ? uint8_t(g_() & 0xf) : uint8_t(0xf));
    } else if (pick < 42) {
      load_move();
    } else if (pick < 52) {
      hostile_row();
    } else if (pick < 54) {
      static const uint32_t kCmds[] = {1u << CmdStartBit, 1u << CmdStopBit, 1u << CmdEstopBit, 1u << CmdFlushBit};
      write(reg_addr("CMD"), (g_() % 4 == 0) ? random_data() : kCmds[g_() % 4], 0xf);
    } else if (pick < 74) {
      read(random_addr());
    } else if (pick < 87) {
      b_.idle(1 + g_() % 20000);
    } else if (pick < 92) {
      b_.side().sw_pins = uint8_t(g_() % (1u << SwW));
    } else if (pick < 96) {
      random_guards();
    } else {
      // Recover: clear the flags and enable, so that later moves can run.
      write(reg_addr("ERR"), 0xffffffffu, 0xf);
      write(reg_addr("CTRL"), field_mask("CTRL", "ENABLE"), 0xf);
    }
    if (g_() % 50 == 0) b_.set_jitter(g_() & 1);
    ++n_.steps;
    sample_coverage();
  }

  // CMD.ESTOP stops the axis within the time the programmed pulse timing
  // needs for the steps still queued (at most 2^(PendW-1) of them); then the
  // flags are cleared and the axis enabled again.
  void check_stoppable() {
    ++n_.stop_checks;
    write(reg_addr("CMD"), 1u << CmdEstopBit, 0xf);
    const PulseTiming& t = b_.model().regs().state().cfg;
    const uint64_t per_step = uint64_t(t.high) + t.low + t.setup + t.hold + 8;
    const uint64_t bound = (uint64_t(1) << (PendW - 1)) * per_step + 64;
    uint64_t waited = 0;
    while (b_.out().busy && waited < bound && !b_.failed()) {
      b_.tick();
      ++waited;
    }
    EXPECT_FALSE(b_.out().busy) << "still busy " << bound << " clocks after CMD.ESTOP (fuzz step " << n_.steps
                                << ")";
    write(reg_addr("ERR"), 0xffffffffu, 0xf);
    write(reg_addr("CTRL"), field_mask("CTRL", "ENABLE"), 0xf);
  }

  const FuzzCounts& counts() const { return n_; }

 private:
  // A careful host between the random traffic: CMD.STOP and wait for rest
  // (CMD.ESTOP if a stop with the random stop limits takes too long), empty
  // the FIFO, clear the flags, usual stop limits, no guards, the switches
  // released and filtered briefly, enable.
  void quiesce() {
    write(reg_addr("CMD"), 1u << CmdStopBit, 0xf);
    for (int i = 0; i < 20'000 && b_.out().busy && !b_.failed(); ++i) b_.tick();
    if (b_.out().busy) check_stoppable();
    b_.side().sw_pins = 0;
    const scurve::StopLimitsResult stop = scurve::encode_stop_limits(1e11, 2e7);
    for (const RegWrite& w : std::get<std::vector<RegWrite>>(stop)) write(w.addr, w.data, 0xf);
    write(reg_addr("SW_CFG"), field_mask("SW_CFG", "LIM_EN") | (16u << SwDebounceLsb), 0xf);
    for (const RegWrite& w : scurve::encode_guard_codes({})) write(w.addr, w.data, 0xf);
    write(reg_addr("CMD"), 1u << CmdFlushBit, 0xf);
    write(reg_addr("ERR"), 0xffffffffu, 0xf);
    write(reg_addr("CTRL"), field_mask("CTRL", "ENABLE"), 0xf);
  }
  void sample_coverage() {
    const CoreOutputs o = b_.model().core().outputs();
    auto rise = [](bool now, bool& last, uint64_t& count) {
      if (now && !last) ++count;
      last = now;
    };
    rise(o.fault_overrun, last_.fault_overrun, n_.overrun);
    rise(o.guard, last_.guard, n_.guard);
    rise(o.discont, last_.discont, n_.discont);
    rise(o.underrun, last_.underrun, n_.underrun);
    rise(o.lim_trip_fwd || o.lim_trip_rev, last_.lim_trip_fwd, n_.limit);
    rise(o.stopping, last_.stopping, n_.stop);
    rise(o.fault_table, last_.fault_table, n_.table);
  }
  uint32_t random_addr() {
    const unsigned k = unsigned(g_() % 10);
    if (k < 7) return addrs_[g_() % addrs_.size()];
    if (k < 9) return uint32_t(g_() % (1u << RegAddrW)) & ~3u;  // any word of the window
    return uint32_t(g_() % (1u << RegAddrW));                   // unaligned too
  }
  uint32_t random_data() {
    switch (g_() % 6) {
      case 0: return 0;
      case 1: return 0xffffffffu;
      case 2: return 1u << (g_() % 32);
      case 3: return uint32_t(g_() % 256);
      default: return uint32_t(g_());
    }
  }
  void write(uint32_t a, uint32_t d, uint8_t strb) {
    const uint8_t resp = b_.write(a, d, strb);
    ++n_.writes;
    tally(resp);
  }
  void read(uint32_t a) {
    const auto [v, resp] = b_.read(a);
    (void)v;
    ++n_.reads;
    tally(resp);
  }
  void tally(uint8_t resp) {
    if (resp == kOkay) ++n_.okay;
    if (resp == kSlvErr) ++n_.slverr;
    if (resp == kDecErr) ++n_.decerr;
  }
  // A valid short move with a random pulse timing (refused parts while busy
  // are part of the test); now and then one from a host that falls behind:
  // the move ends moving without STREAM_END, and the host either sends
  // nothing more (an underrun) or a row that does not continue it (a
  // discontinuity); that one runs to rest before the traffic goes on.
  void load_move() {
    const bool falls_behind = g_() % 8 == 0;
    const int64_t d = falls_behind ? int64_t(100 + g_() % 100) * ((g_() & 1) ? 1 : -1)
                                   : int64_t(1 + g_() % 1000) * ((g_() & 1) ? 1 : -1);
    if (falls_behind || g_() % 4 == 0) quiesce();
    // A host that falls behind runs a brisk move (about 5 ms), so that the
    // wait for its end stays short.
    const double v = falls_behind ? 20000.0 + double(g_() % 30000) : 5000.0 + double(g_() % 100000);
    const double a = falls_behind ? 4e6 + double(g_() % 4'000'000) : 2e5 + double(g_() % 4'000'000);
    const double j = falls_behind ? 2e9 + double(g_() % 4'000'000'000) : 4e7 + double(g_() % 4'000'000'000);
    MoveRequest req = scurve::test::move_request(d, 0, v, falls_behind ? v / 4 : 0, a, j);
    PulseTiming t;
    t.high = uint16_t(1 + g_() % 60);
    t.low = uint16_t(1 + g_() % 60);
    t.setup = uint16_t(1 + g_() % 120);
    t.hold = uint16_t(1 + g_() % 120);
    if (falls_behind) t.high = t.low = t.setup = t.hold = 4;  // fast enough for the end speed
    const PlanResult r = plan_move(req, t);
    const Plan* p = std::get_if<Plan>(&r);
    if (!p || p->segments.size() > 20) return;
    std::vector<RegWrite> writes = encode_move(*p, t, falls_behind || g_() % 4 != 0);
    if (falls_behind) {
      for (auto w = writes.rbegin(); w != writes.rend(); ++w) {
        if (w->addr == uint32_t(RegRowPush)) {
          w->data &= ~(1u << RowPushStreamEndBit);
          break;
        }
      }
    }
    for (const RegWrite& w : writes) write(w.addr, w.data, 0xf);
    ++n_.moves;
    if (!falls_behind) return;
    const unsigned next = unsigned(g_() % 3);
    if (next == 1) hostile_row();
    if (next == 2) outrunning_row(*p, d > 0);
    for (int i = 0; i < 1'000'000 && b_.out().busy && !b_.failed(); ++i) b_.tick();
  }
  // A row that continues the plan's end speed exactly but then accelerates
  // (an acceleration step is allowed by its flag) far beyond what the pulse
  // timing can emit: the step-rate guard must stop it without losing a step.
  void outrunning_row(const Plan& p, bool fwd) {
    Segment s;
    s.phase = Phase::PhCruise;
    s.clocks = 100'000;
    s.vel0 = p.end_state.velocity;
    s.acc0 = (int64_t(1) << 62) * (fwd ? 1 : -1);  // 1/8 pulse/clock within 2^15 clocks
    scurve::RowFlags f;
    f.move_end = true;
    f.stream_end = true;
    f.acc_step = true;
    for (const RegWrite& w : encode_row(s, f)) write(w.addr, w.data, 0xf);
  }
  // A row with random staging values and flags: any velocity, acceleration,
  // jerk and length the registers hold.
  void hostile_row() {
    auto wide = [&](int bits) -> uint64_t {
      const int keep = int(g_() % uint64_t(bits)) + 1;
      return uint64_t(g_()) >> (64 - std::min(keep, 64));
    };
    Segment s;
    s.phase = Phase(g_() % 16);
    s.clocks = uint32_t(g_() % 4 == 0 ? g_() % 4 : g_() % 200000);
    s.jerk = int64_t(wide(JerkW)) * ((g_() & 1) ? 1 : -1);
    s.acc0 = int64_t(wide(AccW - 1)) * ((g_() & 1) ? 1 : -1);
    s.vel0 = (i128(wide(64)) << (g_() % 17)) * ((g_() & 1) ? 1 : -1);  // up to 1 pulse/clock
    scurve::RowFlags f;
    f.move_end = g_() & 1;
    f.stream_end = g_() & 1;
    f.acc_step = g_() & 1;
    f.hold = g_() % 8 == 0;
    for (const RegWrite& w : encode_row(s, f)) write(w.addr, w.data, 0xf);
    ++n_.hostile_rows;
  }
  void random_guards() {
    scurve::GuardLimitCodes c;
    if (g_() & 1) c.vel = u128(uint64_t(g_()) >> (g_() % 64));
    if (g_() & 1) c.acc = uint64_t(g_()) >> (g_() % 64);
    if (g_() & 1) c.jerk = (uint64_t(g_()) >> (g_() % 64)) & ((uint64_t(1) << JerkW) - 1);
    for (const RegWrite& w : scurve::encode_guard_codes(c)) write(w.addr, w.data, 0xf);
  }

  AxiBench& b_;
  std::mt19937_64 g_;
  std::vector<uint32_t> addrs_;
  FuzzCounts n_;
  CoreOutputs last_{};
};

// `steps` fuzz steps: each a transaction, a move's or a row's writes, a
// quiet gap or a switch change.
void run_axi_fuzz(bool with_rtl, uint64_t steps, uint64_t seed) {
  AxiBench b(with_rtl, uint32_t(seed));
  b.reset();
  AxiFuzzer f(b, seed);
  for (uint64_t i = 0; i < steps && !b.failed() && !::testing::Test::HasFailure(); ++i) {
    f.transaction();
    if ((i + 1) % 400 == 0) f.check_stoppable();
  }
  if (!b.failed()) f.check_stoppable();
  ASSERT_FALSE(b.failed()) << b.error() << " (after " << f.counts().steps << " fuzz steps)";
  const FuzzCounts& n = f.counts();
  std::printf("[reg-fuzz] %s: %llu fuzz steps, %llu AXI transactions (%llu writes, %llu reads: %llu OKAY, %llu "
              "SLVERR, %llu DECERR), %llu moves, %llu hostile rows, %llu stop checks, %llu clocks; reached: "
              "%llu step-rate stops, %llu guard stops, %llu discontinuities, %llu underruns, %llu limit trips, "
              "%llu controlled stops, %llu table faults; 0 violations\n",
              with_rtl ? "RTL lockstep" : "model", (unsigned long long)n.steps,
              (unsigned long long)(n.writes + n.reads), (unsigned long long)n.writes, (unsigned long long)n.reads,
              (unsigned long long)n.okay, (unsigned long long)n.slverr, (unsigned long long)n.decerr,
              (unsigned long long)n.moves, (unsigned long long)n.hostile_rows, (unsigned long long)n.stop_checks,
              (unsigned long long)b.clock(), (unsigned long long)n.overrun, (unsigned long long)n.guard,
              (unsigned long long)n.discont, (unsigned long long)n.underrun, (unsigned long long)n.limit,
              (unsigned long long)n.stop, (unsigned long long)n.table);
  EXPECT_GT(n.moves, steps / 20);
  EXPECT_GT(n.slverr, 0u);
  EXPECT_GT(n.decerr, 0u);
  // The traffic reaches every way the core stops a stream.
  for (const uint64_t reached : {n.overrun, n.guard, n.discont, n.underrun, n.limit, n.stop, n.table})
    EXPECT_GT(reached, 0u);
  EXPECT_TRUE(b.pins().errors().empty());
}

// Random byte streams into the board top's UART bridge.
class UartFuzzer {
 public:
  explicit UartFuzzer(uint64_t seed) : g_(seed) {}

  void burst() {
    std::vector<uint8_t> bytes;
    const int frames = 1 + int(g_() % 4);
    for (int i = 0; i < frames; ++i) {
      const unsigned pick = unsigned(g_() % 100);
      std::vector<uint8_t> f = valid_frame();
      if (pick < 45) {
        ++valid_;
      } else if (pick < 65) {
        f[1 + g_() % (f.size() - 1)] ^= uint8_t(1u << (g_() % 8));  // a flipped bit after the sync byte
        ++corrupted_;
      } else if (pick < 80) {
        f.resize(1 + g_() % (f.size() - 1));  // truncated: dropped after the gap
        ++truncated_;
      } else if (pick < 88) {
        f = {uint8_t(UartReqSync), uint8_t(3 + g_() % 253)};  // unknown command
      } else {
        f.clear();
        for (int k = int(g_() % 12); k >= 0; --k) f.push_back(uint8_t(g_()));
        ++garbage_;
      }
      bytes.insert(bytes.end(), f.begin(), f.end());
    }
    bd_.host.transact(bytes, 0, 0);
    ++bursts_;
  }

  // After a frame gap the bridge answers a read of ID correctly.
  void check_in_step() {
    bd_.host.idle(uint64_t(2 * UartTimeoutBits) * 5 * UartClksPerBit);
    const UartResponse r = bd_.host.read(reg_addr("ID"));
    ASSERT_TRUE(r.ok) << "after burst " << bursts_ << ": " << r.error;
    ASSERT_EQ(r.status, kOkay) << "after burst " << bursts_;
    ASSERT_EQ(r.data, reg("ID").reset) << "after burst " << bursts_;
  }

  // An ESTOP frame brings the axis to rest (BUSY clears within the time the
  // slowest pulse timing needs for the queued steps); then clear and enable.
  void check_stoppable() {
    ASSERT_EQ(bd_.host.write(reg_addr("CMD"), 1u << CmdEstopBit).status, kOkay);
    bool busy = true;
    for (int poll = 0; poll < 400 && busy; ++poll) {
      const UartResponse r = bd_.host.read(reg_addr("STATUS"));
      ASSERT_TRUE(r.ok) << r.error;
      busy = r.data & field_mask("STATUS", "BUSY");
      if (busy) bd_.host.idle(uint64_t(5) * 65535 * 4);
    }
    ASSERT_FALSE(busy) << "the axis does not come to rest after ESTOP (burst " << bursts_ << ")";
    ASSERT_EQ(bd_.host.write(reg_addr("ERR"), 0xffffffffu).status, kOkay);
    ASSERT_EQ(bd_.host.write(reg_addr("CTRL"), field_mask("CTRL", "ENABLE")).status, kOkay);
  }

  void report() const {
    std::printf("[reg-fuzz] UART: %llu bursts (%llu valid frames, %llu with a flipped bit, %llu truncated, %llu "
                "garbage runs), 0 violations\n",
                (unsigned long long)bursts_, (unsigned long long)valid_, (unsigned long long)corrupted_,
                (unsigned long long)truncated_, (unsigned long long)garbage_);
  }

 private:
  // A frame the encoder builds: a write of random data to any word of the
  // window (a planned move's rows and START now and then), or a read.
  std::vector<uint8_t> valid_frame() {
    const uint32_t a = uint32_t(g_() % (1u << RegAddrW)) & ~3u;
    const scurve::FrameResult f = (g_() % 3 == 0) ? uart_read_frame(a) : uart_write_frame(a, random_data());
    return std::get<std::vector<uint8_t>>(f);
  }
  uint32_t random_data() {
    switch (g_() % 4) {
      case 0: return 0;
      case 1: return 1u << (g_() % 32);
      case 2: return uint32_t(g_() % 256);
      default: return uint32_t(g_());
    }
  }
  struct Board {
    RtlBoard rtl;
    UartHost host{rtl, UartClksPerBit};
    Board() { host.idle(200); }  // clock stand-in lock + reset synchroniser
  };
  Board bd_;
  std::mt19937_64 g_;
  uint64_t bursts_ = 0, valid_ = 0, corrupted_ = 0, truncated_ = 0, garbage_ = 0;
};

void run_uart_fuzz(int bursts, uint64_t seed) {
  UartFuzzer f(seed);
  for (int i = 0; i < bursts && !::testing::Test::HasFatalFailure(); ++i) {
    f.burst();
    f.check_in_step();
    if ((i + 1) % 50 == 0) f.check_stoppable();
  }
  if (!::testing::Test::HasFatalFailure()) f.check_stoppable();
  f.report();
}

}  // namespace

TEST(RegisterFuzz, RandomUartByteStreamsNeverHangTheBridgeOrLeaveTheAxisUnstoppable) { run_uart_fuzz(300, 4); }

TEST(RegisterFuzz, RandomTransactionsInRtlLockstepKeepThePulseTimingTheStepCountTheBusAndTheStop) {
  run_axi_fuzz(true, 10'000, 1);
}

TEST(RegisterFuzz, RandomTransactionsOnTheModelKeepThePulseTimingTheStepCountTheBusAndTheStop) {
  run_axi_fuzz(false, 30'000, 2);
}

// Nightly size: a million fuzz steps (about 11 million AXI transactions) on
// the model, ten thousand UART bursts.
TEST(RegisterFuzzLong, AMillionFuzzStepsOnTheModel) { run_axi_fuzz(false, 1'000'000, 3); }
TEST(RegisterFuzzLong, TenThousandRandomUartBursts) { run_uart_fuzz(10'000, 5); }
