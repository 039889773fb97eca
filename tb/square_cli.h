// `scurve square`: paper 003's X-Y table case as a named scenario: the
// quadrilateral from (0, 0) through (12, 80), (72, 80), (72, 140),
// (12, 140) mm with exact stops, every axis closed-loop on the stepper
// plant, the Y axis's step rate saturating; S-curve against trapezoid, and
// the neuron-PI cascade against paper 003's fixed-gain PID without and with
// back-calculation anti-windup. Reports the paper's Table 2 indices
// (overshoot), the steady-state and tracking errors beside the paper's,
// and checks every run (lockstep, exact targets, pins, in position).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "scurve/cli/move_flags.h"

namespace sc {

struct SquareCli {
  CLI::App* cmd = nullptr;
  std::string engine = "lockstep";  // lockstep | model
  std::string profile = "both";     // s-curve | trapezoid | both
  std::string controllers = "all";  // all | pid (the two PID runs only)
  scurve::cli::MoveFlags output;    // --json, --json-out
};

void add_square_command(CLI::App& app, SquareCli& c);
// Exit 0: every check held; 1: a check failed; 2: bad input.
int run_square_cli(const SquareCli& c);

}  // namespace sc
