#include "rtl_axi_axis.h"

#include <verilated.h>

#include "Vsc_axi_axis.h"
#include "Vsc_axi_servo.h"
#include "Vsc_board_top.h"

namespace sc {

RtlAxiAxis::RtlAxiAxis() : ctx_(std::make_unique<VerilatedContext>()) {
  m_ = std::make_unique<Vsc_axi_axis>(ctx_.get(), "sc_axi_axis");
  m_->clk_i = 0;
  m_->rst_ni = 0;
  m_->eval();
}

RtlAxiAxis::~RtlAxiAxis() { m_->final(); }

void RtlAxiAxis::reset(int cycles) {
  m_->rst_ni = 0;
  for (int i = 0; i < cycles; ++i) {
    m_->clk_i = 1;
    m_->eval();
    m_->clk_i = 0;
    m_->eval();
  }
  m_->rst_ni = 1;
}

void RtlAxiAxis::step(const AxiIn& in, const RegsSide& side) {
  m_->s_axi_awaddr_i = in.awaddr;
  m_->s_axi_awvalid_i = in.awvalid;
  m_->s_axi_wdata_i = in.wdata;
  m_->s_axi_wstrb_i = in.wstrb & 0xf;
  m_->s_axi_wvalid_i = in.wvalid;
  m_->s_axi_bready_i = in.bready;
  m_->s_axi_araddr_i = in.araddr;
  m_->s_axi_arvalid_i = in.arvalid;
  m_->s_axi_rready_i = in.rready;
  m_->estop_i = side.estop;
  m_->enc_ab_i = side.enc_ab & 3;
  m_->enc_pos_i = uint32_t(side.enc_pos);
  m_->clk_i = 1;
  m_->eval();
  m_->clk_i = 0;
  m_->eval();
}

AxiAxisOutputs RtlAxiAxis::outputs() const {
  AxiAxisOutputs o;
  o.axi.awready = m_->s_axi_awready_o;
  o.axi.wready = m_->s_axi_wready_o;
  o.axi.bvalid = m_->s_axi_bvalid_o;
  o.axi.bresp = m_->s_axi_bresp_o;
  o.axi.arready = m_->s_axi_arready_o;
  o.axi.rvalid = m_->s_axi_rvalid_o;
  o.axi.rdata = m_->s_axi_rdata_o;
  o.axi.rresp = m_->s_axi_rresp_o;
  o.step = m_->step_o;
  o.dir = m_->dir_o;
  o.en = m_->en_o;
  o.busy = m_->busy_o;
  o.done = m_->done_o;
  o.fault = m_->fault_o;
  o.phase = m_->phase_o;
  o.pulse_count = int32_t(m_->pulse_count_o);
  o.ref_pos = int32_t(m_->ref_pos_o);
  return o;
}

RtlAxiServo::RtlAxiServo() : ctx_(std::make_unique<VerilatedContext>()) {
  m_ = std::make_unique<Vsc_axi_servo>(ctx_.get(), "sc_axi_servo");
  m_->clk_i = 0;
  m_->rst_ni = 0;
  m_->eval();
}

RtlAxiServo::~RtlAxiServo() { m_->final(); }

void RtlAxiServo::reset(int cycles) {
  m_->rst_ni = 0;
  for (int i = 0; i < cycles; ++i) {
    m_->clk_i = 1;
    m_->eval();
    m_->clk_i = 0;
    m_->eval();
  }
  m_->rst_ni = 1;
}

void RtlAxiServo::step(const AxiIn& in, const RegsSide& side) {
  m_->s_axi_awaddr_i = in.awaddr;
  m_->s_axi_awvalid_i = in.awvalid;
  m_->s_axi_wdata_i = in.wdata;
  m_->s_axi_wstrb_i = in.wstrb & 0xf;
  m_->s_axi_wvalid_i = in.wvalid;
  m_->s_axi_bready_i = in.bready;
  m_->s_axi_araddr_i = in.araddr;
  m_->s_axi_arvalid_i = in.arvalid;
  m_->s_axi_rready_i = in.rready;
  m_->estop_i = side.estop;
  m_->enc_a_i = side.enc_ab & 1;
  m_->enc_b_i = (side.enc_ab >> 1) & 1;
  m_->clk_i = 1;
  m_->eval();
  m_->clk_i = 0;
  m_->eval();
}

AxiServoOutputs RtlAxiServo::outputs() const {
  AxiServoOutputs o;
  o.axi.awready = m_->s_axi_awready_o;
  o.axi.wready = m_->s_axi_wready_o;
  o.axi.bvalid = m_->s_axi_bvalid_o;
  o.axi.bresp = m_->s_axi_bresp_o;
  o.axi.arready = m_->s_axi_arready_o;
  o.axi.rvalid = m_->s_axi_rvalid_o;
  o.axi.rdata = m_->s_axi_rdata_o;
  o.axi.rresp = m_->s_axi_rresp_o;
  o.step = m_->step_o;
  o.dir = m_->dir_o;
  o.en = m_->en_o;
  o.busy = m_->busy_o;
  o.done = m_->done_o;
  o.fault = m_->fault_o;
  o.phase = m_->phase_o;
  o.pulse_count = int32_t(m_->pulse_count_o);
  o.ref_pos = int32_t(m_->ref_pos_o);
  o.enc_pos = int32_t(m_->enc_pos_o);
  o.in_pos = m_->in_pos_o;
  o.fault_ferr = m_->fault_ferr_o;
  return o;
}

RtlBoard::RtlBoard() : ctx_(std::make_unique<VerilatedContext>()) {
  m_ = std::make_unique<Vsc_board_top>(ctx_.get(), "sc_board_top");
  m_->clk100_i = 0;
  m_->ck_rst_ni = 1;
  m_->uart_rx_i = 1;
  m_->eval();
}

RtlBoard::~RtlBoard() { m_->final(); }

void RtlBoard::tick100(bool uart_rx, bool rst_n, bool estop, bool enc_a, bool enc_b) {
  m_->uart_rx_i = uart_rx;
  m_->ck_rst_ni = rst_n;
  m_->estop_i = estop;
  m_->enc_a_i = enc_a;
  m_->enc_b_i = enc_b;
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
