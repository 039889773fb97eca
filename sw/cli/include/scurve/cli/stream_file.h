// Stream files of `scurve stream FILE` (simulation) and `scurve board
// stream FILE` (a board): parsed through the validation layer (every number
// checked in one place, errors naming the place).
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "scurve/stream_planner.h"

namespace scurve::cli {

// The stream file of `scurve stream`: {"limits": {"a_max", "j_max", "v_max"},
// "moves": [{"distance", "v_cruise", "v_junction_max"}, ...]} (the junction
// limit optional: v_max), and optionally "start_position" (pulses) and
// "soft_limits": {"min", "max", "axis"} (the travel window, either side
// optional; into limits.soft_limits / limits.start_position). Unknown keys,
// wrong types and values out of range throw input::Error naming the place
// ("moves[3].v_cruise").
struct StreamRequest {
  scurve::StreamLimits limits;
  std::vector<scurve::StreamMove> moves;
};
StreamRequest parse_stream_json(const std::string& text);
// Reads and parses the file: the request, or one line naming the file and
// the place ("FILE=s.json: cannot read", "s.json: moves[3].v_cruise=...").
std::variant<StreamRequest, std::string> load_stream_file(const std::string& path);

}  // namespace scurve::cli
