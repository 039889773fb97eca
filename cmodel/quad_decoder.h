// Bit-exact model of rtl/sc_quad_decoder.sv: the A/B/Z synchroniser (Sync,
// bit 0 = A, bit 1 = B, bit 2 = Z), glitch filter (the index Z filtered like
// A and B, so its edges show with the count they came with), 4x Gray
// decoding, saturating illegal counter.
#pragma once

#include <array>
#include <cstdint>

#include "fixed_point.h"
#include "sync.h"

namespace sc {

class QuadDecoder {
 public:
  // Channels, as the synchroniser's bits and the filter's arrays.
  static constexpr int kChA = 0, kChB = 1, kChZ = 2, kChannels = 3;
  struct State {
    std::array<bool, kChannels> f{};        // filtered levels
    std::array<uint8_t, kChannels> cnt{};   // filter counters
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
  static constexpr uint32_t pins(bool a, bool b, bool z) {
    return (uint32_t(z) << kChZ) | (uint32_t(b) << kChB) | (uint32_t(a) << kChA);
  }

  void step(bool enc_a, bool enc_b, bool enc_z, uint8_t filt) {
    filt &= kFiltMask;
    std::array<bool, kChannels> f = q_.f;
    std::array<uint8_t, kChannels> cnt{};
    for (int c = 0; c < kChannels; ++c) {
      const bool s = (sync_.q() >> c) & 1u;
      if (s == q_.f[c]) continue;
      if (q_.cnt[c] >= filt) f[c] = s; else cnt[c] = uint8_t((q_.cnt[c] + 1) & kFiltMask);
    }
    const unsigned diff = (gray_phase(f[kChA], f[kChB]) - gray_phase(q_.f[kChA], q_.f[kChB])) & 3u;
    if (diff == 1) {
      q_.count = add_wrap32(q_.count, 1);
    } else if (diff == 3) {
      q_.count = add_wrap32(q_.count, -1);
    } else if (diff == 2 && q_.illegal != kIllMax) {
      ++q_.illegal;
    }
    q_.f = f;
    q_.cnt = cnt;
    sync_.step(pins(enc_a, enc_b, enc_z));
  }
  // True when step() with these inputs changes nothing but can be skipped.
  bool quiet(bool enc_a, bool enc_b, bool enc_z) const {
    const uint32_t p = pins(enc_a, enc_b, enc_z);
    return sync_.state().meta == p && sync_.state().sync == p && q_.f[kChA] == enc_a && q_.f[kChB] == enc_b &&
           q_.f[kChZ] == enc_z && q_.cnt == std::array<uint8_t, kChannels>{};
  }
  bool index() const { return q_.f[kChZ]; }  // z_o

  const State& state() const { return q_; }
  State& mutable_state() { return q_; }
  const Sync& sync() const { return sync_; }  // u_sync_abz: bit kChA, kChB, kChZ

 private:
  Sync sync_{kChannels, false};
  State q_;
};

static_assert(EncCntW == 32, "QuadDecoder holds the count in int32_t");
static_assert(EncIllW <= 16 && EncFiltW <= 8, "QuadDecoder field widths");

}  // namespace sc
