#include "sim_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "rtl_core.h"
#include "stop_check.h"
#include "scurve/cli/user_input.h"

namespace sc {

const char* engine_name(SimEngine e) {
  switch (e) {
    case SimEngine::Lockstep: return "lockstep";
    case SimEngine::RtlOnly: return "rtl";
    case SimEngine::ModelOnly: return "model";
    case SimEngine::ModelFast: return "model-fast";
  }
  return "?";
}

const std::vector<std::string>& sim_engine_names() {
  static const std::vector<std::string> names{"lockstep", "rtl", "model", "model-fast"};
  return names;
}

SimEngine sim_engine_from_name(const std::string& name) {
  for (const SimEngine e : {SimEngine::RtlOnly, SimEngine::ModelOnly, SimEngine::ModelFast}) {
    if (name == engine_name(e)) return e;
  }
  return SimEngine::Lockstep;
}

std::vector<CoreInputs> load_sequence(const std::vector<Segment>& rows, u128 pos_frac0, const CoreInputs& base) {
  return load_sequence(move_rows(rows), pos_frac0, base);
}

std::vector<CoreInputs> load_sequence(const std::vector<Row>& rows, u128 pos_frac0, const CoreInputs& base) {
  std::vector<CoreInputs> seq;
  for (const Row& r : rows) {
    CoreInputs w = base;
    w.row_push = true;
    w.row = r;
    seq.push_back(w);
  }
  CoreInputs st = base;
  st.pos_frac0 = pos_frac0;
  st.start = true;
  seq.push_back(st);
  return seq;
}

CoreDriver::CoreDriver(SimEngine engine, const PinRules& rules, size_t max_mismatches, const std::string& fst_path,
                       uint64_t fst_from, uint64_t fst_to)
    : engine_(engine), checker_(max_mismatches), pins_(rules) {
  const bool use_rtl = engine == SimEngine::Lockstep || engine == SimEngine::RtlOnly;
  if (!fst_path.empty() && !use_rtl) {
    throw input::Error("fst", fst_path, fmt::format("engine {} runs no RTL to trace", engine_name(engine)));
  }
  if (use_rtl) {
    rtl_ = std::make_unique<RtlCore>();
    if (!fst_path.empty()) rtl_->trace_open(fst_path, fst_from, fst_to);
    rtl_->reset(4);
  }
}

CoreDriver::~CoreDriver() = default;

void CoreDriver::tick(const CoreInputs& ci, bool held) {
  const bool use_model = engine_ != SimEngine::RtlOnly;
  if (held) {
    if (rtl_) rtl_->tick();
    if (use_model) model_.tick();
  } else {
    if (rtl_) rtl_->step(ci);
    if (use_model) model_.step(ci);
  }
  if (engine_ == SimEngine::Lockstep) {
    CoreOutputs& o = checker_.slot(clock_);
    rtl_->read_outputs(o);
    if (!checker_.check(clock_, model_) && checker_.should_stop()) stopped_ = true;
    cur_ = &o;
  } else {
    if (rtl_) rtl_->read_outputs(out_); else model_.read_outputs(out_);
    cur_ = &out_;
  }
  pins_.on_clock(clock_, *cur_);
  ++clock_;
}

void CoreDriver::jump(const CoreInputs& in, uint64_t n) {
  model_.fast_forward(in, n);
  clock_ += n;
  model_.read_outputs(out_);
  cur_ = &out_;
  pins_.on_clock(clock_ - 1, out_);
}

void CoreDriver::close_trace() {
  if (rtl_) rtl_->trace_close();
}

namespace {

// Peak tracking on the reference outputs, every clock: register values and
// per-clock differences (so a jump at a row boundary is seen as accel/jerk).
struct PeakTracker {
  // Register extremes every clock; the per-clock differences inside a row
  // are the acc/jerk registers themselves (the recurrence, lockstep-checked),
  // so differences are only taken where a row is reloaded.
  i128 v_max = 0, v_min = 0;
  int64_t a_max = 0, a_min = 0, j_max = 0, j_min = 0;
  i128 jump_a = 0, jump_j = 0;  // largest |dv|, |da| across a reload
  i128 prev_vel = 0;
  int64_t prev_acc = 0;
  uint8_t prev_idx = 0;
  bool have_prev = false;
  void on_clock(const CoreOutputs& o, bool moving) {
    if (!moving) {
      have_prev = false;
      return;
    }
    if (o.ref_vel > v_max) v_max = o.ref_vel;
    if (o.ref_vel < v_min) v_min = o.ref_vel;
    if (o.ref_acc > a_max) a_max = o.ref_acc;
    if (o.ref_acc < a_min) a_min = o.ref_acc;
    if (o.ref_jerk > j_max) j_max = o.ref_jerk;
    if (o.ref_jerk < j_min) j_min = o.ref_jerk;
    // Reloads only; the jump from rest to the start speed (after the arming
    // clocks, busy but at rest) is not an acceleration of the move.
    if (have_prev && o.seg_idx != prev_idx && (prev_vel != 0 || prev_acc != 0)) [[unlikely]] {
      const i128 dv = o.ref_vel - prev_vel;
      const i128 da = i128(o.ref_acc) - prev_acc;
      jump_a = std::max(jump_a, dv < 0 ? -dv : dv);
      jump_j = std::max(jump_j, da < 0 ? -da : da);
    }
    prev_vel = o.ref_vel;
    prev_acc = o.ref_acc;
    prev_idx = o.seg_idx;
    have_prev = true;
  }
  i128 v() const { return std::max(v_max, -v_min); }
  i128 a() const { return std::max({i128(a_max), -i128(a_min), jump_a}); }
  i128 j() const { return std::max({i128(j_max), -i128(j_min), jump_j}); }
};

}  // namespace

SimResult run_move(const Plan& plan, const PulseTiming& timing, const Limits4Check& limits,
                   const SimOptions& opt) {
  SimResult res;
  res.engine = opt.engine;
  res.distance = plan.distance;
  res.expected_trends = expected_trends(plan.segments);
  // A stop follows no planned duty phase: only its pulses are checked.
  CoreDriver drv(opt.engine, PinRules{timing, !opt.stop_at && !opt.retarget, StepAccounting::ReferencePosition},
                 opt.max_mismatches,
                 opt.fst_path, opt.fst_from, opt.fst_to);
  AxisCore& model = drv.model();
  PinMonitor& pins = drv.pins();
  PeakTracker peaks;
  stopcheck::StopMonitor stop(opt.stop_jerk, opt.stop_acc);

  const auto t0 = std::chrono::steady_clock::now();
  CoreInputs in;
  in.cfg = timing;
  in.enable = true;
  in.stop_jerk = opt.stop_jerk;
  in.stop_acc = opt.stop_acc;
  CoreOutputs out;
  // One clock on the driver; the stop monitor sees every stepped clock.
  auto tick = [&](const CoreInputs& ci, bool held = false) {
    drv.tick(ci, held);
    stop.on_clock(drv.out());
  };
  // Load the table one row per clock, then start.
  for (const CoreInputs& ci : load_sequence(plan.segments, plan.pos_frac0, in)) {
    if (!drv.stopped()) tick(ci);
    in = ci;
  }
  in.start = false;
  const uint64_t start_clock = drv.clock();
  const uint64_t stop_clock = opt.stop_at ? start_clock + *opt.stop_at : UINT64_MAX;
  CoreInputs stop_in = in;
  stop_in.stop = true;
  const uint64_t retarget_clock = opt.retarget ? start_clock + opt.retarget->at_clock : UINT64_MAX;
  bool retarget_refused = false;
  // The retarget's rows, one a clock, the first a replace; the host stops
  // sending once the replace is refused (it reads ERR.RETARGET).
  auto push_retarget = [&]() {
    const SimOptions::Retarget& r = *opt.retarget;
    for (size_t i = 0; i < r.rows.size() && !drv.stopped(); ++i) {
      CoreInputs w = in;
      w.row_push = true;
      w.row = r.rows[i];
      w.row_replace = i == 0;
      w.retarget_row = r.row;
      tick(w);
      retarget_refused = retarget_refused || drv.out().retarget_refused;
      if (i == 0) {
        tick(in);
        retarget_refused = retarget_refused || drv.out().retarget_refused;
        if (retarget_refused) break;
      }
    }
    tick(in);  // the inputs held again from here on
    res.retarget_requested = true;
    res.retarget_row = r.row;
    res.retarget_distance = r.distance;
    res.retarget_taken = !retarget_refused;
  };
  // The peaks are the plan's limits' business; a stop's own motion is the
  // stop monitor's (jerk and deceleration within the stop limits, no reversal).
  auto planned_motion = [](const CoreOutputs& o) { return o.busy && !o.done && !o.stopping; };
  // The run is over: done, or at rest after the stop, or (a stop during the
  // arming) idle without having moved.
  auto over = [&]() {
    return drv.out().done || stop.ended() || (opt.stop_at && drv.clock() > stop_clock + 1 && !drv.out().busy);
  };

  // Run to done. A hang is caught by a limit well past the planned length.
  uint64_t limit = start_clock + plan.total_clocks + 1000 + 4ull * (timing.high + timing.low + timing.setup) +
                   (opt.retarget ? opt.retarget->at_clock + opt.retarget->clocks : 0);
  // A stop may outlast the plan (stop limits below the move's): once it
  // starts, the limit is a generous multiple of its closed-form time.
  bool stop_limit_set = false;
  auto extend_limit = [&]() {
    if (stop_limit_set || !stop.seen()) return;
    stop_limit_set = true;
    const stopcheck::ld ramp = std::fabs(stopcheck::ld(stop.start().a)) / stopcheck::ld(std::max<uint64_t>(1, opt.stop_jerk));
    limit = std::max(limit, drv.clock() + uint64_t(4 * (stop.closed_form_time() + ramp)) + 100000);
  };
  if (opt.engine == SimEngine::ModelFast) {
    // Closed form between pulses: only the clocks around each pulse are
    // stepped, so the pin monitor still sees every edge.
    while (!drv.stopped() && drv.clock() < limit) {
      extend_limit();
      const CoreOutputs before = model.outputs();
      if (drv.clock() > start_clock && over()) break;
      if (drv.clock() == stop_clock) {
        tick(stop_in);
        out = drv.out();
        peaks.on_clock(out, planned_motion(out));
        continue;
      }
      if (drv.clock() == retarget_clock) {
        push_retarget();
        peaks.have_prev = false;
        continue;
      }
      uint64_t n = 1;
      if (const uint64_t ev = model.clocks_to_next_event(in); ev > 1) n = ev - 1;
      if (drv.clock() < stop_clock) n = std::min(n, stop_clock - drv.clock());
      if (drv.clock() < retarget_clock) n = std::min(n, retarget_clock - drv.clock());
      n = std::min(n, limit - drv.clock());
      if (n > 1) {
        // The reference moves smoothly in between: sample its peaks at the
        // jump ends (the per-clock maxima are at row ends or pulses).
        peaks.on_clock(before, planned_motion(before));
        drv.jump(in, n);
        out = drv.out();
        peaks.have_prev = false;
        peaks.on_clock(out, planned_motion(out));
      } else {
        tick(in);
        out = drv.out();
        peaks.on_clock(out, planned_motion(out));
      }
    }
  } else {
    const double expected = double(plan.total_clocks) + 1.0;
    if (!drv.stopped()) tick(drv.clock() == stop_clock ? stop_in : in);  // drops start: from here on the inputs are held
    while (!drv.stopped() && drv.clock() < limit && !over()) {
      extend_limit();
      if (drv.clock() == stop_clock) {
        tick(stop_in);
      } else if (drv.clock() == retarget_clock) {
        push_retarget();
        peaks.have_prev = false;
        continue;
      } else {
        tick(in, drv.clock() != stop_clock + 1);  // the clock after the stop clock drops it
      }
      peaks.on_clock(drv.out(), planned_motion(drv.out()));
      if ((drv.clock() & 0xffffff) == 0 && opt.progress) opt.progress(double(drv.clock() - start_clock) / expected);
    }
  }
  out = drv.out();
  const uint64_t done_clock = drv.clock();
  const bool reached_done = out.done || stop.ended();
  res.clocks = done_clock;
  res.duration_s = double(done_clock - start_clock) / ClkHz;

  // Quiet tail: nothing may move after done.
  const uint64_t tail = opt.tail_clocks ? opt.tail_clocks
                                        : 4ull * (uint64_t(timing.high) + timing.low + timing.setup + timing.hold) + 1000;
  for (uint64_t i = 0; i < tail && !drv.stopped(); ++i) tick(in, true);
  out = drv.out();
  pins.finish(drv.clock());
  drv.close_trace();
  res.total_clocks = drv.clock();
  res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  res.clocks_per_s = res.wall_s > 0 ? double(drv.clock()) / res.wall_s : 0;

  res.pulses = pins.net_steps();
  res.pulse_count_reg = out.pulse_count;
  if (opt.stop_at) res.stop = stop_report(stop, *opt.stop_at, out.ref_pos_int);
  // A move that stopped ends where the stop brought it (a start dropped in
  // the arming: where it stood); every reference step must be on the pins.
  const int64_t target = res.retarget_taken ? opt.retarget->distance : plan.distance;
  res.final_error = (opt.stop_at && !out.done ? int64_t(out.ref_pos_int) : target) - res.pulses;
  res.peak_velocity = vel_to_phys(peaks.v());
  res.peak_acceleration = acc_to_phys(peaks.a());
  res.peak_jerk = jerk_to_phys(peaks.j());
  res.mismatches = drv.checker().mismatches();
  res.matched_clocks = drv.checker().matched();
  if (!drv.checker().errors().empty()) res.first_mismatch = drv.checker().errors().front().to_string();
  res.pin_errors = pins.errors();
  res.phase_runs = pins.runs();
  res.trends = pins.trend_sequence();

  // ---- verdict ---------------------------------------------------------
  auto fail = [&](std::string s) { res.failures.push_back(std::move(s)); };
  if (res.mismatches) fail(fmt::format("{} lockstep mismatches: {}", res.mismatches, res.first_mismatch));
  if (opt.stop_at && !res.stop.taken && !reached_done && res.pulses == 0 && !out.busy) {
    // A stop in the arming clocks drops the start: nothing moved, as it must.
  } else if (!reached_done) {
    fail(fmt::format("no done within {} clocks (hang)", limit));
  } else if (res.final_error != 0) {
    fail(res.stop.taken ? fmt::format("pulses {} != reference position {} after the stop", res.pulses,
                                      out.ref_pos_int)
                        : fmt::format("pulses {} != distance {}{}", res.pulses, target,
                                      res.retarget_taken ? " (retargeted)" : ""));
  }
  for (const std::string& e : stop.errors()) fail("controlled stop: " + e);
  if (res.pulse_count_reg != res.pulses) {
    fail(fmt::format("pulse_count_o {} != pins {}", res.pulse_count_reg, res.pulses));
  }
  for (const std::string& e : res.pin_errors) fail(e);
  if (opt.retarget && !res.retarget_requested) fail("the retarget was never sent (the run ended first)");
  if (!opt.stop_at && !opt.retarget && res.trends != res.expected_trends) {
    auto join = [](const std::vector<DutyTrend>& v) {
      std::string s;
      for (DutyTrend t : v) s += std::string(s.empty() ? "" : ",") + trend_name(t);
      return s;
    };
    // A very short move may have no pulse in a phase: only a missing
    // phase is tolerated, never an extra or out-of-order one.
    const auto& want = res.expected_trends;
    bool subseq = true;
    size_t pos = 0;
    for (DutyTrend t : res.trends) {
      while (pos < want.size() && want[pos] != t) ++pos;
      if (pos == want.size()) {
        subseq = false;
        break;
      }
      ++pos;
    }
    if (!subseq) fail(fmt::format("duty phases {} do not follow the plan's {}", join(res.trends), join(want)));
  }
  const double tol = 1e-9;
  if (limits.v_max > 0 && res.peak_velocity > limits.v_max * (1 + tol)) {
    fail(fmt::format("peak velocity {} > limit {}", res.peak_velocity, limits.v_max));
  }
  if (limits.a_max > 0 && res.peak_acceleration > limits.a_max * (1 + tol)) {
    fail(fmt::format("peak acceleration {} > limit {}", res.peak_acceleration, limits.a_max));
  }
  if (limits.j_max > 0 && res.peak_jerk > limits.j_max * (1 + tol)) {
    fail(fmt::format("peak jerk {} > limit {}", res.peak_jerk, limits.j_max));
  }
  if (opt.engine == SimEngine::Lockstep && res.matched_clocks == 0) fail("lockstep compared nothing");
  return res;
}

}  // namespace sc
