#include "rtl_axi_axis.h"

#include "Vsc_axi_axis.h"
#include "Vsc_axi_servo.h"
#include "Vsc_board_top.h"
#include "verilated_top.h"

namespace sc {

namespace {

// The axis outputs both register-file tops share.
template <class V, class O>
void read_axis(const V& m, O& o) {
  read_step_outputs(m, o);
  o.fault = m.fault_o;
  o.ref_pos = int32_t(m.ref_pos_o);
  o.irq = m.irq_o;
}

}  // namespace

RtlAxiAxis::RtlAxiAxis() : top_(std::make_unique<VerilatedTop<Vsc_axi_axis>>("sc_axi_axis")) {}

RtlAxiAxis::~RtlAxiAxis() = default;

void RtlAxiAxis::reset(int cycles) { top_->reset(cycles); }

void RtlAxiAxis::step(const AxiIn& in, const RegsSide& side) {
  Vsc_axi_axis& m = top_->top();
  drive_axi(m, in);
  m.estop_i = side.estop;
  m.enc_ab_i = side.enc_ab & 3;
  m.enc_pos_i = uint32_t(side.enc_pos);
  m.enc_index_i = side.enc_z;
  m.sw_i = side.sw_pins & ((1u << SwW) - 1);
  top_->tick();
}

AxiAxisOutputs RtlAxiAxis::outputs() const {
  const Vsc_axi_axis& m = top_->top();
  AxiAxisOutputs o;
  o.axi = read_axi(m);
  read_axis(m, o);
  return o;
}

RtlAxiServo::RtlAxiServo() : top_(std::make_unique<VerilatedTop<Vsc_axi_servo>>("sc_axi_servo")) {}

RtlAxiServo::~RtlAxiServo() = default;

void RtlAxiServo::reset(int cycles) { top_->reset(cycles); }

void RtlAxiServo::step(const AxiIn& in, const RegsSide& side) {
  Vsc_axi_servo& m = top_->top();
  drive_axi(m, in);
  m.estop_i = side.estop;
  m.enc_a_i = side.enc_ab & 1;
  m.enc_b_i = (side.enc_ab >> 1) & 1;
  m.enc_z_i = side.enc_z;
  m.sw_i = side.sw_pins & ((1u << SwW) - 1);
  top_->tick();
}

AxiServoOutputs RtlAxiServo::outputs() const {
  const Vsc_axi_servo& m = top_->top();
  AxiServoOutputs o;
  o.axi = read_axi(m);
  read_axis(m, o);
  o.enc_pos = int32_t(m.enc_pos_o);
  o.in_pos = m.in_pos_o;
  o.fault_ferr = m.fault_ferr_o;
  return o;
}

RtlBoard::RtlBoard() : ctx_(std::make_unique<VerilatedContext>()) {
  m_ = std::make_unique<Vsc_board_top>(ctx_.get(), "sc_board_top");
  m_->clk100_i = 0;
  m_->ck_rst_ni = 1;
  m_->uart_rx_i = 1;
  m_->eval();
}

RtlBoard::~RtlBoard() {
  m_->final();
  coverage_collect(*ctx_);
}

void RtlBoard::tick100(bool uart_rx, bool rst_n, bool estop, bool enc_a, bool enc_b, uint8_t sw, bool enc_z) {
  m_->uart_rx_i = uart_rx;
  m_->ck_rst_ni = rst_n;
  m_->estop_i = estop;
  m_->enc_a_i = enc_a;
  m_->enc_b_i = enc_b;
  m_->enc_z_i = enc_z;
  m_->sw_i = sw & ((1u << SwProbe) - 1);  // the axis's switches; the probe has its own pin
  m_->probe_i = (sw >> SwProbe) & 1;
  m_->clk100_i = 1;
  m_->eval();
  m_->clk100_i = 0;
  m_->eval();
  ++clk100_;
}

RtlBoard::Pins RtlBoard::pins() const {
  Pins p;
  p.uart_tx = m_->uart_tx_o;
  p.step = m_->step_o;
  p.dir = m_->dir_o;
  p.en = m_->en_o;
  p.led = m_->led_o;
  return p;
}

}  // namespace sc
