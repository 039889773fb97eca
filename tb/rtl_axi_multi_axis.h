// Adapter to the Verilated sc_axi_multi_axis (2 closed-loop capable axes,
// Servo = 1): the model's types in, per-axis slices of the packed ports out.
#pragma once

#include <array>
#include <memory>

#include "axi_multi_axis.h"

class Vsc_axi_multi_axis2;

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

}  // namespace sc
