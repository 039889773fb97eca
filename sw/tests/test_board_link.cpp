// The board driver's link and load rules against a scripted board on an
// in-process line: which requests are sent again after which failure, that
// a move whose rows did not all arrive is never started, and the errors.
#include <gtest/gtest.h>

#include <deque>
#include <map>

#include "scurve/board.h"
#include "scurve/hw/params.h"

namespace {

using namespace scurve;

constexpr uint32_t bit(int b) { return uint32_t(1) << b; }

// A board behind the line: decodes request frames, keeps registers and a
// FIFO level, and misbehaves as scripted per frame.
class ScriptedBoard : public ByteChannel {
 public:
  enum class Fault { None, LoseAnswer, ExecuteAndLoseAnswer, GarbleAnswer, RejectCrc, BusError };
  std::deque<Fault> script;  // one entry per frame, then None
  std::map<uint32_t, std::deque<Fault>> by_addr;  // one entry per frame to that address (after `script`)
  std::map<uint32_t, uint32_t> regs;
  int fifo_level = 0;
  int drop_pushes = 0;       // ROW_PUSHes answered OKAY but lost inside the board
  std::vector<std::pair<uint32_t, uint32_t>> executed;  // writes that took effect
  // The map: 1-byte frames (the one-axis board), or 2-byte frames and
  // `axes` axis windows (the multi-axis map: DECERR past the last).
  int addr_bytes = 1;
  size_t axes = 0;

  std::optional<Error> send(const std::vector<uint8_t>& bytes) override {
    EXPECT_EQ(bytes[0], uint8_t(hw::UartReqSync));
    const bool is_write = bytes[1] == uint8_t(hw::UartCmdWrite);
    // The bridge takes as many bytes as its frames have and checks their
    // CRC: a frame of the other map fails it (the rest is skipped).
    const size_t len = size_t(3 + addr_bytes + (is_write ? 4 : 0));
    if (bytes.size() < len) return std::nullopt;  // waits for more: dropped after the gap
    const std::vector<uint8_t> f(bytes.begin(), bytes.begin() + ptrdiff_t(len));
    if (crc8(f.data() + 1, len - 2) != f.back()) return answer({uint8_t(hw::UartStCrcErr)});
    uint32_t addr = uint32_t(f[2]) * 4;
    if (addr_bytes == 2) addr = (uint32_t(f[2]) | uint32_t(f[3]) << 8) * 4;
    if (addr_bytes == 2 && (addr >> hw::RegAddrW) > axes) {  // DECERR: no such window (a read answers 4 data bytes)
      return is_write ? answer({3}) : answer({3, 0, 0, 0, 0});
    }
    const size_t data_at = size_t(2 + addr_bytes);
    Fault fault = Fault::None;
    if (!script.empty()) {
      fault = script.front();
      script.pop_front();
    } else if (auto it = by_addr.find(addr); it != by_addr.end() && !it->second.empty()) {
      fault = it->second.front();
      it->second.pop_front();
    }
    if (fault == Fault::LoseAnswer) return std::nullopt;
    if (fault == Fault::RejectCrc) return answer({uint8_t(hw::UartStCrcErr)});
    if (fault == Fault::BusError) return answer({2});
    uint32_t data = 0;
    if (is_write) {
      data = uint32_t(f[data_at]) | uint32_t(f[data_at + 1]) << 8 | uint32_t(f[data_at + 2]) << 16 |
             uint32_t(f[data_at + 3]) << 24;
      execute(addr, data);
    }
    if (fault == Fault::ExecuteAndLoseAnswer) return std::nullopt;
    std::vector<uint8_t> a = {0};
    if (!is_write) {
      const uint32_t v = read(addr);
      for (int i = 0; i < 4; ++i) a.push_back(uint8_t(v >> (8 * i)));
    }
    answer(a);
    if (fault == Fault::GarbleAnswer) out_.back() ^= 0x10;  // the CRC byte
    return std::nullopt;
  }
  std::optional<Error> receive(std::vector<uint8_t>& out, size_t n, double) override {
    while (out.size() < n && !out_.empty()) {
      out.push_back(out_.front());
      out_.pop_front();
    }
    return std::nullopt;
  }
  void discard_input() override { out_.clear(); }
  size_t count(uint32_t addr) const {
    size_t n = 0;
    for (const auto& w : executed) n += w.first == addr;
    return n;
  }

 private:
  std::optional<Error> answer(std::vector<uint8_t> body) {
    std::vector<uint8_t> a = {uint8_t(hw::UartRspSync)};
    a.insert(a.end(), body.begin(), body.end());
    a.push_back(crc8(a.data() + 1, a.size() - 1));
    out_.insert(out_.end(), a.begin(), a.end());
    return std::nullopt;
  }
  void execute(uint32_t addr, uint32_t data) {
    executed.emplace_back(addr, data);
    if (addr == uint32_t(hw::RegRowPush)) {
      if (drop_pushes > 0) {
        --drop_pushes;
      } else {
        ++fifo_level;
      }
    } else if (addr == uint32_t(hw::RegCmd) && (data & bit(hw::CmdFlushBit))) {
      fifo_level = 0;
    } else if (addr == uint32_t(hw::RegCmd) && (data & bit(hw::CmdStartBit))) {
      regs[uint32_t(hw::RegStatus)] |= bit(hw::StatusBusyBit);  // runs: busy, the first row taken
      if (fifo_level > 0) --fifo_level;
    } else {
      regs[addr] = data;
    }
  }
  uint32_t read(uint32_t addr) const {
    if (addr == uint32_t(hw::RegFifoStatus)) return uint32_t(fifo_level);
    auto it = regs.find(addr);
    if ((addr & ((1u << hw::RegAddrW) - 1)) == uint32_t(hw::RegId) && it == regs.end()) {
      return uint32_t(hw::RegIdMagic) << 16 | uint32_t(hw::RegMapVersion);
    }
    return it == regs.end() ? 0 : it->second;
  }
  std::deque<uint8_t> out_;
};

using F = ScriptedBoard::Fault;

Plan short_plan() {
  MoveRequest r;
  r.distance = 500;
  r.v_cruise = 20000;
  r.a_max = 1e6;
  r.j_max = 1e9;
  return std::get<Plan>(Planner{}.plan(r, PulseTiming{}));
}

TEST(UartLink, AReadIsSentAgainAfterLostAndGarbledAnswersAndReturnsTheValue) {
  ScriptedBoard b;
  b.regs[uint32_t(hw::RegRefPos)] = 1234;
  b.script = {F::LoseAnswer, F::GarbleAnswer, F::RejectCrc};
  UartLink link(b, LinkOptions{});
  auto r = link.read(uint32_t(hw::RegRefPos));
  ASSERT_TRUE(std::holds_alternative<uint32_t>(r)) << std::get<Error>(r).message;
  EXPECT_EQ(std::get<uint32_t>(r), 1234u);
  EXPECT_EQ(link.stats().frames, 4u);
  EXPECT_EQ(link.stats().retries, 3u);
  EXPECT_EQ(link.stats().timeouts, 1u);
  EXPECT_EQ(link.stats().bad_responses, 1u);
  EXPECT_EQ(link.stats().crc_rejects, 1u);
}

TEST(UartLink, NoAnswerEndsAfterRetriesPlusOneTriesNamingTheRegister) {
  ScriptedBoard b;
  b.script.assign(10, F::LoseAnswer);
  LinkOptions o;
  o.retries = 2;
  o.timeout = 0.05;
  UartLink link(b, o);
  auto r = link.read(uint32_t(hw::RegStatus));
  ASSERT_TRUE(std::holds_alternative<Error>(r));
  const Error& e = std::get<Error>(r);
  EXPECT_EQ(e.parameter, "port");
  EXPECT_NE(e.message.find("STATUS"), std::string::npos) << e.message;
  EXPECT_NE(e.message.find("no answer after 3 tries of 50 ms"), std::string::npos) << e.message;
  EXPECT_EQ(link.stats().frames, 3u);
  EXPECT_EQ(board_exit_code(e), 2);
}

TEST(UartLink, ARowPushWhoseAnswerIsLostIsNotSentAgain) {
  ScriptedBoard b;
  b.script = {F::ExecuteAndLoseAnswer};
  UartLink link(b, LinkOptions{});
  auto e = link.write(uint32_t(hw::RegRowPush), 3);
  ASSERT_TRUE(e);
  EXPECT_NE(e->message.find("not sent again"), std::string::npos) << e->message;
  EXPECT_EQ(b.count(uint32_t(hw::RegRowPush)), 1u);  // it did take effect, once
  EXPECT_EQ(link.stats().frames, 1u);
}

TEST(UartLink, AStartWhoseAnswerIsGarbledIsNotSentAgainButAStopIs) {
  ScriptedBoard b;
  b.script = {F::GarbleAnswer};
  UartLink link(b, LinkOptions{});
  EXPECT_TRUE(link.write(uint32_t(hw::RegCmd), bit(hw::CmdStartBit)));
  EXPECT_EQ(b.count(uint32_t(hw::RegCmd)), 1u);
  b.script = {F::GarbleAnswer};
  EXPECT_FALSE(link.write(uint32_t(hw::RegCmd), bit(hw::CmdStopBit)));
  EXPECT_EQ(b.count(uint32_t(hw::RegCmd)), 3u);  // the STOP twice: harmless
}

TEST(UartLink, ARowPushTheBoardReceivedGarbledIsSentAgain) {
  ScriptedBoard b;
  b.script = {F::RejectCrc, F::RejectCrc};
  UartLink link(b, LinkOptions{});
  EXPECT_FALSE(link.write(uint32_t(hw::RegRowPush), 0));
  EXPECT_EQ(b.count(uint32_t(hw::RegRowPush)), 1u);
  EXPECT_EQ(link.stats().crc_rejects, 2u);
}

TEST(UartLink, ABusErrorIsTheBoardsAnswerAndNotRetried) {
  ScriptedBoard b;
  b.script = {F::BusError};
  UartLink link(b, LinkOptions{});
  auto e = link.write(uint32_t(hw::RegCmd), bit(hw::CmdStartBit));
  ASSERT_TRUE(e);
  EXPECT_EQ(e->parameter, "board");
  EXPECT_NE(e->message.find("SLVERR"), std::string::npos) << e->message;
  EXPECT_EQ(board_exit_code(*e), 1);
  EXPECT_EQ(link.stats().frames, 1u);
}

TEST(UartLink, OptionsOutOfRangeAreRefusedNamingTheParameter) {
  LinkOptions o;
  o.timeout = 0;
  EXPECT_EQ(check_link_options(o)->parameter, "timeout");
  o = LinkOptions{};
  o.timeout = std::nan("");
  EXPECT_EQ(check_link_options(o)->parameter, "timeout");
  o = LinkOptions{};
  o.retries = -1;
  EXPECT_EQ(check_link_options(o)->parameter, "retries");
  o = LinkOptions{};
  o.baud = 115201;
  auto e = check_link_options(o);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->parameter, "baud");
  EXPECT_NE(e->message.find("115201"), std::string::npos);
  o = LinkOptions{};
  o.addr_bits = 12;
  EXPECT_EQ(check_link_options(o)->parameter, "addr_bits");
  EXPECT_FALSE(check_link_options(LinkOptions{}));
  o.addr_bits = hw::MultiRegAddrW;
  EXPECT_FALSE(check_link_options(o));
}

TEST(BoardMap, TheMapIsToldByTheAnswerToAMultiAxisFrame) {
  ScriptedBoard one;
  auto bits = detect_addr_bits(one, LinkOptions{});
  ASSERT_TRUE(std::holds_alternative<int>(bits)) << std::get<Error>(bits).message;
  EXPECT_EQ(std::get<int>(bits), hw::RegAddrW) << "the one-axis bridge answers the longer frame with a CRC error";
  ScriptedBoard two;
  two.addr_bytes = 2;
  two.axes = 2;
  bits = detect_addr_bits(two, LinkOptions{});
  ASSERT_TRUE(std::holds_alternative<int>(bits)) << std::get<Error>(bits).message;
  EXPECT_EQ(std::get<int>(bits), hw::MultiRegAddrW);
  ScriptedBoard silent;
  silent.script.assign(10, F::LoseAnswer);
  bits = detect_addr_bits(silent, LinkOptions{});
  ASSERT_TRUE(std::holds_alternative<Error>(bits));
  EXPECT_EQ(std::get<Error>(bits).parameter, "port");
}

TEST(BoardMap, AnAxisGroupHasTheAxesWhoseWindowsAnswerAndConfiguresThemThroughTheGroup) {
  for (size_t axes : {size_t(1), size_t(2), size_t(4)}) {
    ScriptedBoard b;
    b.addr_bytes = 2;
    b.axes = axes;
    LinkOptions o;
    o.addr_bits = hw::MultiRegAddrW;
    UartLink link(b, o);
    AxisGroup group(link);
    auto info = group.identify();
    ASSERT_TRUE(std::holds_alternative<BoardInfo>(info)) << std::get<Error>(info).message;
    EXPECT_EQ(std::get<BoardInfo>(info).axes, int(axes));
    EXPECT_EQ(group.axes(), axes);
    b.executed.clear();
    BoardConfig cfg;
    cfg.timing.high = 7;
    ASSERT_FALSE(group.configure(cfg));
    bool pulse_time = false;
    for (const auto& w : b.executed) {
      EXPECT_EQ(w.first >> hw::RegAddrW, 0u) << "configure writes the group window only";
      pulse_time = pulse_time || (w.first == uint32_t(hw::RegPulseTime) && (w.second >> hw::PulseHighLsb & 0xFFFF) == 7);
    }
    EXPECT_TRUE(pulse_time);
    // An axis's status reads its own window.
    b.regs[multi_axis_addr(axes - 1, hw::RegRefPos)] = 1234;
    auto st = group.status();
    ASSERT_TRUE(std::holds_alternative<std::vector<BoardStatus>>(st));
    EXPECT_EQ(std::get<std::vector<BoardStatus>>(st).back().ref_pos, 1234);
  }
}

TEST(BoardLoad, AMoveWithALostRowIsNeverStarted) {
  ScriptedBoard b;
  b.drop_pushes = 1;
  UartLink link(b, LinkOptions{});
  Board board(link);
  auto e = board.load_move(short_plan());
  ASSERT_TRUE(e);
  EXPECT_NE(e->message.find("a row was lost"), std::string::npos) << e->message;
  for (const auto& w : b.executed) {
    EXPECT_FALSE(w.first == uint32_t(hw::RegCmd) && (w.second & bit(hw::CmdStartBit))) << "START was written";
  }
}

TEST(BoardLoad, EveryRowArrivesAndUnchangedStagingWordsAreNotSentAgain) {
  ScriptedBoard b;
  UartLink link(b, LinkOptions{});
  Board board(link);
  const Plan p = short_plan();
  ASSERT_FALSE(board.load_move(p));
  EXPECT_EQ(b.fifo_level, int(p.segments.size()));
  // Each staging word holds what the row needs when it is pushed.
  size_t row = 0;
  std::map<uint32_t, uint32_t> staged;
  for (const auto& w : b.executed) {
    if (w.first != uint32_t(hw::RegRowPush)) {
      staged[w.first] = w.second;
      continue;
    }
    for (const RegWrite& x : encode_row(p.segments[row], move_row_flags(p.segments)[row])) {
      if (x.addr != uint32_t(hw::RegRowPush)) EXPECT_EQ(staged[x.addr], x.data) << reg_name(x.addr) << " row " << row;
    }
    ++row;
  }
  EXPECT_EQ(row, p.segments.size());
  EXPECT_LT(b.executed.size(), 10 * p.segments.size() + 10);  // fewer than every word of every row
}

TEST(BoardLoad, RowPushesAndAStartWhoseFramesOrAnswersAreLostArriveExactlyOnce) {
  ScriptedBoard b;
  const Plan p = short_plan();
  // ROW_PUSH: the 1st request lost on the line, the 2nd executed with its
  // answer lost; START: the request lost, then the answer lost.
  b.by_addr[uint32_t(hw::RegRowPush)] = {F::LoseAnswer, F::None, F::ExecuteAndLoseAnswer};
  b.by_addr[uint32_t(hw::RegCmd)] = {F::None /* FLUSH */, F::LoseAnswer, F::ExecuteAndLoseAnswer};
  UartLink link(b, LinkOptions{});
  Board board(link);
  ASSERT_FALSE(board.load_move(p));
  EXPECT_EQ(b.count(uint32_t(hw::RegRowPush)), p.segments.size());  // each row once
  EXPECT_EQ(b.fifo_level, int(p.segments.size()));
  ASSERT_FALSE(board.start());
  EXPECT_TRUE(b.by_addr[uint32_t(hw::RegRowPush)].empty() && b.by_addr[uint32_t(hw::RegCmd)].empty());
  size_t starts = 0;
  for (const auto& w : b.executed) starts += w.first == uint32_t(hw::RegCmd) && (w.second & bit(hw::CmdStartBit));
  EXPECT_EQ(starts, 1u);
}

TEST(BoardIdentify, AnotherMagicIsNoBoardAndAnotherMajorVersionIsRefused) {
  ScriptedBoard b;
  UartLink link(b, LinkOptions{});
  Board board(link);
  auto ok = board.identify();
  ASSERT_TRUE(std::holds_alternative<BoardInfo>(ok)) << std::get<Error>(ok).message;
  EXPECT_EQ(std::get<BoardInfo>(ok).axes, 1);
  EXPECT_EQ(std::get<BoardInfo>(ok).version_major, hw::RegMapVersion >> 8);
  b.regs[uint32_t(hw::RegId)] = 0x12345678;
  auto other = board.identify();
  ASSERT_TRUE(std::holds_alternative<Error>(other));
  EXPECT_EQ(std::get<Error>(other).parameter, "port");
  EXPECT_NE(std::get<Error>(other).message.find("not an scurve board"), std::string::npos);
  b.regs[uint32_t(hw::RegId)] = uint32_t(hw::RegIdMagic) << 16 | uint32_t((hw::RegMapVersion >> 8) - 1) << 8;
  auto old = board.identify();
  ASSERT_TRUE(std::holds_alternative<Error>(old));
  EXPECT_EQ(std::get<Error>(old).parameter, "board");
  EXPECT_NE(std::get<Error>(old).message.find("register map"), std::string::npos);
}

}  // namespace
