#include "jog_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <optional>

#include "stop_check.h"

namespace sc {

std::variant<std::vector<scurve::VelocityPlan>, scurve::Error> plan_jog(const JogRequest& request,
                                                                         const PulseTiming& timing) {
  if (request.commands.empty()) return scurve::Error{"commands", "commands: give at least one target velocity"};
  const scurve::Planner planner{model_clock()};
  std::vector<scurve::VelocityPlan> plans;
  i128 v = 0;
  for (size_t i = 0; i < request.commands.size(); ++i) {
    const JogCommand& c = request.commands[i];
    const std::string at = fmt::format("commands[{}].", i);
    if (!std::isfinite(c.hold_s) || c.hold_s < 0 || c.hold_s > 1000) {
      return scurve::Error{at + "hold_s", fmt::format("{}hold_s={}: must be within 0..1000 s", at, c.hold_s)};
    }
    auto r = planner.plan_velocity(v, {c.v_target, request.a_max, request.j_max}, to_host(timing));
    if (scurve::Error* e = std::get_if<scurve::Error>(&r)) {
      e->message = at + e->message;
      e->parameter = at + e->parameter;
      return *e;
    }
    plans.push_back(std::get<scurve::VelocityPlan>(std::move(r)));
    v = plans.back().v_end;
  }
  if (v != 0 && !request.stop_at_end) {
    const size_t last = request.commands.size() - 1;
    return scurve::Error{fmt::format("commands[{}].v_target", last),
                         fmt::format("commands[{}].v_target={}: the last command must be 0 (rest) unless the "
                                     "program ends with a stop",
                                     last, request.commands.back().v_target)};
  }
  return plans;
}

JogRunResult run_jog(const JogRequest& request, const std::vector<scurve::VelocityPlan>& plans,
                     const PulseTiming& timing, SimEngine engine, uint64_t stop_jerk, uint64_t stop_acc,
                     const std::function<void(double)>& progress) {
  JogRunResult res;
  res.engine = engine;
  auto fail = [&](std::string s) {
    if (res.failures.size() < 20) res.failures.push_back(std::move(s));
  };
  PinRules rules{timing};
  rules.profile_phases = false;  // holds and ramps: no single-move duty contract
  rules.accounting = StepAccounting::ReferencePosition;
  CoreDriver drv(engine, rules);

  CoreInputs in;
  in.enable = true;
  in.cfg = timing;
  in.pos_frac0 = kOne / 2;
  in.stop_jerk = stop_jerk;
  in.stop_acc = stop_acc;

  // The largest change of v and a in one clock any row or the stop may make.
  const scurve::Clock clock = model_clock();
  const i128 dv_max = std::max<i128>(i128(std::floor(request.a_max * scurve::acc_lsb_per_unit(clock))), stop_acc);
  const i128 da_max = std::max<i128>(i128(std::floor(request.j_max * scurve::jerk_lsb_per_unit(clock))), stop_jerk);
  uint64_t planned = 0;
  for (size_t i = 0; i < plans.size(); ++i) {
    planned += plans[i].ramp_clocks + uint64_t(std::llround(request.commands[i].hold_s * ClkHz));
  }

  std::optional<CoreOutputs> prev;  // the last clock's outputs (none after a jump)
  stopcheck::StopMonitor stop_monitor(stop_jerk, stop_acc);
  uint64_t start_clock = 0;
  auto observe = [&] {
    const CoreOutputs& o = drv.out();
    if (prev) {
      const i128 dv = o.ref_vel - prev->ref_vel, da = i128(o.ref_acc) - prev->ref_acc;
      if (dv > dv_max || -dv > dv_max) {
        fail(fmt::format("clock {}: the velocity changed by {} LSB in one clock (a_max {} LSB)",
                         drv.clock() - start_clock, to_string_i128(dv), to_string_i128(dv_max)));
      }
      if (da > da_max || -da > da_max) {
        fail(fmt::format("clock {}: the acceleration changed by {} LSB in one clock (j_max {} LSB)",
                         drv.clock() - start_clock, to_string_i128(da), to_string_i128(da_max)));
      }
    }
    prev = o;
    stop_monitor.on_clock(o);
  };
  auto tick = [&](const CoreInputs& ci, bool held) {
    drv.tick(ci, held);
    observe();
  };
  // n quiet clocks (the model jumps where nothing pushes and nothing steps).
  auto run_for = [&](uint64_t n) {
    bool first = true;
    while (n > 0 && !drv.stopped()) {
      uint64_t k = 0;
      if (engine == SimEngine::ModelFast) {
        const uint64_t ev = drv.model().clocks_to_next_event(in);
        if (ev > 1) k = std::min(ev - 1, n);
      }
      if (k > 1) {
        drv.jump(in, k);
        prev.reset();
        n -= k;
      } else {
        tick(in, !first && engine != SimEngine::ModelFast);
        --n;
      }
      first = false;
      if (progress && (drv.clock() & 0xffffff) == 0) progress(double(drv.clock() - start_clock) / double(planned + 1));
    }
  };
  auto push = [&](const Row& r) {
    for (uint64_t w = 0; drv.out().fifo_full && w < 100000000 && !drv.stopped(); ++w) tick(in, w > 0);
    CoreInputs p = in;
    p.row_push = true;
    p.row = r;
    tick(p, false);
    ++res.rows;
  };

  const auto t0 = std::chrono::steady_clock::now();
  tick(in, false);
  bool ok = true;
  int64_t pins_at_start = 0;
  for (size_t i = 0; i < plans.size() && ok && !drv.stopped(); ++i) {
    const scurve::VelocityPlan& plan = plans[i];
    const JogCommand& cmd = request.commands[i];
    JogCommandReport rep;
    rep.v_target = cmd.v_target;
    rep.v_held = double(plan.v_end) / scurve::vel_lsb_per_unit(clock);
    rep.ramp_clocks = plan.ramp_clocks;
    const bool idle = !drv.out().busy;
    const std::vector<Row> rows = velocity_rows(plan);
    for (size_t k = 0; k < rows.size(); ++k) {
      push(rows[k]);
      if (k + 1 < rows.size()) run_for(request.push_gap);
    }
    if (idle && !rows.empty()) {
      CoreInputs st = in;
      st.start = true;
      pins_at_start = drv.pins().net_steps();  // PULSE_COUNT counts from START
      tick(st, false);
      if (i == 0) start_clock = drv.clock() - 1;
    }
    rep.queued_clock = drv.clock() - start_clock;
    const uint64_t hold = uint64_t(std::llround(cmd.hold_s * ClkHz));
    run_for(plan.ramp_clocks + 4 + hold);
    const CoreOutputs& o = drv.out();
    if (plan.hold) {
      rep.held = o.busy && !o.stopping && o.ref_vel == plan.v_end && o.ref_acc == 0 && o.ref_jerk == 0;
      if (!rep.held) {
        fail(fmt::format("command {} ({} pulses/s): not held after its ramp and {} s: v {} LSB, a {}, planned v {} "
                         "LSB{}{}",
                         i, cmd.v_target, cmd.hold_s, to_string_i128(o.ref_vel), o.ref_acc,
                         to_string_i128(plan.v_end), o.underrun ? ", UNDERRUN" : "", o.discont ? ", DISCONT" : ""));
        ok = false;
      }
    } else {
      // At rest: done after a ramp to rest; a command to rest from rest has no rows.
      rep.held = (o.done || rows.empty()) && !o.busy && o.ref_vel == 0 && o.ref_acc == 0;
      if (!rep.held) fail(fmt::format("command {} (rest): not at rest and done after its ramp", i));
    }
    res.commands.push_back(rep);
  }
  if (ok && request.stop_at_end && drv.out().busy) {
    CoreInputs s = in;
    s.stop = true;
    tick(s, false);
    for (uint64_t w = 0; w < 400000000 && drv.out().busy && !drv.stopped(); ++w) tick(in, w > 0);
    res.stopped = true;
    if (!stop_monitor.ended()) fail("the controlled stop did not end");
    res.stop_distance = double(stop_monitor.distance());
    res.stop_closed_form = double(stop_monitor.closed_form_distance());
    for (const std::string& e : stop_monitor.errors()) fail("stop: " + e);
  }
  const CoreOutputs end = drv.out();
  res.clocks = drv.clock() - start_clock;
  // Quiet tail: nothing may move at rest.
  const uint64_t tail = 4ull * (uint64_t(timing.high) + timing.low + timing.setup + timing.hold) + 1000;
  for (uint64_t i = 0; i < tail && !drv.stopped(); ++i) tick(in, i > 0);
  drv.pins().finish(drv.clock());
  res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  res.clocks_per_s = res.wall_s > 0 ? double(drv.clock()) / res.wall_s : 0;
  res.pulses = drv.pins().net_steps();
  res.end_position = drv.out().ref_pos_int;
  res.mismatches = drv.checker().mismatches();
  res.matched_clocks = drv.checker().matched();
  if (!drv.checker().errors().empty()) res.first_mismatch = drv.checker().errors().front().to_string();
  res.pin_errors = drv.pins().errors();

  if (res.mismatches) fail(fmt::format("{} lockstep mismatches: {}", res.mismatches, res.first_mismatch));
  if (end.underrun) fail("underrun: a hold must wait for the whole next command");
  if (end.discont) fail("discontinuity: each command must continue the held velocity");
  if (end.guard || end.fault_table) fail("guard or table fault");
  if (end.busy) fail("still moving at the end of the program");
  if (end.ref_vel != 0 || end.ref_acc != 0) fail("not at rest at the end");
  if (drv.out().ref_pos_int != end.ref_pos_int) fail("the position moved after rest");
  if (res.pulses != int64_t(drv.out().ref_pos_int)) {
    fail(fmt::format("pulses {} != reference position {}", res.pulses, drv.out().ref_pos_int));
  }
  if (int64_t(drv.out().pulse_count) != res.pulses - pins_at_start) {
    fail(fmt::format("pulse_count_o {} != pins since the last START {}", drv.out().pulse_count,
                     res.pulses - pins_at_start));
  }
  for (const std::string& e : res.pin_errors) fail(e);
  if (engine == SimEngine::Lockstep && res.matched_clocks == 0) fail("lockstep compared nothing");
  return res;
}

}  // namespace sc
