#include "rtl_row_reach.h"

#include "Vsc_row_reach.h"
#include "verilated_top.h"

namespace sc {

RtlRowReach::RtlRowReach() : top_(std::make_unique<VerilatedTop<Vsc_row_reach>>("sc_row_reach")) {
  Vsc_row_reach& m = top_->top();
  m.start_i = 0;
  m.abort_i = 0;
  m.clocks_i = 0;
  m.jerk_i = 0;
  m.acc0_i = 0;
  put_bits(m.vel0_i, 0, VelW, 0);
  m.eval();
}

RtlRowReach::~RtlRowReach() = default;

void RtlRowReach::reset(int cycles) { top_->reset(cycles); }

ReachOutputs RtlRowReach::outputs() const {
  const Vsc_row_reach& m = top_->top();
  return {bool(m.busy_o), bool(m.done_o), wrap_signed64(int64_t(m.reach_fwd_o), ReachW),
          wrap_signed64(int64_t(m.reach_rev_o), ReachW)};
}

void RtlRowReach::step(const RowReach::Inputs& in) {
  Vsc_row_reach& m = top_->top();
  m.start_i = in.start;
  m.abort_i = in.abort;
  m.clocks_i = in.clocks;
  m.jerk_i = uint64_t(in.jerk) & ((uint64_t(1) << JerkW) - 1);
  m.acc0_i = uint64_t(in.acc0);
  put_bits(m.vel0_i, 0, VelW, u128(in.vel0));
  top_->tick();
}

}  // namespace sc
