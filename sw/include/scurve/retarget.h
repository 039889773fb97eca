// Retarget on the fly: redirect a running move at a future row boundary.
// The executor is deterministic, so the exact state at every boundary of
// the rows it was given is known in advance; the new rows are planned from
// that state and replace the old ones from that row on (RETARGET_ROW and
// ROW_PUSH.REPLACE, encode_retarget()).
//
//   auto r = scurve::plan_retarget(planner, plan, request, {0.03, 2500}, timing);
//   writes = scurve::encode_retarget(r.row, r.plan.segments,
//                                    scurve::move_row_flags(r.plan.segments, true, r.acceleration));
#pragma once

#include <cstdint>
#include <variant>

#include "scurve/planner.h"

namespace scurve {

struct RetargetRequest {
  double at_s = 0;        // when the host decides, seconds after the move's first clock
  int64_t distance = 0;   // the move's new distance from its start, pulses (same direction)
  // Clocks the host needs to send the replace: the boundary lies at least
  // this far after at_s (the register writes of a row take about 40 AXI clocks).
  uint64_t lead_clocks = 2000;
};

struct RetargetPlan {
  uint32_t row = 0;         // RETARGET_ROW: the first row replaced
  uint64_t row_clock = 0;   // its first clock, counted from the first row's first clock
  int64_t position = 0;     // the integer position there, pulses from the start
  int64_t acceleration = 0;  // the executor's acceleration there (LSB): a trapezoid's new rows step from it
  int64_t distance = 0;     // the move's new distance
  Plan plan;                // the new rows, from the exact state at that boundary
};
using RetargetResult = std::variant<RetargetPlan, Error>;

// The first boundary in motion at or after at_s + lead_clocks, and the
// plan from its exact state (velocity, acceleration, position fraction:
// Planner::plan_from_state; a trapezoid's first new row steps the
// acceleration, flagged ACC_STEP by move_row_flags with `acceleration`) to
// the new distance with the request's limits and end speed. Errors name
// "retarget_at" (no such boundary before the move ends) or
// "retarget_distance" (the new target is not ahead of the axis there, or
// too close to reach from that state: the planner's message with the
// shortest distance).
RetargetResult plan_retarget(const Planner& planner, const Plan& running, const MoveRequest& request,
                             const RetargetRequest& retarget, const PulseTiming& timing);

}  // namespace scurve
