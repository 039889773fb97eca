// The one shape of every Verilator adapter: a Verilated top with its own
// context, reset, one clock (rising + falling edge), an FST window, and the
// helpers that pack wide ports. Included only by the adapters' .cpp files
// (they alone see Verilator types); each adapter then binds its own ports.
// The top must have clk_i and an active-low synchronous rst_ni.
#pragma once

#include <verilated.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "axi_regs.h"
#include "coverage_sink.h"
#include "fixed_point.h"
#include "fst_output.h"
#include "profile_exec.h"

// VM_TRACE_FST is defined (0/1) only inside the target verilate() built.
#if defined(VM_TRACE_FST) && VM_TRACE_FST
#include <verilated_fst_c.h>
#define SC_VERILATED_FST 1
#else
#define SC_VERILATED_FST 0
#endif

namespace sc {

template <class V>
class VerilatedTop {
 public:
  explicit VerilatedTop(const char* name) : ctx_(std::make_unique<VerilatedContext>()), m_(ctx_.get(), name) {
    m_.clk_i = 0;
    m_.rst_ni = 0;
    m_.eval();
  }
  ~VerilatedTop() {
    trace_abandon();
    m_.final();
    coverage_collect(*ctx_);
  }
  VerilatedTop(const VerilatedTop&) = delete;
  VerilatedTop& operator=(const VerilatedTop&) = delete;

  V& top() { return m_; }
  const V& top() const { return m_; }
  uint64_t clock() const { return clock_; }

  // Hold rst_ni low for `cycles` clocks, then release it. Reset clocks are
  // not counted (clock 0 is the first after reset) nor traced.
  void reset(int cycles) {
    m_.rst_ni = 0;
    in_reset_ = true;
    for (int i = 0; i < cycles; ++i) {
      edge(1);
      edge(0);
    }
    in_reset_ = false;
    m_.rst_ni = 1;
  }
  // One clock with the inputs as driven now.
  void tick() {
    edge(1);
    edge(0);
    ++clock_;
  }

  static constexpr bool trace_supported() { return SC_VERILATED_FST != 0; }
  // FST waveform of the clocks in [from_clock, to_clock), times in ns,
  // written to `path` when trace_close() finds it whole. `param` names the
  // user's flag in error messages (input::Error).
  void trace_open(const std::string& path, uint64_t from_clock, uint64_t to_clock, const std::string& param = "fst") {
#if SC_VERILATED_FST
    out_ = std::make_unique<FstOutput>(param, path);
    ctx_->traceEverOn(true);
    ctx_->timeunit(-9);
    ctx_->timeprecision(-9);
    fst_ = std::make_unique<VerilatedFstC>();
    m_.trace(fst_.get(), 99);
    fst_->open(out_->part_path().c_str());
    if (!fst_->isOpen()) {
      fst_.reset();
      out_->creation_failed();
    }
    trace_from_ = from_clock;
    trace_to_ = to_clock;
#else
    (void)path;
    (void)from_clock;
    (void)to_clock;
    throw std::runtime_error(param + ": FST tracing needs the tracing build of this top");
#endif
  }
  // Ends the waveform: the file appears whole at its path, or input::Error
  // says why not (and nothing is left behind).
  void trace_close() {
#if SC_VERILATED_FST
    if (fst_) {
      fst_->close();
      fst_.reset();
      std::unique_ptr<FstOutput> out = std::move(out_);
      out->commit();
    }
#endif
  }

 private:
  // A run that ends early (an exception) leaves no waveform behind.
  void trace_abandon() noexcept {
#if SC_VERILATED_FST
    if (fst_) fst_->close();
    fst_.reset();
    out_.reset();
#endif
  }
  void edge(int clk) {
    m_.clk_i = uint8_t(clk);
    m_.eval();
#if SC_VERILATED_FST
    if (fst_ && !in_reset_ && clock_ >= trace_from_ && clock_ < trace_to_) [[unlikely]] {
      fst_->dump(clock_ * 50 + (clk ? 0 : 25));  // ns at 20 MHz
    }
#endif
  }
  std::unique_ptr<VerilatedContext> ctx_;
  V m_;
#if SC_VERILATED_FST
  std::unique_ptr<FstOutput> out_;
  std::unique_ptr<VerilatedFstC> fst_;
  uint64_t trace_from_ = 0, trace_to_ = 0;
#endif
  uint64_t clock_ = 0;
  bool in_reset_ = false;
};

// Write `width` bits of v at bit `lsb` of a Verilated wide port (32-bit words).
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

// `width` bits at bit `lsb` of a port: a scalar (CData .. QData) or a
// Verilated wide port (32-bit words).
template <class P>
u128 get_field(const P& p, int lsb, int width) {
  if constexpr (std::is_integral_v<P>) {
    return mask_bits(u128(uint64_t(p)) >> lsb, width);
  } else {
    u128 v = 0;
    for (int i = 0; i < width;) {
      const int bit = lsb + i, off = bit % 32;
      const int n = std::min(width - i, 32 - off);
      v |= u128((uint64_t(p[bit / 32]) >> off) & ((uint64_t(1) << n) - 1)) << i;
      i += n;
    }
    return v;
  }
}

template <class P>
void set_field(P& p, int lsb, int width, u128 v) {
  if constexpr (std::is_integral_v<P>) {
    const uint64_t m = (width >= 64 ? ~uint64_t(0) : ((uint64_t(1) << width) - 1)) << lsb;
    p = P((uint64_t(p) & ~m) | ((uint64_t(mask_bits(v, width)) << lsb) & m));
  } else {
    put_bits(p, lsb, width, v);
  }
}

// The AXI4-Lite slave ports every register-file top has (sc_axi_axis,
// sc_axi_servo, sc_axi_multi_axis).
template <class V>
void drive_axi(V& m, const AxiIn& in) {
  m.s_axi_awaddr_i = in.awaddr;
  m.s_axi_awvalid_i = in.awvalid;
  m.s_axi_wdata_i = in.wdata;
  m.s_axi_wstrb_i = in.wstrb & 0xf;
  m.s_axi_wvalid_i = in.wvalid;
  m.s_axi_bready_i = in.bready;
  m.s_axi_araddr_i = in.araddr;
  m.s_axi_arvalid_i = in.arvalid;
  m.s_axi_rready_i = in.rready;
}

template <class V>
AxiOut read_axi(const V& m) {
  AxiOut a;
  a.awready = m.s_axi_awready_o;
  a.wready = m.s_axi_wready_o;
  a.bvalid = m.s_axi_bvalid_o;
  a.bresp = m.s_axi_bresp_o;
  a.arready = m.s_axi_arready_o;
  a.rvalid = m.s_axi_rvalid_o;
  a.rdata = m.s_axi_rdata_o;
  a.rresp = m.s_axi_rresp_o;
  return a;
}

// The low `width` bits of v (a port narrower than its C++ type).
inline uint32_t port_bits(int64_t v, int width) { return uint32_t(uint64_t(v) & ((uint64_t(1) << width) - 1)); }
// A `width`-bit port value sign-extended.
inline int32_t sign_extend(uint32_t v, int width) { return int32_t(wrap_signed64(int64_t(v), width)); }

// The row data ports (row_*_i but row_push_i) of the axis tops
// (sc_axis_core, sc_servo_axis).
template <class V>
void drive_row(V& m, const Row& r) {
  const Segment& s = r.seg;
  m.row_flags_i = r.flags;
  m.row_phase_i = uint8_t(s.phase);
  m.row_clocks_i = s.clocks;
  m.row_jerk_i = uint64_t(s.jerk) & ((uint64_t(1) << JerkW) - 1);
  m.row_acc0_i = uint64_t(s.acc0);
  put_bits(m.row_vel0_i, 0, VelW, u128(s.vel0));
}

// The retarget inputs of the axis tops (with row_push_i).
template <class V>
void drive_retarget(V& m, bool replace, uint32_t retarget_row) {
  m.row_replace_i = replace;
  m.retarget_row_i = retarget_row;
}

// The controlled-stop inputs of the axis tops (sc_axis_core, sc_servo_axis).
template <class V>
void drive_stop(V& m, bool stop, uint64_t stop_jerk, uint64_t stop_acc) {
  m.stop_i = stop;
  m.stop_jerk_i = stop_jerk & ((uint64_t(1) << JerkW) - 1);
  m.stop_acc_i = stop_acc;
}

// The row guard inputs of the axis tops (sc_axis_core, sc_servo_axis).
template <class V>
void drive_guards(V& m, const GuardLimits& g) {
  const GuardLimits w = g.masked();
  put_bits(m.guard_vel_i, 0, VelW, w.vel);
  m.guard_acc_i = w.acc;
  m.guard_jerk_i = w.jerk;
}

// The soft-limit look-ahead inputs of the axis tops (sc_axis_core, sc_servo_axis).
template <class V>
void drive_soft(V& m, const SoftWindow& w) {
  m.soft_en_i = w.en;
  m.soft_min_i = uint32_t(w.min);
  m.soft_max_i = uint32_t(w.max);
}

// The limit inputs of the axis tops (sc_axis_core, sc_servo_axis).
template <class V>
void drive_limits(V& m, bool lim_fwd, bool lim_rev, bool lim_hard) {
  m.lim_fwd_i = lim_fwd;
  m.lim_rev_i = lim_rev;
  m.lim_hard_i = lim_hard;
}

// The STEP/DIR and status outputs every top with an axis has under the same
// port names (sc_axis_core, sc_servo_axis, sc_axi_axis, sc_axi_servo).
template <class V, class O>
void read_step_outputs(const V& m, O& o) {
  o.step = m.step_o;
  o.dir = m.dir_o;
  o.en = m.en_o;
  o.busy = m.busy_o;
  o.done = m.done_o;
  o.phase = m.phase_o;
  o.pulse_count = int32_t(m.pulse_count_o);
}

// The fault and reference outputs of the axis tops (sc_axis_core,
// sc_servo_axis) besides the STEP/DIR and status ones.
template <class V, class O>
void read_axis_outputs(const V& m, O& o) {
  read_step_outputs(m, o);
  o.fault_table = m.fault_table_o;
  o.fault_overrun = m.fault_overrun_o;
  o.ref_pos_int = int32_t(m.ref_pos_int_o);
  o.underrun = m.underrun_o;
  o.discont = m.discont_o;
  o.guard = m.guard_o;
  o.reach = m.reach_o;
  o.stopping = m.stopping_o;
  o.overshoot = m.overshoot_o;
  o.move_done = m.move_done_o;
  o.move_idx = m.move_idx_o;
  o.boundary_pos = int32_t(m.boundary_pos_o);
  o.fifo_level = m.fifo_level_o;
  o.fifo_full = m.fifo_full_o;
  o.row_count = m.row_count_o;
  o.retarget_refused = m.retarget_refused_o;
  o.lim_trip_fwd = m.lim_trip_fwd_o;
  o.lim_trip_rev = m.lim_trip_rev_o;
}

}  // namespace sc
