// Bit-exact models of rtl/sc_axi_window_demux.sv (one AXI4-Lite port in
// front of the register windows of a multi-axis map) and of
// rtl/sc_axi_multi_axis.sv (the demux + one AxiRegs per axis +
// MultiAxisCore). Same flops, same update order, one step() per clock.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "axi_regs.h"
#include "multi_axis_core.h"
#include "switch_filter.h"
#include "sync.h"

namespace sc {

// Window of a multi-axis byte address: 0 = the group window, 1 + a = axis a.
constexpr uint32_t multi_window(uint32_t addr) { return addr >> RegAddrW; }
// The multi-axis byte address of register `reg` (one-axis map) in window `w`.
constexpr uint32_t multi_addr(uint32_t window, uint32_t reg) { return (window << RegAddrW) | reg; }

class AxiWindowDemux {
 public:
  struct State {
    bool aw_full = false, w_full = false, w_sent = false, b_own = false;
    uint16_t awaddr = 0;
    uint32_t wdata = 0;
    uint8_t wstrb = 0;
    bool ar_full = false, r_sent = false, r_own = false;
    uint16_t araddr = 0;
    bool operator==(const State&) const = default;
  };
  using SlaveOuts = std::array<AxiOut, MaxAxes>;

  // 1 .. MaxAxes slaves (std::invalid_argument naming `slaves` otherwise).
  explicit AxiWindowDemux(size_t slaves);
  void reset() { q_ = State{}; }
  // The master-side outputs, given the slaves' (registered) outputs.
  AxiOut outputs(const SlaveOuts& slave) const;
  // What the demux drives into slave s this clock.
  AxiIn slave_input(size_t s, const AxiIn& master, const SlaveOuts& slave) const;
  // group_o: the write in flight is the group window's.
  bool group() const { return window(q_.awaddr) == 0; }
  void step(const AxiIn& master, const SlaveOuts& slave);
  const State& state() const { return q_; }

 private:
  static uint32_t window(uint16_t addr) { return multi_window(addr); }
  bool w_selects(size_t s) const { return group() || window(q_.awaddr) == s + 1; }
  bool w_known() const { return window(q_.awaddr) <= slaves_; }
  bool r_known() const { return window(q_.araddr) <= slaves_; }
  size_t r_index() const { return (window(q_.araddr) == 0 || !r_known()) ? 0 : window(q_.araddr) - 1; }
  bool w_issue() const { return q_.aw_full && q_.w_full && !q_.w_sent && !q_.b_own; }
  bool r_issue() const { return q_.ar_full && !q_.r_sent && !q_.r_own; }
  bool b_all(const SlaveOuts& slave) const;
  size_t slaves_;
  State q_;
};

// Per-axis pins of sc_axi_multi_axis for one clock.
struct MultiAxisPins {
  bool enc_a = false, enc_b = false, enc_z = false;
  uint8_t sw = 0;  // bit SwLimNeg, SwLimPos, SwHome, SwProbe
};

// Outputs of sc_axi_multi_axis compared by the lockstep checker.
struct AxiMultiAxisOutputs {
  size_t axes = 0;
  AxiOut axi;
  struct Axis {
    bool step = false, dir = false, en = false;
    bool busy = false, done = false, fault = false;
    uint8_t phase = 0;
    int32_t pulse_count = 0, ref_pos = 0, enc_pos = 0;
    bool in_pos = false, fault_ferr = false;
    bool operator==(const Axis&) const = default;
  };
  std::array<Axis, MaxAxes> axis{};
  bool irq = false;
  bool operator==(const AxiMultiAxisOutputs& o) const {
    if (axes != o.axes || !(axi == o.axi) || irq != o.irq) return false;
    for (size_t a = 0; a < axes; ++a) {
      if (!(axis[a] == o.axis[a])) return false;
    }
    return true;
  }
};

class AxiMultiAxis {
 public:
  // 1 .. MaxAxes axes; servo: closed-loop capable axes (Servo = 1).
  AxiMultiAxis(size_t axes, bool servo);
  void reset();
  void step(const AxiIn& in, bool estop, const std::array<MultiAxisPins, MaxAxes>& pins);
  AxiMultiAxisOutputs outputs() const;

  size_t axes() const { return core_.axes(); }
  const AxiRegs& regs(size_t a) const { return regs_.at(a); }
  const MultiAxisCore& core() const { return core_; }
  const AxiWindowDemux& demux() const { return demux_; }

 private:
  std::vector<AxiRegs> regs_;
  std::vector<SwitchFilter> sw_;
  std::vector<Sync> enc_sync_;  // g_axis[a].u_sync_enc: STATUS.ENC_AB
  MultiAxisCore core_;
  AxiWindowDemux demux_;
  MultiCoreInputs core_in_{};
  std::array<std::array<uint32_t, ClCfgWords>, MaxAxes> cl_words_{};  // the settings core_in_.loop[a].ctl decodes
  MultiCoreOutputs core_out_{};
};

}  // namespace sc
