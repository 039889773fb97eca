// `scurve corner`: paper 002's cornering case as a named scenario (two
// 0.1 m lines at 45 and 135 degrees joined by an exact stop, feed 0.1 m/s,
// A = 1 m/s^2, J = 10 m/s^3): the search for the asymmetric jerks
// (scurve::search_corner), the symmetric and the searched shapes scored on
// the servo model beside the paper's figures, and both shapes run on the
// multi-axis core (RTL and model in lockstep, or the model) with every axis
// checked on its exact integer target at the corner and at the end.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

#include "scurve/cli/move_flags.h"

namespace sc {

struct CornerCli {
  CLI::App* cmd = nullptr;
  uint64_t seed = 1;
  int budget = 2000;
  std::string engine = "lockstep";      // lockstep | model | none (the search and its scores only)
  scurve::cli::MoveFlags output;        // --json, --json-out
};

void add_corner_command(CLI::App& app, CornerCli& c);
// Exit 0: every check held; 1: a check failed; 2: bad input.
int run_corner_cli(const CornerCli& c);

}  // namespace sc
