// `scurve home`: the host library's homing sequence in simulation against a
// home switch in the plant (tb/homing_run.h), one run or many with random
// switch positions and bounce; a table or JSON of the zeros and their spread.
#pragma once

#include <CLI/CLI.hpp>

#include "scurve/cli/homing_flags.h"
#include "scurve/cli/move_flags.h"

namespace sc {

struct HomingCli {
  CLI::App* cmd = nullptr;
  scurve::cli::MoveFlags timing;  // pulse timing, --json, --json-out
  scurve::cli::HomingFlags seq;   // the sequence's flags, shared with scurve board home
  int64_t switch_at = 1500;       // on the direction's side unless --switch-at is given
  double stop_jerk = 0, stop_acc = 0;
  int64_t index_period = 0, index_at = 0;
  uint32_t debounce = 2000, bounce = 0, noise_clocks = 10;
  double noise_rate = 0;
  int runs = 1;
  uint64_t seed = 1;
  std::string engine = "lockstep";
};

void add_homing_command(CLI::App& app, HomingCli& h);
// Exit 0: every run homed with the pins on REF_POS and, without bounce and
// noise, the zero on the switch's release point; 1: a run failed; 2: bad input.
int run_homing_cli(const HomingCli& h);

}  // namespace sc
