#include "axi_multi_axis.h"

#include <stdexcept>
#include <string>

namespace sc {

namespace {

constexpr uint16_t kMultiAddrMask = uint16_t((1u << MultiRegAddrW) - 1);
constexpr uint16_t kWindowAddrMask = uint16_t((1u << RegAddrW) - 1);
static_assert(MultiRegAddrW == RegAddrW + RegWinW, "sc_pkg: MultiRegAddrW is RegAddrW + RegWinW");
static_assert(MultiRegAddrW <= 16, "AxiIn addresses are 16 bits");
static_assert(MaxAxes < (1 << RegWinW), "the group window and MaxAxes axis windows fit RegWinW bits");

}  // namespace

AxiWindowDemux::AxiWindowDemux(size_t slaves) : slaves_(slaves) {
  if (slaves < 1 || slaves > size_t(MaxAxes)) {
    throw std::invalid_argument("slaves = " + std::to_string(slaves) + " is not 1 .. " + std::to_string(MaxAxes));
  }
}

bool AxiWindowDemux::b_all(const SlaveOuts& slave) const {
  for (size_t s = 0; s < slaves_; ++s) {
    if (w_selects(s) && !slave[s].bvalid) return false;
  }
  return true;
}

AxiOut AxiWindowDemux::outputs(const SlaveOuts& slave) const {
  AxiOut o;
  o.awready = !q_.aw_full;
  o.wready = !q_.w_full;
  o.bvalid = q_.b_own || (q_.w_sent && b_all(slave));
  uint8_t worst = 0;  // DECERR > SLVERR > OKAY: the OR of the codes
  for (size_t s = 0; s < slaves_; ++s) {
    if (w_selects(s)) worst = uint8_t(worst | slave[s].bresp);
  }
  o.bresp = q_.b_own ? uint8_t(kDecErr) : worst;
  o.arready = !q_.ar_full;
  const AxiOut& r = slave[r_index()];
  o.rvalid = q_.r_own || (q_.r_sent && r.rvalid);
  o.rresp = q_.r_own ? uint8_t(kDecErr) : r.rresp;
  o.rdata = q_.r_own ? 0 : r.rdata;
  return o;
}

AxiIn AxiWindowDemux::slave_input(size_t s, const AxiIn& master, const SlaveOuts& slave) const {
  AxiIn i;
  const bool w_go = w_issue() && w_known() && w_selects(s);
  i.awaddr = uint16_t(q_.awaddr & kWindowAddrMask);
  i.awvalid = w_go;
  i.wdata = q_.wdata;
  i.wstrb = q_.wstrb;
  i.wvalid = w_go;
  i.bready = q_.w_sent && b_all(slave) && master.bready && w_selects(s);
  i.araddr = uint16_t(q_.araddr & kWindowAddrMask);
  i.arvalid = r_issue() && r_known() && r_index() == s;
  i.rready = q_.r_sent && master.rready && r_index() == s;
  return i;
}

void AxiWindowDemux::step(const AxiIn& master, const SlaveOuts& slave) {
  const AxiOut o = outputs(slave);
  State d = q_;
  if (master.awvalid && !q_.aw_full) {
    d.aw_full = true;
    d.awaddr = uint16_t(master.awaddr & kMultiAddrMask);
  }
  if (master.wvalid && !q_.w_full) {
    d.w_full = true;
    d.wdata = master.wdata;
    d.wstrb = master.wstrb & 0xf;
  }
  if (w_issue()) {
    d.w_sent = w_known();
    d.b_own = !w_known();
  }
  if (o.bvalid && master.bready) {
    d.aw_full = d.w_full = d.w_sent = d.b_own = false;
  }
  if (master.arvalid && !q_.ar_full) {
    d.ar_full = true;
    d.araddr = uint16_t(master.araddr & kMultiAddrMask);
  }
  if (r_issue()) {
    d.r_sent = r_known();
    d.r_own = !r_known();
  }
  if (o.rvalid && master.rready) {
    d.ar_full = d.r_sent = d.r_own = false;
  }
  q_ = d;
}

AxiMultiAxis::AxiMultiAxis(size_t axes, bool servo)
    : core_(axes, servo), demux_(axes) {
  regs_.assign(axes, AxiRegs(servo));
  sw_.assign(axes, SwitchFilter());
  enc_sync_.assign(axes, Sync(2, false));
  reset();
}

void AxiMultiAxis::reset() {
  core_in_ = MultiCoreInputs{};
  for (size_t a = 0; a < cl_words_.size(); ++a) {
    for (int i = 0; i < ClCfgWords; ++i) cl_words_[a][size_t(i)] = AxiRegs::cl_reset(i);
    core_in_.loop[a].ctl = ctl_cfg_from_words(cl_words_[a]);
  }
  for (AxiRegs& r : regs_) r.reset();
  for (SwitchFilter& s : sw_) s.reset();
  for (Sync& s : enc_sync_) s.reset();
  core_.reset();
  demux_.reset();
}

void AxiMultiAxis::step(const AxiIn& in, bool estop, const std::array<MultiAxisPins, MaxAxes>& pins) {
  const size_t n = axes();
  AxiWindowDemux::SlaveOuts so{};
  for (size_t a = 0; a < n; ++a) so[a] = regs_[a].axi_outputs();
  core_.read_outputs(core_out_);

  // the core's inputs: per axis from its register file, the shared ones
  // from axis 0's (written through the group window only)
  MultiCoreInputs& ci = core_in_;
  ci.enable = true;
  ci.abort = false;
  ci.stop = false;
  bool start_ok = true;
  for (size_t a = 0; a < n; ++a) {
    const CoreOutputs& co = core_out_.axis[a];
    ci.axis[a] = regs_[a].core_inputs(sw_[a].level(), co.ref_pos_int);
    ci.enable = ci.enable && ci.axis[a].enable;
    ci.abort = ci.abort || ci.axis[a].abort;
    ci.stop = ci.stop || ci.axis[a].stop;
    start_ok = start_ok && regs_[a].start_able(co);
    if (core_.servo()) {
      LoopInputs& l = ci.loop[a];
      l.closed_loop = regs_[a].state().closed;
      // decoded only when a settings word changed (core_in_ keeps it)
      if (regs_[a].state().cl != cl_words_[a]) {
        cl_words_[a] = regs_[a].state().cl;
        l.ctl = ctl_cfg_from_words(cl_words_[a]);
      }
      l.enc_a = pins[a].enc_a;
      l.enc_b = pins[a].enc_b;
      l.enc_z = pins[a].enc_z;
    }
  }
  const CoreInputs& shared = ci.axis[0];
  ci.row_push = shared.row_push;
  ci.row_replace = shared.row_replace;
  ci.retarget_row = shared.retarget_row;
  ci.row_clocks = shared.row.seg.clocks;
  ci.fifo_flush = shared.fifo_flush;
  ci.start = shared.start;

  const RegsGroup g{demux_.group(), start_ok};
  std::array<uint32_t, MaxAxes> invert{}, debounce{};
  for (size_t a = 0; a < n; ++a) {
    RegsSide rs;
    rs.estop = estop;
    rs.enc_ab = uint8_t(enc_sync_[a].q());
    rs.enc_pos = core_out_.loop[a].enc_pos;
    rs.enc_z = core_out_.loop[a].enc_index;
    rs.sw_level = uint8_t(sw_[a].level());
    rs.sw_edge = uint8_t(sw_[a].edge());
    invert[a] = regs_[a].state().sw_invert;
    debounce[a] = regs_[a].state().sw_debounce;
    regs_[a].step(demux_.slave_input(a, in, so), rs, core_out_.axis[a], servo_status(core_out_.loop[a]), g);
  }
  demux_.step(in, so);
  core_.step(ci);
  for (size_t a = 0; a < n; ++a) {
    enc_sync_[a].step((pins[a].enc_b ? 2u : 0u) | (pins[a].enc_a ? 1u : 0u));
    sw_[a].step(pins[a].sw, invert[a], debounce[a]);
  }
}

AxiMultiAxisOutputs AxiMultiAxis::outputs() const {
  const size_t n = axes();
  AxiWindowDemux::SlaveOuts so{};
  for (size_t a = 0; a < n; ++a) so[a] = regs_[a].axi_outputs();
  const MultiCoreOutputs co = core_.outputs();
  AxiMultiAxisOutputs o;
  o.axes = n;
  o.axi = demux_.outputs(so);
  for (size_t a = 0; a < n; ++a) {
    const CoreOutputs& c = co.axis[a];
    const LoopOutputs& l = co.loop[a];
    AxiMultiAxisOutputs::Axis& x = o.axis[a];
    x.step = c.step;
    x.dir = c.dir;
    x.en = c.en;
    x.busy = regs_[a].busy(c);
    x.done = c.done && !x.busy;
    x.fault = c.fault_table || c.fault_overrun || l.fault_ferr;
    x.phase = c.phase;
    x.pulse_count = c.pulse_count;
    x.ref_pos = c.ref_pos_int;
    x.enc_pos = l.enc_pos;
    x.in_pos = l.in_pos;
    x.fault_ferr = l.fault_ferr;
    o.irq = o.irq || regs_[a].state().irq;
  }
  return o;
}

}  // namespace sc
