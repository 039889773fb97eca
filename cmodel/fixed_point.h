// Fixed-point helpers of the bit-exact model. Widths come from sc_params.h
// (generated from rtl/sc_pkg.sv). The 128-bit types, the closed-form
// executor recurrences and the 128-bit formatting are the host library's
// (<scurve/types.h>): one definition serves the planner and the model.
#pragma once

#include <cstdint>
#include <string>

#include "sc_params.h"
#include "scurve/types.h"

namespace sc {

using scurve::i128;
using scurve::u128;
using scurve::kOne;  // 1 pulse in position LSBs
using scurve::kTwoPowFrac;
using scurve::mask_bits;
// Closed forms of the executor recurrence inside one segment
//   pos += v;  v += a;  a += j      (k = number of integrations)
// evaluated modulo 2^128, which is exact for every value that fits.
using scurve::acc_after;
using scurve::choose2;
using scurve::choose3;
using scurve::pos_gain;
using scurve::vel_after;
using scurve::to_hex_u128;
using scurve::to_string_i128;

static_assert(scurve::hw::FracBits == FracBits, "host library and model built from different packages");
static_assert(PosIntW == 32, "integer position is held in int32_t");

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
// Wrapping add for int64_t (no UB on overflow).
constexpr int64_t add_wrap64(int64_t a, int64_t b) {
  return int64_t(uint64_t(a) + uint64_t(b));
}
constexpr int32_t add_wrap32(int32_t a, int32_t b) {
  return int32_t(uint32_t(a) + uint32_t(b));
}

// Conversions between physical units (pulses, seconds) and LSBs at the
// model's clock (ClkHz).
inline double vel_to_phys(i128 v) { return double(v) / kTwoPowFrac * ClkHz; }
inline double acc_to_phys(i128 a) { return double(a) / kTwoPowFrac * double(ClkHz) * ClkHz; }
inline double jerk_to_phys(i128 j) {
  return double(j) / kTwoPowFrac * double(ClkHz) * ClkHz * ClkHz;
}
inline double pos_to_phys(i128 p) { return double(p) / kTwoPowFrac; }

}  // namespace sc
