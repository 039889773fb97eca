// `scurve jog`: velocity mode in simulation. A program of target velocities
// (--target V[:T], each held T seconds) run on the open-loop core
// (tb/jog_run.h); a table or JSON of each command and the checks.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "scurve/cli/move_flags.h"

namespace sc {

struct JogCli {
  CLI::App* cmd = nullptr;
  scurve::cli::MoveFlags timing;  // pulse timing, --json, --json-out
  std::vector<std::string> targets{"2000:0.05", "-1000:0.05", "0"};
  double a_max = 20000, j_max = 400000;
  double stop_jerk = 0, stop_acc = 0;
  bool stop = false;
  uint64_t push_gap = 0;
  std::string engine = "lockstep";
};

void add_jog_command(CLI::App& app, JogCli& j);
// Exit 0: every check held; 1: a check failed; 2: bad input.
int run_jog_cli(const JogCli& j);

}  // namespace sc
