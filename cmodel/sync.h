// Bit-exact model of rtl/sc_sync.sv: two flops per bit (meta, sync), both
// held at the reset value in reset; q() is the input of two clocks ago.
#pragma once

#include <cstdint>

namespace sc {

class Sync {
 public:
  struct State {
    uint32_t meta = 0, sync = 0;
    bool operator==(const State&) const = default;
  };
  // width <= 32 bits; reset_val is every bit's value in reset (ResetVal).
  explicit Sync(int width = 1, bool reset_val = false)
      : mask_(width >= 32 ? ~0u : ((1u << width) - 1)), reset_(reset_val ? mask_ : 0u) {
    reset();
  }
  void reset() { q_ = State{reset_, reset_}; }
  void step(uint32_t d) {
    q_.sync = q_.meta;
    q_.meta = d & mask_;
  }
  uint32_t q() const { return q_.sync; }
  const State& state() const { return q_; }

 private:
  uint32_t mask_;
  uint32_t reset_;
  State q_{};
};

}  // namespace sc
