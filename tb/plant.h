// Plant model for the closed-loop testbench (double precision): a stepper
// motor driven by the STEP/DIR pins, or the paper's first-order plant, and
// a quadrature encoder producing A/B at clock resolution.
//
// Units: positions in pulses (driver microsteps), time in seconds.
// Stepper (second-order rotor around the commanded step position c):
//   theta'' = -wn^2 g(theta - c) - 2 zeta wn theta' - a_load
//   g(x) = x                                      (linear, default)
//   g(x) = Pe/(2 pi) sin(2 pi x / Pe)             (missed_steps: the real
//          torque-angle curve; past a quarter electrical period Pe the
//          torque falls and the rotor slips whole electrical periods)
// First order (paper 000's 1/(s+1) with time constant tau):
//   theta' = (c - theta) / tau
// Encoder: count = round(theta * counts_per_step + noise), A/B in Gray code
// (00, 10, 11, 01 forward), at most one count change per clock; the index Z
// is high for the one quadrature state of each revolution where
// count = index_at (mod index_period), changing in the clock A/B do.
//
// Defaults resemble a NEMA-23 hybrid stepper (1.26 N m holding torque,
// rotor + load inertia 6e-5 kg m^2, 50 pole pairs: wn = sqrt(63/6e-5) =
// 1025 rad/s = 163 Hz, lightly damped zeta = 0.1) on a driver at 4000
// pulses/rev (20 microsteps) with a 1000-line (4000 counts/rev) encoder:
// 1 count per pulse. Load: 0.02 N m constant (a_load = T/J in pulses/s^2).
#pragma once

#include <cstdint>
#include <random>
#include <string>

namespace sc {

struct PlantConfig {
  enum class Kind { Stepper, FirstOrder };
  Kind kind = Kind::Stepper;
  double pulses_per_rev = 4000;   // driver setting
  double counts_per_step = 1.0;   // encoder counts per pulse (4000 counts/rev / 4000 pulses/rev)
  double f_n = 163.0;             // rotor natural frequency, Hz
  double zeta = 0.1;              // damping ratio
  double load_torque = 0.02;      // N m, constant, opposing forward motion
  double inertia = 6e-5;          // kg m^2 (rotor + load), converts the load torque
  bool missed_steps = false;      // sinusoidal torque-angle curve (can slip)
  double full_steps_per_rev = 200;
  double tau = 1e-3;              // first-order plant time constant, s
  double noise_counts = 0;        // Gaussian encoder noise, sigma in counts
  double glitch_rate = 0;         // A/B glitches per second (Poisson)
  int glitch_clocks = 2;          // length of one glitch, clocks
  int64_t index_period = 0;       // encoder counts between index pulses (counts/rev); 0: no index
  int64_t index_at = 0;           // a count where Z is high
  uint64_t seed = 1;
  int substep = 20;               // clocks per dynamics update (1 us)

  double load_accel() const;      // pulses/s^2
  double electrical_period() const { return 4.0 * pulses_per_rev / full_steps_per_rev; }
  std::string describe() const;
};

class Plant {
 public:
  explicit Plant(const PlantConfig& cfg, double clk_hz);
  // One clock: sample the STEP/DIR pins (after the DUT's clock edge) and
  // advance; enc_a()/enc_b() are the encoder outputs for the next clock.
  void clock(bool step, bool dir) {
    if (step && !last_step_) c_ += dir ? 1 : -1;
    last_step_ = step;
    if (++sub_ >= cfg_.substep) [[unlikely]] dynamics();
    theta_ += omega_ * dt_clk_;
    encoder();
  }
  bool enc_a() const { return glitch_left_ > 0 ? (a_ ^ glitch_a_) : a_; }
  bool enc_b() const { return glitch_left_ > 0 ? (b_ ^ !glitch_a_) : b_; }
  bool enc_z() const {
    if (cfg_.index_period <= 0) return false;
    const int64_t r = (count_ - cfg_.index_at) % cfg_.index_period;
    return r == 0;
  }

  double theta() const { return theta_; }          // rotor position, pulses
  double omega() const { return omega_; }          // pulses/s
  int64_t commanded() const { return c_; }         // net STEP pulses seen
  int64_t count() const { return count_; }         // encoder count
  uint64_t glitches() const { return glitches_; }
  uint64_t slips() const { return slips_; }        // electrical periods slipped

 private:
  void dynamics();
  void encoder() {
    if (glitch_left_ > 0) --glitch_left_;
    if (cfg_.glitch_rate > 0 && ++clk_ >= next_glitch_) [[unlikely]] start_glitch();
    const double x = theta_ * cfg_.counts_per_step + noise_ + 0.5;
    if (x >= double(count_ + 1)) {
      ++count_;
      set_ab();
    } else if (x < double(count_)) {
      --count_;
      set_ab();
    }
  }
  void set_ab() {
    static constexpr bool kA[4] = {false, true, true, false};
    static constexpr bool kB[4] = {false, false, true, true};
    a_ = kA[count_ & 3];
    b_ = kB[count_ & 3];
  }
  void start_glitch();

  PlantConfig cfg_;
  double dt_clk_, dt_sub_;
  double wn_, a_load_, pe_;
  double theta_ = 0, omega_ = 0, noise_ = 0;
  int64_t c_ = 0;
  bool last_step_ = false;
  int sub_ = 0;
  int64_t count_ = 0;
  bool a_ = false, b_ = false;
  int glitch_left_ = 0;
  bool glitch_a_ = true;
  uint64_t clk_ = 0, next_glitch_ = UINT64_MAX, glitches_ = 0;
  uint64_t slips_ = 0;
  std::mt19937_64 rng_;
  std::normal_distribution<double> gauss_{0.0, 1.0};
};

}  // namespace sc
