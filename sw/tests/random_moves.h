// Seeded random move requests over the whole accepted range, at a clock rate.
#pragma once

#include <cmath>
#include <random>

#include "scurve/planner.h"

namespace scurve::test {

inline double log_uniform(std::mt19937_64& g, double lo, double hi) {
  std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
  return std::exp(u(g));
}

struct RandomRequest {
  MoveRequest req;
  PulseTiming timing;
};

inline RandomRequest random_request(std::mt19937_64& g, Clock clock) {
  RandomRequest rr;
  std::uniform_int_distribution<int> coin(0, 99);
  rr.timing.high = uint16_t(1 + g() % 200);
  rr.timing.low = uint16_t(1 + g() % 200);
  const double v_lim = step_rate_limit(rr.timing, clock);
  auto speed = [&](bool can_be_zero) {
    const int c = coin(g);
    if (can_be_zero && c < 30) return 0.0;
    if (c < 35) return v_lim;  // exactly at the step-rate limit
    return log_uniform(g, 1.0, v_lim);
  };
  MoveRequest& r = rr.req;
  r.distance = int64_t(std::llround(log_uniform(g, 1, 2e6)));
  if (coin(g) < 50) r.distance = -r.distance;
  r.v_start = speed(true);
  r.v_cruise = speed(false);
  r.v_end = coin(g) < 20 ? r.v_start : speed(true);
  r.a_max = log_uniform(g, 10, 1e7);
  r.j_max = log_uniform(g, 100, 1e10);
  r.kind = coin(g) < 15 ? ProfileKind::Trapezoid : ProfileKind::SCurve;
  if (coin(g) < 15) {
    r.jerks = std::array<double, 4>{log_uniform(g, 100, 1e10), log_uniform(g, 100, 1e10), log_uniform(g, 100, 1e10),
                                    log_uniform(g, 100, 1e10)};
  }
  r.adjust_end_speed = coin(g) < 10;
  return rr;
}

// The largest jerk the request allows (S-curve), 0 for a trapezoid.
inline double jerk_cap(const MoveRequest& r) {
  if (r.kind != ProfileKind::SCurve) return 0;
  if (!r.jerks) return r.j_max;
  const auto& j = *r.jerks;
  return std::max(std::max(j[0], j[1]), std::max(j[2], j[3]));
}

}  // namespace scurve::test
