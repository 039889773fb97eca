// The host commands of `scurve`: plan (segment table), regs (register
// writes / UART frames) and board (a board driven over its UART). They
// need nothing but the host library; the full project's `scurve` registers
// them next to its simulation commands.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>

namespace scurve::cli {

class HostCommands {
 public:
  virtual ~HostCommands() = default;
  // Runs the selected host command; false if none of them was selected.
  virtual bool run(int* exit_code) const = 0;
};

// Adds `plan`, `regs` and `board` to app; call before app.parse().
std::unique_ptr<HostCommands> add_host_commands(CLI::App& app);

}  // namespace scurve::cli
