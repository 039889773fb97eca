// scurve (host build): plan S-curve moves and encode them for the board.
//   scurve plan --distance L --v-start VS --v-cruise VC --v-end VE --a-max A --j-max J [--clock-hz F] [--json]
//               [--start-pos P] [--soft-min P] [--soft-max P] [--axis NAME]
//   scurve regs (same move flags) [--uart] [--no-start] [--closed-loop] [--json]
// Exit codes: 0 ok, 2 bad input (one line on stderr).
#include <CLI/CLI.hpp>

#include "scurve/cli/host_commands.h"
#include "scurve/cli/move_flags.h"

int main(int argc, char** argv) {
  CLI::App app{"scurve: jerk-limited S-curve step generator - host planner and register encoding"};
  app.require_subcommand(1);
  auto host = scurve::cli::add_host_commands(app);
  if (const auto rc = scurve::cli::parse_command_line(app, argc, argv)) return *rc;
  int rc = 0;
  host->run(&rc);
  return rc;
}
