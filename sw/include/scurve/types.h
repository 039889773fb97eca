// Host-side value types: the clock, the pulse timing, one table row, and the
// executor's integer recurrences in closed form. Widths come from
// <scurve/hw/params.h>, generated from rtl/sc_pkg.sv (the single source of
// widths and codes); nothing here depends on the hardware model.
// Valid C++17 and C++20.
#pragma once

#include <cstdint>
#include <string>

#include "scurve/hw/params.h"

namespace scurve {

using i128 = __int128;
using u128 = unsigned __int128;
using hw::Phase;

static_assert(hw::FracBits + 2 <= 126, "position sum must fit in 128 bits");
static_assert(hw::VelW == hw::FracBits + 1, "velocity is SQ1.FracBits: |v| < 1 pulse/clock");
static_assert(hw::AccW <= 64 && hw::JerkW <= 64, "acc/jerk are held in int64_t");

inline constexpr u128 kOne = u128(1) << hw::FracBits;  // 1 pulse in position LSBs
inline constexpr double kTwoPowFrac = double(kOne);

// The system clock of the board. The planner, the register encoding and the
// unit conversions take it at run time.
struct Clock {
  static constexpr double kDefaultHz = 20e6;
  // Accepted range: below 1 MHz the acceleration/jerk limits no longer fit
  // the register widths; above 1 GHz one jerk LSB exceeds 800 pulses/s^3.
  static constexpr double kMinHz = 1e6;
  static constexpr double kMaxHz = 1e9;
  double hz = kDefaultHz;
  bool operator==(const Clock& o) const { return hz == o.hz; }
  bool operator!=(const Clock& o) const { return !(*this == o); }
};

// Empty if the clock is usable, else one line naming the bound.
std::string check_clock(const Clock& clock);

// STEP/DIR timing in clocks (register PULSE_TIME / DIR_TIME).
struct PulseTiming {
  uint16_t high = 50;    // STEP high time (2.5 us at 20 MHz)
  uint16_t low = 50;     // minimum STEP low time
  uint16_t setup = 100;  // DIR change to STEP rising edge
  uint16_t hold = 100;   // STEP rising edge to DIR change
  bool operator==(const PulseTiming& o) const {
    return high == o.high && low == o.low && setup == o.setup && hold == o.hold;
  }
  bool operator!=(const PulseTiming& o) const { return !(*this == o); }
};

// One row of the segment table the profile executor runs, in LSBs.
struct Segment {
  Phase phase = Phase::PhIdle;
  uint32_t clocks = 0;  // SegClkW bits
  int64_t jerk = 0;     // JerkW bits, sign-extended
  int64_t acc0 = 0;     // AccW bits
  i128 vel0 = 0;        // VelW bits, sign-extended
  bool operator==(const Segment& o) const {
    return phase == o.phase && clocks == o.clocks && jerk == o.jerk && acc0 == o.acc0 && vel0 == o.vel0;
  }
  bool operator!=(const Segment& o) const { return !(*this == o); }
};

constexpr u128 mask_bits(u128 x, int bits) { return bits >= 128 ? x : (x & ((u128(1) << bits) - 1)); }

// Closed forms of the executor recurrence inside one row
//   pos += v;  v += a;  a += j      (k = number of integrations)
// evaluated modulo 2^128, which is exact for every value that fits.
constexpr u128 choose2(uint64_t k) {
  const u128 kk = k;
  return (kk & 1) ? kk * ((kk - 1) / 2) : (kk / 2) * (kk - 1);
}
constexpr u128 choose3(uint64_t k) {
  if (k < 3) return 0;
  // The divisions in 64 bits (128-bit ones are library calls); same value.
  uint64_t a = k, b = k - 1, c = k - 2;
  if (a % 3 == 0) a /= 3; else if (b % 3 == 0) b /= 3; else c /= 3;
  if (a % 2 == 0) a /= 2; else b /= 2;
  return u128(a) * b * c;
}
constexpr i128 acc_after(int64_t a0, int64_t j, uint64_t k) { return i128(a0) + i128(u128(k) * u128(i128(j))); }
constexpr i128 vel_after(i128 v0, int64_t a0, int64_t j, uint64_t k) {
  return i128(u128(v0) + u128(k) * u128(i128(a0)) + choose2(k) * u128(i128(j)));
}
constexpr i128 pos_gain(i128 v0, int64_t a0, int64_t j, uint64_t k) {
  return i128(u128(k) * u128(v0) + choose2(k) * u128(i128(a0)) + choose3(k) * u128(i128(j)));
}

// LSB <-> physical units (pulses, seconds) at a clock rate.
inline double vel_to_phys(i128 v, Clock c) { return double(v) / kTwoPowFrac * c.hz; }
inline double acc_to_phys(i128 a, Clock c) { return double(a) / kTwoPowFrac * c.hz * c.hz; }
inline double jerk_to_phys(i128 j, Clock c) { return double(j) / kTwoPowFrac * c.hz * c.hz * c.hz; }
inline double pos_to_phys(i128 p) { return double(p) / kTwoPowFrac; }
inline double vel_lsb_per_unit(Clock c) { return kTwoPowFrac / c.hz; }
inline double acc_lsb_per_unit(Clock c) { return kTwoPowFrac / (c.hz * c.hz); }
inline double jerk_lsb_per_unit(Clock c) { return kTwoPowFrac / (c.hz * c.hz * c.hz); }

std::string to_string_i128(i128 v);
std::string to_hex_u128(u128 v, int bits);

}  // namespace scurve
