// The board as the host sees it: register reads and writes and the passing
// of board time. The homing sequence and the board driver work on this
// interface; a UART link to a real or virtual board (scurve/board.h) and the
// simulation benches implement it.
#pragma once

#include <cstdint>
#include <optional>
#include <variant>

#include "scurve/planner.h"

namespace scurve {

class RegisterPort {
 public:
  virtual ~RegisterPort() = default;
  // An Error when the access failed: a bus error, no answer.
  virtual std::optional<Error> write(uint32_t addr, uint32_t data) = 0;
  virtual std::variant<uint32_t, Error> read(uint32_t addr) = 0;
  // Let `seconds` of board time pass (a real board: sleep; a simulation:
  // run the clocks).
  virtual void wait(double seconds) = 0;
};

}  // namespace scurve
