// The hardware model's view of the host library (sw/, scurve::): the same
// planner, its request and error types, with the table converted to the
// model's rows (sc::Segment) and the model's clock (ClkHz) as the default.
// The host library knows nothing of the model; this header converts.
#pragma once

#include <cstdint>
#include <optional>
#include <variant>
#include <vector>

#include "fixed_point.h"
#include "profile_exec.h"
#include "scurve/planner.h"
#include "scurve/reg_encode.h"
#include "step_gen.h"

namespace sc {

using scurve::MoveRequest;
using scurve::PlanError;
using scurve::PlannerLimits;
using scurve::ProfileKind;
using scurve::TableReport;

// Both phase enums come from rtl/sc_pkg.sv through the same generator.
#define SC_SAME_PHASE(p) static_assert(uint8_t(scurve::Phase::p) == uint8_t(Phase::p), #p);
SC_SAME_PHASE(PhIdle)
SC_SAME_PHASE(PhAccJerkUp)
SC_SAME_PHASE(PhAccConst)
SC_SAME_PHASE(PhAccJerkDown)
SC_SAME_PHASE(PhCruise)
SC_SAME_PHASE(PhDecJerkUp)
SC_SAME_PHASE(PhDecConst)
SC_SAME_PHASE(PhDecJerkDown)
SC_SAME_PHASE(PhDone)
SC_SAME_PHASE(PhAbort)
SC_SAME_PHASE(PhFault)
SC_SAME_PHASE(PhStop)
#undef SC_SAME_PHASE
static_assert(scurve::hw::FracBits == FracBits && scurve::hw::SegClkW == SegClkW && scurve::hw::MaxSegs == MaxSegs,
              "host library and model built from different packages");

// The model's clock rate (the host library takes any).
inline scurve::Clock model_clock() { return scurve::Clock{double(ClkHz)}; }

inline scurve::PulseTiming to_host(const PulseTiming& t) { return {t.high, t.low, t.setup, t.hold}; }
inline PulseTiming to_model(const scurve::PulseTiming& t) { return {t.high, t.low, t.setup, t.hold}; }

inline Segment to_model(const scurve::Segment& s) {
  Segment m;
  m.phase = Phase(uint8_t(s.phase));
  m.clocks = s.clocks;
  m.jerk = s.jerk;
  m.acc0 = s.acc0;
  m.vel0 = s.vel0;
  return m;
}
inline scurve::Segment to_host(const Segment& s) {
  scurve::Segment h;
  h.phase = scurve::Phase(uint8_t(s.phase));
  h.clocks = s.clocks;
  h.jerk = s.jerk;
  h.acc0 = s.acc0;
  h.vel0 = s.vel0;
  return h;
}

// scurve::Plan with the model's rows.
struct Plan {
  scurve::Clock clock{};
  std::vector<Segment> segments;
  u128 pos_frac0 = 0;
  int64_t distance = 0;
  uint64_t total_clocks = 0;
  double duration_s = 0;
  double peak_velocity = 0;
  double peak_acceleration = 0;
  double peak_jerk = 0;
  double v_plateau = 0;
  double v_end_actual = 0;
  bool end_speed_adjusted = false;
  double v_end_used = 0;
  scurve::JunctionState end_state;
};

inline Plan to_model(const scurve::Plan& p) {
  Plan m;
  m.clock = p.clock;
  for (const scurve::Segment& s : p.segments) m.segments.push_back(to_model(s));
  m.pos_frac0 = p.pos_frac0;
  m.distance = p.distance;
  m.total_clocks = p.total_clocks;
  m.duration_s = p.duration_s;
  m.peak_velocity = p.peak_velocity;
  m.peak_acceleration = p.peak_acceleration;
  m.peak_jerk = p.peak_jerk;
  m.v_plateau = p.v_plateau;
  m.v_end_actual = p.v_end_actual;
  m.end_speed_adjusted = p.end_speed_adjusted;
  m.v_end_used = p.v_end_used;
  m.end_state = p.end_state;
  return m;
}
inline scurve::Plan to_host(const Plan& m) {
  scurve::Plan p;
  p.clock = m.clock;
  for (const Segment& s : m.segments) p.segments.push_back(to_host(s));
  p.pos_frac0 = m.pos_frac0;
  p.distance = m.distance;
  p.total_clocks = m.total_clocks;
  p.duration_s = m.duration_s;
  p.peak_velocity = m.peak_velocity;
  p.peak_acceleration = m.peak_acceleration;
  p.peak_jerk = m.peak_jerk;
  p.v_plateau = m.v_plateau;
  p.v_end_actual = m.v_end_actual;
  p.end_speed_adjusted = m.end_speed_adjusted;
  p.v_end_used = m.v_end_used;
  p.end_state = m.end_state;
  return p;
}

using PlanResult = std::variant<Plan, PlanError>;

inline PlanResult to_model(scurve::PlanResult r) {
  if (auto* e = std::get_if<PlanError>(&r)) return std::move(*e);
  return to_model(std::get<scurve::Plan>(r));
}

// The host planner at `clock` (default: the model's ClkHz).
inline PlanResult plan_move(const MoveRequest& req, const PulseTiming& timing,
                            scurve::Clock clock = model_clock()) {
  return to_model(scurve::Planner(clock).plan(req, to_host(timing)));
}

inline double step_rate_limit(const PulseTiming& timing) {
  return scurve::step_rate_limit(to_host(timing), model_clock());
}

inline TableReport run_table(const std::vector<Segment>& rows, u128 pos_frac0, int direction) {
  std::vector<scurve::Segment> h;
  h.reserve(rows.size());
  for (const Segment& s : rows) h.push_back(to_host(s));
  return scurve::run_table(h, pos_frac0, direction);
}

// A row's RowFlag* bits from the host's flags.
inline uint8_t row_flags(const scurve::RowFlags& f) {
  return uint8_t((f.move_end ? kRowMoveEnd : 0) | (f.stream_end ? kRowStreamEnd : 0) |
                 (f.acc_step ? kRowAccStep : 0) | (f.hold ? kRowHold : 0));
}

// The FIFO words of one planned move (flags: scurve::move_row_flags; a
// retarget's rows with the acceleration they continue from).
inline std::vector<Row> move_rows(const std::vector<Segment>& segments, bool stream_end = true,
                                  std::optional<int64_t> acc_before = std::nullopt) {
  std::vector<scurve::Segment> h;
  h.reserve(segments.size());
  for (const Segment& s : segments) h.push_back(to_host(s));
  const std::vector<scurve::RowFlags> f = scurve::move_row_flags(h, stream_end, acc_before);
  std::vector<Row> rows;
  rows.reserve(segments.size());
  for (size_t i = 0; i < segments.size(); ++i) {
    rows.push_back(Row{segments[i], row_flags(f[i])});
  }
  return rows;
}

// The FIFO words of a velocity-mode command (flags: scurve::velocity_row_flags).
inline std::vector<Row> velocity_rows(const scurve::VelocityPlan& plan) {
  const std::vector<scurve::RowFlags> f = scurve::velocity_row_flags(plan);
  std::vector<Row> rows;
  rows.reserve(plan.segments.size());
  for (size_t i = 0; i < plan.segments.size(); ++i) {
    rows.push_back(Row{to_model(plan.segments[i]), row_flags(f[i])});
  }
  return rows;
}

// Raw rows (tests) made into a valid stream: each row's start velocity
// continues the previous row's end exactly, as the continuity guard
// requires; start accelerations may step (move_rows flags them ACC_STEP).
inline void continue_velocities(std::vector<Segment>& rows) {
  for (size_t i = 1; i < rows.size(); ++i) {
    const Segment& p = rows[i - 1];
    rows[i].vel0 = wrap_signed(vel_after(p.vel0, p.acc0, p.jerk, p.clocks), VelW);
  }
}

// Push the rows of one move into the executor model's FIFO and start it
// (one clock per row, one for the start).
inline void load_and_start(ProfileExec& ex, const std::vector<Segment>& rows, u128 pos_frac0) {
  for (const Row& r : move_rows(rows)) {
    ProfileExec::Inputs w;
    w.row_push = true;
    w.row = r;
    ex.step(w);
  }
  ProfileExec::Inputs st;
  st.start = true;
  st.pos_frac0 = pos_frac0;
  ex.step(st);
}

inline const char* phase_name(Phase p) { return scurve::phase_name(scurve::Phase(uint8_t(p))); }

}  // namespace sc
