#include "pin_monitor.h"

#include <fmt/format.h>

#include "planner.h"

namespace sc {

const char* trend_name(DutyTrend t) {
  switch (t) {
    case DutyTrend::Rising: return "rising";
    case DutyTrend::Steady: return "steady";
    case DutyTrend::Falling: return "falling";
    case DutyTrend::Zero: return "zero";
    case DutyTrend::None: return "none";
  }
  return "?";
}

DutyTrend trend_of_phase(uint8_t phase) {
  switch (Phase(phase)) {
    case Phase::PhAccJerkUp:
    case Phase::PhAccConst:
    case Phase::PhAccJerkDown: return DutyTrend::Rising;
    case Phase::PhCruise: return DutyTrend::Steady;
    case Phase::PhDecJerkUp:
    case Phase::PhDecConst:
    case Phase::PhDecJerkDown: return DutyTrend::Falling;
    case Phase::PhDone: return DutyTrend::Zero;
    default: return DutyTrend::None;
  }
}

std::vector<DutyTrend> expected_trends(const std::vector<Segment>& rows) {
  std::vector<DutyTrend> seq;
  for (const Segment& s : rows) {
    const DutyTrend t = trend_of_phase(uint8_t(s.phase));
    if (seq.empty() || seq.back() != t) seq.push_back(t);
  }
  seq.push_back(DutyTrend::Zero);
  return seq;
}

void PinMonitor::error(std::string s) {
  if (errors_.size() < max_errors_) errors_.push_back(std::move(s));
}

void PinMonitor::check_accounting(uint64_t clock, bool rise, int32_t ref, int32_t queued, const char* when) {
  switch (accounting_) {
    case StepAccounting::None: break;
    case StepAccounting::ReferencePosition: {
      // last_ref_ is the position one clock earlier: its requests are queued by now.
      const int64_t want = int64_t(last_ref_) - ref_origin_;
      if (net_ + queued != want) {
        error(fmt::format("clock {}: step accounting{}: {} net STEP edges + {} queued != {} pulses of reference "
                          "position (executor at {}, started at {})",
                          clock, when, net_, queued, want, last_ref_, ref_origin_));
      }
      break;
    }
    case StepAccounting::PulseCounter:
      // The counter clears when a move starts (no STEP edge that clock).
      if (ref == 0 && !rise) net_at_clear_ = net_;
      if (net_ - net_at_clear_ != ref) {
        error(fmt::format("clock {}: step accounting{}: {} net STEP edges != pulse counter {}", clock, when,
                          net_ - net_at_clear_, ref));
      }
      break;
  }
}

void PinMonitor::on_change(uint64_t clock, bool step, bool dir, bool done, uint8_t phase, int32_t ref,
                           int32_t queued) {
  if (!initialised_) {
    initialised_ = true;
    last_dir_ = dir;
    last_ref_ = ref;
    ref_origin_ = ref;
    net_at_clear_ = 0;
  }
  if (dir != last_dir_) {
    if (step) error(fmt::format("clock {}: DIR changed while STEP high", clock));
    if (any_rise_ && clock - last_rise_ < t_.hold) {
      error(fmt::format("clock {}: DIR hold {} < {} clocks", clock, clock - last_rise_, t_.hold));
    }
    last_dir_change_ = clock;
    any_dir_change_ = true;
  }
  const bool rise = step && !last_step_;
  if (rise) {
    if (profile_ && done_seen_) {
      error(fmt::format("clock {}: STEP pulse after done (done at clock {})", clock, done_clock_));
    }
    if (any_fall_ && clock - last_fall_ < t_.low) {
      error(fmt::format("clock {}: STEP low {} < {} clocks", clock, clock - last_fall_, t_.low));
    }
    if (any_dir_change_ && clock - last_dir_change_ < t_.setup) {
      error(fmt::format("clock {}: DIR setup {} < {} clocks", clock, clock - last_dir_change_, t_.setup));
    }
    const uint8_t ph = phase;
    if (profile_ && (trend_of_phase(ph) == DutyTrend::Zero || trend_of_phase(ph) == DutyTrend::None)) {
      error(fmt::format("clock {}: STEP pulse while phase {}", clock, int(ph)));
    }
    if (profile_ && any_rise_) {
      const uint64_t iv = clock - last_rise_;
      if (runs_.empty() || runs_.back().phase != ph) {
        PhaseRun r;
        r.phase = ph;
        runs_.push_back(r);
      }
      PhaseRun& r = runs_.back();
      // The first interval of a run straddles the phase change (the pulse
      // that opens it was requested a few clocks earlier, in the previous
      // phase), so it is neither judged nor used as the reference.
      if (r.pulses > 0) {
        const DutyTrend tr = trend_of_phase(ph);
        if (r.pulses > 1) {
          // One clock of jitter: edges sit on the clock grid.
          if (tr == DutyTrend::Rising && iv > r.last_interval + 1) ++r.trend_violations;
          if (tr == DutyTrend::Falling && iv + 1 < r.last_interval) ++r.trend_violations;
        }
        r.min_interval = std::min(r.min_interval, iv);
        r.max_interval = std::max(r.max_interval, iv);
      } else {
        r.first_interval = iv;
      }
      r.last_interval = iv;
      r.duty_sum += double(t_.high) / double(iv);
      ++r.pulses;
    }
    last_rise_ = clock;
    any_rise_ = true;
    ++rises_;
    net_ += dir ? 1 : -1;
  }
  if (!step && last_step_) {  // falling edge
    const uint64_t high = clock - last_rise_;
    if (high != t_.high) error(fmt::format("clock {}: STEP high {} != {} clocks", clock, high, t_.high));
    last_fall_ = clock;
    any_fall_ = true;
  }
  if (done && !last_done_) {
    done_seen_ = true;
    done_clock_ = clock;
    if (profile_ && step) error(fmt::format("clock {}: done while STEP high", clock));
  }
  if (!done) done_seen_ = false;
  check_accounting(clock, rise, ref, queued, "");
  last_step_ = step;
  last_dir_ = dir;
  last_done_ = done;
  last_phase_ = phase;
  last_ref_ = ref;
  last_queued_ = queued;
}

void PinMonitor::finish(uint64_t clock) {
  for (const PhaseRun& r : runs_) {
    const DutyTrend tr = trend_of_phase(r.phase);
    if (r.trend_violations > 0) {
      error(fmt::format("phase {} ({}): {} pulse intervals against the {} duty trend", int(r.phase),
                        phase_name(Phase(r.phase)), r.trend_violations, trend_name(tr)));
    }
    if (tr == DutyTrend::Steady && r.pulses > 2 && r.max_interval > r.min_interval + 1) {
      error(fmt::format("cruise: pulse interval varies {}..{} clocks (steady duty expected)", r.min_interval,
                        r.max_interval));
    }
  }
  if (profile_ && !done_seen_) error(fmt::format("clock {}: run ended without done", clock));
  // At rest the queue is empty and the pins have caught up with the reference.
  if (initialised_ && accounting_ != StepAccounting::None) {
    check_accounting(clock, false, last_ref_, last_queued_, " at the end");
    if (accounting_ == StepAccounting::ReferencePosition && last_queued_ != 0) {
      error(fmt::format("clock {}: step accounting at the end: {} steps still queued", clock, last_queued_));
    }
  }
}

std::vector<DutyTrend> PinMonitor::trend_sequence() const {
  std::vector<DutyTrend> seq;
  for (const PhaseRun& r : runs_) {
    const DutyTrend t = trend_of_phase(r.phase);
    if (seq.empty() || seq.back() != t) seq.push_back(t);
  }
  if (done_seen_) seq.push_back(DutyTrend::Zero);
  return seq;
}

}  // namespace sc
