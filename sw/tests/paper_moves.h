// Paper 000 Table 2 moves (L = 30,000 pulses, a = 500 pulses/s^2) with the
// project's jerk limit, for the host library's tests.
#pragma once

#include <cstdint>
#include <string>

#include "scurve/planner.h"

namespace scurve::test {

inline constexpr double kPaperJerk = 2500.0;

// A request from its six numbers (distance, start/cruise/end speed, a, j).
inline MoveRequest move_request(int64_t distance, double v_start, double v_cruise, double v_end, double a_max,
                                double j_max) {
  MoveRequest r;
  r.distance = distance;
  r.v_start = v_start;
  r.v_cruise = v_cruise;
  r.v_end = v_end;
  r.a_max = a_max;
  r.j_max = j_max;
  return r;
}

inline MoveRequest paper_group(int group) {
  static const double speeds[4][3] = {{1500, 3000, 0}, {3000, 1500, 0}, {0, 1500, 3000}, {0, 3000, 1500}};
  const double* s = speeds[(group - 1) & 3];
  MoveRequest r;
  r.distance = 30000;
  r.v_start = s[0];
  r.v_cruise = s[1];
  r.v_end = s[2];
  r.a_max = 500;
  r.j_max = kPaperJerk;
  r.kind = ProfileKind::SCurve;
  return r;
}

}  // namespace scurve::test
