// Fixed-point helpers shared by the bit-exact model and the planner.
// Widths come from sc_params.h (generated from rtl/sc_pkg.sv).
#pragma once

#include <cstdint>
#include <string>

#include "sc_params.h"

namespace sc {

using i128 = __int128;
using u128 = unsigned __int128;

static_assert(FracBits + 2 <= 126, "position sum must fit in 128 bits");
static_assert(VelW == FracBits + 1, "velocity is SQ1.FracBits: |v| < 1 pulse/clock");
static_assert(AccW <= 64 && JerkW <= 64, "acc/jerk are held in int64_t");
static_assert(PosIntW == 32, "integer position is held in int32_t");

inline constexpr u128 kOne = u128(1) << FracBits;  // 1 pulse in position LSBs

// Keep the low `bits` bits of x and sign-extend (two's-complement wrap),
// exactly what a `logic signed [bits-1:0]` register does on overflow.
constexpr i128 wrap_signed(i128 x, int bits) {
  const u128 m = (u128(1) << bits) - 1;
  u128 v = u128(x) & m;
  if (v >> (bits - 1)) v |= ~m;
  return i128(v);
}
constexpr int64_t wrap_signed64(int64_t x, int bits) {
  return int64_t(wrap_signed(i128(x), bits));
}
constexpr u128 mask_bits(u128 x, int bits) {
  return bits >= 128 ? x : (x & ((u128(1) << bits) - 1));
}
// Wrapping add for int64_t (no UB on overflow).
constexpr int64_t add_wrap64(int64_t a, int64_t b) {
  return int64_t(uint64_t(a) + uint64_t(b));
}
constexpr int32_t add_wrap32(int32_t a, int32_t b) {
  return int32_t(uint32_t(a) + uint32_t(b));
}

// Closed forms of the executor recurrence inside one segment
//   pos += v;  v += a;  a += j      (k = number of integrations)
// evaluated modulo 2^128, which is exact for every value that fits.
//   a_k = a0 + k j
//   v_k = v0 + k a0 + C(k,2) j
//   sum_{i<k} v_i = k v0 + C(k,2) a0 + C(k,3) j
constexpr u128 choose2(uint64_t k) {
  const u128 kk = k;
  return (kk & 1) ? kk * ((kk - 1) / 2) : (kk / 2) * (kk - 1);
}
constexpr u128 choose3(uint64_t k) {
  if (k < 3) return 0;
  u128 a = k, b = k - 1, c = k - 2;
  // One of three consecutive numbers is divisible by 3, one of two by 2.
  if (a % 3 == 0) a /= 3; else if (b % 3 == 0) b /= 3; else c /= 3;
  if (a % 2 == 0) a /= 2; else b /= 2;
  return a * b * c;
}
constexpr i128 acc_after(int64_t a0, int64_t j, uint64_t k) {
  return i128(a0) + i128(u128(k) * u128(i128(j)));
}
constexpr i128 vel_after(i128 v0, int64_t a0, int64_t j, uint64_t k) {
  return i128(u128(v0) + u128(k) * u128(i128(a0)) + choose2(k) * u128(i128(j)));
}
constexpr i128 pos_gain(i128 v0, int64_t a0, int64_t j, uint64_t k) {
  return i128(u128(k) * u128(v0) + choose2(k) * u128(i128(a0)) + choose3(k) * u128(i128(j)));
}

// Conversions between physical units (pulses, seconds) and LSBs.
inline constexpr double kTwoPowFrac = double(kOne);
inline double vel_to_phys(i128 v) { return double(v) / kTwoPowFrac * ClkHz; }
inline double acc_to_phys(i128 a) { return double(a) / kTwoPowFrac * double(ClkHz) * ClkHz; }
inline double jerk_to_phys(i128 j) {
  return double(j) / kTwoPowFrac * double(ClkHz) * ClkHz * ClkHz;
}
inline double pos_to_phys(i128 p) { return double(p) / kTwoPowFrac; }

std::string to_string_i128(i128 v);
std::string to_hex_u128(u128 v, int bits);

}  // namespace sc
