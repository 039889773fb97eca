// Host side of the register interface: a planned move as the register
// write sequence (docs/regmap.md "Loading and running a move") and the
// UART bridge frames (CRC-8/0x07) that carry register reads and writes.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "scurve/planner.h"
#include "scurve/servo_config.h"

namespace scurve {

struct RegWrite {
  uint32_t addr = 0;
  uint32_t data = 0;
};

// Register name for an address ("SEG_VEL0_2"), or "?" if none.
std::string reg_name(uint32_t addr);

// CTRL enable, pulse timing, every row of the move (staging + ROW_PUSH with
// move_row_flags()), POS_FRAC0 and, if `start`,
// CMD.START. The FIFO must be empty (after reset, CMD.FLUSH or a finished
// stream) and hold the rows: a planned move has at most MaxSegs rows.
std::vector<RegWrite> encode_move(const Plan& plan, const PulseTiming& timing, bool start = true);
// The controller settings of sc_axi_servo (CL_CFG .. SETTLE_RATE, in
// address order) for a closed-loop configuration (the register file decodes
// them back; enable/closed_loop/timing are not in them).
std::vector<RegWrite> encode_servo_config(const ServoConfig& c);
// The ROW_PUSH flags of a row.
struct RowFlags {
  bool move_end = false;    // last row of a move
  bool stream_end = false;  // last row of the stream
  bool acc_step = false;    // starts with a planned acceleration step (trapezoid)
  bool hold = false;        // velocity mode: holds its constant velocity until a whole move is queued
  bool replace = false;     // retarget: becomes row RETARGET_ROW, dropping the queued rows from there on
  uint32_t word() const;    // the ROW_PUSH value
};
// The flags of a move's rows: the last MOVE_END (and STREAM_END when the
// move ends the stream: a single move's end speed is its stop speed); a row
// whose start acceleration differs from the previous row's end ACC_STEP.
// acc_before: where the rows continue a motion (a retarget), the executor's
// acceleration when the first row loads; the first row is ACC_STEP if it
// starts at another (a trapezoid's planned step).
std::vector<RowFlags> move_row_flags(const std::vector<Segment>& rows, bool stream_end = true,
                                     std::optional<int64_t> acc_before = std::nullopt);
// The flags of a velocity-mode command (Planner::plan_velocity): one move,
// its last row HOLD, or STREAM_END when the target is rest.
std::vector<RowFlags> velocity_row_flags(const VelocityPlan& plan);
// One row's staging writes and its ROW_PUSH.
std::vector<RegWrite> encode_row(const Segment& s, RowFlags flags = {});
// The multi-axis map (sc_axi_multi_axis): the byte address of register
// `reg` (a one-axis map address) in axis `axis`'s window, or in the group
// window (whose writes reach every axis) when `axis` is empty.
uint32_t multi_axis_addr(std::optional<size_t> axis, uint32_t reg);
// One multi-axis row: each axis's staging (SEG_PHASE, SEG_JERK, SEG_ACC0,
// SEG_VEL0) in its own window, then the shared SEG_CLOCKS (axis 0's row's:
// every axis's row lasts the same clocks) and ROW_PUSH in the group window.
std::vector<RegWrite> encode_multi_row(const std::vector<Segment>& axis_rows, RowFlags flags = {});
// Retarget: RETARGET_ROW = `row`, then the rows, the first one with
// ROW_PUSH.REPLACE (it becomes row number `row`; the queued rows from there
// on are dropped), the rest appended behind it. The executor refuses the
// replace (ERR.RETARGET, nothing changes) if that row is already loaded:
// the host reads ERR after the first ROW_PUSH.
std::vector<RegWrite> encode_retarget(uint32_t row, const std::vector<Segment>& rows,
                                      const std::vector<RowFlags>& flags);

// The controlled-stop limits (STOP_JERK, STOP_ACC) for a stop jerk
// (pulses/s^3) and stop deceleration (pulses/s^2) at `clock`: the register
// writes, or an Error naming "stop_jerk" / "stop_acc" when a value is not a
// finite number inside jerk_range() / accel_range(). Written while idle
// (refused while busy); CMD.STOP, an underrun or a discontinuity use them.
using StopLimitsResult = std::variant<std::vector<RegWrite>, Error>;
StopLimitsResult encode_stop_limits(double stop_jerk, double stop_acc, Clock clock = Clock{});
// The same limits as the register values (executor LSBs at `clock`), with
// the same errors.
struct StopLimitCodes {
  uint64_t jerk = 0;  // STOP_JERK
  uint64_t acc = 0;   // STOP_ACC
};
using StopLimitCodesResult = std::variant<StopLimitCodes, Error>;
StopLimitCodesResult stop_limit_codes(double stop_jerk, double stop_acc, Clock clock = Clock{});
// The stop limits a move's own limits give, the default of the tools: its
// acceleration limit and its jerk limit (the largest of asymmetric jerks).
// A trapezoid has no jerk limit: it stops with the jerk that reaches its
// acceleration limit in 1 ms (inside jerk_range(clock)).
struct StopLimits {
  double jerk = 0;  // pulses/s^3
  double acc = 0;   // pulses/s^2
};
StopLimits move_stop_limits(const MoveRequest& request, Clock clock = Clock{});
// The row guards (GUARD_VEL, GUARD_ACC, GUARD_JERK): the largest velocity
// (pulses/s), acceleration (pulses/s^2) and jerk (pulses/s^3) a row may
// start with at `clock`, rounded up (to the next LSB past the conversion's
// rounding, at most a relative 2^-50 above the exact value), so a plan
// within the same limits passes. The register writes, or an Error naming "guard_v"
// (a finite number in (0, clock rate): below one pulse per clock),
// "guard_a" (accel_range()) or "guard_j" (jerk_range()). Written while idle
// (refused while busy); the executor refuses a row over them at its
// boundary (docs/regmap.md).
struct GuardLimitCodes {
  u128 vel = 0;       // GUARD_VEL
  uint64_t acc = 0;   // GUARD_ACC
  uint64_t jerk = 0;  // GUARD_JERK
};
using GuardLimitCodesResult = std::variant<GuardLimitCodes, Error>;
GuardLimitCodesResult guard_limit_codes(double guard_v, double guard_a, double guard_j, Clock clock = Clock{});
// The guards a move's own limits give: its largest speed (v_start, v_cruise,
// v_end), a_max and its jerk limit as move_stop_limits() takes it.
GuardLimitCodesResult move_guard_codes(const MoveRequest& request, Clock clock = Clock{});
// The register writes of guard codes as they are (0 = no limit).
std::vector<RegWrite> encode_guard_codes(const GuardLimitCodes& codes);
using GuardLimitsResult = std::variant<std::vector<RegWrite>, Error>;
GuardLimitsResult encode_guard_limits(double guard_v, double guard_a, double guard_j, Clock clock = Clock{});
// A travel window as the hardware soft limits: SOFT_MIN, SOFT_MAX (an
// unbounded side at the end of REF_POS's 32-bit range) and SW_CFG at its
// reset value with SOFT_EN. The window is in REF_POS coordinates (the
// planner's start_position is REF_POS at the START). An Error naming
// "soft_limits.min_pos" / "soft_limits.max_pos" when a bound is beyond
// REF_POS's range. Written while idle (refused while busy).
using SoftLimitWritesResult = std::variant<std::vector<RegWrite>, Error>;
SoftLimitWritesResult encode_soft_limits(const SoftLimits& window);
// CMD.STOP: the controlled stop with the limits in STOP_JERK / STOP_ACC.
RegWrite stop_command();

// CRC-8, polynomial 0x07, initial 0x00, no reflection, no final XOR.
uint8_t crc8(const uint8_t* data, size_t n, uint8_t crc = 0);
// UART bridge request frames for the register at byte address `addr` (as in
// RegWrite and docs/regmap.md) of a map with `addr_bits` byte address bits:
// RegAddrW (one axis, sc_board_top) or MultiRegAddrW (the multi-axis map,
// sc_board_xy_top). The frame carries the WORD address addr / 4 in
// uart_addr_bytes(addr_bits) bytes, low byte first (one byte reaches the
// 1 KiB window of one axis). An address that is not word-aligned or lies
// outside the map is an Error for parameter "addr"; another width one for
// "addr_bits".
using FrameResult = std::variant<std::vector<uint8_t>, Error>;
FrameResult uart_write_frame(uint32_t addr, uint32_t data, int addr_bits = hw::RegAddrW);
FrameResult uart_read_frame(uint32_t addr, int addr_bits = hw::RegAddrW);
int uart_addr_bytes(int addr_bits);

struct UartResponse {
  bool ok = false;        // well formed and CRC correct
  uint8_t status = 0;     // AXI response or 0x80 / 0x81
  uint32_t data = 0;      // reads
  std::string error;      // why not ok
};
// Parse a response to a write (is_read = false) or read request.
UartResponse parse_uart_response(const std::vector<uint8_t>& bytes, bool is_read);

}  // namespace scurve
