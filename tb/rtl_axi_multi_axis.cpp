#include "rtl_axi_multi_axis.h"

#include "Vsc_axi_multi_axis2.h"
#include "Vsc_board_xy_top.h"
#include "verilated_top.h"

namespace sc {

RtlAxiMultiAxis::RtlAxiMultiAxis()
    : top_(std::make_unique<VerilatedTop<Vsc_axi_multi_axis2>>("sc_axi_multi_axis")) {}

RtlAxiMultiAxis::~RtlAxiMultiAxis() = default;

void RtlAxiMultiAxis::reset(int cycles) { top_->reset(cycles); }

void RtlAxiMultiAxis::step(const AxiIn& in, bool estop, const std::array<MultiAxisPins, MaxAxes>& pins) {
  Vsc_axi_multi_axis2& m = top_->top();
  drive_axi(m, in);
  m.estop_i = estop;
  uint32_t a_bits = 0, b_bits = 0, z_bits = 0, sw = 0;
  for (size_t a = 0; a < kAxes; ++a) {
    a_bits |= uint32_t(pins[a].enc_a) << a;
    b_bits |= uint32_t(pins[a].enc_b) << a;
    z_bits |= uint32_t(pins[a].enc_z) << a;
    sw |= uint32_t(pins[a].sw & ((1u << SwW) - 1)) << (a * SwW);
  }
  m.enc_a_i = a_bits;
  m.enc_b_i = b_bits;
  m.enc_z_i = z_bits;
  m.sw_i = sw;
  top_->tick();
}

AxiMultiAxisOutputs RtlAxiMultiAxis::outputs() const {
  const Vsc_axi_multi_axis2& m = top_->top();
  AxiMultiAxisOutputs o;
  o.axes = kAxes;
  o.axi = read_axi(m);
  for (size_t a = 0; a < kAxes; ++a) {
    AxiMultiAxisOutputs::Axis& x = o.axis[a];
    const int i = int(a);
    x.step = get_field(m.step_o, i, 1) != 0;
    x.dir = get_field(m.dir_o, i, 1) != 0;
    x.en = get_field(m.en_o, i, 1) != 0;
    x.busy = get_field(m.busy_o, i, 1) != 0;
    x.done = get_field(m.done_o, i, 1) != 0;
    x.fault = get_field(m.fault_o, i, 1) != 0;
    x.phase = uint8_t(get_field(m.phase_o, i * PhaseW, PhaseW));
    x.pulse_count = int32_t(uint32_t(get_field(m.pulse_count_o, i * PosIntW, PosIntW)));
    x.ref_pos = int32_t(uint32_t(get_field(m.ref_pos_o, i * PosIntW, PosIntW)));
    x.enc_pos = int32_t(uint32_t(get_field(m.enc_pos_o, i * EncCntW, EncCntW)));
    x.in_pos = get_field(m.in_pos_o, i, 1) != 0;
    x.fault_ferr = get_field(m.fault_ferr_o, i, 1) != 0;
  }
  o.irq = m.irq_o;
  return o;
}

RtlBoardXY::RtlBoardXY() : ctx_(std::make_unique<VerilatedContext>()) {
  m_ = std::make_unique<Vsc_board_xy_top>(ctx_.get(), "sc_board_xy_top");
  m_->clk100_i = 0;
  m_->ck_rst_ni = 1;
  m_->uart_rx_i = 1;
  m_->eval();
}

RtlBoardXY::~RtlBoardXY() {
  m_->final();
  coverage_collect(*ctx_);
}

void RtlBoardXY::tick100(bool uart_rx, bool estop, uint8_t sw, bool probe, uint8_t enc_a, uint8_t enc_b,
                         uint8_t enc_z, bool rst_n) {
  m_->ck_rst_ni = rst_n;
  m_->uart_rx_i = uart_rx;
  m_->estop_i = estop;
  m_->sw_i = sw & 0x3f;
  m_->probe_i = probe;
  m_->enc_a_i = enc_a & 0x3;
  m_->enc_b_i = enc_b & 0x3;
  m_->enc_z_i = enc_z & 0x3;
  m_->clk100_i = 1;
  m_->eval();
  m_->clk100_i = 0;
  m_->eval();
  ++clk100_;
}

RtlBoardXY::Pins RtlBoardXY::pins() const {
  Pins p;
  p.uart_tx = m_->uart_tx_o;
  for (size_t a = 0; a < kAxes; ++a) {
    p.step[a] = (m_->step_o >> a) & 1;
    p.dir[a] = (m_->dir_o >> a) & 1;
    p.en[a] = (m_->en_o >> a) & 1;
  }
  p.irq = m_->irq_o;
  p.led = m_->led_o;
  return p;
}

}  // namespace sc
