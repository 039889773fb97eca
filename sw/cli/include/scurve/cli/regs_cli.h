// `scurve regs`: a planned move as the register write sequence of the
// AXI4-Lite register file, or as UART bridge frames (docs/regmap.md).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "scurve/cli/move_flags.h"
#include "scurve/planner.h"

namespace scurve::cli {

struct RegsCliFlags {
  bool uart = false;      // print UART frames (hex) instead of address/data
  bool no_start = false;  // leave out the final CMD.START
  bool closed_loop = false;  // sc_axi_servo: controller settings + CTRL.CLOSED_LOOP
  StopFlags stop;            // stop limits (always written) and --stop-at
};

void add_regs_flags(CLI::App* cmd, RegsCliFlags& f);
// Prints the writes for `plan` of `request` (the plan's clock sets the
// controller's period, the request the default stop limits). With
// --stop-at the last write is CMD.STOP, marked with the time it is due.
// json_out: also write the writes as JSON to this file (empty: no file).
int run_regs_cli(const RegsCliFlags& f, const MoveRequest& request, const Plan& plan, const PulseTiming& timing,
                 bool json, const std::string& json_out = {});

}  // namespace scurve::cli
