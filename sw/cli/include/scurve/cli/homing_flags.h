// The homing sequence's flags (scurve home in simulation, scurve board home
// on a board): one definition of each flag, its default and its range.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>

#include "scurve/homing.h"

namespace scurve::cli {

struct HomingFlags {
  int direction = -1;
  double seek_speed = 20000, latch_speed = 0, a_max = 1e6, j_max = 1e9;
  int64_t max_travel = 20000, max_backoff = 2000, offset = 0, max_index_travel = 0;
  double poll_period = 1e-3;
};

// --direction, --seek-speed, --latch-speed, --a-max, --j-max, --max-travel,
// --max-backoff, --offset, --max-index-travel, --poll-period.
void add_homing_flags(CLI::App* app, HomingFlags& f);
// The request; latch_speed 0 (not given) becomes `default_latch`, and
// max_index_travel the given value or `default_index_travel`. An Error for
// --direction 0; the rest is check_homing_request()'s.
std::variant<HomingRequest, Error> to_homing_request(const CLI::App* app, const HomingFlags& f, double default_latch,
                                                     int64_t default_index_travel = 0);

}  // namespace scurve::cli
