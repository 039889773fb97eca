// Thin adapter between the Verilated sc_row_reach and the model's types
// (RowReach::Inputs in, the four outputs back). Knows nothing of the checks.
#pragma once

#include <memory>

#include "row_reach.h"

class Vsc_row_reach;

namespace sc {

template <class V>
class VerilatedTop;

struct ReachOutputs {
  bool busy = false;
  bool done = false;
  int64_t fwd = 0;  // ReachW bits, sign-extended
  int64_t rev = 0;
  bool operator==(const ReachOutputs&) const = default;
};

// The model's outputs in the same shape.
inline ReachOutputs outputs_of(const RowReach& m) { return {m.busy(), m.done(), m.reach_fwd(), m.reach_rev()}; }

class RtlRowReach {
 public:
  RtlRowReach();
  ~RtlRowReach();
  RtlRowReach(const RtlRowReach&) = delete;
  RtlRowReach& operator=(const RtlRowReach&) = delete;

  void reset(int cycles = 2);
  // Outputs of the current clock (before its edge).
  ReachOutputs outputs() const;
  // Drive the inputs, then one clock edge.
  void step(const RowReach::Inputs& in);

 private:
  std::unique_ptr<VerilatedTop<Vsc_row_reach>> top_;
};

}  // namespace sc
