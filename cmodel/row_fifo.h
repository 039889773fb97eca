// Bit-exact model of rtl/sc_row_fifo.sv: a FIFO in LUT RAM with an
// asynchronous read of the head. step() is one clock.
#pragma once

#include <array>
#include <cstddef>

namespace sc {

template <typename Word, size_t Depth>
class RowFifo {
  static_assert((Depth & (Depth - 1)) == 0, "sc_row_fifo: Depth is a power of two");

 public:
  void reset() {
    wr_ = rd_ = 0;
    level_ = 0;
  }
  bool empty() const { return level_ == 0; }
  bool full() const { return level_ == Depth; }
  size_t level() const { return level_; }
  const Word& head() const { return mem_[rd_]; }  // valid while !empty()
  // The entry `k` places behind the head (peek_o).
  const Word& peek(size_t k) const { return mem_[(rd_ + k) & (Depth - 1)]; }
  // The head's address (the side array of sc_row_fifo is indexed like mem_).
  size_t rd() const { return rd_; }
  // One clock: flush wins over push and pop; a push while full and a pop
  // while empty are ignored.
  // replace (instead of push): keep the first `keep` entries (from the head
  // before this clock's pop), drop the rest, write wdata behind them; the
  // caller checks pop <= keep <= level and that the result fits.
  void step(bool flush, bool push, const Word& wdata, bool pop, bool replace = false, size_t keep = 0) {
    if (flush) {
      rd_ = wr_;
      level_ = 0;
      return;
    }
    const bool do_pop = pop && !empty();
    if (replace) {
      mem_[(rd_ + keep) & (Depth - 1)] = wdata;
      wr_ = (rd_ + keep + 1) & (Depth - 1);
      level_ = keep + 1 - (do_pop ? 1 : 0);
      if (do_pop) rd_ = (rd_ + 1) & (Depth - 1);
      return;
    }
    const bool do_push = push && !full();
    if (do_push) {
      mem_[wr_] = wdata;
      wr_ = (wr_ + 1) & (Depth - 1);
    }
    if (do_pop) rd_ = (rd_ + 1) & (Depth - 1);
    if (do_push && !do_pop) ++level_;
    if (do_pop && !do_push) --level_;
  }

 private:
  std::array<Word, Depth> mem_{};
  size_t wr_ = 0, rd_ = 0, level_ = 0;
};

}  // namespace sc
