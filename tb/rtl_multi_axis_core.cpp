#include "rtl_multi_axis_core.h"

#include <stdexcept>
#include <string>
#include <type_traits>

#include "Vsc_multi_axis_core2.h"
#include "Vsc_multi_axis_core3.h"
#include "Vsc_multi_servo_core2.h"
#include "sc_layout.h"
#include "verilated_top.h"

namespace sc {
namespace {

// Axis a's slice of a packed [Axes][W] port.
#define SC_GET(port, a, w) get_field(m.port, int(a) * (w), (w))
#define SC_SET(port, a, w, v) set_field(m.port, int(a) * (w), (w), u128(v))

}  // namespace

struct RtlMultiAxisCore::Impl {
  virtual ~Impl() = default;
  virtual void reset(int cycles) = 0;
  virtual void step(const MultiCoreInputs& in) = 0;
  virtual void read_outputs(MultiCoreOutputs& o) const = 0;
};

namespace {

template <class V>
class MultiImpl final : public RtlMultiAxisCore::Impl {
 public:
  MultiImpl(size_t axes, bool servo) : axes_(axes), servo_(servo), top_("sc_multi_axis_core") {
    drive(last_, true);
    top_.top().eval();
  }
  void reset(int cycles) override { top_.reset(cycles); }
  void step(const MultiCoreInputs& in) override {
    drive(in, false);
    last_ = in;
    top_.tick();
  }
  void read_outputs(MultiCoreOutputs& o) const override {
    const V& m = top_.top();
    o.axes = axes_;
    for (size_t a = 0; a < axes_; ++a) {
      CoreOutputs& c = o.axis[a];
      c.step = SC_GET(step_o, a, 1) != 0;
      c.dir = SC_GET(dir_o, a, 1) != 0;
      c.en = SC_GET(en_o, a, 1) != 0;
      c.busy = SC_GET(busy_o, a, 1) != 0;
      c.done = SC_GET(done_o, a, 1) != 0;
      c.phase = uint8_t(SC_GET(phase_o, a, PhaseW));
      c.fault_table = SC_GET(fault_table_o, a, 1) != 0;
      c.fault_overrun = SC_GET(fault_overrun_o, a, 1) != 0;
      c.underrun = SC_GET(underrun_o, a, 1) != 0;
      c.discont = SC_GET(discont_o, a, 1) != 0;
      c.guard = SC_GET(guard_o, a, 1) != 0;
      c.reach = SC_GET(reach_o, a, 1) != 0;
      c.stopping = SC_GET(stopping_o, a, 1) != 0;
      c.overshoot = SC_GET(overshoot_o, a, 1) != 0;
      c.move_done = SC_GET(move_done_o, a, 1) != 0;
      c.move_idx = uint32_t(SC_GET(move_idx_o, a, MoveIdxW));
      c.boundary_pos = int32_t(uint32_t(SC_GET(boundary_pos_o, a, PosIntW)));
      c.fifo_level = uint8_t(SC_GET(fifo_level_o, a, RowLevelW));
      c.fifo_full = SC_GET(fifo_full_o, a, 1) != 0;
      c.row_count = uint32_t(SC_GET(row_count_o, a, RowCountW));
      c.retarget_refused = SC_GET(retarget_refused_o, a, 1) != 0;
      c.pulse_count = int32_t(uint32_t(SC_GET(pulse_count_o, a, PosIntW)));
      c.ref_pos_int = int32_t(uint32_t(SC_GET(ref_pos_int_o, a, PosIntW)));
      c.ref_pos_frac = SC_GET(ref_pos_frac_o, a, FracBits);
      c.ref_vel = wrap_signed(i128(SC_GET(ref_vel_o, a, VelW)), VelW);
      c.ref_acc = int64_t(uint64_t(SC_GET(ref_acc_o, a, AccW)));
      c.ref_jerk = int64_t(wrap_signed(i128(SC_GET(ref_jerk_o, a, JerkW)), JerkW));
      c.seg_idx = uint8_t(SC_GET(seg_idx_o, a, SegIdxW));
      c.step_pending = int8_t(wrap_signed(i128(SC_GET(step_pending_o, a, PendW)), PendW));
      c.lim_trip_fwd = SC_GET(lim_trip_fwd_o, a, 1) != 0;
      c.lim_trip_rev = SC_GET(lim_trip_rev_o, a, 1) != 0;
    }
    o.servo = servo_;
    if (!servo_) return;
    for (size_t a = 0; a < axes_; ++a) {
      LoopOutputs& l = o.loop[a];
      l.fault_ferr = SC_GET(fault_ferr_o, a, 1) != 0;
      l.in_pos = SC_GET(in_pos_o, a, 1) != 0;
      l.enc_pos = int32_t(uint32_t(SC_GET(enc_pos_o, a, EncCntW)));
      l.enc_illegal = uint16_t(SC_GET(enc_illegal_o, a, EncIllW));
      l.enc_index = SC_GET(enc_index_o, a, 1) != 0;
      l.ctl_active = SC_GET(ctl_active_o, a, 1) != 0;
      l.ctl_state = uint8_t(SC_GET(ctl_state_o, a, CtlStW));
      l.u = int32_t(uint32_t(SC_GET(u_o, a, CtlW)));
      l.v_cmd = int32_t(uint32_t(SC_GET(v_cmd_o, a, CtlW)));
      l.e_p = int32_t(uint32_t(SC_GET(e_p_o, a, CtlW)));
      l.e_v = int32_t(uint32_t(SC_GET(e_v_o, a, CtlW)));
      l.w_p1 = int32_t(wrap_signed(i128(SC_GET(w_p1_o, a, WgtW)), WgtW));
      l.w_p2 = int32_t(wrap_signed(i128(SC_GET(w_p2_o, a, WgtW)), WgtW));
      l.w_v1 = int32_t(wrap_signed(i128(SC_GET(w_v1_o, a, WgtW)), WgtW));
      l.w_v2 = int32_t(wrap_signed(i128(SC_GET(w_v2_o, a, WgtW)), WgtW));
      l.nco_phase = int64_t(wrap_signed(i128(SC_GET(nco_phase_o, a, NcoW)), NcoW));
    }
  }

 private:
  // Ports are written only when their value changes (all of them with `all`).
  void drive(const MultiCoreInputs& in, bool all) {
    V& m = top_.top();
    if (all || in.enable != last_.enable) m.enable_i = in.enable;
    if (all || in.row_push != last_.row_push) m.row_push_i = in.row_push;
    if (all || in.row_replace != last_.row_replace) m.row_replace_i = in.row_replace;
    if (all || in.retarget_row != last_.retarget_row) m.retarget_row_i = in.retarget_row;
    if (all || in.fifo_flush != last_.fifo_flush) m.fifo_flush_i = in.fifo_flush;
    if (all || in.start != last_.start) m.start_i = in.start;
    if (all || in.abort != last_.abort) m.abort_i = in.abort;
    if (all || in.stop != last_.stop) m.stop_i = in.stop;
    if (all || in.row_push) m.row_clocks_i = in.row_clocks;
    for (size_t a = 0; a < axes_; ++a) {
      const CoreInputs& x = in.axis[a];
      const CoreInputs& l = last_.axis[a];
      if (all || !(x.cfg == l.cfg)) {
        SC_SET(cfg_high_i, a, PulseTimeW, x.cfg.high);
        SC_SET(cfg_low_i, a, PulseTimeW, x.cfg.low);
        SC_SET(cfg_setup_i, a, PulseTimeW, x.cfg.setup);
        SC_SET(cfg_hold_i, a, PulseTimeW, x.cfg.hold);
      }
      if (all || in.row_push) {
        SC_SET(row_flags_i, a, RowFlagW, x.row.flags);
        SC_SET(row_phase_i, a, PhaseW, uint8_t(x.row.seg.phase));
        SC_SET(row_jerk_i, a, JerkW, uint64_t(x.row.seg.jerk));
        SC_SET(row_acc0_i, a, AccW, uint64_t(x.row.seg.acc0));
        SC_SET(row_vel0_i, a, VelW, x.row.seg.vel0);
      }
      if (all || x.pos_frac0 != l.pos_frac0) SC_SET(pos_frac0_i, a, FracBits, x.pos_frac0);
      if (all || x.stop_jerk != l.stop_jerk || x.stop_acc != l.stop_acc) {
        SC_SET(stop_jerk_i, a, JerkW, x.stop_jerk);
        SC_SET(stop_acc_i, a, AccW, x.stop_acc);
      }
      if (all || !(x.guard == l.guard)) {
        const GuardLimits g = x.guard.masked();
        SC_SET(guard_vel_i, a, VelW, g.vel);
        SC_SET(guard_acc_i, a, AccW, g.acc);
        SC_SET(guard_jerk_i, a, JerkW, g.jerk);
      }
      if (all || !(x.soft == l.soft)) {
        SC_SET(soft_en_i, a, 1, x.soft.en);
        SC_SET(soft_min_i, a, PosIntW, uint32_t(x.soft.min));
        SC_SET(soft_max_i, a, PosIntW, uint32_t(x.soft.max));
      }
      if (all || x.lim_fwd != l.lim_fwd || x.lim_rev != l.lim_rev || x.lim_hard != l.lim_hard) {
        SC_SET(lim_fwd_i, a, 1, x.lim_fwd);
        SC_SET(lim_rev_i, a, 1, x.lim_rev);
        SC_SET(lim_hard_i, a, 1, x.lim_hard);
      }
      if (!servo_) continue;
      const LoopInputs& y = in.loop[a];
      const LoopInputs& k = last_.loop[a];
      if (all || y.closed_loop != k.closed_loop) SC_SET(closed_loop_i, a, 1, y.closed_loop);
      if (all || !(y.ctl == k.ctl)) {
        const auto words = ctl_cfg_pack(y.ctl);
        for (size_t w = 0; w < words.size(); ++w) {
          const int lsb = int(w) * 32;
          put_bits(m.ctl_cfg_i, int(a) * CtlCfgW + lsb, std::min(32, CtlCfgW - lsb), words[w]);
        }
      }
      if (all || y.enc_a != k.enc_a) SC_SET(enc_a_i, a, 1, y.enc_a);
      if (all || y.enc_b != k.enc_b) SC_SET(enc_b_i, a, 1, y.enc_b);
      if (all || y.enc_z != k.enc_z) SC_SET(enc_z_i, a, 1, y.enc_z);
    }
  }

  size_t axes_;
  bool servo_;
  VerilatedTop<V> top_;
  MultiCoreInputs last_{};
};

}  // namespace

RtlMultiAxisCore::RtlMultiAxisCore(size_t axes, bool servo) : axes_(axes), servo_(servo) {
  if (!supported(axes, servo)) {
    throw std::invalid_argument("axes=" + std::to_string(axes) + ": the RTL is built for 2 and 3 axes (" +
                                "2 with the closed loop)");
  }
  if (servo) {
    impl_ = std::make_unique<MultiImpl<Vsc_multi_servo_core2>>(axes, true);
  } else if (axes == 2) {
    impl_ = std::make_unique<MultiImpl<Vsc_multi_axis_core2>>(axes, false);
  } else {
    impl_ = std::make_unique<MultiImpl<Vsc_multi_axis_core3>>(axes, false);
  }
}

RtlMultiAxisCore::~RtlMultiAxisCore() = default;

void RtlMultiAxisCore::reset(int cycles) { impl_->reset(cycles); }

void RtlMultiAxisCore::step(const MultiCoreInputs& in) { impl_->step(in); }

MultiCoreOutputs RtlMultiAxisCore::outputs() const {
  MultiCoreOutputs o;
  read_outputs(o);
  return o;
}

void RtlMultiAxisCore::read_outputs(MultiCoreOutputs& o) const { impl_->read_outputs(o); }

}  // namespace sc
