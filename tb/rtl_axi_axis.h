// Thin adapters to the Verilated sc_axi_axis and sc_board_top.
#pragma once

#include <cstdint>
#include <memory>

#include "axi_regs.h"

class VerilatedContext;
class Vsc_axi_axis;
class Vsc_axi_servo;
class Vsc_board_top;

namespace sc {

template <class V>
class VerilatedTop;

class RtlAxiAxis {
 public:
  RtlAxiAxis();
  ~RtlAxiAxis();
  RtlAxiAxis(const RtlAxiAxis&) = delete;
  RtlAxiAxis& operator=(const RtlAxiAxis&) = delete;
  void reset(int cycles = 4);
  void step(const AxiIn& in, const RegsSide& side);
  AxiAxisOutputs outputs() const;

 private:
  std::unique_ptr<VerilatedTop<Vsc_axi_axis>> top_;
};

// Verilated sc_axi_servo; side.enc_ab drives enc_a_i (bit 0) / enc_b_i (bit 1),
// side.enc_z the index enc_z_i.
class RtlAxiServo {
 public:
  RtlAxiServo();
  ~RtlAxiServo();
  RtlAxiServo(const RtlAxiServo&) = delete;
  RtlAxiServo& operator=(const RtlAxiServo&) = delete;
  void reset(int cycles = 4);
  void step(const AxiIn& in, const RegsSide& side);
  AxiServoOutputs outputs() const;

 private:
  std::unique_ptr<VerilatedTop<Vsc_axi_servo>> top_;
};

// The whole board: 100 MHz pin clock (the simulation stand-in of the MMCM
// divides it by 5), UART pins, Pmod pins, LEDs.
class RtlBoard {
 public:
  struct Pins {
    bool uart_tx = true, step = false, dir = false, en = false;
    uint8_t led = 0;
  };
  RtlBoard();
  ~RtlBoard();
  RtlBoard(const RtlBoard&) = delete;
  RtlBoard& operator=(const RtlBoard&) = delete;
  // One 100 MHz period (rising + falling edge) with these input levels.
  void tick100(bool uart_rx, bool rst_n = true, bool estop = false, bool enc_a = false, bool enc_b = false,
               uint8_t sw = 0,   // sw: the switch pins (bit 0 limit -, 1 limit +, 2 home, 3 probe)
               bool enc_z = false);
  Pins pins() const;
  uint64_t clocks100() const { return clk100_; }

 private:
  std::unique_ptr<VerilatedContext> ctx_;
  std::unique_ptr<Vsc_board_top> m_;
  uint64_t clk100_ = 0;
};

}  // namespace sc
