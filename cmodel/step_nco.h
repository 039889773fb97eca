// Bit-exact model of rtl/sc_step_nco.sv: phase accumulator with modulus
// M = div << (CtlFrac + shift); a wrap is one step request (next clock).
#pragma once

#include <cstdint>

#include "fixed_point.h"

namespace sc {

class StepNco {
 public:
  struct State {
    int64_t acc = 0;  // NcoW bits, signed
    bool req = false;
    bool fwd = true;
    bool operator==(const State&) const = default;
  };
  StepNco() { reset(); }
  void reset() { q_ = State{}; }
  static int64_t modulus(uint16_t div, uint8_t shift) {
    return wrap_signed64(int64_t(uint64_t(div) << (CtlFrac + (shift & ((1u << EncShiftW) - 1)))), NcoW);
  }
  void step(uint16_t div, uint8_t shift, bool load, bool run, int32_t u) {
    const int64_t m = modulus(div, shift);
    q_.req = false;
    if (load) {
      q_.acc = m >> 1;
    } else if (run) {
      const int64_t sum = wrap_signed64(q_.acc + int64_t(u), NcoW);
      if (sum >= m) {
        q_.acc = wrap_signed64(sum - m, NcoW);
        q_.req = true;
        q_.fwd = true;
      } else if (sum < 0) {
        q_.acc = wrap_signed64(sum + m, NcoW);
        q_.req = true;
        q_.fwd = false;
      } else {
        q_.acc = sum;
      }
    }
  }
  const State& state() const { return q_; }

 private:
  State q_;
};

static_assert(NcoW <= 62 && CtlW == 32, "StepNco holds the phase in int64_t");

}  // namespace sc
