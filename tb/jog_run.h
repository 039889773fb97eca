// Velocity mode (jog) on the open-loop core: a program of target velocities.
// Each command is planned from the exact velocity the last one holds
// (scurve::Planner::plan_velocity) and pushed as one move whose last row is
// a HOLD row; the axis holds each target until the next command is queued,
// and the program ends at rest (a last target of 0) or with a controlled
// stop (CMD.STOP while holding). RTL and model in lockstep (or either alone,
// or the model's fast-forward), the pin monitor on every pulse.
//
// Checked without the executor's own arithmetic: each hold runs at exactly
// the planner's target velocity with a = j = 0; every clock the velocity and
// acceleration change by at most the request's a_max and j_max (or the stop
// limits during the stop): no velocity step anywhere; the pins' count equals
// the reference position; a stop ends at rest within one pulse of the
// closed-form stopping distance; nothing moves after the end.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <variant>
#include <vector>

#include "planner.h"
#include "sim_run.h"

namespace sc {

struct JogCommand {
  double v_target = 0;  // pulses/s, signed
  double hold_s = 0;    // time at the target before the next command (the last: before the stop)
};

struct JogRequest {
  double a_max = 0;  // pulses/s^2
  double j_max = 0;  // pulses/s^3
  std::vector<JogCommand> commands;
  bool stop_at_end = false;  // end with CMD.STOP while the last target holds
  // Clocks between two rows of one command (a slow host: the hold waits for
  // the whole command, so the ramp never starts on a part of it).
  uint64_t push_gap = 0;
};

// The commands' plans in order, each from the last one's v_end; an error
// names the command ("commands[2].v_target=...: ...").
std::variant<std::vector<scurve::VelocityPlan>, scurve::Error> plan_jog(const JogRequest& request,
                                                                         const PulseTiming& timing);

struct JogCommandReport {
  double v_target = 0;     // pulses/s, as asked
  double v_held = 0;       // pulses/s, the exact target of the plan
  uint64_t ramp_clocks = 0;
  uint64_t queued_clock = 0;  // the command's last row pushed, clocks from START
  bool held = false;          // at the end of its hold: the planned velocity, a = j = 0
};

struct JogRunResult {
  SimEngine engine = SimEngine::Lockstep;
  std::vector<JogCommandReport> commands;
  uint64_t rows = 0;
  uint64_t clocks = 0;         // START to rest
  int64_t pulses = 0;          // net STEP pulses on the pins
  int64_t end_position = 0;    // reference position at rest
  bool stopped = false;        // ended by CMD.STOP
  double stop_distance = 0, stop_closed_form = 0;  // pulses
  uint64_t mismatches = 0, matched_clocks = 0;
  std::string first_mismatch;
  std::vector<std::string> pin_errors;
  double wall_s = 0, clocks_per_s = 0;
  std::vector<std::string> failures;
  bool pass() const { return failures.empty(); }
};

// Runs the planned commands (plan_jog) with the stop limits (executor LSBs).
JogRunResult run_jog(const JogRequest& request, const std::vector<scurve::VelocityPlan>& plans,
                     const PulseTiming& timing, SimEngine engine, uint64_t stop_jerk, uint64_t stop_acc,
                     const std::function<void(double)>& progress = {});

}  // namespace sc
