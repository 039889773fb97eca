#include "multi_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <climits>
#include <memory>
#include <stdexcept>

#include "lockstep.h"
#include "pin_monitor.h"
#include "planner.h"
#include "rtl_multi_axis_core.h"

namespace sc {

MultiRows line_rows(const scurve::LinePlan& plan) {
  MultiRows m;
  for (const scurve::Plan& p : plan.axes) {
    std::vector<Segment> segs;
    segs.reserve(p.segments.size());
    for (const scurve::Segment& s : p.segments) segs.push_back(to_model(s));
    m.rows.push_back(move_rows(segs, true));
    m.pos_frac0.push_back(p.pos_frac0);
  }
  return m;
}

MultiRows path_rows(const scurve::PathPlan& plan) {
  MultiRows m;
  for (const scurve::PathAxisRows& ax : plan.axes) {
    std::vector<Row> r;
    r.reserve(ax.rows.size());
    for (size_t k = 0; k < ax.rows.size(); ++k) r.push_back(Row{to_model(ax.rows[k]), row_flags(ax.flags[k])});
    m.rows.push_back(std::move(r));
    m.pos_frac0.push_back(ax.pos_frac0);
  }
  for (const scurve::PlannedPathMove& mv : plan.moves) {
    std::vector<u128> f;
    for (const scurve::Plan& a : mv.line.axes) f.push_back(a.pos_frac0);
    m.move_frac0.push_back(std::move(f));
  }
  return m;
}

std::vector<std::vector<double>> path_polyline(const scurve::PathPlan& plan) {
  std::vector<std::vector<double>> poly;
  if (plan.moves.empty()) return poly;
  const std::vector<int64_t>& origin = plan.moves.front().start;
  const double one = std::ldexp(1.0, FracBits);
  for (const scurve::PlannedPathMove& m : plan.moves) {
    std::vector<double> v;
    for (size_t a = 0; a < origin.size(); ++a) {
      v.push_back(double(m.start[a] - origin[a]) + double(m.line.axes[a].pos_frac0) / one);
    }
    poly.push_back(std::move(v));
  }
  std::vector<double> last;
  for (size_t a = 0; a < origin.size(); ++a) last.push_back(double(plan.moves.back().target[a] - origin[a]) + 0.5);
  poly.push_back(std::move(last));
  return poly;
}

std::variant<std::vector<scurve::StopLimitCodes>, scurve::Error> line_stop_codes(
    const std::vector<int64_t>& distances, double stop_jerk, double stop_acc, scurve::Clock clock) {
  double length2 = 0;
  for (int64_t d : distances) length2 += double(d) * double(d);
  const double length = std::sqrt(length2);
  std::vector<scurve::StopLimitCodes> codes;
  for (int64_t d : distances) {
    const double share = d == 0 || length == 0 ? 1.0 : std::abs(double(d)) / length;
    auto c = scurve::stop_limit_codes(stop_jerk * share, stop_acc * share, clock);
    if (auto* e = std::get_if<scurve::Error>(&c)) return *e;
    codes.push_back(std::get<scurve::StopLimitCodes>(c));
  }
  return codes;
}

namespace {

double position(const CoreOutputs& o) {
  return double(o.ref_pos_int) + std::ldexp(double(o.ref_pos_frac), -FracBits);
}

// The model alone, no stop: where every axis's reference ends.
std::vector<double> end_positions(const MultiRows& rows, const MultiRunOptions& options);

class Run {
 public:
  // trace: record options.trace_every's trace (not in the pre-pass).
  Run(const MultiRows& rows, const MultiRunOptions& options, bool rtl, bool stop, bool trace)
      : rows_(rows),
        opt_(options),
        model_(rows.axes(), options.loop.has_value()),
        stop_(stop),
        trace_every_(trace ? options.trace_every : 0),
        closed_(options.loop && options.loop->closed) {
    if (rtl) rtl_ = std::make_unique<RtlMultiAxisCore>(rows.axes(), options.loop.has_value());
    in_.enable = true;
    for (size_t a = 0; a < rows.axes(); ++a) {
      CoreInputs& x = in_.axis[a];
      x.cfg = options.timing;
      x.pos_frac0 = rows.pos_frac0[a];
      if (!options.stop.empty()) {
        x.stop_jerk = options.stop[a].jerk;
        x.stop_acc = options.stop[a].acc;
      }
      if (!options.soft.empty()) x.soft = options.soft[a];
      PinRules r{options.timing};
      // Closed loop: the pulses follow the controller, counted against the
      // step generator's counter (no exact reference to count against).
      r.profile_phases = !stop && !closed_ && options.check_phases;
      r.accounting = closed_ ? StepAccounting::PulseCounter : StepAccounting::ReferencePosition;
      pins_.emplace_back(r);
      if (options.loop) {
        in_.loop[a].closed_loop = options.loop->closed;
        in_.loop[a].ctl = options.loop->ctl_per_axis.empty() ? options.loop->ctl : options.loop->ctl_per_axis.at(a);
        const bool own = !options.loop->plant_per_axis.empty();
        PlantConfig pc = own ? options.loop->plant_per_axis.at(a) : options.loop->plant;
        if (!own) pc.seed += a;
        plants_.emplace_back(pc, double(ClkHz));
      }
    }
    if (rtl_) rtl_->reset();
    model_.reset();
  }

  // Steps to the end; `line` (start and end per axis) measures the deviation.
  MultiRunResult run(const std::vector<double>* line_end) {
    const size_t n = rows_.axes();
    const size_t count = rows_.rows[0].size();
    MultiRunResult r;
    r.axes = n;
    r.stop_clock.assign(n, UINT64_MAX);
    r.min_pos_before_stop.assign(n, 0);
    r.max_pos_before_stop.assign(n, 0);
    bool any_stopped = false;
    r.reversed.assign(n, false);
    std::vector<int> vel_sign(n, 0);
    r.peak_velocity.assign(n, 0);
    r.peak_acceleration.assign(n, 0);
    r.peak_jerk.assign(n, 0);
    const double vel_lsb = std::ldexp(double(ClkHz), -FracBits);  // pulses/s per LSB
    const double acc_lsb = vel_lsb * double(ClkHz);
    const double jerk_lsb = acc_lsb * double(ClkHz);
    double contour_sum2 = 0, contour_now = 0;
    uint64_t contour_clocks = 0;
    // The next clock to sample: never without a trace, so a run without one
    // pays one compare per clock; START and each move end set it to now.
    uint64_t next_sample = UINT64_MAX;
    r.trace.axes = n;
    if (trace_every_ > 0) {
      const size_t expect = size_t(std::min<uint64_t>(opt_.max_clocks / trace_every_ + 16, 1u << 20));
      r.trace.clock.reserve(expect);
      r.trace.pos.reserve(expect * n);
      r.trace.vel.reserve(expect * n);
      if (opt_.loop) r.trace.measured.reserve(expect * n);
      r.trace.contour.reserve(expect);
    }
    uint32_t moves_done = 0;
    std::vector<double> start(n), dir(n);
    MultiLockstepChecker check(4);
    MultiCoreOutputs out, rtl_out;
    model_.read_outputs(out);
    // The executor takes its start fraction when it starts.
    for (size_t a = 0; a < n; ++a) {
      start[a] = double(out.axis[a].ref_pos_int) + std::ldexp(double(rows_.pos_frac0[a]), -FracBits);
    }
    double dir_len2 = 0;
    if (line_end) {
      for (size_t a = 0; a < n; ++a) {
        dir[a] = (*line_end)[a] - start[a];
        dir_len2 += dir[a] * dir[a];
      }
    }
    const auto t0 = std::chrono::steady_clock::now();
    size_t next = 0;
    bool started = false;
    uint64_t clock = 0, start_clock = 0;
    // settle_each_move: the rows of the move under way end before `push_end`;
    // the next move is pushed once every axis is done with this one.
    const bool fine = opt_.settle_each_move;
    size_t move = 0;
    size_t push_end = fine ? move_end_row(0) : count;
    bool move_started = false;
    uint64_t move_start_clock = 0, last_move_end_clock = 0;
    for (;; ++clock) {
      in_.row_push = false;
      in_.start = false;
      in_.stop = false;
      if (next < push_end && out.axis[0].fifo_level < RowFifoDepth) {
        in_.row_push = true;
        in_.row_clocks = rows_.rows[0][next].seg.clocks;
        for (size_t a = 0; a < n; ++a) in_.axis[a].row = rows_.rows[a][next];
        ++next;
      } else if (!move_started) {
        in_.start = true;
        move_started = true;
        move_start_clock = clock;
        if (!started) {
          started = true;
          start_clock = clock;
          if (trace_every_ > 0) next_sample = clock;
        }
      }
      if (started && stop_ && opt_.stop_at && clock == start_clock + *opt_.stop_at) in_.stop = true;
      if (stop_ && opt_.limit_at && (started ? clock >= start_clock + *opt_.limit_at : *opt_.limit_at == 0)) {
        CoreInputs& x = in_.axis[opt_.limit_axis];
        x.lim_fwd = x.lim_rev = true;
        x.lim_hard = opt_.limit_hard;
      }
      model_.step(in_);
      model_.read_outputs(out);
      if (rtl_) {
        rtl_->step(in_);
        rtl_->read_outputs(rtl_out);
        check.compare(clock, rtl_out, out);
      }
      for (size_t a = 0; a < n; ++a) any_stopped = any_stopped || out.axis[a].stopping;
      for (size_t a = 0; a < n; ++a) {
        const CoreOutputs& o = out.axis[a];
        if (!any_stopped) {
          r.min_pos_before_stop[a] = std::min(r.min_pos_before_stop[a], o.ref_pos_int);
          r.max_pos_before_stop[a] = std::max(r.max_pos_before_stop[a], o.ref_pos_int);
        }
        if (closed_) {
          pins_[a].on_clock(clock, o.step, o.dir, o.done, o.phase, o.pulse_count);
        } else {
          pins_[a].on_clock(clock, o);
        }
        if (o.stopping && r.stop_clock[a] == UINT64_MAX) r.stop_clock[a] = clock - start_clock;
        const int s = o.ref_vel > 0 ? 1 : o.ref_vel < 0 ? -1 : 0;
        if (s != 0) {
          if (vel_sign[a] != 0 && s != vel_sign[a]) r.reversed[a] = true;
          vel_sign[a] = s;
        }
        if (a > 0 && opt_.check_sync && (o.row_count != out.axis[0].row_count || o.move_idx != out.axis[0].move_idx ||
                      o.seg_idx != out.axis[0].seg_idx || o.fifo_level != out.axis[0].fifo_level)) {
          if (sync_errors_++ == 0) {
            r.errors.push_back(fmt::format("clock {}: axis {} out of step with axis 0 (rows {} / {}, row {} / {})",
                                           clock, a, o.row_count, out.axis[0].row_count, o.seg_idx,
                                           out.axis[0].seg_idx));
          }
        }
      }
      if (!plants_.empty()) track(r, out, clock, start_clock, started, moves_done);
      double v2 = 0, a2 = 0;
      for (size_t a = 0; a < n; ++a) {
        const CoreOutputs& o = out.axis[a];
        const double v = std::abs(double(o.ref_vel)) * vel_lsb, acc = std::abs(double(o.ref_acc)) * acc_lsb;
        v2 += v * v;
        a2 += acc * acc;
        r.peak_velocity[a] = std::max(r.peak_velocity[a], v);
        r.peak_acceleration[a] = std::max(r.peak_acceleration[a], acc);
        r.peak_jerk[a] = std::max(r.peak_jerk[a], std::abs(double(o.ref_jerk)) * jerk_lsb);
      }
      r.peak_path_velocity = std::max(r.peak_path_velocity, std::sqrt(v2));
      r.peak_path_acceleration = std::max(r.peak_path_acceleration, std::sqrt(a2));
      if (out.axis[0].move_done) {
        ++moves_done;
        last_move_end_clock = clock;
        MultiMoveEnd e{clock - start_clock, {}};
        for (size_t a = 0; a < n; ++a) e.ref_pos.push_back(out.axis[a].ref_pos_int);
        r.move_ends.push_back(std::move(e));
        if (trace_every_ > 0) next_sample = clock;
      }
      if (opt_.polyline.size() >= 2 && out.axis[0].row_count > 0) {
        const double d = contour_distance(out, std::min<size_t>(moves_done, opt_.polyline.size() - 2));
        r.contour_max = std::max(r.contour_max, d);
        contour_sum2 += d * d;
        ++contour_clocks;
        contour_now = d;
      }
      if (clock >= next_sample) [[unlikely]] {
        sample(r.trace, clock - start_clock, out, contour_now, vel_lsb);
        next_sample = start_clock + ((clock - start_clock) / trace_every_ + 1) * trace_every_;
      }
      if (opt_.progress && (clock & 0xfffff) == 0) opt_.progress(double(next) / double(count));
      if (line_end && dir_len2 > 0 && out.axis[0].row_count > 0) {
        double dot = 0, p2 = 0;
        for (size_t a = 0; a < n; ++a) {
          const double p = position(out.axis[a]) - start[a];
          dot += p * dir[a];
          p2 += p * p;
        }
        const double dev2 = p2 - dot * dot / dir_len2;
        if (dev2 > 0) r.max_line_deviation = std::max(r.max_line_deviation, std::sqrt(dev2));
      }
      if (check.should_stop()) break;
      bool idle = true;
      for (size_t a = 0; a < n; ++a) idle = idle && !out.axis[a].busy;
      if (move_started && clock > move_start_clock + 2 && idle) {
        if (!fine || move + 1 >= rows_.move_frac0.size() || next >= count) break;
        // Every axis done (in position): the next move from the corner, each
        // axis's POS_FRAC0 the fraction the plan starts it from.
        ++move;
        push_end = move_end_row(next);
        move_started = false;
        r.junction_wait.push_back(clock + 1 - last_move_end_clock);
        r.corner_error.push_back(plants_.empty() ? 0.0 : corner_distance(out));
        for (size_t a = 0; a < n; ++a) in_.axis[a].pos_frac0 = rows_.move_frac0[move][a];
      }
      if (clock - start_clock > opt_.max_clocks) {
        r.errors.push_back(fmt::format("not at rest after {} clocks (max_clocks)", opt_.max_clocks));
        break;
      }
    }
    // The last clock, at rest (unless a sample fell on it).
    if (trace_every_ > 0 && started && (r.trace.size() == 0 || r.trace.clock.back() != clock - start_clock)) {
      sample(r.trace, clock - start_clock, out, contour_now, vel_lsb);
    }
    if (contour_clocks > 0) r.contour_rms = std::sqrt(contour_sum2 / double(contour_clocks));
    if (measured_clocks_ > 0) r.measured_contour_rms = std::sqrt(measured_sum2_ / double(measured_clocks_));
    r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.clocks = clock - start_clock;
    r.compared = check.matched() + check.mismatches();
    r.mismatches = check.mismatches();
    for (const Mismatch& m : check.errors()) r.errors.push_back(m.to_string());
    for (size_t a = 0; a < n; ++a) {
      pins_[a].finish(clock);
      for (const std::string& e : pins_[a].errors()) r.errors.push_back(fmt::format("axis {} pins: {}", a, e));
      r.ref_pos.push_back(out.axis[a].ref_pos_int);
      r.pin_steps.push_back(pins_[a].net_steps());
      r.done.push_back(out.axis[a].done);
      r.reach.push_back(out.axis[a].reach);
      if (!plants_.empty()) {
        r.measured_pos.push_back(measured(out, a));
        r.final_error.push_back(double(out.axis[a].ref_pos_int) - measured(out, a));
        r.in_pos.push_back(out.loop[a].in_pos);
        r.ferr.push_back(out.loop[a].fault_ferr);
      }
    }
    return r;
  }

  // One past the first MOVE_END row at or after row `from` (the end of the
  // rows when there is none).
  size_t move_end_row(size_t from) const {
    const std::vector<Row>& r0 = rows_.rows[0];
    for (size_t k = from; k < r0.size(); ++k) {
      if (r0[k].flags & kRowMoveEnd) return k + 1;
    }
    return r0.size();
  }

  // The measured position's distance from where the references rest (pulses).
  double corner_distance(const MultiCoreOutputs& out) const {
    double d2 = 0;
    for (size_t a = 0; a < rows_.axes(); ++a) {
      const double e = double(out.axis[a].ref_pos_int) - measured(out, a);
      d2 += e * e;
    }
    return std::sqrt(d2);
  }

  // The measured position of axis a, pulses.
  double measured(const MultiCoreOutputs& out, size_t a) const {
    return double(out.loop[a].enc_pos) / opt_.loop->plant.counts_per_step;
  }

  // The plants take this clock's pins; their encoders are next clock's
  // inputs. Tracking and the measured contour once the motion started.
  void track(MultiRunResult& r, const MultiCoreOutputs& out, uint64_t clock, uint64_t start_clock, bool started,
             uint32_t moves_done) {
    const size_t n = rows_.axes();
    if (r.max_tracking_error.size() != n) {
      r.max_tracking_error.assign(n, 0);
      r.overshoot.assign(n, 0);
      r.overshoot_percent.assign(n, 0);
    }
    std::array<double, MaxAxes> meas{};
    for (size_t a = 0; a < n; ++a) {
      const CoreOutputs& o = out.axis[a];
      plants_[a].clock(o.step, o.dir);
      in_.loop[a].enc_a = plants_[a].enc_a();
      in_.loop[a].enc_b = plants_[a].enc_b();
      in_.loop[a].enc_z = plants_[a].enc_z();
      // (the polyline is in the reference's coordinates, P* = measured + 1/2)
      meas[a] = measured(out, a) + 0.5;
      if (!started || clock <= start_clock) continue;
      // The loop follows P* - 1/2 while the reference moves, its integer
      // position at rest (sc_neuron_pi's reference).
      const double ref = o.ref_vel != 0 || o.ref_acc != 0 ? position(o) - 0.5 : double(o.ref_pos_int);
      r.max_tracking_error[a] = std::max(r.max_tracking_error[a], std::abs(ref - measured(out, a)));
      if (opt_.polyline.size() >= 2) overshoot(r, a, o, meas[a], moves_done);
    }
    if (started && opt_.polyline.size() >= 2 && out.axis[0].row_count > 0) {
      const double d = contour_of(meas.data(), std::min<size_t>(moves_done, opt_.polyline.size() - 2));
      r.measured_contour_max = std::max(r.measured_contour_max, d);
      measured_sum2_ += d * d;
      ++measured_clocks_;
    }
  }

  // Overshoot of axis a: how far the measured position (reference
  // coordinates) passes the target of the last line that moved the axis, in
  // the direction of that line, pulses and percent of the axis's travel on
  // it (paper 003's index; the axis's own target, so a line that moves the
  // axis on is not counted against the previous one once it moves).
  void overshoot(MultiRunResult& r, size_t a, const CoreOutputs& o, double pos, uint32_t moves_done) {
    const size_t last = opt_.polyline.size() - 2;
    if (o.ref_vel != 0) moving_line_[a] = std::min<size_t>(moves_done, last);
    const size_t k = moving_line_[a];
    if (k > last) return;  // the axis has not moved yet
    const double from = opt_.polyline[k][a], to = opt_.polyline[k + 1][a];
    if (to == from) return;
    const double past = to > from ? pos - to : to - pos;
    if (past > r.overshoot[a]) r.overshoot[a] = past;
    const double pct = 100 * past / std::abs(to - from);
    if (pct > r.overshoot_percent[a]) r.overshoot_percent[a] = pct;
  }

  // The reference's distance from polyline segment k (its projection
  // clamped to the segment).
  double contour_distance(const MultiCoreOutputs& out, size_t k) const {
    std::array<double, MaxAxes> pos{};
    for (size_t a = 0; a < rows_.axes(); ++a) pos[a] = position(out.axis[a]);
    return contour_of(pos.data(), k);
  }

  // The distance of a point (one position per axis) from polyline segment
  // k (or the next one, if nearer, with contour_adjacent).
  double contour_of(const double* pos, size_t k) const {
    const double d = segment_distance(pos, k);
    if (!opt_.contour_adjacent || k + 2 >= opt_.polyline.size()) return d;
    return std::min(d, segment_distance(pos, k + 1));
  }

  double segment_distance(const double* pos, size_t k) const {
    const std::vector<double>& p0 = opt_.polyline[k];
    const std::vector<double>& p1 = opt_.polyline[k + 1];
    double len2 = 0, dot = 0;
    for (size_t a = 0; a < rows_.axes(); ++a) {
      len2 += (p1[a] - p0[a]) * (p1[a] - p0[a]);
      dot += (pos[a] - p0[a]) * (p1[a] - p0[a]);
    }
    const double t = len2 > 0 ? std::clamp(dot / len2, 0.0, 1.0) : 0.0;
    double d2 = 0;
    for (size_t a = 0; a < rows_.axes(); ++a) {
      const double e = pos[a] - (p0[a] + t * (p1[a] - p0[a]));
      d2 += e * e;
    }
    return std::sqrt(d2);
  }

  void sample(MultiTrace& t, uint64_t clock, const MultiCoreOutputs& out, double contour, double vel_lsb) const {
    t.clock.push_back(clock);
    for (size_t a = 0; a < rows_.axes(); ++a) {
      t.pos.push_back(position(out.axis[a]));
      t.vel.push_back(double(out.axis[a].ref_vel) * vel_lsb);
      // in the reference's coordinates, where the loop at rest equals P*
      if (opt_.loop) t.measured.push_back(measured(out, a) + 0.5);
    }
    t.contour.push_back(contour);
  }

  std::vector<double> final_positions() const {
    std::vector<double> p;
    for (size_t a = 0; a < rows_.axes(); ++a) p.push_back(position(model_.axis(a).outputs()));
    return p;
  }

 private:
  const MultiRows& rows_;
  const MultiRunOptions& opt_;
  MultiAxisCore model_;
  std::unique_ptr<RtlMultiAxisCore> rtl_;
  MultiCoreInputs in_{};
  std::vector<PinMonitor> pins_;
  bool stop_;
  uint64_t trace_every_;
  bool closed_;
  std::vector<Plant> plants_;  // with options.loop
  double measured_sum2_ = 0;
  uint64_t measured_clocks_ = 0;
  // per axis: the last line (polyline segment) its reference moved on; none yet: SIZE_MAX
  std::array<size_t, MaxAxes> moving_line_ = [] {
    std::array<size_t, MaxAxes> a{};
    a.fill(SIZE_MAX);
    return a;
  }();
  uint64_t sync_errors_ = 0;
};

std::vector<double> end_positions(const MultiRows& rows, const MultiRunOptions& options) {
  // The reference does not depend on the loop: the open-loop core finds it
  // without waiting for the loops to settle.
  MultiRunOptions open = options;
  open.loop.reset();
  Run pre(rows, open, false, false, false);
  pre.run(nullptr);
  return pre.final_positions();
}

}  // namespace

MultiRunResult run_multi(const MultiRows& rows, const MultiRunOptions& options) {
  if (options.limit_at && options.limit_axis >= rows.axes()) {
    throw std::invalid_argument(fmt::format("run_multi: limit_axis={} but only {} axes", options.limit_axis,
                                            rows.axes()));
  }
  if (!options.soft.empty() && options.soft.size() != rows.axes()) {
    throw std::invalid_argument(fmt::format("run_multi: {} soft-limit windows for {} axes", options.soft.size(),
                                            rows.axes()));
  }
  if (rows.rows.empty() || rows.pos_frac0.size() != rows.axes()) {
    throw std::invalid_argument("run_multi: rows and pos_frac0 need one entry per axis");
  }
  if (options.settle_each_move && rows.move_frac0.empty()) {
    throw std::invalid_argument("run_multi: settle_each_move needs the moves' start fractions (path_rows)");
  }
  for (const auto& r : rows.rows) {
    if (r.size() != rows.rows[0].size() || r.empty()) {
      throw std::invalid_argument("run_multi: every axis needs the same number of rows (at least one)");
    }
    for (size_t k = 0; k < r.size(); ++k) {
      if (r[k].seg.clocks != rows.rows[0][k].seg.clocks) {
        throw std::invalid_argument(fmt::format("run_multi: row {} lasts {} clocks on one axis, {} on axis 0", k,
                                                r[k].seg.clocks, rows.rows[0][k].seg.clocks));
      }
    }
  }
  if (options.loop) {
    const size_t plants = options.loop->plant_per_axis.size(), ctls = options.loop->ctl_per_axis.size();
    if ((plants != 0 && plants != rows.axes()) || (ctls != 0 && ctls != rows.axes())) {
      throw std::invalid_argument(fmt::format("run_multi: {} plants and {} controller settings for {} axes", plants,
                                              ctls, rows.axes()));
    }
  }
  std::vector<double> line;
  if (options.measure_line) line = end_positions(rows, options);
  Run run(rows, options, options.rtl,
          options.stop_at.has_value() || options.limit_at.has_value() || !options.soft.empty(), true);
  return run.run(options.measure_line ? &line : nullptr);
}

}  // namespace sc
