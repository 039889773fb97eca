// The multi-axis register map (sc_axi_multi_axis: two closed-loop capable
// axes behind one AXI4-Lite slave) against its model in lockstep, every
// clock; the windows and the group writes as docs/regmap.md documents them
// (the group window reaches every axis, an axis's window only it, the
// shared row fields and START only through the group); coordinated lines
// loaded through the registers end every axis on its exact target, the
// pins counted by a monitor per axis; random transactions over every
// window keep the pins, the bus and the stop; and the two-axis board top
// does the same over its UART, driven by the host library's AxisGroup.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "board_regs.h"
#include "closed_loop_run.h"
#include "multi_run.h"
#include "planner.h"
#include "scurve/board.h"
#include "scurve/path_planner.h"
#include "virtual_board.h"

namespace sc {
namespace {

using board_test::field_mask;
using board_test::reg_addr;
using scurve::multi_axis_addr;

constexpr size_t kAxes = RtlAxiMultiAxis::kAxes;

uint32_t group(const std::string& name) { return multi_axis_addr(std::nullopt, reg_addr(name)); }
uint32_t axis_reg(size_t a, const std::string& name) { return multi_axis_addr(a, reg_addr(name)); }

void enable_all(AxiMultiBench& b) {
  EXPECT_EQ(b.write(group("ERR"), 0xffffffffu), kOkay);
  EXPECT_EQ(b.write(group("CTRL"), field_mask("CTRL", "ENABLE")), kOkay);
}

// Every axis's POS_FRAC0, in its window.
std::vector<scurve::RegWrite> frac0_writes(const MultiRows& rows) {
  std::vector<scurve::RegWrite> out;
  for (size_t a = 0; a < kAxes; ++a) {
    const u128 f = rows.pos_frac0[a];
    out.push_back({axis_reg(a, "POS_FRAC0_0"), uint32_t(f)});
    out.push_back({axis_reg(a, "POS_FRAC0_1"), uint32_t(f >> 32)});
    out.push_back({axis_reg(a, "POS_FRAC0_2"), uint32_t(f >> 64)});
  }
  return out;
}

// Multi-axis row k: each axis's staging in its window, the clocks and the
// push (with the row's flags) in the group window.
std::vector<scurve::RegWrite> row_writes(const MultiRows& rows, size_t k) {
  std::vector<scurve::Segment> segs;
  for (size_t a = 0; a < kAxes; ++a) segs.push_back(to_host(rows.rows[a][k].seg));
  const uint8_t flags = rows.rows[0][k].flags;
  scurve::RowFlags f;
  f.move_end = flags & (1u << RowFlagMoveEnd);
  f.stream_end = flags & (1u << RowFlagStreamEnd);
  f.acc_step = flags & (1u << RowFlagAccStep);
  f.hold = flags & (1u << RowFlagHold);
  return scurve::encode_multi_row(segs, f);
}

std::string where(uint32_t addr) {
  return scurve::reg_name(addr & ((1u << RegAddrW) - 1)) + " in window " + std::to_string(addr >> RegAddrW);
}

// Push multi-axis rows from `from` on while the FIFO has room; returns the
// next row to push.
size_t push_rows(AxiMultiBench& b, const MultiRows& rows, size_t from) {
  const size_t n = rows.rows[0].size();
  while (from < n && !b.failed()) {
    const uint32_t level = (b.read(group("FIFO_STATUS")).first & field_mask("FIFO_STATUS", "LEVEL")) >>
                           FifoLevelLsb;
    if (level >= uint32_t(RowFifoDepth)) break;
    for (const scurve::RegWrite& w : row_writes(rows, from)) EXPECT_EQ(b.write(w.addr, w.data), kOkay) << where(w.addr);
    ++from;
  }
  return from;
}

// Load a line through the registers (POS_FRAC0 per axis, the rows through
// the staging windows and group pushes), START, stream the rest, run to rest.
void run_line(AxiMultiBench& b, const MultiRows& rows) {
  for (const scurve::RegWrite& w : frac0_writes(rows)) EXPECT_EQ(b.write(w.addr, w.data), kOkay) << where(w.addr);
  size_t next = push_rows(b, rows, 0);
  EXPECT_EQ(b.write(group("CMD"), 1u << CmdStartBit), kOkay);
  uint64_t guard = 0;
  while ((b.out().axis[0].busy || next < rows.rows[0].size()) && !b.failed() && guard++ < 2'000'000) {
    next = push_rows(b, rows, next);
    b.idle(200);
  }
  b.idle(50);
}

TEST(MultiAxisRegs, WindowsGroupWritesAndRefusals) {
  AxiMultiBench b(true, 3);
  b.idle(8);
  // ID in the group window and in each axis's; no register above the axes
  const uint32_t id = (uint32_t(RegIdMagic) << 16) | uint32_t(RegMapVersion);
  EXPECT_EQ(b.read(group("ID")), std::make_pair(id, uint8_t(kOkay)));
  for (size_t a = 0; a < kAxes; ++a) EXPECT_EQ(b.read(axis_reg(a, "ID")).first, id);
  ASSERT_FALSE(b.failed()) << b.error();
  for (uint32_t w = kAxes + 1; w < (1u << RegWinW); ++w) {
    EXPECT_EQ(b.read((w << RegAddrW) | reg_addr("ID")).second, kDecErr) << "window " << w;
    ASSERT_FALSE(b.failed()) << b.error();
    EXPECT_EQ(b.write((w << RegAddrW) | reg_addr("SOFT_MIN"), 5), kDecErr) << "window " << w;
  }
  // a group write reaches every axis; an axis's write only that axis
  EXPECT_EQ(b.write(group("SOFT_MIN"), uint32_t(-1234)), kOkay);
  for (size_t a = 0; a < kAxes; ++a) EXPECT_EQ(b.read(axis_reg(a, "SOFT_MIN")).first, uint32_t(-1234));
  EXPECT_EQ(b.write(axis_reg(1, "SOFT_MIN"), 77), kOkay);
  EXPECT_EQ(b.read(axis_reg(0, "SOFT_MIN")).first, uint32_t(-1234));
  EXPECT_EQ(b.read(axis_reg(1, "SOFT_MIN")).first, 77u);
  EXPECT_EQ(b.read(group("SOFT_MIN")).first, uint32_t(-1234)) << "group reads answer axis 0";
  // the shared row fields, the push and START / FLUSH: group window only
  const uint32_t reject = field_mask("ERR", "REJECT");
  const std::vector<std::pair<std::string, uint32_t>> shared = {
      {"SEG_CLOCKS", 10}, {"ROW_PUSH", 0}, {"RETARGET_ROW", 1}, {"CMD", 1u << CmdStartBit}, {"CMD", 1u << CmdFlushBit}};
  for (const auto& [name, data] : shared) {
    EXPECT_EQ(b.write(group("ERR"), 0xffffffffu), kOkay);
    EXPECT_EQ(b.write(axis_reg(1, name), data), kSlvErr) << name;
    EXPECT_EQ(b.read(axis_reg(1, "ERR")).first & reject, reject) << name;
    EXPECT_EQ(b.read(axis_reg(0, "ERR")).first & reject, 0u) << name;
    EXPECT_EQ(b.read(group("FIFO_STATUS")).first & field_mask("FIFO_STATUS", "LEVEL"), 0u) << name;
  }
  EXPECT_EQ(b.read(axis_reg(1, "SEG_CLOCKS")).first, 0u) << "a refused write changes nothing";
  // START is taken by every axis or by none: axis 1 disabled refuses it
  enable_all(b);
  EXPECT_EQ(b.write(axis_reg(1, "CTRL"), 0), kOkay);
  EXPECT_EQ(b.write(group("CMD"), 1u << CmdStartBit), kSlvErr);
  b.idle(4);
  for (size_t a = 0; a < kAxes; ++a) {
    EXPECT_FALSE(b.out().axis[a].busy) << a;
    EXPECT_EQ(b.read(axis_reg(a, "ERR")).first & reject, reject) << a;
  }
  // STOP and ESTOP act from any window (ESTOP latches on the axis it names)
  EXPECT_EQ(b.write(axis_reg(1, "CMD"), 1u << CmdEstopBit), kOkay);
  EXPECT_NE(b.read(axis_reg(1, "ERR")).first & field_mask("ERR", "ESTOP"), 0u);
  EXPECT_EQ(b.read(axis_reg(0, "ERR")).first & field_mask("ERR", "ESTOP"), 0u);
  EXPECT_FALSE(b.failed()) << b.error();
  EXPECT_GT(b.matched(), 0u);
}

// Random 2-axis lines (both directions, zero on one axis now and then)
// loaded through the multi-axis map: every axis on its exact target, the
// pins on the reference, RTL = model every clock.
TEST(MultiAxisRegs, PlannedLinesThroughTheRegistersEndEveryAxisExactly) {
  AxiMultiBench b(true, 5);
  b.idle(8);
  enable_all(b);
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<int64_t> pos(kAxes, 0);
  for (int k = 0; k < 4 && !b.failed(); ++k) {
    scurve::LineRequest r;
    const double scale = std::pow(10.0, 1 + 2.0 * u(rng));
    for (size_t a = 0; a < kAxes; ++a) {
      int64_t d = int64_t(std::llround(scale * u(rng))) * (u(rng) < 0.5 ? -1 : 1);
      if (u(rng) < 0.15) d = 0;
      r.distances.push_back(d);
    }
    if (r.distances[0] == 0 && r.distances[1] == 0) r.distances[0] = 7;
    r.v_path = 20000 + 100000 * u(rng);
    r.a_path = 2e6 + 2e7 * u(rng);
    r.j_path = 2e8 + 5e9 * u(rng);
    auto p = scurve::plan_line(scurve::Planner{model_clock()}, r, to_host(PulseTiming{}));
    ASSERT_TRUE(std::holds_alternative<scurve::LinePlan>(p));
    const MultiRows rows = line_rows(std::get<scurve::LinePlan>(p));
    const uint64_t before = b.clock();
    run_line(b, rows);
    for (size_t a = 0; a < kAxes; ++a) {
      // REF_POS goes on from the last move's end; PULSE_COUNT counts from START
      pos[a] += r.distances[a];
      EXPECT_EQ(int64_t(int32_t(b.read(axis_reg(a, "REF_POS")).first)), pos[a]) << "line " << k << " axis " << a;
      EXPECT_EQ(b.out().axis[a].pulse_count, r.distances[a]) << "line " << k << " axis " << a;
      EXPECT_EQ(b.pins(a).net_steps(), pos[a]) << "line " << k << " axis " << a;
      EXPECT_FALSE(b.out().axis[a].busy);
      EXPECT_TRUE(b.out().axis[a].done);
    }
    EXPECT_GT(b.clock() - before, 0u);
  }
  EXPECT_FALSE(b.failed()) << b.error();
  EXPECT_GT(b.matched(), 100'000u);
}

// Both axes closed-loop through the multi-axis map, a stepper plant on
// each: the controller settings written once through the group window,
// CTRL.CLOSED_LOOP per axis, a line loaded and started through the
// windows; RTL = model every clock (the controllers' states and weights
// read back through CL_STATUS .. CTL_W_V2 as they run), both loops in
// position at the end with the encoder on the target.
TEST(MultiAxisRegs, ClosedLoopLineThroughTheRegistersSettlesBothAxesOnTarget) {
  AxiMultiBench b(true, 11);
  b.attach_plants(PlantConfig{});
  b.idle(8);
  ServoConfig cfg;
  ASSERT_EQ(to_servo_config(ControllerParams{}, PlantConfig{}, PulseTiming{}, cfg), "");
  for (const RegWrite& w : encode_servo_config(cfg)) {
    ASSERT_EQ(b.write(multi_axis_addr(std::nullopt, w.addr), w.data), kOkay) << scurve::reg_name(w.addr);
  }
  const uint32_t ctrl = field_mask("CTRL", "ENABLE") | field_mask("CTRL", "CLOSED_LOOP");
  ASSERT_EQ(b.write(group("CTRL"), ctrl), kOkay);
  scurve::LineRequest r;
  r.distances = {400, -250};
  r.v_path = 4000;
  r.a_path = 1e5;
  r.j_path = 4e6;
  auto p = scurve::plan_line(scurve::Planner{model_clock()}, r, to_host(PulseTiming{}));
  ASSERT_TRUE(std::holds_alternative<scurve::LinePlan>(p));
  const MultiRows rows = line_rows(std::get<scurve::LinePlan>(p));
  for (const scurve::RegWrite& w : frac0_writes(rows)) ASSERT_EQ(b.write(w.addr, w.data), kOkay) << where(w.addr);
  size_t next = push_rows(b, rows, 0);
  ASSERT_EQ(b.write(group("CMD"), 1u << CmdStartBit), kOkay);
  bool saw_u = false, done = false;
  for (int i = 0; i < 4000 && !done && !b.failed(); ++i) {
    next = push_rows(b, rows, next);
    for (size_t a = 0; a < kAxes; ++a) saw_u = saw_u || b.read(axis_reg(a, "CTL_U")).first != 0;
    const uint32_t s0 = b.read(axis_reg(0, "STATUS")).first, s1 = b.read(axis_reg(1, "STATUS")).first;
    done = (s0 & field_mask("STATUS", "DONE")) && (s1 & field_mask("STATUS", "DONE"));
    b.idle(2000);
  }
  EXPECT_TRUE(done) << "both axes in position";
  EXPECT_TRUE(saw_u);
  for (size_t a = 0; a < kAxes; ++a) {
    const uint32_t cs = b.read(axis_reg(a, "CL_STATUS")).first;
    EXPECT_TRUE(cs & field_mask("CL_STATUS", "IN_POS")) << "axis " << a;
    EXPECT_FALSE(cs & field_mask("CL_STATUS", "FAULT_FERR")) << "axis " << a;
    const int32_t enc = int32_t(b.read(axis_reg(a, "ENC_POS")).first);
    EXPECT_LE(std::abs(enc - int32_t(r.distances[a])), 2) << "axis " << a << " encoder " << enc;
    EXPECT_EQ(int64_t(int32_t(b.read(axis_reg(a, "REF_POS")).first)), r.distances[a]) << "axis " << a;
  }
  EXPECT_FALSE(b.failed()) << b.error();
}

// Random transactions over all windows: documented registers in the group
// window, either axis's or no axis's, random data and strobes, reads,
// commands, bus timing and switch pins, now and then a planned line. Every
// clock RTL = model; the pins keep their timing and count (monitor per
// axis); every transaction is answered; every 200 transactions CMD.ESTOP
// brings both axes to rest.
TEST(MultiAxisRegs, RandomTransactionsOverEveryWindowMatchAndStayStoppable) {
  AxiMultiBench b(true, 9);
  b.idle(8);
  std::mt19937_64 g(23);
  std::vector<uint32_t> offsets;
  for (const regmap::Reg& r : regmap::kRegs) offsets.push_back(r.addr);
  uint64_t okay = 0, slverr = 0, decerr = 0, lines = 0, stops = 0;
  auto tally = [&](uint8_t resp) {
    okay += resp == kOkay;
    slverr += resp == kSlvErr;
    decerr += resp == kDecErr;
  };
  const int kTransactions = 10'000;
  for (int t = 0; t < kTransactions && !b.failed(); ++t) {
    const uint32_t window = (g() % 8 == 0) ? uint32_t(g() % (1u << RegWinW)) : uint32_t(g() % (kAxes + 1));
    const uint32_t addr = (window << RegAddrW) | offsets[g() % offsets.size()];
    const unsigned pick = unsigned(g() % 100);
    if (pick < 40) {
      const uint32_t data = (g() % 3 == 0) ? uint32_t(g() % 256) : uint32_t(g());
      tally(b.write(addr, data, (g() % 5 == 0) ? uint8_t(g() & 0xf) : uint8_t(0xf)));
    } else if (pick < 75) {
      tally(b.read(addr).second);
    } else if (pick < 80) {
      static const uint32_t kCmds[] = {1u << CmdStartBit, 1u << CmdStopBit, 1u << CmdEstopBit, 1u << CmdFlushBit};
      tally(b.write(window << RegAddrW | reg_addr("CMD"), kCmds[g() % 4]));
    } else if (pick < 88) {
      b.idle(1 + g() % 3000);
    } else if (pick < 92) {
      b.pins_in()[g() % kAxes].sw = uint8_t(g() % (1u << SwW));
    } else if (pick < 96) {
      b.set_jitter(g() & 1);
    } else {
      // a short line from a careful host: stop (at once if the random stop
      // limits take long), flush, clear, enable, load
      tally(b.write(group("CMD"), 1u << CmdStopBit));
      for (int i = 0; i < 100 && b.out().axis[0].busy && !b.failed(); ++i) b.idle(1000);
      if (b.out().axis[0].busy) tally(b.write(group("CMD"), 1u << CmdEstopBit));
      b.idle(2000);
      tally(b.write(group("CMD"), 1u << CmdFlushBit));
      for (size_t a = 0; a < kAxes; ++a) b.pins_in()[a].sw = 0;
      scurve::LineRequest r;
      r.distances = {int64_t(g() % 400) - 200, int64_t(g() % 400) - 200};
      if (r.distances[0] == 0) r.distances[0] = 3;
      r.v_path = 50000;
      r.a_path = 1e7;
      r.j_path = 3e9;
      auto p = scurve::plan_line(scurve::Planner{model_clock()}, r, to_host(PulseTiming{}));
      if (auto* lp = std::get_if<scurve::LinePlan>(&p)) {
        const MultiRows rows = line_rows(*lp);
        if (rows.rows[0].size() <= size_t(RowFifoDepth)) {
          enable_all(b);
          push_rows(b, rows, 0);
          tally(b.write(group("CMD"), 1u << CmdStartBit));
          ++lines;
        }
      }
    }
    if (t % 200 == 199) {
      ++stops;
      tally(b.write(group("CMD"), 1u << CmdEstopBit));
      uint64_t waited = 0;
      while ((b.out().axis[0].busy || b.out().axis[1].busy) && waited < 20'000 && !b.failed()) {
        b.tick();
        ++waited;
      }
      EXPECT_FALSE(b.out().axis[0].busy || b.out().axis[1].busy) << "still moving after CMD.ESTOP, transaction " << t;
      enable_all(b);
    }
  }
  EXPECT_FALSE(b.failed()) << b.error();
  std::printf("multi-axis register fuzz: %d transactions, %llu OKAY, %llu SLVERR, %llu DECERR, %llu lines, "
              "%llu e-stops, %llu clocks compared\n",
              kTransactions, (unsigned long long)okay, (unsigned long long)slverr, (unsigned long long)decerr,
              (unsigned long long)lines, (unsigned long long)stops, (unsigned long long)b.matched());
  EXPECT_GT(okay, 1000u);
  EXPECT_GT(slverr, 10u);
  EXPECT_GT(decerr, 10u);
  EXPECT_GT(lines, 10u);
}

// The two-axis board top over its UART (two-byte word addresses): the
// windows answer as on the bus, a line loaded through the group and axis
// windows runs both axes to their targets, counted on the board's pins; a
// word beyond the map answers DECERR from the bridge itself.
TEST(BoardXY, LineOverTheUartRunsBothAxesToTheirTargets) {
  RtlBoardXY board;
  UartHostXY host(board, RtlBoardXY::kClksPerBit);
  host.idle(2000);
  const uint32_t id = (uint32_t(RegIdMagic) << 16) | uint32_t(RegMapVersion);
  for (const uint32_t addr : {group("ID"), axis_reg(0, "ID"), axis_reg(1, "ID")}) {
    const UartResponse r = host.read(addr);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.status, kOkay);
    EXPECT_EQ(r.data, id);
  }
  EXPECT_EQ(host.read((3u << RegAddrW) | reg_addr("ID")).status, kDecErr) << "no axis 2 on this board";
  // a word address past the 13-bit map: the bridge answers, no bus access
  const std::vector<uint8_t> far = {uint8_t(UartReqSync), uint8_t(UartCmdRead), 0x00, 0x08};
  std::vector<uint8_t> frame = far;
  frame.push_back(scurve::crc8(frame.data() + 1, frame.size() - 1));
  const UartResponse beyond = scurve::parse_uart_response(host.transact(frame, 7), true);
  ASSERT_TRUE(beyond.ok) << beyond.error;
  EXPECT_EQ(beyond.status, kDecErr);

  scurve::LineRequest req;
  req.distances = {300, -170};
  req.v_path = 10000;
  req.a_path = 2e6;
  req.j_path = 4e8;
  auto p = scurve::plan_line(scurve::Planner{model_clock()}, req, to_host(PulseTiming{}));
  ASSERT_TRUE(std::holds_alternative<scurve::LinePlan>(p));
  const MultiRows rows = line_rows(std::get<scurve::LinePlan>(p));
  auto write = [&](uint32_t addr, uint32_t data) {
    const UartResponse r = host.write(addr, data);
    EXPECT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.status, kOkay) << where(addr);
  };
  write(group("CTRL"), field_mask("CTRL", "ENABLE"));
  for (const scurve::RegWrite& w : frac0_writes(rows)) write(w.addr, w.data);
  // the first FIFO-full of rows, START, then the rest as the FIFO drains
  for (size_t k = 0; k < rows.rows[0].size(); ++k) {
    if (k == size_t(RowFifoDepth)) write(group("CMD"), 1u << CmdStartBit);
    if (k >= size_t(RowFifoDepth)) {
      for (int i = 0; i < 1000; ++i) {
        const UartResponse lv = host.read(group("FIFO_STATUS"));
        if (lv.ok && (lv.data & field_mask("FIFO_STATUS", "LEVEL")) < uint32_t(RowFifoDepth)) break;
      }
    }
    for (const scurve::RegWrite& w : row_writes(rows, k)) write(w.addr, w.data);
  }
  if (rows.rows[0].size() <= size_t(RowFifoDepth)) write(group("CMD"), 1u << CmdStartBit);
  for (int i = 0; i < 400; ++i) {
    host.idle(20'000);
    const UartResponse st = host.read(group("STATUS"));
    if (st.ok && !(st.data & field_mask("STATUS", "BUSY"))) break;
  }
  for (size_t a = 0; a < kAxes; ++a) {
    EXPECT_EQ(host.pins(a).net_steps(), req.distances[a]) << "axis " << a;
    for (const std::string& e : host.pins(a).errors()) ADD_FAILURE() << "axis " << a << ": " << e;
    const UartResponse ref = host.read(axis_reg(a, "REF_POS"));
    EXPECT_EQ(int32_t(ref.data), req.distances[a]) << "axis " << a;
  }
}

// The host's link to the in-process virtual board; waiting is board time.
class VirtualLink : public scurve::UartLink {
 public:
  VirtualLink(VirtualBoardChannel& line, VirtualBoard& board, const scurve::LinkOptions& o)
      : scurve::UartLink(line, o), b_(board) {}
  void wait(double seconds) override {
    std::vector<uint8_t> none;
    b_.run(uint64_t(seconds * double(ClkHz)), none);
  }

 private:
  VirtualBoard& b_;
};

TEST(BoardXY, TheHostDriverRunsRandomPathsEveryAxisEndingOnItsTargets) {
  VirtualBoardConfig vc;
  vc.axes = kAxes;
  VirtualBoard board(vc);
  VirtualBoardChannel line(board);
  scurve::LinkOptions lo;
  lo.addr_bits = MultiRegAddrW;
  lo.timeout = 0.005;  // board time: an exchange takes about 0.1 ms
  VirtualLink link(line, board, lo);
  std::vector<uint8_t> none;
  board.run(1000, none);
  auto bits = scurve::detect_addr_bits(line, lo);
  ASSERT_TRUE(std::holds_alternative<int>(bits));
  EXPECT_EQ(std::get<int>(bits), MultiRegAddrW);
  scurve::AxisGroup xy(link, scurve::Clock{double(ClkHz)});
  auto info = xy.identify();
  ASSERT_TRUE(std::holds_alternative<scurve::BoardInfo>(info)) << std::get<scurve::Error>(info).message;
  ASSERT_EQ(xy.axes(), kAxes);
  scurve::BoardConfig cfg;
  ASSERT_FALSE(xy.configure(cfg));

  std::mt19937_64 rng(20261206);
  auto uni = [&](double lo_, double hi_) { return lo_ + (hi_ - lo_) * double(rng() >> 11) * 0x1.0p-53; };
  std::vector<int64_t> at(kAxes, 0);
  for (int path = 0; path < 3; ++path) {
    scurve::PathRequest req;
    req.axes = kAxes;
    req.start = at;
    const int moves = 3 + path % 2;
    std::vector<int64_t> p = at;
    for (int m = 0; m < moves; ++m) {
      for (size_t a = 0; a < kAxes; ++a) {
        const int64_t d = int64_t(uni(40, 400)) * (rng() & 1 ? 1 : -1);
        p[a] += (rng() % 5 == 0) ? 0 : d;  // now and then an axis stays
      }
      req.moves.push_back({p, uni(3000, 8000), m + 1});
    }
    req.limits = {8000, uni(2e5, 5e5), uni(1e7, 3e7)};
    if (path == 2) {
      req.junction = scurve::Junction::kBlend;
      req.tolerance = 5;
    }
    auto planned = scurve::plan_path(scurve::Planner{scurve::Clock{double(ClkHz)}}, req, scurve::PulseTiming{});
    ASSERT_TRUE(std::holds_alternative<scurve::PathPlan>(planned)) << std::get<scurve::Error>(planned).message;
    const scurve::PathPlan& plan = std::get<scurve::PathPlan>(planned);
    auto run = xy.run_path(plan, 600);
    ASSERT_TRUE(std::holds_alternative<scurve::PathRunReport>(run))
        << "path " << path << ": " << std::get<scurve::Error>(run).message;
    const scurve::PathRunReport& r = std::get<scurve::PathRunReport>(run);
    EXPECT_GT(r.boundaries_checked, 0u);
    EXPECT_GT(r.rows, size_t(RowFifoDepth)) << "the FIFO is topped up while the path runs";
    for (size_t a = 0; a < kAxes; ++a) {
      // The pins, counted on the plant: not the board's own account.
      EXPECT_EQ(board.position(a), plan.moves.back().target[a]) << "path " << path << " axis " << a;
      EXPECT_EQ(board.encoder(a), plan.moves.back().target[a]) << "path " << path << " axis " << a;
      EXPECT_EQ(r.final_status[a].ref_pos, plan.moves.back().target[a]);
      EXPECT_TRUE(r.final_status[a].faults().empty());
    }
    at = plan.moves.back().target;
  }
  EXPECT_EQ(link.stats().retries, 0u);
}

}  // namespace
}  // namespace sc
