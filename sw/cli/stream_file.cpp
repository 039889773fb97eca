#include "scurve/cli/stream_file.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "scurve/cli/user_input.h"

namespace scurve::cli {

StreamRequest parse_stream_json(const std::string& text) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const std::exception& e) {
    throw input::Error("stream", "file", "not JSON: " + std::string(e.what()));
  }
  using namespace input;
  // Bounds kAnyReal: the planner checks the ranges and names them.
  StreamRequest r;
  json_object("stream", j);
  json_known_keys("stream", j, {"_comment", "limits", "moves", "soft_limits", "start_position"});
  if (!j.contains("limits")) throw input::Error("limits", "missing", "needs {\"a_max\", \"j_max\", \"v_max\"}");
  if (!j.contains("moves")) throw input::Error("moves", "missing", "needs an array of moves");
  const nlohmann::json& l = json_object("limits", j["limits"]);
  json_known_keys("limits", l, {"a_max", "j_max", "v_max"});
  for (const char* k : {"a_max", "j_max", "v_max"}) {
    if (!l.contains(k)) throw input::Error(std::string("limits.") + k, "missing", "required");
  }
  r.limits.a_max = json_real("limits.a_max", l["a_max"], 0, kAnyReal);
  r.limits.j_max = json_real("limits.j_max", l["j_max"], 0, kAnyReal);
  r.limits.v_max = json_real("limits.v_max", l["v_max"], 0, kAnyReal);
  constexpr int64_t kPos = scurve::PlannerLimits::kMaxPosition;
  if (j.contains("start_position")) {
    r.limits.start_position = json_int("start_position", j["start_position"], -kPos, kPos);
  }
  if (j.contains("soft_limits")) {
    const nlohmann::json& w = json_object("soft_limits", j["soft_limits"]);
    json_known_keys("soft_limits", w, {"min", "max", "axis"});
    if (!w.contains("min") && !w.contains("max")) {
      throw input::Error("soft_limits", shown(w), "needs \"min\" and/or \"max\"");
    }
    scurve::SoftLimits sl;
    if (w.contains("min")) sl.min_pos = json_int("soft_limits.min", w["min"], -kPos, kPos);
    if (w.contains("max")) sl.max_pos = json_int("soft_limits.max", w["max"], -kPos, kPos);
    if (w.contains("axis")) {
      sl.axis = parse_name("soft_limits.axis", json_string("soft_limits.axis", w["axis"]),
                           scurve::SoftLimits::kMaxAxisName);
    }
    if (sl.min_pos && sl.max_pos && *sl.min_pos > *sl.max_pos) {
      throw input::Error("soft_limits.min", std::to_string(*sl.min_pos),
                  fmt::format("must be <= soft_limits.max={}", *sl.max_pos));
    }
    r.limits.soft_limits = sl;
  }
  const nlohmann::json& ms = json_array("moves", j["moves"]);
  if (ms.empty()) throw input::Error("moves", "[]", "needs at least one move");
  for (size_t i = 0; i < ms.size(); ++i) {
    const std::string at = fmt::format("moves[{}]", i);
    const nlohmann::json& m = json_object(at, ms[i]);
    json_known_keys(at, m, {"distance", "v_cruise", "v_junction_max"});
    if (!m.contains("distance")) throw input::Error(at + ".distance", "missing", "required");
    if (!m.contains("v_cruise")) throw input::Error(at + ".v_cruise", "missing", "required");
    scurve::StreamMove mv;
    mv.distance = json_int(at + ".distance", m["distance"], -scurve::PlannerLimits::kMaxDistance,
                           scurve::PlannerLimits::kMaxDistance);
    mv.v_cruise = json_real(at + ".v_cruise", m["v_cruise"], 0, kAnyReal);
    mv.v_junction_max = m.contains("v_junction_max")
                            ? json_real(at + ".v_junction_max", m["v_junction_max"], 0, kAnyReal)
                            : r.limits.v_max;
    r.moves.push_back(mv);
  }
  return r;
}

std::variant<StreamRequest, std::string> load_stream_file(const std::string& path) {
  std::ifstream in(path);
  if (!std::filesystem::is_regular_file(path) || !in) {
    return fmt::format("FILE={}: cannot read", input::printable(path));
  }
  std::stringstream ss;
  ss << in.rdbuf();
  try {
    return parse_stream_json(ss.str());
  } catch (const input::Error& e) {
    return fmt::format("{}: {}", input::printable(path), e.what());
  }
}

}  // namespace scurve::cli
