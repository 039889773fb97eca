// `scurve board --port DEV info|status|run|stream|stop|estop|clear|home|watch`:
// a board (or the virtual board's pseudo-terminal) driven over its UART.
// Exit codes: 0 ok, 1 the board reported a refusal or a fault (or a check
// of what it did failed), 2 bad input, no board, a broken line.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>

namespace scurve::cli {

class BoardCommand {
 public:
  virtual ~BoardCommand() = default;
  // Runs `board` if it was selected; false otherwise.
  virtual bool run(int* exit_code) const = 0;
};

std::unique_ptr<BoardCommand> add_board_command(CLI::App& app);

}  // namespace scurve::cli
