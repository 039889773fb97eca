#include "rtl_core.h"

#include <verilated.h>

#include <algorithm>
#include <stdexcept>

#include "Vsc_axis_core.h"
#if VM_TRACE_FST
#include <verilated_fst_c.h>
#else
class VerilatedFstC {};
#endif

namespace sc {

namespace {

template <typename W>
void put_bits(W& w, int lsb, int width, u128 v) {
  v = mask_bits(v, width);
  while (width > 0) {
    const int word = lsb / 32, off = lsb % 32;
    const int n = std::min(width, 32 - off);
    const uint32_t m = (n == 32 ? ~0u : ((1u << n) - 1)) << off;
    w[word] = (w[word] & ~m) | ((uint32_t(v) << off) & m);
    v >>= n;
    lsb += n;
    width -= n;
  }
}
template <typename W>
u128 get_u128(const W& w, int words) {
  u128 v = 0;
  for (int i = words - 1; i >= 0; --i) v = (v << 32) | w[i];
  return v;
}

}  // namespace

RtlCore::RtlCore() : ctx_(std::make_unique<VerilatedContext>()) {
  m_ = std::make_unique<Vsc_axis_core>(ctx_.get(), "sc_axis_core");
  m_->clk_i = 0;
  m_->rst_ni = 0;
  m_->eval();
}

RtlCore::~RtlCore() {
  trace_close();
  m_->final();
}

void RtlCore::eval_edge(int clk) {
  m_->clk_i = clk;
  m_->eval();
#if VM_TRACE_FST
  if (fst_ && clock_ >= trace_from_ && clock_ < trace_to_) {
    fst_->dump(clock_ * 50 + (clk ? 0 : 25));  // ns
  }
#endif
}

void RtlCore::reset(int cycles) {
  m_->rst_ni = 0;
  for (int i = 0; i < cycles; ++i) {
    eval_edge(1);
    eval_edge(0);
  }
  m_->rst_ni = 1;
}

void RtlCore::step(const CoreInputs& in) {
  m_->enable_i = in.enable;
  m_->cfg_high_i = in.cfg.high;
  m_->cfg_low_i = in.cfg.low;
  m_->cfg_setup_i = in.cfg.setup;
  m_->cfg_hold_i = in.cfg.hold;
  m_->seg_we_i = in.seg_we;
  if (in.seg_we) {
    m_->seg_waddr_i = in.seg_waddr;
    const Segment& s = in.seg_wdata;
    m_->seg_phase_i = uint8_t(s.phase);
    m_->seg_clocks_i = s.clocks;
    m_->seg_jerk_i = uint64_t(s.jerk) & ((uint64_t(1) << JerkW) - 1);
    m_->seg_acc0_i = uint64_t(s.acc0);
    put_bits(m_->seg_vel0_i, 0, VelW, u128(s.vel0));
  }
  m_->seg_count_i = in.seg_count;
  if (in.pos_frac0 != pos_frac0_) {
    pos_frac0_ = in.pos_frac0;
    put_bits(m_->pos_frac0_i, 0, FracBits, in.pos_frac0);
  }
  m_->start_i = in.start;
  m_->abort_i = in.abort;
  eval_edge(1);
  eval_edge(0);
  ++clock_;
}

CoreOutputs RtlCore::outputs() const {
  CoreOutputs o;
  o.step = m_->step_o;
  o.dir = m_->dir_o;
  o.en = m_->en_o;
  o.busy = m_->busy_o;
  o.done = m_->done_o;
  o.phase = m_->phase_o;
  o.fault_table = m_->fault_table_o;
  o.fault_overrun = m_->fault_overrun_o;
  o.pulse_count = int32_t(m_->pulse_count_o);
  o.ref_pos_int = int32_t(m_->ref_pos_int_o);
  o.ref_pos_frac = get_u128(m_->ref_pos_frac_o, 3);
  o.ref_vel = wrap_signed(i128(get_u128(m_->ref_vel_o, 3)), VelW);
  o.ref_acc = wrap_signed64(int64_t(m_->ref_acc_o), AccW);
  o.ref_jerk = wrap_signed64(int64_t(m_->ref_jerk_o), JerkW);
  o.seg_idx = m_->seg_idx_o;
  o.step_pending = int8_t(wrap_signed64(m_->step_pending_o, PendW));
  return o;
}

bool RtlCore::trace_supported() const { return VM_TRACE_FST != 0; }

void RtlCore::trace_open(const std::string& path, uint64_t from_clock, uint64_t to_clock) {
#if VM_TRACE_FST
  ctx_->traceEverOn(true);
  fst_ = std::make_unique<VerilatedFstC>();
  m_->trace(fst_.get(), 99);
  fst_->open(path.c_str());
  trace_from_ = from_clock;
  trace_to_ = to_clock;
#else
  (void)path;
  (void)from_clock;
  (void)to_clock;
  throw std::runtime_error("FST tracing needs the tracing build (scurve was built without it)");
#endif
}

void RtlCore::trace_close() {
#if VM_TRACE_FST
  if (fst_) {
    fst_->close();
    fst_.reset();
  }
#endif
}

}  // namespace sc
