// Red-team helpers: plan a request, time the planner, execute the table on
// the bit-exact executor model and check the guarantees independently of
// the planner's own re-check (run_table).
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "planner.h"
#include "profile_exec.h"
#include "random_moves.h"

namespace rt {

using namespace sc;

struct Outcome {
  bool accepted = false;
  PlanError err;
  Plan plan;
  double plan_ms = 0;
  // execution (model, per-clock step() when short, else fast_forward)
  int64_t steps = 0;
  bool mid_pulse = false;
  bool finished = false;
  // independent per-clock checks (only with per-clock execution)
  bool stepped = false;
  double peak_v = 0, peak_a = 0, peak_j = 0;  // physical, incl. final stop
  double end_v = 0;                           // last velocity register before stop (physical)
  bool reversed = false;
  std::string problems;
};

inline Outcome run(const MoveRequest& r, const PulseTiming& t, uint64_t step_limit = 20'000'000) {
  Outcome o;
  const auto t0 = std::chrono::steady_clock::now();
  PlanResult pr = plan_move(r, t);
  o.plan_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (auto* e = std::get_if<PlanError>(&pr)) {
    o.err = *e;
    if (e->parameter == "internal") o.problems += "internal error; ";
    if (e->message.find('\n') != std::string::npos) o.problems += "multi-line error; ";
    if (e->message.find(e->parameter) == std::string::npos) o.problems += "error does not name parameter; ";
    if (o.plan_ms > 100) o.problems += "slow planning; ";
    return o;
  }
  o.accepted = true;
  o.plan = std::get<Plan>(pr);
  if (o.plan_ms > 100) o.problems += "slow planning; ";
  const Plan& p = o.plan;
  ProfileExec ex;
  load_and_start(ex, p.segments, p.pos_frac0);
  const int32_t p0 = ex.state().pint;
  const int dir = r.distance < 0 ? -1 : 1;
  if (p.total_clocks <= step_limit) {
    o.stepped = true;
    ProfileExec::Inputs q;
    i128 pv = 0, vmax = 0;
    i128 pa = 0;
    i128 amax = 0, jmax = 0;
    // clock-by-clock: velocity register, dv per clock, d(dv) per clock
    i128 prev_v = 0, prev_dv = 0;
    bool first = true;
    uint64_t n = 0;
    while (ex.state().run && n < p.total_clocks + 10) {
      const i128 v = ex.state().vel;
      if (dir * v < 0) o.reversed = true;
      vmax = std::max(vmax, v < 0 ? -v : v);
      if (!first) {
        const i128 dv = v - prev_v;
        amax = std::max(amax, dv < 0 ? -dv : dv);
        const i128 ddv = dv - prev_dv;
        jmax = std::max(jmax, ddv < 0 ? -ddv : ddv);
        prev_dv = dv;
      } else {
        // starting from rest-acceleration: first dv is acc0 of row 0
      }
      prev_v = v;
      first = false;
      ex.step(q);
      ++n;
    }
    // The stop: velocity drops from prev_v to 0 (what a following move or a
    // motor sees); acceleration must have been ~0 at the end.
    o.end_v = vel_to_phys(prev_v);
    (void)pv;
    (void)pa;
    o.peak_v = vel_to_phys(vmax);
    o.peak_a = acc_to_phys(amax);
    o.peak_j = jerk_to_phys(jmax);
    ex.step(q);
  } else {
    ex.fast_forward(p.total_clocks + 1);
  }
  o.steps = int64_t(ex.state().pint - p0);
  o.mid_pulse = ex.state().frac == (kOne >> 1);
  o.finished = ex.state().finished && !ex.state().run;
  if (!o.finished) o.problems += "not finished; ";
  if (o.steps != r.distance) o.problems += "steps " + std::to_string(o.steps) + " != distance; ";
  if (!o.mid_pulse) o.problems += "not mid-pulse; ";
  const double vcap = std::min(std::max({r.v_cruise, r.v_start, p.v_end_used}), step_rate_limit(t));
  const TableReport rep = run_table(p.segments, p.pos_frac0, dir);
  if (rep.min_signed_vel < 0 || o.reversed) o.problems += "velocity reverses; ";
  const double pv = o.stepped ? o.peak_v : vel_to_phys(rep.peak_vel);
  if (pv > vcap * (1 + 1e-12)) o.problems += "v " + std::to_string(pv) + " > " + std::to_string(vcap) + "; ";
  const double pa = o.stepped ? o.peak_a : acc_to_phys(rep.peak_acc);
  if (pa > r.a_max * (1 + 1e-12)) o.problems += "a " + std::to_string(pa) + " > a_max; ";
  if (r.kind == ProfileKind::SCurve) {
    const double j = scurve::test::jerk_cap(r);
    const double pj = o.stepped ? o.peak_j : jerk_to_phys(rep.peak_jerk);
    if (pj > j * (1 + 1e-12)) o.problems += "j " + std::to_string(pj) + " > j_max; ";
  }
  return o;
}

inline std::string describe(const MoveRequest& r, const PulseTiming& t) {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "--distance %lld --v-start %.17g --v-cruise %.17g --v-end %.17g --a-max %.17g --j-max %.17g%s%s "
                "--pulse-high %u --pulse-low %u --dir-setup %u --dir-hold %u",
                (long long)r.distance, r.v_start, r.v_cruise, r.v_end, r.a_max, r.j_max,
                r.kind == ProfileKind::Trapezoid ? " --profile trapezoid" : "",
                r.adjust_end_speed ? " --adjust-end-speed" : "", t.high, t.low, t.setup, t.hold);
  std::string s = buf;
  if (r.jerks) {
    std::snprintf(buf, sizeof buf, " --jerks %.17g %.17g %.17g %.17g", (*r.jerks)[0], (*r.jerks)[1], (*r.jerks)[2],
                  (*r.jerks)[3]);
    s += buf;
  }
  return s;
}

}  // namespace rt
