// Reference scenarios: paper 000 Table 2 (L = 30,000 pulses, a = 500
// pulses/s^2) with our documented jerk limit, and the default pulse timing.
#pragma once

#include <string>

#include "planner.h"

namespace sc {

// The paper gives no jerk limit. 2500 pulses/s^3 makes each jerk phase
// a/j = 0.2 s long, so the 1500 pulses/s speed changes spend about 12 % of
// their time shaping the acceleration (the S) and 88 % at a = 500.
inline constexpr double kPaperJerk = 2500.0;
inline constexpr int64_t kPaperDistance = 30000;
inline constexpr double kPaperAccel = 500.0;

inline MoveRequest paper_group(int group) {
  static const double speeds[4][3] = {
      {1500, 3000, 0}, {3000, 1500, 0}, {0, 1500, 3000}, {0, 3000, 1500}};
  const double* s = speeds[(group - 1) & 3];
  MoveRequest r;
  r.distance = kPaperDistance;
  r.v_start = s[0];
  r.v_cruise = s[1];
  r.v_end = s[2];
  r.a_max = kPaperAccel;
  r.j_max = kPaperJerk;
  r.kind = ProfileKind::SCurve;
  return r;
}

inline std::string paper_group_name(int group) { return "group" + std::to_string(group); }

}  // namespace sc
