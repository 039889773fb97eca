// Host-side move planner: a move request in, a segment table (or an error
// naming the parameter and the bound) out. The table is what sc_profile_exec
// runs; its endpoint is exact by construction:
//   * every row starts from exact integer acceleration/velocity,
//   * the planner sums the executor's integer recurrences in closed form,
//   * the cruise length and the initial position fraction absorb the rest,
// so the move ends at exactly distance + 1/2 pulse: |distance| steps.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "scurve/types.h"

namespace scurve {

enum class ProfileKind { SCurve, Trapezoid };

// The travel window of one axis (soft limits), inclusive, in pulses; an
// empty side is unbounded. Checked before solving: the axis name (quoted in
// messages) is 1 to kMaxAxisName characters of A-Z a-z 0-9 _ - ., each
// bound within +-PlannerLimits::kMaxPosition, min_pos <= max_pos; an error
// names the field ("soft_limits.min_pos", ...).
struct SoftLimits {
  static constexpr size_t kMaxAxisName = 32;
  std::string axis = "x";
  std::optional<int64_t> min_pos;
  std::optional<int64_t> max_pos;
};

struct MoveRequest {
  int64_t distance = 0;   // pulses; the sign is the direction
  double v_start = 0;     // pulses/s, >= 0
  double v_cruise = 0;    // pulses/s, > 0
  double v_end = 0;       // pulses/s, >= 0
  double a_max = 0;       // pulses/s^2
  double j_max = 0;       // pulses/s^3 (S-curve only)
  ProfileKind kind = ProfileKind::SCurve;
  // Paper 002's asymmetric S-shape: jerk while |a| rises / falls when
  // speeding up (Ts1, Ts2) and when slowing down (Te1, Te2). Unset: j_max.
  std::optional<std::array<double, 4>> jerks;
  // Paper 000's rule: when v_end cannot be reached within the distance, use
  // the closest reachable end speed instead of failing. Off by default.
  bool adjust_end_speed = false;
  // The window the move must stay in, and where the move starts (pulses,
  // within +-PlannerLimits::kMaxPosition; the table does not depend on it). A
  // planned move never reverses (its speed is >= 0 in the move direction
  // throughout: run_table's min_signed_vel >= 0), so its extreme position is
  // its target start_position + distance and the window check needs only
  // the target:
  //   * a target inside [min_pos, max_pos] is accepted (also from a start
  //     outside the window: the move goes into it);
  //   * a target beyond a limit is refused (parameter "soft_limits.max_pos"
  //     or "soft_limits.min_pos"), naming the axis, the target and the limit:
  //     "axis x: target position 1200 is beyond soft limit max=1000 pulses
  //     (start 200, distance +1000)";
  //   * except from a start already beyond that limit: a move back toward
  //     the window is accepted (leaving an active limit is allowed), one
  //     further out is refused naming the start (parameter "start_position").
  std::optional<SoftLimits> soft_limits;
  int64_t start_position = 0;
};

// Accepted bounds (besides the step-rate limit set by the pulse timing, and
// the acceleration/jerk register widths at the clock rate: see
// accel_range() / jerk_range()).
struct PlannerLimits {
  static constexpr int64_t kMaxDistance = (int64_t(1) << 31) - 2;
  static constexpr double kMinAccel = 0.01, kMaxAccel = 1e8;
  static constexpr double kMinJerk = 10.0, kMaxJerk = 1e11;
  // Slower cruises cannot cover a pulse within the table's 16 rows of 214 s.
  static constexpr double kMinCruise = 1e-3;
  // Positions (start_position, soft limits): start + distance never overflows.
  static constexpr int64_t kMaxPosition = int64_t(1) << 62;
};

// The executor's exact state where one move hands over to the next (the
// acceleration is 0 there). Streamed moves start from the previous move's
// end state, so the position fraction carries over from move to move.
struct JunctionState {
  i128 velocity = 0;  // LSB per clock, signed: the sign is the direction
  u128 frac = 0;      // position fraction in [0, 2^FracBits): position - floor(position)
};

// The executor's exact state at a row boundary (Planner::plan_from_state):
// any velocity and acceleration, e.g. where a running move is retargeted.
struct ExactState {
  i128 velocity = 0;         // LSB per clock, signed: the sign is the direction
  int64_t acceleration = 0;  // LSB per clock^2, signed
  u128 frac = 0;             // position fraction in [0, 2^FracBits)
};

struct Plan {
  Clock clock{};                 // the clock the table is counted in
  std::vector<Segment> segments;
  u128 pos_frac0 = 0;
  int64_t distance = 0;
  uint64_t total_clocks = 0;
  double duration_s = 0;
  double peak_velocity = 0;      // pulses/s, from the table
  double peak_acceleration = 0;  // pulses/s^2
  double peak_jerk = 0;          // pulses/s^3
  double v_plateau = 0;          // velocity between the two transitions
  double v_end_actual = 0;       // realised end velocity (pulses/s)
  bool end_speed_adjusted = false;
  double v_end_used = 0;         // end speed the plan aimed at
  // Exact state after the last row. plan(): frac is always 1/2 pulse (the
  // move ends mid-pulse). plan_from(): the next move's start state.
  JunctionState end_state;
};

// The one error type of the host library (planner, unit conversion).
struct Error {
  std::string parameter;  // the request field (or "clock_hz", "pulse_high", ...)
  std::string message;    // one line: "<param>=<value> ...: needs/limit ..."
};

using PlanError = Error;
using PlanResult = std::variant<Plan, Error>;

// Velocity mode (jog): a change of velocity with jerk-limited transitions,
// held until the next command.
struct VelocityRequest {
  double v_target = 0;  // pulses/s, signed (the sign is the direction); |v_target| <= the step-rate limit
  double a_max = 0;     // pulses/s^2
  double j_max = 0;     // pulses/s^3
};

struct VelocityPlan {
  // The ramp from the start velocity (a = 0) to the target, fastest for the
  // limits; through zero at a direction change. Unless the target is 0, a
  // last one-clock row at the target velocity that the rows mark HOLD: the
  // executor keeps that velocity until the next whole command is queued.
  std::vector<Segment> segments;
  bool hold = false;          // the last row holds (target != 0)
  i128 v_end = 0;             // the exact velocity reached (LSB per clock, signed): the next command's start
  uint64_t ramp_clocks = 0;   // clocks of the ramp (the hold row not counted)
  i128 ramp_gain = 0;         // position LSBs covered by the ramp, signed
};
using VelocityResult = std::variant<VelocityPlan, Error>;

// The planner for a board clocked at `clock` (default 20 MHz):
//   scurve::Planner planner{scurve::Clock{25e6}};
//   scurve::PlanResult r = planner.plan(request, timing);
class Planner {
 public:
  explicit Planner(Clock clock = Clock{}) : clock_(clock) {}
  // Limits are checked before solving (clock, timing, distance, speeds,
  // a_max, jerks, the soft limits); the table is re-executed and checked
  // after solving.
  PlanResult plan(const MoveRequest& req, const PulseTiming& timing) const;

  // Plans a move that continues an exact executor state (a row stream):
  // the start speed is start.velocity (req.v_start is not used), the
  // acceleration 0, and the position starts at start.frac (pos_frac0).
  // Step rule: a step each time floor(position / 2^FracBits) changes, so a
  // move of `distance` pulses ends in the half-open one-pulse window
  //   [distance, distance + 1) pulses from the start's integer part,
  // i.e. exactly |distance| steps; the cruise length places the end as near
  // mid-pulse as its speed allows. Every transition ends at exactly its
  // target speed, so end_state.velocity is the requested end speed (in LSB,
  // floored). A start velocity against the move's direction is an error
  // (a reversal needs junction speed 0). No table-size limit is applied
  // (the stream has no 16-row table). The soft limits apply as in plan().
  PlanResult plan_from(const JunctionState& start, const MoveRequest& req, const PulseTiming& timing) const;

  // Retarget on the fly: plans a move from an exact executor state whose
  // acceleration may be nonzero. The first row starts at exactly
  // (start.velocity, start.acceleration); the end, end_state, the end speed
  // and adjust_end_speed follow plan_from, and with acceleration 0 the
  // result is plan_from's. Every clock keeps |a| <= a_max, |jerk| <= the
  // jerk limits and |v| <= the step-rate limit, and the move never reverses.
  // Refused ("start_velocity", "start_acceleration"): a speed or an
  // acceleration beyond its limit, a velocity against the move, and an
  // acceleration that cannot be ended (at the jerk limit) before the speed
  // passes the step-rate limit or through 0; in particular from v = 0 an
  // acceleration against the move is refused (a reversal needs rest first).
  // A state that overshoots the target whatever it does is refused naming
  // "distance" (end speed 0) or "v_end", with the shortest distance it can
  // stop in / reach v_end within.
  // Construction (S-curve): the acceleration either ramps to 0 at full jerk
  // and plan_from's solver continues from there, or, when the plan wants to
  // go the way the acceleration points, the ramp continues (jerk on to the
  // plan's peak, hold, jerk down) straight to the plateau; the faster of the
  // two is kept. Trapezoid: the acceleration steps anyway, as plan_from.
  // Duration against the continuous time-optimal profile for the same start
  // state, limits and travel (test PlanFromState.DurationIsNearTheContinuous-
  // TimeOptimum, moves of >= 2000 clocks): symmetric jerk, at most 0.01 %
  // longer over 44,000 random starts; plan_from loses up to 0.005 % on the
  // same requests. Starts above v_cruise (or that must pass it) come down to
  // it when that fits, as plan_from does: at most 0.001 % longer than the
  // optimum capped at v_cruise. Asymmetric jerks: at most 0.21 % longer
  // over 6,600 starts. A transition lands exactly on its target speed by
  // one more clock at its peak acceleration and part of its ramp down a
  // clock earlier (|a| only falls there, so the smaller jerk never slows it).
  PlanResult plan_from_state(const ExactState& start, const MoveRequest& req, const PulseTiming& timing) const;

  // Velocity mode: rows from the exact constant velocity v_from (LSB per
  // clock, signed; 0 at rest, else the v_end of the last VelocityPlan) to
  // req.v_target. Checked: v_from and v_target within the step-rate limit
  // ("v_from", "v_target"), a_max and j_max as in plan(). The target is
  // reached exactly on the LSB grid (floored magnitude).
  VelocityResult plan_velocity(i128 v_from, const VelocityRequest& req, const PulseTiming& timing) const;
  Clock clock() const { return clock_; }

 private:
  Clock clock_;
};

// Largest speed the step generator can emit with this timing (pulses/s).
double step_rate_limit(const PulseTiming& timing, Clock clock = Clock{});

// Accepted a_max / jerk range at a clock rate (pulses/s^2, pulses/s^3): the
// PlannerLimits bounds, narrowed to what the register widths represent
// (at least one LSB, at most half the register range).
struct LimitRange {
  double lo = 0, hi = 0;
};
LimitRange accel_range(Clock clock = Clock{});
LimitRange jerk_range(Clock clock = Clock{});

// Executes a table in closed form, independent of how it was built, and
// reports what the hardware will do: the end position, the number of steps
// and the peaks over every clock (velocity/acceleration registers and the
// per-clock differences at row boundaries). Counts in clocks and LSBs only.
struct TableReport {
  bool ok = true;
  std::string error;
  uint64_t clocks = 0;
  i128 end_pos = 0;          // LSBs, from integer position 0 + pos_frac0
  int64_t steps = 0;         // floor(end_pos) - floor(start)
  i128 peak_vel = 0;         // max |v| (LSB)
  i128 min_signed_vel = 0;   // min of sign(distance) * v: < 0 means reversal
  int64_t peak_acc = 0;      // max |a| over the register and over dv per clock
  int64_t peak_jerk = 0;     // max |j| over the register and da per clock
};
TableReport run_table(const std::vector<Segment>& rows, u128 pos_frac0, int direction);

const char* phase_name(Phase p);

}  // namespace scurve
