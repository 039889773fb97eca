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
  // Drive every input once so last_ mirrors the ports.
  m_->enable_i = last_.enable;
  m_->cfg_high_i = last_.cfg.high;
  m_->cfg_low_i = last_.cfg.low;
  m_->cfg_setup_i = last_.cfg.setup;
  m_->cfg_hold_i = last_.cfg.hold;
  m_->seg_we_i = 0;
  m_->seg_count_i = 0;
  put_bits(m_->pos_frac0_i, 0, FracBits, 0);
  m_->start_i = 0;
  m_->abort_i = 0;
  // No external step source on the plain core (ExtStep = 0).
  m_->ext_sel_i = 0;
  m_->ext_req_i = 0;
  m_->ext_fwd_i = 0;
  m_->ext_hint_valid_i = 0;
  m_->ext_hint_i = 0;
  m_->ext_busy_i = 0;
  m_->ext_abort_i = 0;
  m_->ext_done_i = 0;
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
  // Inputs are written only when they change (cheaper, and no store right
  // before eval() to bytes the model then loads with a wider access).
  if (in.enable != last_.enable) m_->enable_i = in.enable;
  if (!(in.cfg == last_.cfg)) {
    m_->cfg_high_i = in.cfg.high;
    m_->cfg_low_i = in.cfg.low;
    m_->cfg_setup_i = in.cfg.setup;
    m_->cfg_hold_i = in.cfg.hold;
  }
  if (in.seg_we != last_.seg_we) m_->seg_we_i = in.seg_we;
  if (in.seg_we) {
    m_->seg_waddr_i = in.seg_waddr;
    const Segment& s = in.seg_wdata;
    m_->seg_phase_i = uint8_t(s.phase);
    m_->seg_clocks_i = s.clocks;
    m_->seg_jerk_i = uint64_t(s.jerk) & ((uint64_t(1) << JerkW) - 1);
    m_->seg_acc0_i = uint64_t(s.acc0);
    put_bits(m_->seg_vel0_i, 0, VelW, u128(s.vel0));
  }
  if (in.seg_count != last_.seg_count) m_->seg_count_i = in.seg_count;
  if (in.pos_frac0 != last_.pos_frac0) put_bits(m_->pos_frac0_i, 0, FracBits, in.pos_frac0);
  if (in.start != last_.start) m_->start_i = in.start;
  if (in.abort != last_.abort) m_->abort_i = in.abort;
  last_.enable = in.enable;
  last_.cfg = in.cfg;
  last_.seg_we = in.seg_we;
  last_.seg_count = in.seg_count;
  last_.pos_frac0 = in.pos_frac0;
  last_.start = in.start;
  last_.abort = in.abort;
  tick();
}

CoreOutputs RtlCore::outputs() const {
  CoreOutputs o;
  read_outputs(o);
  return o;
}

void RtlCore::read_outputs(CoreOutputs& o) const {
  static_assert(FracBits > 64 && FracBits <= 96 && VelW > 64 && VelW <= 96, "3-word wide ports");
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
  const auto& f = m_->ref_pos_frac_o;
  o.ref_pos_frac = (u128(f[2]) << 64) | (uint64_t(f[1]) << 32) | f[0];
  const auto& v = m_->ref_vel_o;
  // Sign-extend bit VelW-1 of the top word (bits 64..VelW-1).
  const int64_t v_hi = int64_t(uint64_t(v[2]) << (128 - VelW)) >> (128 - VelW);
  o.ref_vel = i128((u128(uint64_t(v_hi)) << 64) | (uint64_t(v[1]) << 32) | v[0]);
  o.ref_acc = int64_t(m_->ref_acc_o);
  static_assert(AccW == 64, "ref_acc_o needs no sign extension");
  o.ref_jerk = int64_t(uint64_t(m_->ref_jerk_o) << (64 - JerkW)) >> (64 - JerkW);
  o.seg_idx = m_->seg_idx_o;
  o.step_pending = int8_t(uint8_t(m_->step_pending_o << (8 - PendW))) >> (8 - PendW);
}

bool RtlCore::trace_supported() const { return VM_TRACE_FST != 0; }

void RtlCore::trace_open(const std::string& path, uint64_t from_clock, uint64_t to_clock) {
#if VM_TRACE_FST
  ctx_->traceEverOn(true);
  // Dump times are in ns (50 per 20 MHz clock): make the file say so.
  ctx_->timeunit(-9);
  ctx_->timeprecision(-9);
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
