// Bit-exact model of rtl/sc_quad_decoder.sv: the A/B synchroniser (Sync,
// bit 0 = A, bit 1 = B), glitch filter, 4x Gray decoding, saturating
// illegal counter.
#pragma once

#include <cstdint>

#include "fixed_point.h"
#include "sync.h"

namespace sc {

class QuadDecoder {
 public:
  struct State {
    bool a_f = false, b_f = false;  // filtered levels
    uint8_t a_cnt = 0, b_cnt = 0;
    int32_t count = 0;
    uint16_t illegal = 0;
    bool operator==(const State&) const = default;
  };
  static constexpr uint32_t kIllMax = (1u << EncIllW) - 1;
  static constexpr uint32_t kFiltMask = (1u << EncFiltW) - 1;

  QuadDecoder() { reset(); }
  void reset() {
    q_ = State{};
    sync_.reset();
  }
  // Quarter-cycle phase of a Gray pair: 00->0, 10->1, 11->2, 01->3.
  static constexpr unsigned gray_phase(bool a, bool b) { return (unsigned(b) << 1) | unsigned(a ^ b); }

  void step(bool enc_a, bool enc_b, uint8_t filt) {
    filt &= kFiltMask;
    const bool a_s = sync_.q() & 1u, b_s = (sync_.q() >> 1) & 1u;
    bool a_f = q_.a_f, b_f = q_.b_f;
    uint8_t a_cnt = 0, b_cnt = 0;
    if (a_s != q_.a_f) {
      if (q_.a_cnt >= filt) a_f = a_s; else a_cnt = uint8_t((q_.a_cnt + 1) & kFiltMask);
    }
    if (b_s != q_.b_f) {
      if (q_.b_cnt >= filt) b_f = b_s; else b_cnt = uint8_t((q_.b_cnt + 1) & kFiltMask);
    }
    const unsigned diff = (gray_phase(a_f, b_f) - gray_phase(q_.a_f, q_.b_f)) & 3u;
    if (diff == 1) {
      q_.count = add_wrap32(q_.count, 1);
    } else if (diff == 3) {
      q_.count = add_wrap32(q_.count, -1);
    } else if (diff == 2 && q_.illegal != kIllMax) {
      ++q_.illegal;
    }
    q_.a_f = a_f;
    q_.b_f = b_f;
    q_.a_cnt = a_cnt;
    q_.b_cnt = b_cnt;
    sync_.step((uint32_t(enc_b) << 1) | uint32_t(enc_a));
  }
  // True when step() with these inputs changes nothing but can be skipped.
  bool quiet(bool enc_a, bool enc_b) const {
    const uint32_t ab = (uint32_t(enc_b) << 1) | uint32_t(enc_a);
    return sync_.state().meta == ab && sync_.state().sync == ab && q_.a_f == enc_a && q_.b_f == enc_b &&
           q_.a_cnt == 0 && q_.b_cnt == 0;
  }

  const State& state() const { return q_; }
  State& mutable_state() { return q_; }
  const Sync& sync() const { return sync_; }  // u_sync_ab: bit 0 = A, bit 1 = B

 private:
  Sync sync_{2, false};
  State q_;
};

static_assert(EncCntW == 32, "QuadDecoder holds the count in int32_t");
static_assert(EncIllW <= 16 && EncFiltW <= 8, "QuadDecoder field widths");

}  // namespace sc
