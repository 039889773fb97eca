#include "closed_loop_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <memory>

#include "rtl_servo.h"

namespace sc {

const char* cl_engine_name(ClEngine e) {
  switch (e) {
    case ClEngine::Lockstep: return "lockstep";
    case ClEngine::RtlOnly: return "rtl";
    case ClEngine::ModelOnly: return "model";
  }
  return "?";
}

namespace {

uint32_t coef(double v) { return uint32_t(std::llround(v * double(1u << CoefFrac))); }
int32_t wgt(double v) { return int32_t(std::llround(v * double(1 << WgtFrac))); }

}  // namespace

std::string to_servo_config(const ControllerParams& p, const PlantConfig& plant, const PulseTiming& t,
                            ServoConfig& out) {
  ServoConfig c;
  c.enable = true;
  c.closed_loop = p.closed_loop;
  c.timing = t;
  if (p.enc_filt < 0 || p.enc_filt >= (1 << EncFiltW)) return fmt::format("enc-filter={} outside 0..{}", p.enc_filt, (1 << EncFiltW) - 1);
  NeuronConfig& n = c.ctl;
  n.enc_filt = uint8_t(p.enc_filt);
  const double div = std::round(double(ClkHz) / p.rate_hz);
  if (!(div >= NeuronPi::kMinDiv && div < 65536))
    return fmt::format("ctl-rate={} Hz: needs {}..{} Hz ({}..65535 clocks)", p.rate_hz, ClkHz / 65535.0,
                       double(ClkHz) / NeuronPi::kMinDiv, NeuronPi::kMinDiv);
  n.div = uint16_t(div);
  const double cps = plant.counts_per_step;
  const int shift = int(std::lround(std::log2(cps)));
  if (!(cps >= 1) || std::ldexp(1.0, shift) != cps || shift >= (1 << EncShiftW)) {
    return fmt::format("counts-per-step={} must be a power of two 1..{}", cps, 1 << ((1 << EncShiftW) - 1));
  }
  n.shift = uint8_t(shift);
  n.ff_en = p.ff;
  if (p.learn_shift < 0 || p.learn_shift >= (1 << LearnShW)) return fmt::format("learn-shift={} outside 0..31", p.learn_shift);
  n.learn_shift = uint8_t(p.learn_shift);
  const double q8 = double(1 << CtlFrac);
  n.learn_dz_p = uint32_t(std::llround(p.learn_dz_p * cps * q8));
  n.learn_dz_v = uint32_t(std::llround(p.learn_dz_v * cps * q8));
  const double cmax = double(1u << (CoefW - CoefFrac));
  for (double v : {p.k_p, p.k_v, p.kb, p.eta_p1, p.eta_p2, p.eta_v1, p.eta_v2}) {
    if (!(v >= 0 && v < cmax)) return fmt::format("gain/learning rate {} outside [0, {})", v, cmax);
  }
  n.k_p = coef(p.k_p);
  n.k_v = coef(p.k_v);
  n.kb = coef(p.kb);
  const double k = p.adaptive ? 1.0 : 0.0;
  n.eta_p1 = coef(p.eta_p1 * k);
  n.eta_p2 = coef(p.eta_p2 * k);
  n.eta_v1 = coef(p.eta_v1 * k);
  n.eta_v2 = coef(p.eta_v2 * k);
  const double wmax = double(1 << (WgtW - 1 - WgtFrac));
  for (double v : {p.w_p1, p.w_p2, p.w_v1, p.w_v2, p.w_min, p.w_p1_max, p.w_p2_max, p.w_v1_max, p.w_v2_max}) {
    if (!(v > -wmax && v < wmax)) return fmt::format("weight {} outside (-{}, {})", v, wmax, wmax);
  }
  n.w_p1 = wgt(p.adaptive ? p.w_p1 : p.fixed_w_p1);
  n.w_p2 = wgt(p.w_p2);
  n.w_v1 = wgt(p.w_v1);
  n.w_v2 = wgt(p.w_v2);
  n.w_min = wgt(p.w_min);
  n.w_p1_max = wgt(p.w_p1_max);
  n.w_p2_max = wgt(p.w_p2_max);
  n.w_v1_max = wgt(p.w_v1_max);
  n.w_v2_max = wgt(p.w_v2_max);
  // speeds: pulses/s -> counts per control period, Q.CtlFrac
  const double per = div / double(ClkHz) * cps * q8;
  const double rate_limit = double(ClkHz) / (double(t.high) + double(t.low));
  const double u_lim = p.u_lim > 0 ? p.u_lim : 0.9 * rate_limit;
  if (u_lim > rate_limit) return fmt::format("u-lim={} pulses/s above the step-rate limit {}", u_lim, rate_limit);
  n.v_lim = uint32_t(std::llround(std::min(p.v_lim * per, 2147483647.0)));
  n.u_lim = uint32_t(std::llround(u_lim * per));
  n.ferr_lim = uint32_t(std::llround(std::min(p.ferr_lim * cps * q8, 2147483647.0)));
  n.inpos_win = uint32_t(std::llround(p.inpos_win * cps * q8));
  n.settle_rate = uint32_t(std::llround(p.settle_rate * per));
  const double hold = std::ceil(p.inpos_hold_s * p.rate_hz);
  n.inpos_hold = uint16_t(std::clamp(hold, 1.0, 65535.0));
  out = c;
  return {};
}

std::vector<std::pair<std::string, std::string>> render_servo(const ServoOutputs& o) {
  std::vector<std::pair<std::string, std::string>> v;
  auto add = [&](const char* n, auto x) { v.emplace_back(n, fmt::format("{}", x)); };
  add("step_o", int(o.step));
  add("dir_o", int(o.dir));
  add("en_o", int(o.en));
  add("busy_o", int(o.busy));
  add("done_o", int(o.done));
  add("phase_o", int(o.phase));
  add("fault_table_o", int(o.fault_table));
  add("fault_overrun_o", int(o.fault_overrun));
  add("fault_ferr_o", int(o.fault_ferr));
  add("in_pos_o", int(o.in_pos));
  add("pulse_count_o", o.pulse_count);
  add("enc_pos_o", o.enc_pos);
  add("enc_illegal_o", o.enc_illegal);
  add("ref_pos_int_o", o.ref_pos_int);
  add("ref_frac_hi_o", o.ref_frac_hi);
  add("ref_vel_o", o.ref_vel);
  add("ref_done_o", int(o.ref_done));
  add("ctl_active_o", int(o.ctl_active));
  add("ctl_state_o", int(o.ctl_state));
  add("u_o", o.u);
  add("v_cmd_o", o.v_cmd);
  add("e_p_o", o.e_p);
  add("e_v_o", o.e_v);
  add("w_p1_o", o.w_p1);
  add("w_p2_o", o.w_p2);
  add("w_v1_o", o.w_v1);
  add("w_v2_o", o.w_v2);
  add("wn_p1_o", o.wn_p1);
  add("wn_p2_o", o.wn_p2);
  add("wn_v1_o", o.wn_v1);
  add("wn_v2_o", o.wn_v2);
  add("nco_phase_o", o.nco_phase);
  add("step_pending_o", int(o.step_pending));
  return v;
}

bool write_weights_csv(const std::string& path, const std::vector<WeightSample>& w) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) return false;
  std::fputs("t_s,w_p1,w_p2,w_v1,w_v2,wn_p1,wn_p2,wn_v1,wn_v2,e_p\n", f);
  for (const WeightSample& s : w) {
    std::fprintf(f, "%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.4f\n", s.t, s.w[0], s.w[1], s.w[2], s.w[3],
                 s.wn[0], s.wn[1], s.wn[2], s.wn[3], s.e_p);
  }
  return std::fclose(f) == 0;
}

namespace {

// Peak |acceleration| and |jerk| from a position sampled every `dt` s:
// two cascaded moving averages of `win` samples, then differences over
// `lag` samples. The same filter runs on the encoder and on the reference,
// so the two figures are comparable (quantisation noise shows in both).
class KinEstimator {
 public:
  KinEstimator(double dt, int win, int lag) : dt_(dt), win_(win), lag_(lag) {}
  void add(double p) {
    s1_ += p;
    b1_.push_back(p);
    if (int(b1_.size()) > win_) {
      s1_ -= b1_.front();
      b1_.pop_front();
    }
    if (int(b1_.size()) < win_) return;
    const double m1 = s1_ / win_;
    s2_ += m1;
    b2_.push_back(m1);
    if (int(b2_.size()) > win_) {
      s2_ -= b2_.front();
      b2_.pop_front();
    }
    if (int(b2_.size()) < win_) return;
    hist_.push_back(s2_ / win_);
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
  int win_, lag_;
  double s1_ = 0, s2_ = 0;
  std::deque<double> b1_, b2_, hist_;
};

}  // namespace

ClosedLoopResult run_closed_loop(const Plan& plan, const ClosedLoopOptions& opt) {
  ClosedLoopResult res;
  res.engine = opt.engine;
  res.distance = plan.distance;
  ServoConfig cfg;
  if (std::string err = to_servo_config(opt.ctl, opt.plant, opt.timing, cfg); !err.empty()) {
    res.failures.push_back(err);
    return res;
  }
  const bool use_rtl = opt.engine != ClEngine::ModelOnly;
  const bool use_model = opt.engine != ClEngine::RtlOnly;
  const bool lockstep = opt.engine == ClEngine::Lockstep;
  std::unique_ptr<RtlServo> rtl;
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
  ServoOutputs out;
  uint64_t clock = 0;
  bool stopped = false;
  uint64_t mism = 0, matched = 0;

  auto tick = [&](const ServoInputs& si) {
    if (opt.inject) opt.inject(clock, model);
    if (rtl) rtl->step(si);
    if (use_model) model.step(si);
    out = rtl ? rtl->outputs() : model.outputs();
    if (lockstep) {
      const ServoOutputs mo = model.outputs();
      if (out == mo) [[likely]] {
        ++matched;
      } else {
        ++mism;
        if (res.first_mismatch.empty()) {
          const auto a = render_servo(out), b = render_servo(mo);
          for (size_t i = 0; i < a.size(); ++i) {
            if (a[i].second != b[i].second) {
              res.first_mismatch = fmt::format("clock {} signal {}: rtl={} model={}", clock, a[i].first,
                                               a[i].second, b[i].second);
              break;
            }
          }
        }
        if (mism >= opt.max_mismatches) stopped = true;
      }
    }
    plant.clock(out.step, out.dir);
    in.enc_a = plant.enc_a();
    in.enc_b = plant.enc_b();
    ++clock;
  };

  const auto t0 = std::chrono::steady_clock::now();
  for (size_t i = 0; i < plan.segments.size() && !stopped; ++i) {
    ServoInputs w = in;
    w.seg_we = true;
    w.seg_waddr = uint8_t(i);
    w.seg_wdata = plan.segments[i];
    tick(w);
  }
  in.seg_count = uint8_t(plan.segments.size());
  in.pos_frac0 = plan.pos_frac0;
  {
    ServoInputs st = in;
    st.start = true;
    if (!stopped) tick(st);
  }
  const uint64_t start_clock = clock;
  const uint64_t limit = start_clock + plan.total_clocks + uint64_t(2.0 * ClkHz);

  // metrics
  const double L = double(plan.distance);
  double max_err = 0, sum_sq = 0;
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
  const double expected = double(plan.total_clocks) + 1.0;
  auto ref_pos = [&](const ServoOutputs& o) {
    return o.ref_done ? double(o.ref_pos_int) : double(o.ref_pos_int) + double(o.ref_frac_hi) * frac_scale - 0.5;
  };

  while (!stopped && clock < limit && !out.done && !out.fault_ferr) {
    tick(in);
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
    enc_dev = std::max(enc_dev, std::fabs(double(out.enc_pos) - L * cps));
  }
  res.total_clocks = clock;
  res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  res.clocks_per_s = res.wall_s > 0 ? double(clock) / res.wall_s : 0;

  res.max_error = max_err;
  res.rmse = n_err ? std::sqrt(sum_sq / double(n_err)) : 0;
  res.relative_error = L != 0 ? res.rmse / std::fabs(L) : 0;
  res.final_error = plan.distance - int64_t(std::llround(double(out.enc_pos) * inv_cps));
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
  res.mismatches = mism;
  res.matched_clocks = matched;

  auto fail = [&](std::string s) { res.failures.push_back(std::move(s)); };
  if (mism) fail(fmt::format("{} lockstep mismatches: {}", mism, res.first_mismatch));
  if (lockstep && matched == 0) fail("lockstep compared nothing");
  if (res.fault_ferr) fail("following-error fault");
  if (!stopped && !res.in_pos && opt.ctl.closed_loop) fail(fmt::format("not in position within {} clocks", limit));
  if (res.final_error != 0) fail(fmt::format("final error {} pulses", res.final_error));
  if (res.fault_overrun) fail("step queue overrun");
  return res;
}

}  // namespace sc
