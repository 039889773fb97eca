#include "plant.h"

#include <fmt/format.h>

#include <cmath>

namespace sc {

double PlantConfig::load_accel() const {
  // T / J in rad/s^2, then to pulses/s^2.
  return inertia > 0 ? load_torque / inertia * pulses_per_rev / (2.0 * M_PI) : 0.0;
}

std::string PlantConfig::describe() const {
  if (kind == Kind::FirstOrder) {
    return fmt::format("first-order 1/(tau s + 1), tau = {} s; encoder {} counts/pulse", tau, counts_per_step);
  }
  return fmt::format(
      "stepper: f_n {} Hz, zeta {}, load {} N m ({:.0f} pulses/s^2), {} pulses/rev, {}{}; encoder {} "
      "counts/pulse, noise {} counts, glitches {}/s",
      f_n, zeta, load_torque, load_accel(), pulses_per_rev, missed_steps ? "missed steps on" : "linear",
      "", counts_per_step, noise_counts, glitch_rate);
}

Plant::Plant(const PlantConfig& cfg, double clk_hz) : cfg_(cfg), rng_(cfg.seed) {
  if (cfg_.substep < 1) cfg_.substep = 1;
  dt_clk_ = 1.0 / clk_hz;
  dt_sub_ = dt_clk_ * cfg_.substep;
  wn_ = 2.0 * M_PI * cfg_.f_n;
  a_load_ = cfg_.load_accel();
  pe_ = cfg_.electrical_period();
  if (cfg_.glitch_rate > 0) {
    std::exponential_distribution<double> ex(cfg_.glitch_rate / clk_hz);
    next_glitch_ = uint64_t(ex(rng_)) + 1;
  }
}

void Plant::dynamics() {
  sub_ = 0;
  const double err = theta_ - double(c_);
  if (cfg_.kind == PlantConfig::Kind::FirstOrder) {
    omega_ = -err / cfg_.tau;
  } else {
    double g = err;
    if (cfg_.missed_steps) {
      g = pe_ / (2.0 * M_PI) * std::sin(2.0 * M_PI * err / pe_);
      // Count a slip whenever the rotor falls a further electrical period behind.
      const double k = std::floor(std::fabs(err) / pe_ + 0.5);
      if (k > double(slips_)) slips_ = uint64_t(k);
    }
    const double acc = -wn_ * wn_ * g - 2.0 * cfg_.zeta * wn_ * omega_ - a_load_;
    omega_ += acc * dt_sub_;  // semi-implicit Euler: theta uses the new omega
  }
  if (cfg_.noise_counts > 0) noise_ = cfg_.noise_counts * gauss_(rng_);
}

void Plant::start_glitch() {
  std::exponential_distribution<double> ex(cfg_.glitch_rate * dt_clk_);
  next_glitch_ = clk_ + uint64_t(ex(rng_)) + 1;
  glitch_left_ = cfg_.glitch_clocks;
  glitch_a_ = (rng_() & 1) != 0;
  ++glitches_;
}

}  // namespace sc
