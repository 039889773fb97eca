#include "scurve/cli/plan_report.h"

#include <fmt/format.h>

#include <cmath>

namespace scurve::cli {

nlohmann::json clock_to_json(Clock c) {
  if (c.hz == std::floor(c.hz) && std::fabs(c.hz) < 9e15) return int64_t(c.hz);
  return c.hz;
}

nlohmann::json plan_to_json(const Plan& p) {
  const Clock c = p.clock;
  nlohmann::json segs = nlohmann::json::array();
  uint64_t t = 0;
  for (const Segment& s : p.segments) {
    segs.push_back({
        {"phase", phase_name(s.phase)},
        {"phase_code", int(s.phase)},
        {"start_clock", t},
        {"clocks", s.clocks},
        {"duration_s", double(s.clocks) / c.hz},
        {"jerk", jerk_to_phys(s.jerk, c)},
        {"acc0", acc_to_phys(s.acc0, c)},
        {"vel0", vel_to_phys(s.vel0, c)},
        {"jerk_lsb", to_string_i128(s.jerk)},
        {"acc0_lsb", to_string_i128(s.acc0)},
        {"vel0_lsb", to_string_i128(s.vel0)},
    });
    t += s.clocks;
  }
  return {
      {"pulses", p.distance},
      {"duration_s", p.duration_s},
      {"clocks", p.total_clocks},
      {"peak_velocity", p.peak_velocity},
      {"peak_acceleration", p.peak_acceleration},
      {"peak_jerk", p.peak_jerk},
      {"v_plateau", p.v_plateau},
      {"v_end_actual", p.v_end_actual},
      {"end_speed_adjusted", p.end_speed_adjusted},
      {"v_end_used", p.v_end_used},
      {"pos_frac0", to_hex_u128(p.pos_frac0, hw::FracBits)},
      {"lsb", {{"frac_bits", hw::FracBits}, {"clock_hz", clock_to_json(c)}}},
      {"segments", segs},
  };
}

std::string plan_to_table(const Plan& p) {
  const Clock c = p.clock;
  std::string s = fmt::format("{:>3} {:<14} {:>12} {:>11} {:>14} {:>14} {:>12}\n", "#", "phase", "clocks",
                              "time_s", "jerk_p/s3", "acc0_p/s2", "vel0_p/s");
  int i = 0;
  for (const Segment& g : p.segments) {
    s += fmt::format("{:>3} {:<14} {:>12} {:>11.6f} {:>14.3f} {:>14.3f} {:>12.4f}\n", i++, phase_name(g.phase),
                     g.clocks, double(g.clocks) / c.hz, jerk_to_phys(g.jerk, c), acc_to_phys(g.acc0, c),
                     vel_to_phys(g.vel0, c));
  }
  s += fmt::format("pulses {}  duration {:.6f} s ({} clocks)  peak v {:.4f} p/s  a {:.4f} p/s^2  j {:.4f} p/s^3\n",
                   p.distance, p.duration_s, p.total_clocks, p.peak_velocity, p.peak_acceleration, p.peak_jerk);
  if (p.end_speed_adjusted) s += fmt::format("note: end speed adjusted to {:.4f} p/s\n", p.v_end_used);
  return s;
}

namespace {

bool has_window(const MoveRequest& r) { return r.soft_limits || r.start_position != 0; }

}  // namespace

nlohmann::json plan_to_json(const Plan& p, const MoveRequest& request) {
  nlohmann::json j = plan_to_json(p);
  if (!has_window(request)) return j;
  j["start_position"] = request.start_position;
  j["target_position"] = request.start_position + p.distance;
  if (const auto& w = request.soft_limits) {
    const auto bound = [](const std::optional<int64_t>& b) { return b ? nlohmann::json(*b) : nlohmann::json(nullptr); };
    j["soft_limits"] = {{"axis", w->axis}, {"min", bound(w->min_pos)}, {"max", bound(w->max_pos)}};
  }
  return j;
}

std::string plan_to_table(const Plan& p, const MoveRequest& request) {
  std::string s = plan_to_table(p);
  if (!has_window(request)) return s;
  s += fmt::format("start position {}  target {}", request.start_position, request.start_position + p.distance);
  if (const auto& w = request.soft_limits) {
    const auto bound = [](const std::optional<int64_t>& b) { return b ? std::to_string(*b) : std::string("none"); };
    s += fmt::format("  axis {} soft limits min {} max {}", w->axis, bound(w->min_pos), bound(w->max_pos));
  }
  return s + " (pulses)\n";
}

}  // namespace scurve::cli
