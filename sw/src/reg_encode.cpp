#include "scurve/reg_encode.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "scurve/hw/regmap.h"

namespace scurve {

using namespace hw;

std::string reg_name(uint32_t addr) {
  for (const regmap::Reg& r : regmap::kRegs)
    if (r.addr == addr) return r.name;
  return "?";
}

uint32_t RowFlags::word() const {
  return (move_end ? 1u << RowPushMoveEndBit : 0u) | (stream_end ? 1u << RowPushStreamEndBit : 0u) |
         (acc_step ? 1u << RowPushAccStepBit : 0u) | (hold ? 1u << RowPushHoldBit : 0u) |
         (replace ? 1u << RowPushReplaceBit : 0u);
}

std::vector<RowFlags> move_row_flags(const std::vector<Segment>& rows, bool stream_end,
                                     std::optional<int64_t> acc_before) {
  std::vector<RowFlags> f(rows.size());
  if (!rows.empty() && acc_before) f[0].acc_step = rows[0].acc0 != *acc_before;
  for (size_t i = 1; i < rows.size(); ++i) {
    const Segment& p = rows[i - 1];
    f[i].acc_step = i128(rows[i].acc0) != acc_after(p.acc0, p.jerk, p.clocks);
  }
  if (!f.empty()) {
    f.back().move_end = true;
    f.back().stream_end = stream_end;
  }
  return f;
}

std::vector<RegWrite> encode_retarget(uint32_t row, const std::vector<Segment>& rows,
                                      const std::vector<RowFlags>& flags) {
  std::vector<RegWrite> w{{RegRetargetRow, row}};
  for (size_t i = 0; i < rows.size(); ++i) {
    RowFlags f = i < flags.size() ? flags[i] : RowFlags{};
    f.replace = i == 0;
    for (const RegWrite& r : encode_row(rows[i], f)) w.push_back(r);
  }
  return w;
}

std::vector<RowFlags> velocity_row_flags(const VelocityPlan& plan) {
  std::vector<RowFlags> f = move_row_flags(plan.segments, !plan.hold);
  if (!f.empty()) f.back().hold = plan.hold;
  return f;
}

std::vector<RegWrite> encode_row(const Segment& s, RowFlags flags) {
  const uint64_t jerk = uint64_t(s.jerk) & ((uint64_t(1) << JerkW) - 1);
  const uint64_t acc = uint64_t(s.acc0);
  const u128 vel = mask_bits(u128(s.vel0), VelW);
  return {
      {uint32_t(RegSegPhase), uint32_t(uint8_t(s.phase)) << SegPhaseLsb},
      {uint32_t(RegSegClocks), s.clocks},
      {uint32_t(RegSegJerk), uint32_t(jerk)},
      {uint32_t(RegSegJerk + 4), uint32_t(jerk >> 32)},
      {uint32_t(RegSegAcc0), uint32_t(acc)},
      {uint32_t(RegSegAcc0 + 4), uint32_t(acc >> 32)},
      {uint32_t(RegSegVel0), uint32_t(vel)},
      {uint32_t(RegSegVel0 + 4), uint32_t(vel >> 32)},
      {uint32_t(RegSegVel0 + 8), uint32_t(vel >> 64)},
      {uint32_t(RegRowPush), flags.word()},
  };
}

uint32_t multi_axis_addr(std::optional<size_t> axis, uint32_t reg) {
  const uint32_t window = axis ? uint32_t(*axis) + 1 : 0;
  return (window << RegAddrW) | (reg & ((uint32_t(1) << RegAddrW) - 1));
}

std::vector<RegWrite> encode_multi_row(const std::vector<Segment>& axis_rows, RowFlags flags) {
  std::vector<RegWrite> out;
  for (size_t a = 0; a < axis_rows.size(); ++a) {
    for (const RegWrite& w : encode_row(axis_rows[a], flags)) {
      if (w.addr == uint32_t(RegSegClocks) || w.addr == uint32_t(RegRowPush)) continue;
      out.push_back({multi_axis_addr(a, w.addr), w.data});
    }
  }
  const uint32_t clocks = axis_rows.empty() ? 0 : axis_rows[0].clocks;
  out.push_back({multi_axis_addr(std::nullopt, uint32_t(RegSegClocks)), clocks});
  out.push_back({multi_axis_addr(std::nullopt, uint32_t(RegRowPush)), flags.word()});
  return out;
}

StopLimitCodesResult stop_limit_codes(double stop_jerk, double stop_acc, Clock clock) {
  auto check = [](const char* name, double v, LimitRange r) -> std::optional<Error> {
    if (std::isfinite(v) && v >= r.lo && v <= r.hi) return std::nullopt;
    return Error{name, fmt::format("{}={}: needs a number in [{}, {}]", name, v, r.lo, r.hi)};
  };
  if (auto e = check("stop_jerk", stop_jerk, jerk_range(clock))) return *e;
  if (auto e = check("stop_acc", stop_acc, accel_range(clock))) return *e;
  // At least one LSB; below half the register range (the ranges guarantee it).
  return StopLimitCodes{std::max<uint64_t>(1, uint64_t(stop_jerk * jerk_lsb_per_unit(clock))),
                        std::max<uint64_t>(1, uint64_t(stop_acc * acc_lsb_per_unit(clock)))};
}

StopLimitsResult encode_stop_limits(double stop_jerk, double stop_acc, Clock clock) {
  const StopLimitCodesResult r = stop_limit_codes(stop_jerk, stop_acc, clock);
  if (const Error* e = std::get_if<Error>(&r)) return *e;
  const StopLimitCodes c = std::get<StopLimitCodes>(r);
  return std::vector<RegWrite>{
      {uint32_t(RegStopJerk), uint32_t(c.jerk)},
      {uint32_t(RegStopJerk + 4), uint32_t(c.jerk >> 32)},
      {uint32_t(RegStopAcc), uint32_t(c.acc)},
      {uint32_t(RegStopAcc + 4), uint32_t(c.acc >> 32)},
  };
}

GuardLimitCodesResult guard_limit_codes(double guard_v, double guard_a, double guard_j, Clock clock) {
  auto check = [](const char* name, double v, LimitRange r) -> std::optional<Error> {
    if (std::isfinite(v) && v >= r.lo && v <= r.hi) return std::nullopt;
    return Error{name, fmt::format("{}={}: needs a number in [{}, {}]", name, v, r.lo, r.hi)};
  };
  if (!std::isfinite(guard_v) || guard_v <= 0 || guard_v >= clock.hz) {
    return Error{"guard_v", fmt::format("guard_v={}: needs a number in (0, {}) (below one pulse per clock)",
                                        guard_v, clock.hz)};
  }
  if (auto e = check("guard_a", guard_a, accel_range(clock))) return *e;
  if (auto e = check("guard_j", guard_j, jerk_range(clock))) return *e;
  // Rounded up past the conversion's own rounding (a relative 2^-50 covers
  // it): a row planned within the same limits is never over them. |v| < 1
  // pulse/clock keeps the velocity code at most 2^FracBits.
  auto up = [](long double lsb) { return u128(std::ceil(lsb + lsb * 0x1p-50L)); };
  const long double hz = clock.hz, one = kTwoPowFrac;
  return GuardLimitCodes{std::min(up(guard_v * one / hz), kOne), uint64_t(up(guard_a * one / (hz * hz))),
                         uint64_t(up(guard_j * one / (hz * hz * hz)))};
}

GuardLimitCodesResult move_guard_codes(const MoveRequest& r, Clock clock) {
  return guard_limit_codes(std::max({r.v_start, r.v_cruise, r.v_end}), r.a_max, move_stop_limits(r, clock).jerk,
                           clock);
}

std::vector<RegWrite> encode_guard_codes(const GuardLimitCodes& c) {
  return {
      {uint32_t(RegGuardVel), uint32_t(c.vel)},
      {uint32_t(RegGuardVel + 4), uint32_t(c.vel >> 32)},
      {uint32_t(RegGuardVel + 8), uint32_t(c.vel >> 64)},
      {uint32_t(RegGuardAcc), uint32_t(c.acc)},
      {uint32_t(RegGuardAcc + 4), uint32_t(c.acc >> 32)},
      {uint32_t(RegGuardJerk), uint32_t(c.jerk)},
      {uint32_t(RegGuardJerk + 4), uint32_t(c.jerk >> 32)},
  };
}

SoftLimitWritesResult encode_soft_limits(const SoftLimits& w) {
  constexpr int64_t lo = -(int64_t(1) << (PosIntW - 1)), hi = (int64_t(1) << (PosIntW - 1)) - 1;
  const int64_t mn = w.min_pos.value_or(lo), mx = w.max_pos.value_or(hi);
  if (mn < lo || mn > hi) {
    return Error{"soft_limits.min_pos",
                 fmt::format("soft_limits.min_pos={}: the hardware window needs {} .. {} (REF_POS)", mn, lo, hi)};
  }
  if (mx < lo || mx > hi) {
    return Error{"soft_limits.max_pos",
                 fmt::format("soft_limits.max_pos={}: the hardware window needs {} .. {} (REF_POS)", mx, lo, hi)};
  }
  const uint32_t sw_cfg = (1u << SwLimEnBit) | (1u << SwSoftEnBit) | (uint32_t(RstDebounce) << SwDebounceLsb);
  return std::vector<RegWrite>{{uint32_t(RegSoftMin), uint32_t(int32_t(mn))},
                               {uint32_t(RegSoftMax), uint32_t(int32_t(mx))},
                               {uint32_t(RegSwCfg), sw_cfg}};
}

GuardLimitsResult encode_guard_limits(double guard_v, double guard_a, double guard_j, Clock clock) {
  const GuardLimitCodesResult r = guard_limit_codes(guard_v, guard_a, guard_j, clock);
  if (const Error* e = std::get_if<Error>(&r)) return *e;
  return encode_guard_codes(std::get<GuardLimitCodes>(r));
}

StopLimits move_stop_limits(const MoveRequest& r, Clock clock) {
  StopLimits s;
  s.acc = r.a_max;
  if (r.kind == ProfileKind::SCurve) {
    s.jerk = r.jerks ? std::max({(*r.jerks)[0], (*r.jerks)[1], (*r.jerks)[2], (*r.jerks)[3]}) : r.j_max;
  } else {
    const LimitRange jr = jerk_range(clock);
    s.jerk = std::clamp(r.a_max / 1e-3, jr.lo, jr.hi);
  }
  return s;
}

RegWrite stop_command() { return {uint32_t(RegCmd), 1u << CmdStopBit}; }

std::vector<RegWrite> encode_servo_config(const ServoConfig& c) {
  const std::array<uint32_t, hw::ClCfgWords> words = hw::ctl_cfg_to_words(c.ctl);
  std::vector<RegWrite> out;
  for (int i = 0; i < ClCfgWords; ++i) out.push_back({uint32_t(RegClFirst + 4 * i), words[size_t(i)]});
  return out;
}

std::vector<RegWrite> encode_move(const Plan& plan, const PulseTiming& t, bool start) {
  std::vector<RegWrite> w;
  w.push_back({uint32_t(RegCtrl), 1u << CtrlEnableBit});
  w.push_back({uint32_t(RegPulseTime), (uint32_t(t.high) << PulseHighLsb) | (uint32_t(t.low) << PulseLowLsb)});
  w.push_back({uint32_t(RegDirTime), (uint32_t(t.setup) << DirSetupLsb) | (uint32_t(t.hold) << DirHoldLsb)});
  const std::vector<RowFlags> flags = move_row_flags(plan.segments);
  for (size_t i = 0; i < plan.segments.size(); ++i) {
    const auto row = encode_row(plan.segments[i], flags[i]);
    w.insert(w.end(), row.begin(), row.end());
  }
  const u128 f = mask_bits(plan.pos_frac0, FracBits);
  w.push_back({uint32_t(RegPosFrac0), uint32_t(f)});
  w.push_back({uint32_t(RegPosFrac0 + 4), uint32_t(f >> 32)});
  w.push_back({uint32_t(RegPosFrac0 + 8), uint32_t(f >> 64)});
  if (start) w.push_back({uint32_t(RegCmd), 1u << CmdStartBit});
  return w;
}

uint8_t crc8(const uint8_t* data, size_t n, uint8_t crc) {
  for (size_t i = 0; i < n; ++i) {
    crc ^= data[i];
    for (int b = 0; b < 8; ++b) crc = (crc & 0x80) ? uint8_t((crc << 1) ^ 0x07) : uint8_t(crc << 1);
  }
  return crc;
}

namespace {

// The frame's address bytes (the word address, low byte first), or why
// `addr` has none in a map of `addr_bits` byte address bits.
std::variant<std::vector<uint8_t>, Error> frame_addr(uint32_t addr, int addr_bits) {
  if (addr_bits != RegAddrW && addr_bits != MultiRegAddrW) {
    return Error{"addr_bits", fmt::format("addr_bits={}: the register maps have {} (one axis) or {} (multi-axis) "
                                          "address bits", addr_bits, RegAddrW, MultiRegAddrW)};
  }
  const uint32_t map = uint32_t(1) << addr_bits;  // bytes
  if (addr % 4 != 0)
    return Error{"addr", fmt::format("addr=0x{:X}: not word-aligned (must be a multiple of 4)", addr)};
  if (addr >= map)
    return Error{"addr", fmt::format("addr=0x{:X}: outside the register map 0x000..0x{:03X}", addr, map - 4)};
  std::vector<uint8_t> bytes;
  for (int i = 0; i < uart_addr_bytes(addr_bits); ++i) bytes.push_back(uint8_t((addr / 4) >> (8 * i)));
  return bytes;
}

FrameResult request_frame(uint8_t cmd, uint32_t addr, const uint32_t* data, int addr_bits) {
  const auto a = frame_addr(addr, addr_bits);
  if (const Error* e = std::get_if<Error>(&a)) return *e;
  std::vector<uint8_t> f = {uint8_t(UartReqSync), cmd};
  for (uint8_t byte : std::get<std::vector<uint8_t>>(a)) f.push_back(byte);
  if (data) {
    for (int i = 0; i < 4; ++i) f.push_back(uint8_t(*data >> (8 * i)));
  }
  f.push_back(crc8(f.data() + 1, f.size() - 1));
  return f;
}

}  // namespace

int uart_addr_bytes(int addr_bits) { return (addr_bits - 2 + 7) / 8; }

FrameResult uart_write_frame(uint32_t addr, uint32_t data, int addr_bits) {
  return request_frame(uint8_t(UartCmdWrite), addr, &data, addr_bits);
}

FrameResult uart_read_frame(uint32_t addr, int addr_bits) {
  return request_frame(uint8_t(UartCmdRead), addr, nullptr, addr_bits);
}

UartResponse parse_uart_response(const std::vector<uint8_t>& b, bool is_read) {
  UartResponse r;
  if (b.size() < 3 || b[0] != uint8_t(UartRspSync)) {
    r.error = fmt::format("no response sync ({} bytes)", b.size());
    return r;
  }
  r.status = b[1];
  const bool has_data = is_read && r.status < 0x80;
  const size_t len = has_data ? 7 : 3;
  if (b.size() != len) {
    r.error = fmt::format("response length {} != {}", b.size(), len);
    return r;
  }
  if (crc8(b.data() + 1, len - 2) != b[len - 1]) {
    r.error = "response CRC wrong";
    return r;
  }
  if (has_data) r.data = uint32_t(b[2]) | uint32_t(b[3]) << 8 | uint32_t(b[4]) << 16 | uint32_t(b[5]) << 24;
  r.ok = true;
  return r;
}

}  // namespace scurve
