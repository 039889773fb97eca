// Bit-exact model of rtl/sc_switch_filter.sv: synchroniser, polarity and a
// debounce filter per switch input.
#pragma once

#include <array>
#include <cstdint>

#include "sc_params.h"
#include "sync.h"

namespace sc {

class SwitchFilter {
 public:
  static constexpr int kWidth = SwW;
  struct State {
    std::array<uint32_t, kWidth> cnt{};  // DebounceW bits
    uint32_t level = 0;                  // bit i: filtered level of input i
    uint32_t edge = 0;                   // bit i: level changed a clock ago
    bool operator==(const State&) const = default;
  };

  SwitchFilter() { reset(); }
  void reset() {
    sync_.reset();
    q_ = State{};
  }
  // One clock: `pins` at this edge, `invert` and `debounce` the register
  // file's outputs during it.
  void step(uint32_t pins, uint32_t invert, uint32_t debounce) {
    const uint32_t raw = (sync_.q() ^ invert) & kMask;
    State d = q_;
    d.edge = 0;
    for (int i = 0; i < kWidth; ++i) {
      const uint32_t bit = 1u << i;
      d.cnt[i] = 0;
      if ((raw & bit) != (q_.level & bit)) {
        if (q_.cnt[i] >= debounce) {
          d.level = (d.level & ~bit) | (raw & bit);
        } else {
          d.cnt[i] = (q_.cnt[i] + 1) & kCntMask;
        }
      }
    }
    d.edge = d.level ^ q_.level;
    sync_.step(pins);
    q_ = d;
  }
  uint32_t level() const { return q_.level; }
  uint32_t edge() const { return q_.edge; }
  const State& state() const { return q_; }

 private:
  static constexpr uint32_t kMask = (1u << kWidth) - 1;
  static constexpr uint32_t kCntMask = (1u << DebounceW) - 1;
  Sync sync_{kWidth, false};
  State q_{};
};

}  // namespace sc
