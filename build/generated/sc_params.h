// Generated from rtl/sc_pkg.sv by scripts/gen_params.py - do not edit.
#pragma once
#include <cstdint>

namespace sc {

inline constexpr int ClkHz = 20000000;
inline constexpr int FracBits = 80;
inline constexpr int PosIntW = 32;
inline constexpr int VelW = 81;
inline constexpr int AccW = 64;
inline constexpr int JerkW = 48;
inline constexpr int SegClkW = 32;
inline constexpr int MaxSegs = 16;
inline constexpr int SegIdxW = 4;
inline constexpr int SegCntW = 5;
inline constexpr int PulseTimeW = 16;
inline constexpr int PendW = 4;
inline constexpr int PhaseW = 4;

enum class Phase : uint8_t {
  PhIdle = 0,
  PhAccJerkUp = 1,
  PhAccConst = 2,
  PhAccJerkDown = 3,
  PhCruise = 4,
  PhDecJerkUp = 5,
  PhDecConst = 6,
  PhDecJerkDown = 7,
  PhDone = 8,
  PhAbort = 9,
  PhFault = 10,
};

}  // namespace sc
