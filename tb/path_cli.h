// `scurve path FILE`: a path file (JSON points or the G-code subset,
// sw/cli/include/scurve/cli/path_file.h) planned with exact stops or blended
// junctions at its corners (scurve::plan_path) and run on the multi-axis core
// (sc_multi_axis_core; with --closed-loop every axis in its own loop on the
// plant model) in RTL/model lockstep or on the model alone; a
// table or JSON of every move and the whole path; with --plot DIR a decimated
// trace (CSV) and its figures (scripts/plot_path.py, matplotlib).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "scenario_json.h"
#include <vector>

#include "scurve/cli/move_flags.h"

namespace sc {

struct PathCli {
  CLI::App* cmd = nullptr;
  std::string file;
  scurve::cli::MoveFlags timing;  // pulse timing, --json, --json-out
  size_t axes = 0;                // 0: the file's (JSON) or 2 (G-code)
  std::vector<std::string> pulses_per_mm;
  double feed_limit = 0, accel = 0, jerk = 0;  // 0: the file's or the G-code defaults
  std::string junction = "exact-stop";
  std::string tolerance;  // --tolerance: blend corner tolerance, mm (validated with the other values)
  std::string engine = "lockstep";
  bool closed_loop = false;  // every axis in its own loop (the Servo = 1 core) on the plant model
  ControllerInput ctl{};     // --controller and its settings (with --closed-loop)
  std::string plot_dir;  // --plot: trace CSV and PNG figures here (empty: none)
};

void add_path_command(CLI::App& app, PathCli& p);
// Exit 0: every check held; 1: a check failed; 2: bad input.
int run_path_cli(const PathCli& p);

}  // namespace sc
