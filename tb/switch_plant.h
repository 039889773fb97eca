// A mechanical switch on the axis, for the register-level benches: active on
// the far side of a position of the pins' own count (the pin monitor, not
// the core's counters), with contact bounce of a given length on every change
// of state and, optionally, electrical noise (short random glitches).
#pragma once

#include <cstdint>
#include <random>

namespace sc {

class SwitchPlant {
 public:
  // Active at dir > 0: position >= at; dir < 0: position <= at. On every
  // change of state the contact bounces for `bounce` clocks (random pin
  // levels) before it settles.
  SwitchPlant(int64_t at, int dir, int bounce, bool invert, uint64_t seed)
      : at_(at), dir_(dir), bounce_(bounce), invert_(invert), g_(seed) {}
  // Noise: each clock a glitch (the pin inverted) starts with probability
  // `rate` and lasts `clocks` clocks.
  void set_noise(double rate, int clocks) {
    noise_rate_ = rate;
    noise_clocks_ = clocks;
  }
  // The pin level for the axis at `pos` this clock.
  bool pin(int64_t pos) {
    const bool active = dir_ > 0 ? pos >= at_ : pos <= at_;
    if (active != active_) {
      active_ = active;
      left_ = bounce_;
      if (active) ++activations_;
    }
    bool level = active_;
    if (left_ > 0) {
      --left_;
      level = (g_() & 1) != 0;
    }
    if (noise_left_ == 0 && noise_rate_ > 0 && std::uniform_real_distribution<double>(0, 1)(g_) < noise_rate_) {
      noise_left_ = noise_clocks_;
      ++glitches_;
    }
    if (noise_left_ > 0) {
      --noise_left_;
      level = !level;
    }
    return level != invert_;
  }
  bool active() const { return active_; }
  int activations() const { return activations_; }
  uint64_t glitches() const { return glitches_; }
  // The first position off the switch, coming from its active side.
  int64_t release_point() const { return at_ - dir_; }

 private:
  int64_t at_;
  int dir_;
  int bounce_;
  bool invert_;
  std::mt19937_64 g_;
  bool active_ = false;
  int left_ = 0;
  int activations_ = 0;
  double noise_rate_ = 0;
  int noise_clocks_ = 0;
  int noise_left_ = 0;
  uint64_t glitches_ = 0;
};

}  // namespace sc
