#include "report.h"

#include <fmt/format.h>

#include <cmath>

namespace sc {

nlohmann::json stop_to_json(const StopReport& s) {
  if (!s.requested) return nullptr;
  return {{"cause", s.by_fault ? "fault" : "stop"},
          {"at_clock", s.by_fault ? nlohmann::json(nullptr) : nlohmann::json(s.at_clock)},
          {"taken", s.taken},
          {"v0", s.v0},
          {"a0", s.a0},
          {"clocks", s.clocks},
          {"distance", s.distance},
          {"closed_form_distance", s.closed_form_distance},
          {"overshoot", s.overshoot},
          {"end_position", s.end_position}};
}

std::string stop_line(const std::string& name, const StopReport& s) {
  if (!s.requested) return {};
  if (!s.taken) return fmt::format("  {}: stop at clock {} not taken (the move had not started)\n", name, s.at_clock);
  const std::string what = s.by_fault ? std::string("controlled stop on a fault") : fmt::format("stop at clock {}", s.at_clock);
  return fmt::format("  {}: {} from v {:.2f} p/s, a {:.2f} p/s^2: {} clocks, {:.3f} pulses (closed form "
                     "{:.3f}), at rest at {}{}\n",
                     name, what, s.v0, s.a0, s.clocks, s.distance, s.closed_form_distance, s.end_position,
                     s.overshoot ? ", OVERSHOOT" : "");
}

nlohmann::json sim_to_json(const SimResult& r) {
  nlohmann::json runs = nlohmann::json::array();
  for (const PhaseRun& pr : r.phase_runs) {
    runs.push_back({{"phase", phase_name(Phase(pr.phase))},
                    {"pulses", pr.pulses},
                    {"min_interval_clocks", pr.min_interval == UINT64_MAX ? 0 : pr.min_interval},
                    {"max_interval_clocks", pr.max_interval},
                    {"mean_duty", pr.mean_duty()}});
  }
  auto trends = [](const std::vector<DutyTrend>& v) {
    nlohmann::json a = nlohmann::json::array();
    for (DutyTrend t : v) a.push_back(trend_name(t));
    return a;
  };
  return {
      {"name", r.name},
      {"engine", engine_name(r.engine)},
      {"distance", r.distance},
      {"clocks", r.clocks},
      {"total_clocks", r.total_clocks},
      {"pulses", r.pulses},
      {"final_error", r.final_error},
      {"duration_s", r.duration_s},
      {"peak_velocity", r.peak_velocity},
      {"peak_acceleration", r.peak_acceleration},
      {"peak_jerk", r.peak_jerk},
      {"mismatches", r.mismatches},
      {"matched_clocks", r.matched_clocks},
      {"first_mismatch", r.first_mismatch},
      {"duty_phases", trends(r.trends)},
      {"expected_duty_phases", trends(r.expected_trends)},
      {"phase_runs", runs},
      {"wall_s", r.wall_s},
      {"clocks_per_s", r.clocks_per_s},
      {"realtime_ratio", r.clocks_per_s / ClkHz},
      {"stop", stop_to_json(r.stop)},
      {"retarget", r.retarget_requested ? nlohmann::json{{"row", r.retarget_row},
                                                          {"distance", r.retarget_distance},
                                                          {"taken", r.retarget_taken}}
                                        : nlohmann::json()},
      {"pass", r.pass()},
      {"failures", r.failures},
  };
}

std::string sim_table(const std::vector<SimResult>& rs) {
  std::string s = fmt::format("{:<10} {:<10} {:>11} {:>7} {:>9} {:>6} {:>9} {:>9} {:>9} {:>6} {:>7} {:>8} {:>6} {}\n",
                              "run", "engine", "clocks", "pulses", "time_s", "f.err", "peak_v", "peak_a",
                              "peak_j", "mism", "wall_s", "Mclk/s", "x_rt", "result");
  for (const SimResult& r : rs) {
    s += fmt::format("{:<10} {:<10} {:>11} {:>7} {:>9.4f} {:>6} {:>9.2f} {:>9.2f} {:>9.2f} {:>6} {:>7.2f} {:>8.2f} {:>6.2f} {}\n",
                     r.name, engine_name(r.engine), r.clocks, r.pulses, r.duration_s, r.final_error,
                     r.peak_velocity, r.peak_acceleration, r.peak_jerk, r.mismatches, r.wall_s,
                     r.clocks_per_s / 1e6, r.clocks_per_s / ClkHz, r.pass() ? "PASS" : "FAIL");
  }
  for (const SimResult& r : rs) s += stop_line(r.name, r.stop);
  for (const SimResult& r : rs) {
    if (r.retarget_requested) {
      s += fmt::format("  {}: retarget from row {} to distance {}: {}\n", r.name, r.retarget_row, r.retarget_distance,
                       r.retarget_taken ? "taken" : "refused (the row had loaded)");
    }
  }
  for (const SimResult& r : rs) {
    for (const std::string& f : r.failures) s += fmt::format("  {}: {}\n", r.name, f);
  }
  return s;
}

nlohmann::json stream_to_json(const StreamRunResult& r) {
  nlohmann::json closed = nullptr;
  if (r.closed_loop) {
    closed = {{"max_tracking_error", r.max_error},
              {"rmse", r.rmse},
              {"final_error", r.final_error},
              {"in_position", r.in_position}};
  }
  nlohmann::json moves = nlohmann::json::array();
  for (const StreamMoveReport& m : r.moves) {
    moves.push_back({{"index", m.index},
                     {"distance", m.distance},
                     {"v_in", m.v_in},
                     {"v_out", m.v_out},
                     {"planned_start_clock", m.planned_start},
                     {"planned_end_clock", m.planned_end},
                     {"end_clock", m.reached ? nlohmann::json(m.end_clock) : nlohmann::json(nullptr)},
                     {"end_position", m.reached ? nlohmann::json(m.end_position) : nlohmann::json(nullptr)},
                     {"expected_end_position", m.expected_end_position}});
  }
  return {
      {"engine", engine_name(r.engine)},
      {"closed_loop", closed},
      {"moves", moves},
      {"move_count", r.moves.size()},
      {"rows", r.rows},
      {"pulses", r.pulses},
      {"clocks", r.clocks},
      {"duration_s", r.duration_s},
      {"planned_duration_s", r.planned_s},
      {"stop_at_every_junction_s", std::isfinite(r.stop_each_s) ? nlohmann::json(r.stop_each_s) : nlohmann::json(nullptr)},
      {"mismatches", r.mismatches},
      {"matched_clocks", r.matched_clocks},
      {"first_mismatch", r.first_mismatch},
      {"wall_s", r.wall_s},
      {"clocks_per_s", r.clocks_per_s},
      {"realtime_ratio", r.clocks_per_s / ClkHz},
      {"pass", r.pass()},
      {"failures", r.failures},
  };
}

std::string stream_table(const StreamRunResult& r) {
  std::string s = fmt::format("{:>5} {:>9} {:>10} {:>10} {:>12} {:>12} {:>10} {:>10}\n", "move", "distance", "v_in",
                              "v_out", "start_clk", "end_clk", "end_pos", "planned");
  for (const StreamMoveReport& m : r.moves) {
    s += fmt::format("{:>5} {:>9} {:>10.2f} {:>10.2f} {:>12} {:>12} {:>10} {:>10}\n", m.index, m.distance, m.v_in,
                     m.v_out, m.planned_start, m.reached ? fmt::format("{}", m.end_clock) : "-",
                     m.reached ? fmt::format("{}", m.end_position) : "-", m.expected_end_position);
  }
  s += fmt::format(
      "{} moves, {} rows, {} pulses, {:.4f} s ({:.4f} s stopping at every junction), {} mismatches, engine {}, "
      "{:.2f} s wall, {:.2f} M clocks/s ({:.2f}x real time): {}\n",
      r.moves.size(), r.rows, r.pulses, r.duration_s, r.stop_each_s, r.mismatches, engine_name(r.engine), r.wall_s,
      r.clocks_per_s / 1e6, r.clocks_per_s / ClkHz, r.pass() ? "PASS" : "FAIL");
  if (r.closed_loop) {
    s += fmt::format("closed loop: max tracking error {:.3f} pulses, RMSE {:.4f}, final error {}, {}\n", r.max_error,
                     r.rmse, r.final_error, r.in_position ? "in position" : "NOT in position");
  }
  for (const std::string& f : r.failures) s += "  " + f + "\n";
  return s;
}

}  // namespace sc
