#include "scurve/cli/homing_flags.h"

#include "scurve/cli/move_flags.h"

namespace scurve::cli {

void add_homing_flags(CLI::App* c, HomingFlags& h) {
  int_flag(c, "--direction", h.direction, -1, 1, "where the home switch lies: -1 (default) or 1");
  real_flag(c, "--seek-speed", h.seek_speed, "seek speed toward the switch, pulses/s (default 20000)");
  real_flag(c, "--latch-speed", h.latch_speed,
            "back-off speed off the switch, pulses/s (default: half the speed that keeps the zero exact)");
  real_flag(c, "--a-max", h.a_max, "acceleration of the seek and back-off, pulses/s^2 (default 1e6)");
  real_flag(c, "--j-max", h.j_max, "jerk of the seek and back-off, pulses/s^3 (default 1e9)");
  int_flag(c, "--max-travel", h.max_travel, -(int64_t(1) << 62), int64_t(1) << 62,
           "pulses the seek may run (default 20000)");
  int_flag(c, "--max-backoff", h.max_backoff, -(int64_t(1) << 62), int64_t(1) << 62,
           "pulses the back-off may run (default 2000)");
  int_flag(c, "--offset", h.offset, -(int64_t(1) << 62), int64_t(1) << 62,
           "machine position of the zero point: the release, or the index (default 0)");
  int_flag(c, "--max-index-travel", h.max_index_travel, -(int64_t(1) << 62), int64_t(1) << 62,
           "home on the encoder index: pulses the axis may creep on past the release to find it (0: the zero is "
           "the release)");
  real_flag(c, "--poll-period", h.poll_period, "seconds between STATUS reads while a move runs (default 0.001)");
}

std::variant<HomingRequest, Error> to_homing_request(const CLI::App* app, const HomingFlags& h, double default_latch,
                                                     int64_t default_index_travel) {
  if (h.direction == 0) return Error{"direction", "--direction=0: needs -1 or 1"};
  HomingRequest r;
  r.direction = h.direction;
  r.seek_speed = h.seek_speed;
  r.latch_speed = h.latch_speed > 0 ? h.latch_speed : default_latch;
  r.a_max = h.a_max;
  r.j_max = h.j_max;
  r.max_travel = h.max_travel;
  r.max_backoff = h.max_backoff;
  r.offset = h.offset;
  r.max_index_travel = app->count("--max-index-travel") > 0 ? h.max_index_travel : default_index_travel;
  r.poll_period = h.poll_period;
  return r;
}

}  // namespace scurve::cli
