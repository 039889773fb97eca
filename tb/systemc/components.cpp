// Components of the SystemC bench (C++20 side; see components.h).
#include "components.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <vector>

#include "axis_core.h"
#include "fst_flags.h"
#include "kin_trace.h"
#include "lockstep.h"
#include "model_fst.h"
#include "pin_monitor.h"
#include "planner.h"
#include "scenarios.h"
#include "scurve/cli/move_flags.h"

namespace sc::bench {

namespace {

// ---- model ------------------------------------------------------------------
class ModelCore : public Core {
 public:
  explicit ModelCore(uint64_t inject_clock) : inject_clock_(inject_clock) {}
  void reset(int) override { model_.reset(); }
  void step(const CoreInputs& in) override {
    model_.step(in);
    after_clock();
  }
  void tick() override {
    model_.tick();
    after_clock();
  }
  // Built on demand: the scoreboard compares against the state in place.
  const CoreOutputs& outputs() const override {
    if (stale_) {
      out_ = model_.outputs();
      stale_ = false;
    }
    return out_;
  }
  bool done() const override { return outputs().done; }
  uint32_t phase() const override { return outputs().phase; }
  int32_t pulse_count() const override { return outputs().pulse_count; }
  const AxisCore& axis() const { return model_; }

 private:
  void after_clock() {
    stale_ = true;
    // Test hook: one extra count in the model's pulse counter after clock
    // `inject_clock_`, so the checker and the trace diff must report a
    // divergence at exactly that clock.
    if (clock_++ == inject_clock_) [[unlikely]] model_.step_gen().mutable_state().count += 1;
  }
  AxisCore model_;
  mutable CoreOutputs out_{};
  mutable bool stale_ = true;
  uint64_t clock_ = 0;
  uint64_t inject_clock_;
};

// ---- scoreboard ---------------------------------------------------------------
// Peaks of the reference (register values and per-clock differences, so a
// jump at a row boundary counts as acceleration/jerk), in LSBs.
struct ReferencePeaks {
  i128 v = 0, a = 0, j = 0;
  i128 prev_vel = 0;
  int64_t prev_acc = 0;
  bool have_prev = false;
  void on_clock(const CoreOutputs& o) {
    if (!o.busy || o.done) {
      have_prev = false;
      return;
    }
    auto mag = [](i128 x) { return x < 0 ? -x : x; };
    v = std::max(v, mag(o.ref_vel));
    a = std::max(a, mag(i128(o.ref_acc)));
    j = std::max(j, mag(i128(o.ref_jerk)));
    // The jump from rest to the start speed (and the arming clocks before
    // it, busy but at rest) is not an acceleration of the move.
    const bool prev_at_rest = prev_vel == 0 && prev_acc == 0;
    if (have_prev && !prev_at_rest) {
      a = std::max(a, mag(o.ref_vel - prev_vel));
      j = std::max(j, mag(i128(o.ref_acc) - prev_acc));
    }
    prev_vel = o.ref_vel;
    prev_acc = o.ref_acc;
    have_prev = true;
  }
};

class LockstepScoreboard : public Checker {
 public:
  LockstepScoreboard(const AxisCore& model, size_t max_mismatches) : model_(model), checker_(max_mismatches) {}
  bool compare(uint64_t clock, const CoreOutputs& rtl) override {
    peaks_.on_clock(rtl);
    checker_.slot(clock) = rtl;  // kept as context for a later mismatch report
    return checker_.check(clock, model_);
  }
  const AxisCore& model_;
  bool should_stop() const override { return checker_.should_stop(); }
  uint64_t mismatches() const override { return checker_.mismatches(); }
  LockstepChecker checker_;
  ReferencePeaks peaks_;
};

// ---- open-loop plant ------------------------------------------------------------
// An ideal stepper that follows STEP/DIR, checked by the pin monitor (pulse
// timing, DIR setup/hold, no pulse after done, duty phases). Tracking error
// = reference travel - stepper travel, sampled every control period (like
// the paper's 10 kHz loop) and at every STEP edge.
class OpenLoopPlant : public Plant {
 public:
  OpenLoopPlant(const PulseTiming& timing, uint64_t sample_period)
      : pins_(PinRules{timing, true, StepAccounting::ReferencePosition}), period_(std::max<uint64_t>(1, sample_period)), countdown_(period_) {}
  PlantFeedback on_clock(uint64_t clock, const CoreOutputs& o) override {
    pins_.on_clock(clock, o);
    if (--countdown_ == 0 || o.step != last_step_) [[unlikely]] sample(o);
    return {};
  }
  void finish(uint64_t clock) override { pins_.finish(clock); }
  int32_t position() const override { return int32_t(pins_.net_steps()); }
  double max_error() const { return max_err_; }
  double rmse() const { return n_ ? std::sqrt(sum_sq_ / double(n_)) : 0.0; }
  PinMonitor pins_;

 private:
  void sample(const CoreOutputs& o) {
    countdown_ = period_;
    last_step_ = o.step;
    if (!o.busy && !o.done) return;  // before the move
    if (!have_origin_) {
      have_origin_ = true;
      origin_ = o.ref_pos_int;
    }
    const double ref = double(o.ref_pos_int - origin_) + pos_to_phys(i128(o.ref_pos_frac));
    const double err = std::abs(ref - double(pins_.net_steps()));
    max_err_ = std::max(max_err_, err);
    sum_sq_ += err * err;
    ++n_;
  }
  uint64_t period_, countdown_;
  bool last_step_ = false, have_origin_ = false;
  int64_t origin_ = 0;
  double max_err_ = 0, sum_sq_ = 0;
  uint64_t n_ = 0;
};

// ---- traces -------------------------------------------------------------------
class KinTracer : public Tracer {
 public:
  explicit KinTracer(const BenchOptions& o) : opt_(o) {
    if (!o.trace_rtl.empty()) rtl_ = std::make_unique<KinTraceWriter>(o.trace_rtl, "rtl", o.trace_decimate);
    if (!o.trace_model.empty()) model_ = std::make_unique<KinTraceWriter>(o.trace_model, "model", o.trace_decimate);
    if (!o.fst_model_path.empty()) {
      fst_ = std::make_unique<ModelFstWriter>("fst-model", o.fst_model_path, o.fst_from, o.fst_to);
    }
  }
  void on_clock(uint64_t clock, const CoreOutputs& rtl, const CoreOutputs& model) override {
    if (rtl_) rtl_->on_clock(clock, rtl);
    if (model_) model_->on_clock(clock, model);
    if (fst_) fst_->on_clock(clock, model);
  }
  void close(uint64_t end_clock) override {
    // The trace writers say what failed; the message names the flag.
    auto close_trace = [end_clock](std::unique_ptr<KinTraceWriter>& w, const char* flag, const std::string& path) {
      if (!w) return;
      try {
        w->close(end_clock);
      } catch (const std::runtime_error& e) {
        throw input::Error(flag, path, e.what());
      }
    };
    close_trace(rtl_, "trace-rtl", opt_.trace_rtl);
    close_trace(model_, "trace-model", opt_.trace_model);
    if (fst_) fst_->close(end_clock);
  }

 private:
  const BenchOptions& opt_;
  std::unique_ptr<KinTraceWriter> rtl_, model_;
  std::unique_ptr<ModelFstWriter> fst_;
};

// ---- stimulus -----------------------------------------------------------------
class MoveStimulus : public Stimulus {
 public:
  MoveStimulus(const Plan& plan, const PulseTiming& timing) : plan_(plan) {
    CoreInputs in;
    in.cfg = timing;
    in.enable = true;
    for (const Row& r : move_rows(plan.segments)) {
      CoreInputs w = in;
      w.row_push = true;
      w.row = r;
      rows_.push_back(w);
    }
    in.pos_frac0 = plan.pos_frac0;
    run_ = in;
    start_ = in;
    start_.start = true;
    const uint64_t pulse_period = uint64_t(timing.high) + timing.low + timing.setup;
    // Same limits as the plain harness (tb/sim_run.cpp).
    limit_ = plan.total_clocks + 1000 + 4 * pulse_period;
    tail_ = 4 * (pulse_period + timing.hold) + 1000;
  }
  size_t rows() const override { return rows_.size(); }
  const CoreInputs& row_write(size_t i) const override { return rows_[i]; }
  const CoreInputs& start() const override { return start_; }
  const CoreInputs& run() const override { return run_; }
  uint64_t max_move_clocks() const override { return limit_; }
  uint64_t tail_clocks() const override { return tail_; }
  uint64_t planned_clocks() const override { return plan_.total_clocks; }

 private:
  const Plan& plan_;
  std::vector<CoreInputs> rows_;
  CoreInputs start_, run_;
  uint64_t limit_ = 0, tail_ = 0;
};

// ---- result ---------------------------------------------------------------------
struct Limits {
  double v_max = 0, a_max = 0, j_max = 0;  // 0 = not checked
};

std::string join(const std::vector<DutyTrend>& v) {
  std::string s;
  for (DutyTrend t : v) s += std::string(s.empty() ? "" : ",") + trend_name(t);
  return s;
}

// A very short move may show no pulse in some phase: only a missing phase is
// tolerated, never an extra or out-of-order one.
bool is_subsequence(const std::vector<DutyTrend>& got, const std::vector<DutyTrend>& want) {
  size_t pos = 0;
  for (DutyTrend t : got) {
    while (pos < want.size() && want[pos] != t) ++pos;
    if (pos == want.size()) return false;
    ++pos;
  }
  return true;
}

// ---- the run ----------------------------------------------------------------------
class BenchRunImpl : public BenchRun {
 public:
  BenchRunImpl(BenchOptions opt, std::string name, Plan plan, PulseTiming timing, Limits limits)
      : opt_(std::move(opt)),
        name_(std::move(name)),
        plan_(std::move(plan)),
        timing_(timing),
        limits_(limits),
        model_(opt_.inject_model_fault),
        scoreboard_(model_.axis(), opt_.max_mismatches),
        plant_(timing_, opt_.sync_period),
        stimulus_(plan_, timing_) {
    if (!opt_.trace_rtl.empty() || !opt_.trace_model.empty() || !opt_.fst_model_path.empty()) {
      tracer_ = std::make_unique<KinTracer>(opt_);
    }
  }
  const BenchOptions& options() const override { return opt_; }
  Core& model() override { return model_; }
  Checker& checker() override { return scoreboard_; }
  Plant& plant() override { return plant_; }
  Tracer* tracer() override { return tracer_.get(); }
  const Stimulus& stimulus() const override { return stimulus_; }
  int report(const RunStats& st) override;
  int close_outputs(uint64_t end_clock, Core* rtl) override {
    try {
      if (rtl) rtl->close_outputs();
      if (tracer_) tracer_->close(end_clock);
    } catch (const std::exception& e) {
      return scurve::cli::bad_input(e.what());
    }
    return 0;
  }

 private:
  BenchOptions opt_;
  std::string name_;
  Plan plan_;
  PulseTiming timing_;
  Limits limits_;
  ModelCore model_;
  LockstepScoreboard scoreboard_;
  OpenLoopPlant plant_;
  MoveStimulus stimulus_;
  std::unique_ptr<KinTracer> tracer_;
};

int BenchRunImpl::report(const RunStats& st) {
  const LockstepChecker& ck = scoreboard_.checker_;
  const PinMonitor& pins = plant_.pins_;
  const uint64_t start_clock = plan_.segments.size() + 1;
  const int64_t pulses = pins.net_steps();
  const int64_t pulse_reg = st.last_rtl ? st.last_rtl->pulse_count : 0;
  const std::vector<DutyTrend> trends = pins.trend_sequence(), expected = expected_trends(plan_.segments);
  const double peak_v = vel_to_phys(scoreboard_.peaks_.v);
  const double peak_a = acc_to_phys(scoreboard_.peaks_.a);
  const double peak_j = jerk_to_phys(scoreboard_.peaks_.j);
  const double cps = st.wall_s > 0 ? double(st.total_clocks) / st.wall_s : 0;
  const std::string first = ck.errors().empty() ? "" : ck.errors().front().to_string();

  std::vector<std::string> failures;
  auto fail = [&](std::string s) { failures.push_back(std::move(s)); };
  if (ck.mismatches()) fail(fmt::format("{} lockstep mismatches: {}", ck.mismatches(), first));
  if (!st.reached_done) fail("no done (hang, or stopped early)");
  if (pulses != plan_.distance) fail(fmt::format("pulses {} != distance {}", pulses, plan_.distance));
  if (pulse_reg != pulses) fail(fmt::format("pulse_count_o {} != pins {}", pulse_reg, pulses));
  for (const std::string& e : pins.errors()) fail(e);
  if (trends != expected && !is_subsequence(trends, expected)) {
    fail(fmt::format("duty phases {} do not follow the plan's {}", join(trends), join(expected)));
  }
  const double tol = 1 + 1e-9;
  if (limits_.v_max > 0 && peak_v > limits_.v_max * tol) fail(fmt::format("peak velocity {} > {}", peak_v, limits_.v_max));
  if (limits_.a_max > 0 && peak_a > limits_.a_max * tol) fail(fmt::format("peak acceleration {} > {}", peak_a, limits_.a_max));
  if (limits_.j_max > 0 && peak_j > limits_.j_max * tol) fail(fmt::format("peak jerk {} > {}", peak_j, limits_.j_max));
  if (ck.matched() == 0) fail("lockstep compared nothing");

  const bool pass = failures.empty();
  if (opt_.json) {
    auto arr = [](const std::vector<DutyTrend>& v) {
      nlohmann::json a = nlohmann::json::array();
      for (DutyTrend t : v) a.push_back(trend_name(t));
      return a;
    };
    nlohmann::json j = {
        {"name", name_},
        {"bench", st.bench},
        {"distance", plan_.distance},
        {"clocks", st.done_clock},
        {"total_clocks", st.total_clocks},
        {"pulses", pulses},
        {"final_error", plan_.distance - pulses},
        {"max_error", plant_.max_error()},
        {"rmse", plant_.rmse()},
        {"duration_s", double(st.done_clock - start_clock) / ClkHz},
        {"peak_velocity", peak_v},
        {"peak_acceleration", peak_a},
        {"peak_jerk", peak_j},
        {"mismatches", ck.mismatches()},
        {"matched_clocks", ck.matched()},
        {"first_mismatch", first},
        {"duty_phases", arr(trends)},
        {"expected_duty_phases", arr(expected)},
        {"quantum", opt_.quantum},
        {"syncs", st.syncs},
        {"wall_s", st.wall_s},
        {"clocks_per_s", cps},
        {"realtime_ratio", cps / ClkHz},
        {"pass", pass},
        {"failures", failures},
    };
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << fmt::format("{:<10} {:<16} {:>11} {:>7} {:>6} {:>7} {:>7} {:>9} {:>9} {:>9} {:>5} {:>7} {:>7} {}\n",
                             "run", "bench", "clocks", "pulses", "f.err", "max_e", "rmse", "peak_v", "peak_a",
                             "peak_j", "mism", "wall_s", "Mclk/s", "result");
    std::cout << fmt::format(
        "{:<10} {:<16} {:>11} {:>7} {:>6} {:>7.3f} {:>7.3f} {:>9.2f} {:>9.2f} {:>9.2f} {:>5} {:>7.2f} {:>7.2f} {}\n",
        name_, st.bench, st.done_clock, pulses, plan_.distance - pulses, plant_.max_error(), plant_.rmse(), peak_v,
        peak_a, peak_j, ck.mismatches(), st.wall_s, cps / 1e6, pass ? "PASS" : "FAIL");
    for (const std::string& f : failures) std::cout << "  " << f << "\n";
  }
  return pass ? 0 : 1;
}

// ---- pins ---------------------------------------------------------------------------
void put_words(uint32_t* w, u128 v, int bits) {
  v = mask_bits(v, bits);
  for (int i = 0; i * 32 < bits; ++i) w[i] = uint32_t(v >> (32 * i));
}
u128 get_words(const uint32_t* w, int bits) {
  u128 v = 0;
  for (int i = (bits - 1) / 32; i >= 0; --i) v = (v << 32) | w[i];
  return mask_bits(v, bits);
}

class PinCoreImpl : public PinCore {
 public:
  void reset(int) override {}
  void step(const CoreInputs&) override {}  // clocked by the sc_clock, not here
  void tick() override {}
  const CoreOutputs& outputs() const override { return out_; }
  bool done() const override { return out_.done; }
  uint32_t phase() const override { return out_.phase; }
  int32_t pulse_count() const override { return out_.pulse_count; }
  void latch(const PinOutputs& p) override {
    CoreOutputs& o = out_;
    o.step = p.step;
    o.dir = p.dir;
    o.en = p.en;
    o.busy = p.busy;
    o.done = p.done;
    o.phase = uint8_t(p.phase);
    o.fault_table = p.fault_table;
    o.fault_overrun = p.fault_overrun;
    o.underrun = p.underrun;
    o.discont = p.discont;
    o.stopping = p.stopping;
    o.overshoot = p.overshoot;
    o.move_done = p.move_done;
    o.fifo_full = p.fifo_full;
    o.row_count = p.row_count;
    o.retarget_refused = p.retarget_refused;
    o.move_idx = p.move_idx;
    o.boundary_pos = int32_t(p.boundary_pos);
    o.fifo_level = uint8_t(p.fifo_level);
    o.pulse_count = int32_t(p.pulse_count);
    o.ref_pos_int = int32_t(p.ref_pos_int);
    o.ref_pos_frac = get_words(p.ref_pos_frac, FracBits);
    o.ref_vel = wrap_signed(i128(get_words(p.ref_vel, VelW)), VelW);
    o.ref_acc = wrap_signed64(int64_t(p.ref_acc), AccW);
    o.ref_jerk = wrap_signed64(int64_t(p.ref_jerk), JerkW);
    o.seg_idx = uint8_t(p.seg_idx);
    o.step_pending = int8_t(wrap_signed64(int64_t(p.step_pending), PendW));
  }

 private:
  CoreOutputs out_{};
};

}  // namespace

void PinCore::encode(const CoreInputs& in, PinInputs* p) {
  p->enable = in.enable;
  p->row_push = in.row_push;
  p->fifo_flush = in.fifo_flush;
  p->start = in.start;
  p->abort = in.abort;
  p->stop = in.stop;
  p->stop_jerk = in.stop_jerk & ((uint64_t(1) << JerkW) - 1);
  p->stop_acc = in.stop_acc;
  p->cfg_high = in.cfg.high;
  p->cfg_low = in.cfg.low;
  p->cfg_setup = in.cfg.setup;
  p->cfg_hold = in.cfg.hold;
  p->row_flags = in.row.flags;
  p->seg_phase = uint32_t(in.row.seg.phase);
  p->seg_clocks = in.row.seg.clocks;
  p->seg_jerk = uint64_t(in.row.seg.jerk) & ((uint64_t(1) << JerkW) - 1);
  p->seg_acc0 = uint64_t(in.row.seg.acc0);
  put_words(p->seg_vel0, u128(in.row.seg.vel0), VelW);
  put_words(p->pos_frac0, in.pos_frac0, FracBits);
}

std::unique_ptr<PinCore> make_pin_core() { return std::make_unique<PinCoreImpl>(); }

std::unique_ptr<BenchRun> BenchRun::from_args(int argc, char** argv, bool batched, int* exit_code) {
  CLI::App app{batched ? "sc_bench: SystemC lockstep bench, Verilated --cc RTL advanced in quanta (temporal decoupling)"
                       : "sc_bench_pin: SystemC lockstep bench, pin-accurate Verilated --sc RTL on an sc_clock"};
  BenchOptions opt;
  int group = 0;
  scurve::cli::MoveFlags move;  // the move flags of `scurve plan` / `scurve sim`
  using scurve::cli::int_flag;
  using scurve::cli::output_file_flag;
  constexpr int64_t kMaxClocks = int64_t(1) << 40;
  int_flag(&app, "--group", group, 1, 4, "paper 000 Table 2 group 1..4 (L=30000, a=500, j=2500)");
  std::vector<CLI::Option*> move_opts;
  scurve::cli::add_move_flags(&app, move, &move_opts);
  app.add_option("--name", opt.name, "run name in the report");
  app.add_flag("--json", opt.json, "print one JSON object");
  output_file_flag(&app, "--trace-rtl", opt.trace_rtl, "kinematics trace (CSV) of the RTL");
  output_file_flag(&app, "--trace-model", opt.trace_model, "kinematics trace (CSV) of the model");
  int_flag(&app, "--trace-decimate", opt.trace_decimate, 1, kMaxClocks,
           "sample the reference every N clocks (pins: every change)");
  FstFlags fst;
  if (batched) {
    int_flag(&app, "--quantum", opt.quantum, 1, kMaxClocks, "clocks per SystemC wait() (temporal decoupling)");
    int_flag(&app, "--sync-period", opt.sync_period, 1, kMaxClocks,
             "quanta end on multiples of this many clocks (control period)");
    add_fst_flags(&app, fst, "the RTL");
    output_file_flag(&app, "--fst-model", opt.fst_model_path, "FST of the model's outputs (RTL port names, same window)");
    int_flag(&app, "--max-mismatches", opt.max_mismatches, 1, int64_t(1) << 30,
             "stop after this many mismatching signals");
    int_flag(&app, "--inject-model-fault", opt.inject_model_fault, 0, kMaxClocks,
             "test hook: add 1 to the model's pulse counter after this clock");
  }
  if (const auto rc = scurve::cli::parse_command_line(app, argc, argv)) {
    *exit_code = *rc;
    return nullptr;
  }
  // --fst-model shares the window of --fst and works without it.
  const std::string fst_path = fst.path;
  if (fst.path.empty() && !opt.fst_model_path.empty()) fst.path = opt.fst_model_path;
  if (const std::string e = fst.resolve(); !e.empty()) {
    *exit_code = scurve::cli::bad_input(e);
    return nullptr;
  }
  opt.fst_path = fst_path;
  opt.fst_from = fst.from;
  opt.fst_to = fst.to;
  std::string name = opt.name;
  MoveRequest req = scurve::cli::to_request(move);
  if (group) {
    for (const CLI::Option* o : move_opts) {
      if (o->count() > 0) {
        std::fprintf(stderr, "error: %s: give --group 1..4 or a move, not both\n", o->get_name().c_str());
        *exit_code = 2;
        return nullptr;
      }
    }
    req = paper_group(group);
    if (name.empty()) name = paper_group_name(group);
  } else {
    if (const std::string e = scurve::cli::check_move_flags(move); !e.empty()) {
      *exit_code = scurve::cli::bad_input(e + "; or give --group 1..4");
      return nullptr;
    }
    if (name.empty()) name = "move";
  }
  const PulseTiming t = to_model(scurve::cli::to_timing(move));
  PlanResult r = plan_move(req, t);
  if (const auto* e = std::get_if<PlanError>(&r)) {
    std::fprintf(stderr, "error: %s\n", e->message.c_str());
    *exit_code = 2;
    return nullptr;
  }
  Plan plan = std::get<Plan>(std::move(r));
  // Checked against the request's limits, not the plan's own peaks.
  Limits lim;
  lim.v_max = std::max({req.v_cruise, req.v_start, plan.v_end_used});
  lim.a_max = req.a_max;
  if (req.kind == ProfileKind::SCurve) {
    lim.j_max = req.jerks ? std::max({(*req.jerks)[0], (*req.jerks)[1], (*req.jerks)[2], (*req.jerks)[3]}) : req.j_max;
  }
  try {
    auto run = std::make_unique<BenchRunImpl>(opt, name, std::move(plan), t, lim);
    *exit_code = 0;
    return run;
  } catch (const std::exception& e) {  // an output file that cannot be created
    *exit_code = scurve::cli::bad_input(e.what());
    return nullptr;
  }
}

}  // namespace sc::bench
