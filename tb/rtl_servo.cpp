#include "rtl_servo.h"

#include <verilated.h>

#include <algorithm>
#include <stdexcept>

#include "Vsc_servo_axis.h"
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
inline uint32_t bits(int64_t v, int w) { return uint32_t(uint64_t(v) & ((uint64_t(1) << w) - 1)); }
inline int32_t sx(uint32_t v, int w) { return int32_t(wrap_signed64(int64_t(v), w)); }

}  // namespace

RtlServo::RtlServo() : ctx_(std::make_unique<VerilatedContext>()) {
  m_ = std::make_unique<Vsc_servo_axis>(ctx_.get(), "sc_servo_axis");
  m_->clk_i = 0;
  m_->rst_ni = 0;
  m_->eval();
}

RtlServo::~RtlServo() {
  trace_close();
  m_->final();
}

void RtlServo::eval_edge(int clk) {
  m_->clk_i = clk;
  m_->eval();
#if VM_TRACE_FST
  if (fst_ && clock_ >= trace_from_ && clock_ < trace_to_) fst_->dump(clock_ * 50 + (clk ? 0 : 25));
#endif
}

void RtlServo::reset(int cycles) {
  m_->rst_ni = 0;
  for (int i = 0; i < cycles; ++i) {
    eval_edge(1);
    eval_edge(0);
  }
  m_->rst_ni = 1;
}

void RtlServo::apply_cfg(const ServoConfig& c) {
  m_->enable_i = c.enable;
  m_->closed_loop_i = c.closed_loop;
  m_->cfg_high_i = c.timing.high;
  m_->cfg_low_i = c.timing.low;
  m_->cfg_setup_i = c.timing.setup;
  m_->cfg_hold_i = c.timing.hold;
  const auto v = ctl_cfg_pack(c.ctl);
  for (size_t i = 0; i < v.size(); ++i) m_->ctl_cfg_i[i] = v[i];
}

void RtlServo::step(const ServoInputs& in) {
  if (!cfg_set_ || !(in.cfg == cfg_)) [[unlikely]] {
    cfg_ = in.cfg;
    cfg_set_ = true;
    apply_cfg(cfg_);
  }
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
  m_->enc_a_i = in.enc_a;
  m_->enc_b_i = in.enc_b;
  eval_edge(1);
  eval_edge(0);
  ++clock_;
}

ServoOutputs RtlServo::outputs() const {
  ServoOutputs o;
  o.step = m_->step_o;
  o.dir = m_->dir_o;
  o.en = m_->en_o;
  o.busy = m_->busy_o;
  o.done = m_->done_o;
  o.phase = m_->phase_o;
  o.fault_table = m_->fault_table_o;
  o.fault_overrun = m_->fault_overrun_o;
  o.fault_ferr = m_->fault_ferr_o;
  o.in_pos = m_->in_pos_o;
  o.pulse_count = int32_t(m_->pulse_count_o);
  o.enc_pos = int32_t(m_->enc_pos_o);
  o.enc_illegal = uint16_t(m_->enc_illegal_o);
  o.ref_pos_int = int32_t(m_->ref_pos_int_o);
  o.ref_frac_hi = uint32_t(m_->ref_frac_hi_o);
  o.ref_vel = int32_t(m_->ref_vel_o);
  o.ref_done = m_->ref_done_o;
  o.ctl_active = m_->ctl_active_o;
  o.ctl_state = m_->ctl_state_o;
  o.u = int32_t(m_->u_o);
  o.v_cmd = int32_t(m_->v_cmd_o);
  o.e_p = int32_t(m_->e_p_o);
  o.e_v = int32_t(m_->e_v_o);
  o.w_p1 = sx(m_->w_p1_o, WgtW);
  o.w_p2 = sx(m_->w_p2_o, WgtW);
  o.w_v1 = sx(m_->w_v1_o, WgtW);
  o.w_v2 = sx(m_->w_v2_o, WgtW);
  o.wn_p1 = sx(m_->wn_p1_o, NWgtW);
  o.wn_p2 = sx(m_->wn_p2_o, NWgtW);
  o.wn_v1 = sx(m_->wn_v1_o, NWgtW);
  o.wn_v2 = sx(m_->wn_v2_o, NWgtW);
  o.nco_phase = wrap_signed64(int64_t(m_->nco_phase_o), NcoW);
  o.step_pending = int8_t(wrap_signed64(m_->step_pending_o, PendW));
  return o;
}

bool RtlServo::trace_supported() const { return VM_TRACE_FST != 0; }

void RtlServo::trace_open(const std::string& path, uint64_t from_clock, uint64_t to_clock) {
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
  throw std::runtime_error("FST tracing needs the tracing build");
#endif
}

void RtlServo::trace_close() {
#if VM_TRACE_FST
  if (fst_) {
    fst_->close();
    fst_.reset();
  }
#endif
}

}  // namespace sc
