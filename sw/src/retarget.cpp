#include "scurve/retarget.h"

#include <fmt/format.h>

#include <cmath>

namespace scurve {

RetargetResult plan_retarget(const Planner& planner, const Plan& running, const MoveRequest& request,
                             const RetargetRequest& retarget, const PulseTiming& timing) {
  if (!std::isfinite(retarget.at_s) || retarget.at_s < 0) {
    return Error{"retarget_at", fmt::format("retarget_at={}: must be a finite time >= 0 s", retarget.at_s)};
  }
  const int dir = running.distance < 0 ? -1 : 1;
  const double earliest = retarget.at_s * running.clock.hz + double(retarget.lead_clocks);
  // Walk the rows in closed form: the exact position at each boundary.
  i128 pos = i128(running.pos_frac0);
  uint64_t clock = 0;
  for (size_t k = 0; k < running.segments.size(); ++k) {
    const Segment& s = running.segments[k];
    // Any boundary of the motion: plan_from_state starts at any acceleration.
    if (k > 0 && double(clock) >= earliest && s.vel0 != 0) {
      // The executor's acceleration there: the last row's end (a trapezoid's
      // next row may step from it).
      const Segment& last = running.segments[k - 1];
      const int64_t acc = int64_t(acc_after(last.acc0, last.jerk, last.clocks));
      const i128 one = i128(kOne);
      const i128 whole = pos >= 0 ? pos / one : -((-pos + one - 1) / one);
      RetargetPlan r;
      r.row = uint32_t(k);
      r.row_clock = clock;
      r.position = int64_t(whole);
      r.acceleration = acc;
      r.distance = retarget.distance;
      const int64_t rest = retarget.distance - r.position;
      if (rest == 0 || (rest < 0) != (dir < 0)) {
        return Error{"retarget_distance",
                     fmt::format("retarget_distance={}: the axis is at {} pulses at the boundary of row {} ({} s); "
                                 "the new target must lie ahead of it (a reversal needs a stop first)",
                                 retarget.distance, r.position, k, double(clock) / running.clock.hz)};
      }
      MoveRequest more = request;  // the limits, the end speed and the window
      more.distance = rest;
      more.start_position = request.start_position + r.position;
      PlanResult p = planner.plan_from_state({s.vel0, acc, u128(pos - whole * one)}, more, timing);
      if (const Error* e = std::get_if<Error>(&p)) {
        return Error{"retarget_distance", fmt::format("retarget_distance={}: from {} pulses at the boundary of row "
                                                      "{}: {}",
                                                      retarget.distance, r.position, k, e->message)};
      }
      r.plan = std::get<Plan>(std::move(p));
      return r;
    }
    pos += pos_gain(s.vel0, s.acc0, s.jerk, s.clocks);
    clock += s.clocks;
  }
  return Error{"retarget_at", fmt::format("retarget_at={}: no row boundary in motion from {} s on "
                                          "(with {} clocks to send the rows) before the move ends at {} s",
                                          retarget.at_s, earliest / running.clock.hz, retarget.lead_clocks,
                                          double(clock) / running.clock.hz)};
}

}  // namespace scurve
