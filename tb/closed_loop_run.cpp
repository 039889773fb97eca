#include "closed_loop_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <deque>
#include <memory>

#include "pin_monitor.h"
#include "reg_encode.h"
#include "rtl_servo.h"
#include "scurve/cli/user_input.h"

namespace sc {

const char* cl_engine_name(ClEngine e) {
  switch (e) {
    case ClEngine::Lockstep: return "lockstep";
    case ClEngine::RtlOnly: return "rtl";
    case ClEngine::ModelOnly: return "model";
  }
  return "?";
}

std::string to_servo_config(const ControllerParams& p, const PlantConfig& plant, const PulseTiming& t,
                            ServoConfig& out) {
  const scurve::ServoConfigResult r = scurve::to_servo_config(p, plant.counts_per_step, to_host(t), model_clock());
  if (const auto* e = std::get_if<scurve::Error>(&r)) return e->message;
  out = to_model(std::get<scurve::ServoConfig>(r));
  return {};
}

SignalValues render_servo(const ServoOutputs& o) {
  SignalValues v;
  auto add = [&](const char* n, int64_t x, int width) { v.emplace_back(n, hex_bits(x, width)); };
  add("step_o", o.step, 1);
  add("dir_o", o.dir, 1);
  add("en_o", o.en, 1);
  add("busy_o", o.busy, 1);
  add("done_o", o.done, 1);
  add("phase_o", o.phase, PhaseW);
  add("fault_table_o", o.fault_table, 1);
  add("fault_overrun_o", o.fault_overrun, 1);
  add("fault_ferr_o", o.fault_ferr, 1);
  add("in_pos_o", o.in_pos, 1);
  add("underrun_o", o.underrun, 1);
  add("discont_o", o.discont, 1);
  add("guard_o", o.guard, 1);
  add("reach_o", o.reach, 1);
  add("stopping_o", o.stopping, 1);
  add("overshoot_o", o.overshoot, 1);
  add("move_done_o", o.move_done, 1);
  add("move_idx_o", o.move_idx, MoveIdxW);
  add("boundary_pos_o", o.boundary_pos, 32);
  add("fifo_level_o", o.fifo_level, RowLevelW);
  add("fifo_full_o", o.fifo_full, 1);
  add("row_count_o", o.row_count, RowCountW);
  add("retarget_refused_o", o.retarget_refused, 1);
  add("pulse_count_o", o.pulse_count, 32);
  add("enc_pos_o", o.enc_pos, 32);
  add("enc_illegal_o", o.enc_illegal, 16);
  add("enc_index_o", o.enc_index, 1);
  add("ref_pos_int_o", o.ref_pos_int, 32);
  add("ref_frac_hi_o", o.ref_frac_hi, 32);
  add("ref_vel_o", o.ref_vel, 32);
  add("ref_done_o", o.ref_done, 1);
  add("ctl_active_o", o.ctl_active, 1);
  add("ctl_state_o", o.ctl_state, 8);
  add("u_o", o.u, 32);
  add("v_cmd_o", o.v_cmd, 32);
  add("e_p_o", o.e_p, 32);
  add("e_v_o", o.e_v, 32);
  add("w_p1_o", o.w_p1, WgtW);
  add("w_p2_o", o.w_p2, WgtW);
  add("w_v1_o", o.w_v1, WgtW);
  add("w_v2_o", o.w_v2, WgtW);
  add("wn_p1_o", o.wn_p1, NWgtW);
  add("wn_p2_o", o.wn_p2, NWgtW);
  add("wn_v1_o", o.wn_v1, NWgtW);
  add("wn_v2_o", o.wn_v2, NWgtW);
  add("nco_phase_o", o.nco_phase, NcoW);
  add("step_pending_o", o.step_pending, PendW);
  return v;
}

namespace {

// The CSV text into `f`; false on the first failed write (errno says why).
bool put_weights_csv(std::FILE* f, const std::vector<WeightSample>& w) {
  if (std::fputs("t_s,w_p1,w_p2,w_v1,w_v2,wn_p1,wn_p2,wn_v1,wn_v2,e_p\n", f) < 0) return false;
  for (const WeightSample& s : w) {
    if (std::fprintf(f, "%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.4f\n", s.t, s.w[0], s.w[1], s.w[2], s.w[3],
                     s.wn[0], s.wn[1], s.wn[2], s.wn[3], s.e_p) < 0) {
      return false;
    }
  }
  return std::fflush(f) == 0;
}

}  // namespace

std::string write_weights_csvs(const std::vector<WeightsCsv>& files) {
  std::vector<std::string> parts;
  auto remove_parts = [&parts] {
    for (const std::string& p : parts) std::remove(p.c_str());
  };
  for (const WeightsCsv& c : files) {
    const std::string part = c.path + ".part";
    errno = 0;
    std::FILE* f = std::fopen(part.c_str(), "w");
    if (!f) {
      const std::string why = std::strerror(errno);
      remove_parts();
      return part + ": " + why;
    }
    parts.push_back(part);
    const bool written = put_weights_csv(f, *c.samples);
    const int write_errno = errno;
    const bool closed = std::fclose(f) == 0;
    if (!written || !closed) {
      const std::string why = std::strerror(written ? errno : write_errno);
      remove_parts();
      return part + ": " + why;
    }
  }
  for (size_t i = 0; i < files.size(); ++i) {
    if (std::rename(parts[i].c_str(), files[i].path.c_str()) != 0) {
      const std::string why = std::strerror(errno);
      parts.erase(parts.begin(), parts.begin() + std::ptrdiff_t(i));  // the ones before are in place
      remove_parts();
      return files[i].path + ": " + why;
    }
  }
  return {};
}

namespace {

// Mean of the last `win` values added.
class MovingAverage {
 public:
  explicit MovingAverage(int win) : win_(win) {}
  // Adds x; once `win` values are in, true with their mean in *mean.
  bool add(double x, double* mean) {
    sum_ += x;
    buf_.push_back(x);
    if (int(buf_.size()) > win_) {
      sum_ -= buf_.front();
      buf_.pop_front();
    }
    if (int(buf_.size()) < win_) return false;
    *mean = sum_ / win_;
    return true;
  }

 private:
  int win_;
  double sum_ = 0;
  std::deque<double> buf_;
};

// Peak |acceleration| and |jerk| from a position sampled every `dt` s:
// two cascaded moving averages of `win` samples, then differences over
// `lag` samples. The same filter runs on the encoder and on the reference,
// so the two figures are comparable (quantisation noise shows in both).
class KinEstimator {
 public:
  KinEstimator(double dt, int win, int lag) : dt_(dt), lag_(lag), avg1_(win), avg2_(win) {}
  void add(double p) {
    double m1 = 0, m2 = 0;
    if (!avg1_.add(p, &m1) || !avg2_.add(m1, &m2)) return;
    hist_.push_back(m2);
    if (int(hist_.size()) > 3 * lag_ + 1) hist_.pop_front();
    if (int(hist_.size()) == 3 * lag_ + 1) {
      const double h = dt_ * lag_;
      const double p0 = hist_[0], p1 = hist_[lag_], p2 = hist_[2 * lag_], p3 = hist_[3 * lag_];
      const double a = (p3 - 2 * p2 + p1) / (h * h);
      const double j = (p3 - 3 * p2 + 3 * p1 - p0) / (h * h * h);
      peak_a = std::max(peak_a, std::fabs(a));
      peak_j = std::max(peak_j, std::fabs(j));
    }
  }
  double peak_a = 0, peak_j = 0;

 private:
  double dt_;
  int lag_;
  MovingAverage avg1_, avg2_;
  std::deque<double> hist_;
};

}  // namespace

namespace {

// What the host feeds the axis: the rows of one move or of a stream, each
// move's end position (the running sum of the distances), the planned
// length and the position fraction the executor starts from.
struct RowJob {
  std::deque<Row> rows;
  std::deque<int64_t> move_ends;
  uint64_t planned_clocks = 0;
  u128 pos_frac0 = 0;
};

// The rows through sc_servo_axis: the first ones (up to the FIFO depth)
// before START, the rest pushed in every clock the FIFO has room; every
// MOVE_DONE's boundary checked against the running sum.
ClosedLoopResult run_rows(RowJob job, const ClosedLoopOptions& opt) {
  ClosedLoopResult res;
  res.engine = opt.engine;
  res.distance = job.move_ends.empty() ? 0 : job.move_ends.back();
  ServoConfig cfg;
  if (std::string err = to_servo_config(opt.ctl, opt.plant, opt.timing, cfg); !err.empty()) {
    res.failures.push_back(err);
    return res;
  }
  const bool use_rtl = opt.engine != ClEngine::ModelOnly;
  const bool use_model = opt.engine != ClEngine::RtlOnly;
  const bool lockstep = opt.engine == ClEngine::Lockstep;
  std::unique_ptr<RtlServo> rtl;
  if (!opt.fst_path.empty() && !use_rtl) throw input::Error("fst", opt.fst_path, "the model engine runs no RTL to trace");
  if (use_rtl) {
    rtl = std::make_unique<RtlServo>();
    if (!opt.fst_path.empty()) rtl->trace_open(opt.fst_path, opt.fst_from, opt.fst_to);
    rtl->reset(4);
  }
  ServoAxis model;
  Plant plant(opt.plant, ClkHz);
  const double cps = opt.plant.counts_per_step;
  const double inv_cps = 1.0 / cps;

  ServoInputs in;
  in.cfg = cfg;
  in.stop_jerk = opt.stop_jerk;
  in.stop_acc = opt.stop_acc;
  ServoOutputs out;
  uint64_t clock = 0;
  bool stopped = false;
  Lockstep<ServoOutputs> checker(&render_servo, opt.max_mismatches);
  // Open loop: the pins against the executor's position; closed loop:
  // against the step generator's counter (the controller has no exact
  // reference to count against).
  const bool closed = cfg.closed_loop;
  // The duty-phase contract is one move's (open loop): a stream or a stop
  // follows no single planned phase order, only its pulses are checked.
  PinMonitor pins(PinRules{opt.timing, !closed && !opt.stop_at && job.move_ends.size() == 1,
                           closed ? StepAccounting::PulseCounter : StepAccounting::ReferencePosition});
  // The stop's reference, on the model's executor (RTL = model every clock in
  // lockstep; the RTL alone shows no executor state to check).
  stopcheck::StopMonitor stop(opt.stop_jerk, opt.stop_acc, /*reference_only=*/closed);
  // A following-error fault with ferr_stop is a controlled stop too.
  const bool ferr_stop = opt.ctl.closed_loop && opt.ctl.ferr_stop;
  const bool watch_stop = (opt.stop_at || ferr_stop) && use_model;

  auto tick = [&](const ServoInputs& si) {
    if (opt.inject) opt.inject(clock, model);
    if (rtl) rtl->step(si);
    if (use_model) model.step(si);
    if (watch_stop) stop.on_clock(model.core().outputs());
    out = rtl ? rtl->outputs() : model.outputs();
    if (lockstep && !checker.compare(clock, out, model.outputs()) && checker.should_stop()) stopped = true;
    if (closed) {
      pins.on_clock(clock, out.step, out.dir, out.done, out.phase, out.pulse_count);
    } else {
      pins.on_clock(clock, out.step, out.dir, out.done, out.phase, out.ref_pos_int, out.step_pending);
    }
    plant.clock(out.step, out.dir);
    in.enc_a = plant.enc_a();
    in.enc_b = plant.enc_b();
    in.enc_z = plant.enc_z();
    ++clock;
  };

  const auto t0 = std::chrono::steady_clock::now();
  for (size_t i = 0; i < RowFifoDepth && !job.rows.empty() && !stopped; ++i) {
    ServoInputs w = in;
    w.row_push = true;
    w.row = job.rows.front();
    job.rows.pop_front();
    tick(w);
  }
  in.pos_frac0 = job.pos_frac0;
  {
    ServoInputs st = in;
    st.start = true;
    if (!stopped) tick(st);
  }
  const uint64_t start_clock = clock;
  uint64_t limit = start_clock + job.planned_clocks + uint64_t(2.0 * ClkHz);
  const uint64_t stop_clock = opt.stop_at ? start_clock + *opt.stop_at : UINT64_MAX;
  ServoInputs stop_in = in;
  stop_in.stop = true;
  // A stop may outlast the plan (stop limits below the move's): once it
  // starts, the limit is a generous multiple of its closed-form time.
  bool stop_limit_set = false;
  auto extend_limit = [&]() {
    if (stop_limit_set || !stop.seen()) return;
    stop_limit_set = true;
    const stopcheck::ld ramp =
        std::fabs(stopcheck::ld(stop.start().a)) / stopcheck::ld(std::max<uint64_t>(1, opt.stop_jerk));
    limit = std::max(limit, clock + uint64_t(4 * (stop.closed_form_time() + ramp)) + uint64_t(2.0 * ClkHz));
  };
  // Stopped: the stop was requested and the axis is idle again (in position
  // after the reference came to rest, or the start dropped in the arming).
  auto stopped_idle = [&]() {
    return ((opt.stop_at && clock > stop_clock + 1) || (ferr_stop && out.fault_ferr)) && !out.busy;
  };

  // metrics
  const double L = double(res.distance);
  double max_err = 0, sum_sq = 0;
  int64_t peak_ref_vel = 0;  // the largest |V*|, Q.VffFrac pulses/clock
  uint64_t n_err = 0;
  uint64_t ref_done_clock = 0;
  const uint32_t kin_every = ClkHz / 1000;  // 1 ms samples
  // 50 ms windows: the 1-count encoder quantisation stays below the
  // S-curve's 2500 pulses/s^3 (a 10 ms filter reads millions on it).
  KinEstimator kin_enc(1e-3, 50, 50), kin_ref(1e-3, 50, 50);
  uint32_t kin_cnt = 0;
  const uint64_t wper = uint64_t(cfg.ctl.div) * std::max<uint32_t>(1, opt.weight_every);
  uint64_t wcnt = 0;
  const double wscale = 1.0 / double(1 << WgtFrac), nscale = 1.0 / double(1 << NWgtFrac);
  const double frac_scale = std::ldexp(1.0, -MulAW);
  const double expected = double(job.planned_clocks) + 1.0;
  // The host: a row in every clock the FIFO has room.
  ServoInputs push_in;
  auto host_inputs = [&]() -> const ServoInputs& {
    if (job.rows.empty() || out.fifo_full) [[likely]] return in;
    push_in = in;
    push_in.row_push = true;
    push_in.row = job.rows.front();
    job.rows.pop_front();
    return push_in;
  };
  size_t moves_done = 0;
  auto ref_pos = [&](const ServoOutputs& o) {
    return o.ref_done ? double(o.ref_pos_int) : double(o.ref_pos_int) + double(o.ref_frac_hi) * frac_scale - 0.5;
  };

  while (!stopped && clock < limit && !out.done && !(out.fault_ferr && !ferr_stop) && !stopped_idle()) {
    extend_limit();
    tick(clock == stop_clock ? stop_in : host_inputs());
    if (out.move_done) [[unlikely]] {
      StreamMoveReport m;
      m.index = moves_done;
      m.reached = true;
      m.end_clock = clock - 1 - start_clock;
      m.end_position = out.boundary_pos;
      m.expected_end_position = moves_done < job.move_ends.size() ? job.move_ends[moves_done] : 0;
      res.moves.push_back(m);
      ++moves_done;
    }
    peak_ref_vel = std::max(peak_ref_vel, std::abs(int64_t(out.ref_vel)));
    const double e = ref_pos(out) - double(out.enc_pos) * inv_cps;
    const double ae = std::fabs(e);
    if (ae > max_err) max_err = ae;
    sum_sq += e * e;
    ++n_err;
    if (out.ref_done && ref_done_clock == 0) ref_done_clock = clock;
    if (++kin_cnt == kin_every && !out.ref_done) [[unlikely]] {  // the move itself, not the settling
      kin_cnt = 0;
      kin_enc.add(double(out.enc_pos) * inv_cps);
      kin_ref.add(ref_pos(out));
    }
    if (++wcnt == wper) [[unlikely]] {
      wcnt = 0;
      WeightSample s;
      s.t = double(clock - start_clock) / ClkHz;
      const int32_t w[4] = {out.w_p1, out.w_p2, out.w_v1, out.w_v2};
      const int32_t n[4] = {out.wn_p1, out.wn_p2, out.wn_v1, out.wn_v2};
      for (int i = 0; i < 4; ++i) {
        s.w[i] = w[i] * wscale;
        s.wn[i] = n[i] * nscale;
      }
      s.e_p = double(out.e_p) / double(1 << CtlFrac) * inv_cps;
      res.weights.push_back(s);
    }
    if ((clock & 0xffffff) == 0 && opt.progress) opt.progress(double(clock - start_clock) / expected);
  }
  const uint64_t done_clock = clock;
  // Where the axis must end: the move's distance, or where the stop left the
  // reference (the controller settles on its integer position).
  // (A stop in the arming clocks drops the start: the target is where the
  // axis stands.)
  const bool stop_taken = (opt.stop_at || (ferr_stop && out.fault_ferr)) && !out.done;
  res.target = stop_taken ? int64_t(out.ref_pos_int) : res.distance;
  const double target = double(res.target);
  res.in_pos = out.in_pos;
  res.fault_ferr = out.fault_ferr;
  res.clocks = done_clock - start_clock;
  res.duration_s = double(res.clocks) / ClkHz;
  res.ref_duration_s = ref_done_clock ? double(ref_done_clock - start_clock) / ClkHz : 0;
  res.settle_time_s = ref_done_clock ? double(done_clock - ref_done_clock) / ClkHz : 0;

  // Quiet tail: residual vibration of the rotor and on the encoder.
  const uint64_t tail = uint64_t(opt.tail_s * ClkHz);
  double th_min = plant.theta(), th_max = plant.theta();
  double enc_dev = 0;
  for (uint64_t i = 0; i < tail && !stopped; ++i) {
    tick(in);
    th_min = std::min(th_min, plant.theta());
    th_max = std::max(th_max, plant.theta());
    enc_dev = std::max(enc_dev, std::fabs(double(out.enc_pos) - target * cps));
  }
  pins.finish(clock);
  if (rtl) rtl->trace_close();
  res.total_clocks = clock;
  res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  res.clocks_per_s = res.wall_s > 0 ? double(clock) / res.wall_s : 0;

  res.max_error = max_err;
  res.rmse = n_err ? std::sqrt(sum_sq / double(n_err)) : 0;
  res.relative_error = L != 0 ? res.rmse / std::fabs(L) : 0;
  res.rows_left = job.rows.size();
  res.final_error = res.target - int64_t(std::llround(double(out.enc_pos) * inv_cps));
  if (opt.stop_at || stop.seen()) {
    res.stop = stop_report(stop, opt.stop_at.value_or(0), out.ref_pos_int);
    res.stop.by_fault = !opt.stop_at;
  }
  res.pulses = plant.commanded();
  res.peak_acc_enc = kin_enc.peak_a;
  res.peak_jerk_enc = kin_enc.peak_j;
  res.peak_acc_ref = kin_ref.peak_a;
  res.peak_jerk_ref = kin_ref.peak_j;
  res.residual_vib = th_max - th_min;
  res.residual_enc = enc_dev;
  res.fault_overrun = out.fault_overrun;
  res.enc_illegal = out.enc_illegal;
  res.glitches = plant.glitches();
  res.slips = plant.slips();
  res.mismatches = checker.mismatches();
  res.matched_clocks = checker.matched();
  if (!checker.errors().empty()) res.first_mismatch = checker.errors().front().to_string();
  res.pin_errors = pins.errors();

  auto fail = [&](std::string s) { res.failures.push_back(std::move(s)); };
  if (res.mismatches) fail(fmt::format("{} lockstep mismatches: {}", res.mismatches, res.first_mismatch));
  if (lockstep && checker.compared_nothing()) fail("lockstep compared nothing");
  for (const std::string& e : res.pin_errors) fail("pins: " + e);
  for (const std::string& e : stop.errors()) fail("controlled stop: " + e);
  if (stop.seen() && out.done) fail("a stopped move reads done");
  if (stop_taken && out.busy) fail("busy at the end of the run after the stop");
  if (res.fault_ferr) fail("following-error fault");
  // The PID (no feed-forward) lags by about v / Kp on a ramp: its bound is
  // that lag at the reference's peak speed, with a margin for the ramps.
  const double v_peak = double(peak_ref_vel) * ClkHz / std::ldexp(1.0, VffFrac);
  const double pid_lag_limit =
      opt.ctl.pid_kp > 0 ? 1.25 * v_peak / opt.ctl.pid_kp + 5.0 : 0.0;  // no P: no bound
  const double max_error_limit = opt.max_error_limit.value_or(
      opt.ctl.kind == scurve::ControllerKind::kPidAw ? pid_lag_limit : default_max_error_limit(opt.ctl));
  if (max_error_limit > 0 && res.max_error > max_error_limit) {
    fail(fmt::format("max tracking error {:.3f} > {} pulses", res.max_error, max_error_limit));
  }
  // A stop in the arming clocks drops the start: the controller never ran.
  const bool start_dropped = opt.stop_at && !out.done && !stop.seen() && res.pulses == 0;
  if (!stopped && !res.in_pos && opt.ctl.closed_loop && !start_dropped) fail(fmt::format("not in position within {} clocks", limit));
  if (res.final_error != 0) fail(fmt::format("final error {} pulses", res.final_error));
  for (const StreamMoveReport& m : res.moves) {
    if (m.end_position != m.expected_end_position) {
      fail(fmt::format("move {} ended at {}, planned {}", m.index, m.end_position, m.expected_end_position));
    }
  }
  if (!stop_taken && !stopped && res.moves.size() != job.move_ends.size()) {
    fail(fmt::format("{} MOVE_DONE for {} moves", res.moves.size(), job.move_ends.size()));
  }
  if (!stop_taken && (out.underrun || out.discont)) {
    fail(fmt::format("{} after {} moves", out.underrun ? "underrun" : "discontinuity", res.moves.size()));
  }
  if (res.fault_overrun) fail("step queue overrun");
  return res;
}

}  // namespace

ClosedLoopResult run_closed_loop(const Plan& plan, const ClosedLoopOptions& opt) {
  RowJob job;
  for (const Row& r : move_rows(plan.segments)) job.rows.push_back(r);
  job.move_ends = {plan.distance};
  job.planned_clocks = plan.total_clocks;
  job.pos_frac0 = plan.pos_frac0;
  return run_rows(std::move(job), opt);
}

StreamRunResult run_closed_loop_stream(const PlannedStream& stream, const StreamRequest& request,
                                       const ClosedLoopOptions& opt) {
  RowJob job;
  job.rows = stream.rows;
  job.move_ends = stream.move_ends;
  job.planned_clocks = stream.moves.empty() ? 0 : stream.moves.back().end_clock;
  job.pos_frac0 = kOne / 2;  // the stream planner's start fraction
  const ClosedLoopResult c = run_rows(std::move(job), opt);

  StreamRunResult r = stream_report(stream, request, opt.timing);
  r.engine = opt.engine == ClEngine::RtlOnly    ? SimEngine::RtlOnly
             : opt.engine == ClEngine::ModelOnly ? SimEngine::ModelOnly
                                                 : SimEngine::Lockstep;
  r.rows = stream.rows.size() - c.rows_left;
  r.clocks = c.clocks;
  r.duration_s = c.duration_s;
  r.pulses = c.pulses;
  r.mismatches = c.mismatches;
  r.matched_clocks = c.matched_clocks;
  r.first_mismatch = c.first_mismatch;
  r.pin_errors = c.pin_errors;
  r.wall_s = c.wall_s;
  r.clocks_per_s = c.clocks_per_s;
  r.closed_loop = true;
  r.max_error = c.max_error;
  r.rmse = c.rmse;
  r.final_error = c.final_error;
  r.in_position = c.in_pos;
  r.failures = c.failures;
  for (size_t i = 0; i < c.moves.size() && i < r.moves.size(); ++i) {
    r.moves[i].reached = true;
    r.moves[i].end_clock = c.moves[i].end_clock;
    r.moves[i].end_position = c.moves[i].end_position;
  }
  check_boundary_clocks(r);
  return r;
}

}  // namespace sc
