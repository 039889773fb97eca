// Checks of coordinated rows shared by the line and path tests: the
// executor's recurrence run clock by clock on every axis (written here, not
// the planner's closed forms) and the distance of the axes from a straight
// line at every clock.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "scurve/types.h"

namespace scurve::test {

// A straight line in the axes' positions (pulses): through `anchor` along
// `direction`. A point's offset from it is, per axis, its offset from where
// the lead's coordinate puts it on the line (a bound of the distance from
// the line, as plan_line reports it).
struct StraightLine {
  std::vector<long double> anchor, direction;
  size_t lead = 0;

  // The squared offset of positions given in LSB.
  long double offset2(const std::vector<i128>& pos) const {
    const long double one = (long double)kOne;
    const long double lead_off = (long double)pos[lead] / one - anchor[lead];
    long double sum = 0;
    for (size_t i = 0; i < pos.size(); ++i) {
      const long double e = ((long double)pos[i] / one - anchor[i]) - direction[i] / direction[lead] * lead_off;
      sum += e * e;
    }
    return sum;
  }
};

// The executor's registers of every axis (pos in LSB with its integer part).
struct AxesState {
  std::vector<i128> pos, vel;
  std::vector<int64_t> acc;
  explicit AxesState(std::vector<i128> start) : pos(std::move(start)), vel(pos.size(), 0), acc(pos.size(), 0) {}
};

// Runs rows [first, last) of every axis clock by clock from `state` and calls
// on_clock(state) at the start and after every clock.
template <class OnClock>
void run_rows_each_clock(const std::vector<const std::vector<Segment>*>& rows, size_t first, size_t last,
                         AxesState& state, OnClock&& on_clock) {
  const size_t n = rows.size();
  on_clock(state);
  for (size_t k = first; k < last; ++k) {
    for (uint64_t t = 0; t < (*rows[0])[k].clocks; ++t) {
      for (size_t i = 0; i < n; ++i) {
        state.pos[i] += state.vel[i];
        state.vel[i] += state.acc[i];
        state.acc[i] += (*rows[i])[k].jerk;
      }
      on_clock(state);
    }
  }
}

// Runs rows [first, last) of every axis (rows[i] is axis i's table; the
// same clocks row by row) clock by clock, pos += v; v += a; a += j, from
// `state`, and returns the largest offset from `line` at the start and
// after every clock (pulses).
inline double run_rows_per_clock(const std::vector<const std::vector<Segment>*>& rows, size_t first, size_t last,
                                 AxesState& state, const StraightLine& line) {
  long double worst = 0;
  run_rows_each_clock(rows, first, last, state,
                      [&](const AxesState& s) { worst = std::max(worst, line.offset2(s.pos)); });
  return double(std::sqrt(worst));
}

}  // namespace scurve::test
