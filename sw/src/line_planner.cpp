#include "scurve/line_planner.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>

#include "solver.h"

namespace scurve {

namespace {

i128 abs128(i128 x) { return x < 0 ? -x : x; }

// round(x * num / den) for den > 0, num >= 0, halves away from zero.
i128 scale_round(i128 x, i128 num, i128 den) {
  const i128 m = (abs128(x) * num + den / 2) / den;
  return x < 0 ? -m : m;
}

// floor(x / c) for c > 0.
i128 floor_div(i128 x, i128 c) {
  const i128 q = x / c;
  return (x % c != 0 && x < 0) ? q - 1 : q;
}

std::optional<Error> check_positive(const char* name, double v) {
  if (std::isfinite(v) && v > 0) return std::nullopt;
  return Error{name, fmt::format("{}={}: needs a finite number > 0", name, v)};
}

// The request's path limits, lowered so that no axis passes its own.
struct LineLimits {
  double v = 0, a = 0, j = 0;
};

// travel: each axis's travel in pulses (magnitude), length: their Euclidean length.
std::variant<LineLimits, Error> path_limits(const LineRequest& r, const std::vector<double>& travel, double length) {
  LineLimits p{r.v_path, r.a_path, r.j_path};
  for (size_t i = 0; i < r.axis_limits.size(); ++i) {
    const AxisLimits& l = r.axis_limits[i];
    const double share = travel[i] / length;
    const auto lower = [&](double& path, double limit, const char* field) -> std::optional<Error> {
      if (!std::isfinite(limit) || limit < 0) {
        return Error{"axis_limits", fmt::format("axis_limits[{}].{}={}: needs a finite number >= 0 (0: none)", i,
                                                field, limit)};
      }
      if (limit > 0 && share > 0) path = std::min(path, limit / share);
      return std::nullopt;
    };
    if (auto e = lower(p.v, l.v_max, "v_max")) return *e;
    if (auto e = lower(p.a, l.a_max, "a_max")) return *e;
    if (auto e = lower(p.j, l.j_max, "j_max")) return *e;
  }
  return p;
}

}  // namespace

LineResult plan_line(const Planner& planner, const LineRequest& r, const PulseTiming& timing) {
  const size_t n = r.distances.size();
  if (n == 0 || n > LineRequest::kMaxAxes) {
    return Error{"distances", fmt::format("distances: {} axes, needs 1 to {}", n, LineRequest::kMaxAxes)};
  }
  for (size_t i = 0; i < n; ++i) {
    const int64_t d = r.distances[i];
    if (d > PlannerLimits::kMaxDistance || d < -PlannerLimits::kMaxDistance) {
      return Error{"distances", fmt::format("distances[{}]={}: needs |distance| <= {} pulses", i, d,
                                            PlannerLimits::kMaxDistance)};
    }
  }
  if (std::all_of(r.distances.begin(), r.distances.end(), [](int64_t d) { return d == 0; })) {
    return Error{"distances", "distances: all 0, needs one axis that moves"};
  }
  if (auto e = check_positive("v_path", r.v_path)) return *e;
  if (auto e = check_positive("a_path", r.a_path)) return *e;
  if (auto e = check_positive("j_path", r.j_path)) return *e;
  if (r.jerks) {
    static const char* kJerkNames[4] = {"Ts1", "Ts2", "Te1", "Te2"};
    for (size_t k = 0; k < 4; ++k) {
      const double j = (*r.jerks)[k];
      if (!(std::isfinite(j) && j > 0 && j <= r.j_path)) {
        return Error{"jerks", fmt::format("jerks[{}] ({})={}: needs a finite number > 0 and <= j_path={} pulses/s^3",
                                          k, kJerkNames[k], j, r.j_path)};
      }
    }
  }
  if (!r.axis_limits.empty() && r.axis_limits.size() != n) {
    return Error{"axis_limits", fmt::format("axis_limits: {} entries for {} axes, needs none or one per axis",
                                            r.axis_limits.size(), n)};
  }
  const bool carried = !r.start_fracs.empty();
  if (carried && r.start_fracs.size() != n) {
    return Error{"start_fracs", fmt::format("start_fracs: {} entries for {} axes, needs none or one per axis",
                                            r.start_fracs.size(), n)};
  }
  for (size_t i = 0; i < r.start_fracs.size(); ++i) {
    if (r.start_fracs[i] >= kOne) {
      return Error{"start_fracs", fmt::format("start_fracs[{}]={}: must be < 2^{} (one pulse)", i,
                                              to_hex_u128(r.start_fracs[i], 128), hw::FracBits)};
    }
  }

  const i128 one = i128(kOne);
  std::vector<i128> mag(n);
  for (size_t i = 0; i < n; ++i) mag[i] = abs128(r.distances[i]);
  // Magnitude form: each axis runs forward from p0[i]; a backward axis's
  // real fraction is 1 - p0, so its p0 lies in (0, 1] pulse.
  const auto dir_of = [&](size_t i) { return r.distances[i] < 0 ? -1 : 1; };
  std::vector<i128> p0(n, 0);
  // Each axis's travel (LSB, magnitude): on its own, the distance itself (the
  // start fraction absorbs the rest); from a given fraction, from there to
  // the middle of its target's pulse (a still axis stays where it is).
  std::vector<i128> travel(n);
  for (size_t i = 0; i < n; ++i) {
    if (!carried) {
      travel[i] = mag[i];
      continue;
    }
    const i128 f = i128(r.start_fracs[i]);
    p0[i] = dir_of(i) > 0 ? f : one - f;
    travel[i] = mag[i] == 0 ? 0 : mag[i] * one + one / 2 - p0[i];
  }
  size_t lead = 0;
  for (size_t i = 0; i < n; ++i) {
    if (travel[i] > travel[lead]) lead = i;
  }
  std::vector<double> travel_pulses(n);
  double length = 0;
  for (size_t i = 0; i < n; ++i) {
    travel_pulses[i] = carried ? double(travel[i]) / double(one) : double(mag[i]);
    length += travel_pulses[i] * travel_pulses[i];
  }
  length = std::sqrt(length);
  auto limits = path_limits(r, travel_pulses, length);
  if (const Error* e = std::get_if<Error>(&limits)) return *e;
  const LineLimits& path = std::get<LineLimits>(limits);

  // The lead axis: the path profile scaled to its share, in magnitude form.
  const double lead_share = travel_pulses[lead] / length;
  MoveRequest lead_req;
  lead_req.distance = int64_t(mag[lead]);
  lead_req.v_cruise = path.v * lead_share;
  lead_req.a_max = path.a * lead_share;
  lead_req.j_max = path.j * lead_share;
  if (r.jerks) {
    std::array<double, 4> lead_jerks{};
    for (size_t k = 0; k < 4; ++k) lead_jerks[k] = std::min((*r.jerks)[k], path.j) * lead_share;
    lead_req.jerks = lead_jerks;
  }
  PlanResult lead_plan = [&] {
    if (!carried) return planner.plan(lead_req, timing);
    // From its own fraction (signed: plan_from takes the executor's state).
    MoveRequest signed_req = lead_req;
    signed_req.distance = r.distances[lead];
    return planner.plan_from(JunctionState{0, r.start_fracs[lead]}, signed_req, timing);
  }();
  if (const Error* e = std::get_if<Error>(&lead_plan)) {
    const std::string field = e->parameter == "v_cruise" ? "v_path"
                              : e->parameter == "a_max"  ? "a_path"
                              : e->parameter == "j_max"  ? "j_path"
                              : e->parameter.rfind("jerk_", 0) == 0 ? "jerks"
                                                         : "distances";
    return Error{field, fmt::format("lead axis {} (distance {}, {:.6g} of the path): {}", lead,
                                    r.distances[lead], lead_share, e->message)};
  }
  const Plan& lp = std::get<Plan>(lead_plan);
  std::vector<Segment> lr = lp.segments;
  if (carried && dir_of(lead) < 0) {
    for (Segment& s : lr) {
      s.jerk = -s.jerk;
      s.acc0 = -s.acc0;
      s.vel0 = -s.vel0;
    }
  }

  // Each axis's share of the lead's profile: travel[i] / travel[lead], as an
  // integer ratio whose products with an acceleration (< 2^63) fit in 127
  // bits. A travel from a fraction has up to 111 bits; dropping its low bits
  // changes the share by less than 2^-60.
  int shift = 0;
  while ((travel[lead] >> shift) >= (i128(1) << 62)) ++shift;
  std::vector<i128> share_num(n);
  for (size_t i = 0; i < n; ++i) share_num[i] = travel[i] >> shift;
  const i128 share_den = std::max<i128>(1, travel[lead] >> shift);

  // Each axis's acceleration at the lead's row boundaries: the lead's,
  // scaled to the axis's share and rounded (the lead's own exactly).
  std::vector<int64_t> lead_acc(lr.size() + 1);
  lead_acc[0] = lr.empty() ? 0 : lr[0].acc0;
  for (size_t k = 0; k < lr.size(); ++k) lead_acc[k + 1] = int64_t(acc_after(lr[k].acc0, lr[k].jerk, lr[k].clocks));

  // Within lead row k an axis runs jerk q + 1 for its first `head` and from
  // its clock `tail` on, q between: exactly its next boundary's
  // acceleration. Half the steeper clocks at each end keep the velocity the
  // row gains within about one LSB per clock of its share (all of them
  // first would lead it by up to c^2/8). `bias` raises the boundaries where
  // the lead brakes (magnitude form) by that many LSB.
  struct RowSplit {
    i128 q = 0, head = 0, tail = 0;
  };
  const auto split = [&](size_t i, size_t k, i128 bias) {
    const uint64_t c = lr[k].clocks;
    const auto target = [&](size_t b) {
      return scale_round(lead_acc[b], share_num[i], share_den) + (lead_acc[b] < 0 ? bias : 0);
    };
    const i128 d = target(k + 1) - target(k);
    RowSplit r;
    r.q = floor_div(d, i128(c));
    const i128 rem = d - r.q * i128(c);
    r.head = rem / 2;
    r.tail = i128(c) - (rem - rem / 2);
    return r;
  };
  // The axis's velocity at the end of the lead's rows.
  const auto end_velocity = [&](size_t i, i128 bias) {
    i128 v = 0;
    int64_t a = 0;
    for (size_t k = 0; k < lr.size(); ++k) {
      const RowSplit r = split(i, k, bias);
      const uint64_t c = lr[k].clocks;
      const std::pair<uint64_t, i128> parts[3] = {{uint64_t(r.head), r.q + 1},
                                                  {uint64_t(r.tail - r.head), r.q},
                                                  {c - uint64_t(r.tail), r.q + 1}};
      for (const auto& [n_clk, j] : parts) {
        v = vel_after(v, a, int64_t(j), n_clk);
        a = int64_t(acc_after(a, int64_t(j), n_clk));
      }
    }
    return v;
  };
  // The velocity a braking axis still has at the end must not be below 0
  // (it would creep back): the smallest bias that ends it at or above 0,
  // so that the trim below brakes it to rest without reversing. Each LSB of
  // bias adds at least half the braking rows' clocks.
  std::vector<i128> bias(n, 0);
  uint64_t braking_clocks = 0;
  for (size_t k = 0; k < lr.size(); ++k) {
    if (lead_acc[k] < 0 || lead_acc[k + 1] < 0) braking_clocks += lr[k].clocks;
  }
  for (size_t i = 0; i < n; ++i) {
    for (int it = 0; it < 64 && mag[i] != 0; ++it) {
      const i128 v = end_velocity(i, bias[i]);
      if (v >= 0) break;
      bias[i] += std::max<i128>(1, (-v * 2 + i128(braking_clocks) - 1) / std::max<uint64_t>(1, braking_clocks));
    }
  }

  // The shared rows: each lead row cut wherever an axis's jerk changes.
  std::vector<uint64_t> clocks;
  std::vector<std::vector<int64_t>> jerks;  // [row][axis]
  std::vector<Phase> phases;
  for (size_t k = 0; k < lr.size(); ++k) {
    const uint64_t c = lr[k].clocks;
    std::vector<RowSplit> rs(n);
    std::vector<uint64_t> cuts{0, c};
    for (size_t i = 0; i < n; ++i) {
      rs[i] = split(i, k, bias[i]);
      cuts.push_back(uint64_t(rs[i].head));
      cuts.push_back(uint64_t(rs[i].tail));
    }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    for (size_t p = 0; p + 1 < cuts.size(); ++p) {
      std::vector<int64_t> j(n);
      for (size_t i = 0; i < n; ++i) {
        const i128 at = cuts[p];
        j[i] = int64_t(at < rs[i].head || at >= rs[i].tail ? rs[i].q + 1 : rs[i].q);
      }
      jerks.push_back(std::move(j));
      clocks.push_back(cuts[p + 1] - cuts[p]);
      phases.push_back(lr[k].phase);
    }
  }

  // Chain every axis; the velocity left at the end (the rounding's, and
  // the lead's own: plan() ends a move within less than one clock of peak
  // acceleration of rest), removed by each axis in turn after the last row,
  // in jerk-limited pulses within its own peak jerk and acceleration.
  for (size_t i = 0; i < n; ++i) {
    if (mag[i] == 0) continue;
    // One pass over the axis's rows: its velocity now and its peaks.
    i128 v_left = 0;
    int64_t a = 0, peak_jerk = 1, peak_acc = 1;
    for (size_t k = 0; k < clocks.size(); ++k) {
      peak_jerk = std::max<int64_t>(peak_jerk, int64_t(abs128(jerks[k][i])));
      peak_acc = std::max<int64_t>(peak_acc, int64_t(abs128(a)));
      v_left = vel_after(v_left, a, jerks[k][i], clocks[k]);
      a = int64_t(acc_after(a, jerks[k][i], clocks[k]));
    }
    if (v_left == 0) continue;
    detail::RowList trim;
    detail::append_exact_tail(trim, abs128(v_left), v_left < 0 ? 1 : -1, peak_jerk, peak_acc, Phase::PhDecJerkUp,
                              Phase::PhDecJerkDown);
    for (const detail::Row& t : trim) {
      std::vector<int64_t> j(n, 0);
      j[i] = t.jerk;
      jerks.push_back(std::move(j));
      clocks.push_back(t.clocks);
      phases.push_back(t.phase);
    }
  }

  LinePlan out;
  out.lead = lead;
  out.path_length = length;
  for (const uint64_t c : clocks) {
    if (c > UINT32_MAX) {
      return Error{"distances", fmt::format("distances: a row of {} clocks, more than a row holds ({}); split the "
                                            "line", c, UINT32_MAX)};
    }
    out.total_clocks += c;
  }
  out.duration_s = double(out.total_clocks) / lp.clock.hz;
  // Per axis: rows in magnitude form, the start fraction that ends it in the
  // middle of its target's pulse (as plan() ends the lead), then mirrored.
  std::vector<std::vector<Segment>> mag_rows(n);
  std::vector<u128> frac(n);
  for (size_t i = 0; i < n; ++i) {
    i128 v = 0, gain = 0;
    int64_t a = 0;
    for (size_t k = 0; k < clocks.size(); ++k) {
      Segment s;
      s.phase = phases[k];
      s.clocks = uint32_t(clocks[k]);
      s.jerk = jerks[k][i];
      s.acc0 = a;
      s.vel0 = v;
      gain += pos_gain(v, a, s.jerk, s.clocks);
      v = vel_after(v, a, s.jerk, s.clocks);
      a = int64_t(acc_after(a, s.jerk, s.clocks));
      mag_rows[i].push_back(s);
    }
    // Mid-pulse, unless that would start it outside its first pulse (a
    // lead that starts near a whole pulse): then from the nearest fraction.
    // Mirrored, the start is 1 - p0, so a move backward needs p0 in (0, 1]
    // and its end in (distance, distance + 1].
    // From a given fraction the start is fixed; the share aimed its end.
    const int dir = dir_of(i);
    const i128 lo = dir > 0 ? 0 : 1;
    const i128 start = carried ? p0[i] : std::clamp<i128>(mag[i] * one + one / 2 - gain, lo, lo + one - 1);
    const i128 end = start + gain;
    if (v != 0 || a != 0 || end < mag[i] * one + lo || end >= (mag[i] + 1) * one + lo) {
      return Error{"distances", fmt::format("distances[{}]={}: the scaled rows travel {} pulses, not within its "
                                            "target's pulse; split the line",
                                            i, r.distances[i], double(gain) / double(one))};
    }
    frac[i] = u128(start);
    Plan p;
    p.clock = lp.clock;
    p.distance = r.distances[i];
    p.pos_frac0 = dir > 0 ? u128(start) : kOne - u128(start);
    for (const Segment& m : mag_rows[i]) {
      Segment s = m;
      s.jerk *= dir;
      s.acc0 *= dir;
      s.vel0 *= dir;
      p.segments.push_back(s);
    }
    p.total_clocks = out.total_clocks;
    p.duration_s = out.duration_s;
    const TableReport rep = run_table(p.segments, p.pos_frac0, dir);
    if (!rep.ok || rep.steps != r.distances[i] || rep.min_signed_vel < 0) {
      return Error{"distances", fmt::format("distances[{}]={}: the scaled rows emit {} steps{} ({})", i,
                                            r.distances[i], rep.steps,
                                            rep.min_signed_vel < 0 ? " and reverse" : "", rep.error)};
    }
    p.peak_velocity = vel_to_phys(rep.peak_vel, p.clock);
    p.peak_acceleration = acc_to_phys(rep.peak_acc, p.clock);
    p.peak_jerk = jerk_to_phys(rep.peak_jerk, p.clock);
    p.v_end_used = 0;
    p.end_state = JunctionState{0, u128(((rep.end_pos % one) + one) % one)};
    out.axes.push_back(std::move(p));
  }

  // Distance from the line: on its own, the line runs through the point at
  // half a pulse on every axis in the direction of the distances (where
  // each axis's start fraction puts it); from given fractions, through the
  // start point in the direction of the travels. Each axis's offset from
  // where the lead's progress puts it on the line.
  std::vector<i128> pos(n), anchor(n, one / 2);
  for (size_t i = 0; i < n; ++i) {
    pos[i] = i128(frac[i]);
    if (carried) anchor[i] = pos[i];
  }
  const auto deviation = [&](const std::vector<i128>& at) {
    const long double lead_off = (long double)(at[lead] - anchor[lead]) / (long double)one;
    long double sum = 0;
    for (size_t i = 0; i < n; ++i) {
      const long double share = (long double)travel[i] / (long double)travel[lead];
      const long double e = (long double)(at[i] - anchor[i]) / (long double)one - share * lead_off;
      sum += e * e;
    }
    return double(std::sqrt(sum));
  };
  for (size_t k = 0; k < clocks.size(); ++k) {
    const uint64_t c = clocks[k];
    std::vector<i128> at(n);
    for (uint64_t step = 0; step <= 16; ++step) {
      const uint64_t t = c * step / 16;
      for (size_t i = 0; i < n; ++i) {
        const Segment& s = mag_rows[i][k];
        at[i] = pos[i] + pos_gain(s.vel0, s.acc0, s.jerk, t);
      }
      out.max_line_deviation = std::max(out.max_line_deviation, deviation(at));
    }
    for (size_t i = 0; i < n; ++i) pos[i] = at[i];
  }
  return out;
}

}  // namespace scurve
