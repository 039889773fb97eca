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

  std::optional<Error> send(const std::vector<uint8_t>& f) override {
    EXPECT_EQ(f[0], uint8_t(hw::UartReqSync));
    const bool is_write = f[1] == uint8_t(hw::UartCmdWrite);
    const uint32_t addr = uint32_t(f[2]) * 4;
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
      data = uint32_t(f[3]) | uint32_t(f[4]) << 8 | uint32_t(f[5]) << 16 | uint32_t(f[6]) << 24;
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
    if (addr == uint32_t(hw::RegId) && it == regs.end()) {
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
  EXPECT_FALSE(check_link_options(LinkOptions{}));
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
