#include "rtl_stop_gen.h"

#include "Vsc_stop_gen.h"
#include "verilated_top.h"

namespace sc {

RtlStopGen::RtlStopGen() : top_(std::make_unique<VerilatedTop<Vsc_stop_gen>>("sc_stop_gen")) {
  Vsc_stop_gen& m = top_->top();
  m.start_i = 0;
  put_bits(m.vel_i, 0, VelW, 0);
  m.acc_i = 0;
  m.stop_jerk_i = 1;
  m.stop_acc_i = 1;
  m.eval();
}

RtlStopGen::~RtlStopGen() = default;

void RtlStopGen::reset(int cycles) { top_->reset(cycles); }

StopOutputs RtlStopGen::outputs() const {
  const Vsc_stop_gen& m = top_->top();
  return {bool(m.active_o), bool(m.done_o), bool(m.overshoot_o), wrap_signed64(int64_t(m.jerk_o), JerkW)};
}

void RtlStopGen::step(const StopGen::Inputs& in) {
  Vsc_stop_gen& m = top_->top();
  m.start_i = in.start;
  if (in.start) {
    put_bits(m.vel_i, 0, VelW, u128(in.vel));
    m.acc_i = uint64_t(in.acc);
    m.stop_jerk_i = in.stop_jerk & ((uint64_t(1) << JerkW) - 1);
    m.stop_acc_i = in.stop_acc;
  }
  top_->tick();
}

}  // namespace sc
