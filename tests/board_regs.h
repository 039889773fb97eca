// Helpers shared by the register-level board tests (test_board.cpp,
// test_board_servo.cpp): registers and fields looked up in the generated
// register table (the documented map, not the RTL constants), the reset
// read-back check, a planner call that throws on a rejected request, the
// host library's request helper, a move's and a stream's rows through the
// registers.
#pragma once

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <variant>

#include "axi_bench.h"
#include "paper_moves.h"
#include "planner.h"
#include "reg_encode.h"
#include "sc_regmap.h"

namespace sc::board_test {

inline const regmap::Reg& reg(const std::string& name) {
  for (const regmap::Reg& r : regmap::kRegs)
    if (name == r.name) return r;
  throw std::runtime_error("no register " + name);
}
// Field mask from the generated table (the docs), not from the RTL constants.
inline uint32_t field_mask(const std::string& rname, const std::string& fname) {
  const regmap::Reg& r = reg(rname);
  for (int i = 0; i < r.nfields; ++i)
    if (fname == r.fields[i].name) return ((r.fields[i].width >= 32 ? 0 : (1u << r.fields[i].width)) - 1) << r.fields[i].lsb;
  throw std::runtime_error("no field " + rname + "." + fname);
}
inline uint32_t reg_addr(const std::string& name) { return reg(name).addr; }

// Read right after reset: OKAY, reserved bits 0 and, for the registers the
// host writes (RW, WO) and ID, the reset value.
template <class Bench>
void expect_reset_read(Bench& b, const regmap::Reg& r) {
  const auto [v, resp] = b.read(r.addr);
  EXPECT_EQ(resp, kOkay) << r.name;
  EXPECT_EQ(v & ~r.mask, 0u) << r.name << ": reserved bits read 1";
  if (r.access == regmap::Access::RW || r.access == regmap::Access::WO || std::string(r.name) == "ID") {
    EXPECT_EQ(v, r.reset) << r.name << " reset value";
  }
}

inline Plan plan_or_die(const MoveRequest& req, const PulseTiming& t = PulseTiming{}) {
  const PlanResult r = plan_move(req, t);
  if (const auto* e = std::get_if<PlanError>(&r)) throw std::runtime_error(e->message);
  return std::get<Plan>(r);
}

// STOP_JERK / STOP_ACC from physical limits (pulses/s^3, pulses/s^2).
template <class Bench>
void set_stop_limits(Bench& b, double stop_jerk, double stop_acc) {
  const auto w = scurve::encode_stop_limits(stop_jerk, stop_acc);
  ASSERT_TRUE(std::holds_alternative<std::vector<RegWrite>>(w));
  for (const RegWrite& r : std::get<std::vector<RegWrite>>(w)) ASSERT_EQ(b.write(r.addr, r.data), kOkay);
}

// A planned move's rows, pulse timing and POS_FRAC0 through the registers (no START).
template <class Bench>
void load(Bench& b, const Plan& p, const PulseTiming& t) {
  for (const RegWrite& w : encode_move(p, t, false)) {
    ASSERT_EQ(b.write(w.addr, w.data), kOkay) << reg_name(w.addr);
  }
}

// Streams host rows (the stream planner's, with their ROW_PUSH flags) as a
// host does while the axis runs: a ROW_PUSH refused because the FIFO is full
// is retried (the staged row is kept) until there is room.
template <class Bench>
void push_rows(Bench& b, const std::vector<scurve::Segment>& rows, const std::vector<scurve::RowFlags>& flags) {
  for (size_t i = 0; i < rows.size(); ++i) {
    for (const scurve::RegWrite& w : scurve::encode_row(rows[i], flags[i])) {
      if (w.addr != uint32_t(reg_addr("ROW_PUSH"))) {
        ASSERT_EQ(b.write(w.addr, w.data), kOkay) << scurve::reg_name(w.addr) << " row " << i;
        continue;
      }
      for (int tries = 0; b.write(w.addr, w.data) != kOkay; ++tries) {
        ASSERT_LT(tries, 100000) << "row " << i << ": the FIFO never drains";
        ASSERT_EQ(b.read(reg_addr("ERR")).first & field_mask("ERR", "FIFO_FULL"), field_mask("ERR", "FIFO_FULL"));
        b.idle(200);
      }
    }
  }
  if (b.read(reg_addr("ERR")).first & field_mask("ERR", "FIFO_FULL")) {
    ASSERT_EQ(b.write(reg_addr("ERR"), field_mask("ERR", "FIFO_FULL")), kOkay);
  }
}

}  // namespace sc::board_test
