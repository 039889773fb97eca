// The quadrature decoder model (QuadDecoder, the twin of sc_quad_decoder):
// every legal and illegal transition, the glitch filter, the index. The RTL
// against the model on random A/B/Z streams is QuadDecoderLockstep.* in
// test_closed_loop.cpp (this file also builds without Verilator, for the
// sanitizer stage).
#include <gtest/gtest.h>

#include <random>

#include "quad_decoder.h"

namespace sc {
namespace {

constexpr bool kA[4] = {false, true, true, false};
constexpr bool kB[4] = {false, false, true, true};

// Drive (a,b) for enough clocks to pass the synchronisers and the filter.
void hold(QuadDecoder& d, bool a, bool b, int clocks, uint8_t filt) {
  for (int i = 0; i < clocks; ++i) d.step(a, b, false, filt);
}

TEST(QuadDecoder, EveryTransitionFromEveryState) {
  for (unsigned from = 0; from < 4; ++from) {
    for (unsigned to = 0; to < 4; ++to) {
      for (uint8_t filt : {uint8_t(0), uint8_t(3)}) {
        QuadDecoder d;
        // walk legally to `from` first
        for (unsigned k = 1; k <= from; ++k) hold(d, kA[k], kB[k], 8, filt);
        ASSERT_EQ(d.state().count, int32_t(from));
        ASSERT_EQ(d.state().illegal, 0);
        hold(d, kA[to], kB[to], 8, filt);
        const unsigned diff = (to - from) & 3;
        const int32_t want = int32_t(from) + (diff == 1 ? 1 : diff == 3 ? -1 : 0);
        EXPECT_EQ(d.state().count, want) << "from " << from << " to " << to;
        EXPECT_EQ(d.state().illegal, diff == 2 ? 1 : 0) << "from " << from << " to " << to;
      }
    }
  }
}

TEST(QuadDecoder, LatencyIsSyncPlusFilter) {
  for (uint8_t filt = 0; filt < 6; ++filt) {
    QuadDecoder d;
    int clocks = 0;
    while (d.state().count == 0 && clocks < 100) {
      d.step(true, false, false, filt);
      ++clocks;
    }
    // two synchroniser flops, then accepted on the (filt+1)-th clock seen
    EXPECT_EQ(clocks, 2 + filt + 1) << "filt " << int(filt);
  }
}

TEST(QuadDecoder, GlitchFilterRejectsShortPulses) {
  for (uint8_t filt = 0; filt < 8; ++filt) {
    for (int len = 1; len <= 10; ++len) {
      QuadDecoder d;
      hold(d, false, false, 10, filt);
      hold(d, true, false, len, filt);  // glitch on A
      hold(d, false, false, 20, filt);
      const bool passes = len > filt;
      // A pulse that passes gives +1 then -1: count back to 0, never illegal.
      EXPECT_EQ(d.state().count, 0);
      EXPECT_EQ(d.state().illegal, 0);
      // Probe: a passing pulse must have been seen (a_f toggled); watch it.
      QuadDecoder e;
      hold(e, false, false, 10, filt);
      bool seen = false;
      for (int i = 0; i < len; ++i) {
        e.step(true, false, false, filt);
        seen = seen || e.state().count != 0;
      }
      for (int i = 0; i < 20; ++i) {
        e.step(false, false, false, filt);
        seen = seen || e.state().count != 0;
      }
      EXPECT_EQ(seen, passes) << "filt " << int(filt) << " len " << len;
    }
  }
}

TEST(QuadDecoder, LongRandomWalkCountsExactly) {
  std::mt19937_64 rng(7);
  QuadDecoder d;
  int64_t pos = 0;
  for (int i = 0; i < 20000; ++i) {
    pos += (rng() & 1) ? 1 : -1;
    const unsigned ph = unsigned(pos) & 3;
    hold(d, kA[ph], kB[ph], 1 + int(rng() % 4), 0);
  }
  hold(d, kA[unsigned(pos) & 3], kB[unsigned(pos) & 3], 8, 0);
  EXPECT_EQ(d.state().count, pos);
  EXPECT_EQ(d.state().illegal, 0);
}

// The index goes through the same synchroniser and filter: on a random walk
// with Z high in one quadrature state per "revolution", the filtered Z is
// high in exactly the clocks the count shows that state, for every filter
// length, and a Z pulse no longer than the filter never shows.
TEST(QuadDecoder, IndexShowsInTheClocksTheCountShowsItsState) {
  constexpr int64_t kPeriod = 20, kAt = 7;
  for (uint8_t filt : {uint8_t(0), uint8_t(2), uint8_t(5)}) {
    std::mt19937_64 rng(11 + filt);
    QuadDecoder d;
    int64_t pos = 0, highs = 0;
    auto z_of = [&](int64_t c) { return ((c - kAt) % kPeriod + kPeriod) % kPeriod == 0; };
    for (int i = 0; i < 20000; ++i) {
      pos += (rng() % 3 == 0) ? -1 : 1;
      const unsigned ph = unsigned(pos) & 3;
      for (int k = 0, n = int(filt) + 1 + int(rng() % 4); k < n; ++k) {
        d.step(kA[ph], kB[ph], z_of(pos), filt);
        ASSERT_EQ(d.index(), z_of(d.state().count)) << "filt " << int(filt) << ", count " << d.state().count;
        highs += d.index();
      }
    }
    EXPECT_GT(highs, 100) << "the walk crossed the index";
    // a Z glitch of filt clocks on a still encoder is not taken
    for (int k = 0; k < 10; ++k) d.step(kA[unsigned(pos) & 3], kB[unsigned(pos) & 3], false, filt);
    if (!z_of(pos)) {
      for (int k = 0; k < filt; ++k) d.step(kA[unsigned(pos) & 3], kB[unsigned(pos) & 3], true, filt);
      for (int k = 0; k < 10; ++k) {
        d.step(kA[unsigned(pos) & 3], kB[unsigned(pos) & 3], false, filt);
        EXPECT_FALSE(d.index()) << "filt " << int(filt);
      }
    }
  }
}

TEST(QuadDecoder, IllegalCounterSaturates) {
  QuadDecoder d;
  d.mutable_state().illegal = uint16_t(QuadDecoder::kIllMax - 1);
  for (int i = 0; i < 4; ++i) {
    hold(d, true, true, 6, 0);
    hold(d, false, false, 6, 0);
  }
  EXPECT_EQ(d.state().illegal, QuadDecoder::kIllMax);
  EXPECT_EQ(d.state().count, 0);
}

}  // namespace
}  // namespace sc
