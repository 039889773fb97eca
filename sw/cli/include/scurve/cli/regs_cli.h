// `scurve regs`: a planned move as the register write sequence of the
// AXI4-Lite register file, or as UART bridge frames (docs/regmap.md).
#pragma once

#include <string>
#include <variant>

#include <nlohmann/json.hpp>

#include <CLI/CLI.hpp>

#include "scurve/cli/move_flags.h"
#include "scurve/planner.h"

namespace scurve::cli {

struct RegsCliFlags {
  bool uart = false;      // print UART frames (hex) instead of address/data
  bool no_start = false;  // leave out the final CMD.START
  bool closed_loop = false;  // sc_axi_servo: controller settings + CTRL.CLOSED_LOOP
  bool guard = false;        // GUARD_VEL / GUARD_ACC / GUARD_JERK from the move's limits
  StopFlags stop;            // stop limits (always written) and --stop-at
  RetargetFlags retarget;    // --retarget-at, --retarget-distance
};

void add_regs_flags(CLI::App* cmd, RegsCliFlags& f);
// The writes for `plan` of `request` as the JSON array `scurve regs --json`
// prints ({addr, reg, data}, "frame" with --uart, "at_clock"/"at_s" on a
// CMD.STOP due at --stop-at and on the first write of a retarget due at
// --retarget-at, whose ROW_PUSH.REPLACE the host checks through
// ERR.RETARGET before the rest), or one line naming the flag.
std::variant<nlohmann::json, Error> regs_to_json(const RegsCliFlags& f, const MoveRequest& request, const Plan& plan,
                                                 const PulseTiming& timing);
// Prints the writes for `plan` of `request` (the plan's clock sets the
// controller's period, the request the default stop limits). With
// --stop-at the last write is CMD.STOP, marked with the time it is due.
// json_out: also write the writes as JSON to this file (empty: no file).
int run_regs_cli(const RegsCliFlags& f, const MoveRequest& request, const Plan& plan, const PulseTiming& timing,
                 bool json, const std::string& json_out = {});

}  // namespace scurve::cli
