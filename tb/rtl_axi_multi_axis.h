// Adapter to the Verilated sc_axi_multi_axis (2 closed-loop capable axes,
// Servo = 1): the model's types in, per-axis slices of the packed ports out.
#pragma once

#include <array>
#include <memory>

#include "axi_multi_axis.h"

class Vsc_axi_multi_axis2;
class Vsc_board_xy_top;
class VerilatedContext;

namespace sc {

template <class V>
class VerilatedTop;

class RtlAxiMultiAxis {
 public:
  static constexpr size_t kAxes = 2;
  static constexpr bool kServo = true;
  RtlAxiMultiAxis();
  ~RtlAxiMultiAxis();
  RtlAxiMultiAxis(const RtlAxiMultiAxis&) = delete;
  RtlAxiMultiAxis& operator=(const RtlAxiMultiAxis&) = delete;
  void reset(int cycles = 4);
  void step(const AxiIn& in, bool estop, const std::array<MultiAxisPins, MaxAxes>& pins);
  AxiMultiAxisOutputs outputs() const;

 private:
  std::unique_ptr<VerilatedTop<Vsc_axi_multi_axis2>> top_;
};

// The two-axis board top (sc_board_xy_top), Verilated with a fast UART
// (kClksPerBit system clocks per bit): 100 MHz pin clock (the clock
// stand-in divides it by 5), UART pins, both axes' Pmod pins, LEDs.
class RtlBoardXY {
 public:
  static constexpr size_t kAxes = 2;
  static constexpr int kClksPerBit = 16;
  struct Pins {
    bool uart_tx = true;
    std::array<bool, kAxes> step{}, dir{}, en{};
    bool irq = false;
    uint8_t led = 0;
  };
  RtlBoardXY();
  ~RtlBoardXY();
  RtlBoardXY(const RtlBoardXY&) = delete;
  RtlBoardXY& operator=(const RtlBoardXY&) = delete;
  // One 100 MHz period with these input levels; sw: X limit -, +, home in
  // bits 0-2, Y's in bits 3-5; encoder pins: bit a for axis a.
  void tick100(bool uart_rx, bool estop = false, uint8_t sw = 0, bool probe = false, uint8_t enc_a = 0,
               uint8_t enc_b = 0, uint8_t enc_z = 0, bool rst_n = true);
  Pins pins() const;
  uint64_t clocks100() const { return clk100_; }

 private:
  std::unique_ptr<VerilatedContext> ctx_;
  std::unique_ptr<Vsc_board_xy_top> m_;
  uint64_t clk100_ = 0;
};

}  // namespace sc
