// Path files (coordinated paths on several axes, positions in mm): JSON or
// a small G-code subset, parsed through the validation layer (every number
// checked in one place) into the host library's units (pulses) for
// scurve::plan_path. Errors throw input::Error naming the line (G-code:
// "line 7 col 12 M=3: ..."; JSON syntax: the line and column of the byte
// nlohmann stopped at) or the place ("points[3][1]=...").
//
// JSON:   {"axes": 2, "pulses_per_mm": [100, 100],
//          "limits": {"feed": 100, "accel": 1000, "jerk": 10000},      mm/s, mm/s^2, mm/s^3
//          "axis_limits": [{"v_max": 80, "a_max": 800, "j_max": 8000}, {}],  optional, mm units
//          "start": [0, 0],                                             optional, mm (default 0)
//          "points": [[12, 80], {"to": [72, 80], "feed": 50}]}          absolute mm; feed mm/s
//          a point object may add "jerks": [Ts1, Ts2, Te1, Te2]: its line's asymmetric S-shape
//          (scurve::PathMove::jerks), mm/s^3 along the path, each > 0 and <= limits.jerk
// G-code: G0/G1 with X Y Z F, G90/G91, G21 (G20 refused), F in mm/min
//         (modal), G0 at the feed limit, comments ; and ( ), N numbers,
//         % lines; any other word is an error naming the line and the word.
// Every absolute position is rounded to the nearest pulse once (halves away
// from 0), so relative moves do not accumulate rounding.
#pragma once

#include <cstddef>
#include <string>
#include <variant>
#include <vector>

#include "scurve/path_planner.h"

namespace scurve::cli {

enum class PathFormat { kAuto, kJson, kGCode };

// What the file does not say (the command line's part).
struct PathFileOptions {
  static constexpr double kDefaultPulsesPerMm = 100;  // 10 um per pulse
  // A G-code file's path limits (a JSON file gives its own "limits"):
  // paper 002's X-Y table, 6000 mm/min, 1 m/s^2, 10 m/s^3.
  static constexpr double kDefaultFeedLimit = 100;  // mm/s: the highest feed, and G0's
  static constexpr double kDefaultAccel = 1000;     // mm/s^2
  static constexpr double kDefaultJerk = 10000;     // mm/s^3
  // G-code: 0 means 2 (X Y); 1 to 3 name X, X Y, X Y Z. JSON: 0 takes the
  // file's "axes", another value must equal it.
  size_t axes = 0;
  // Empty: the file's (JSON) or kDefaultPulsesPerMm on every axis; else one
  // per axis (a JSON file that gives other values is refused).
  std::vector<double> pulses_per_mm;
  double feed_limit = kDefaultFeedLimit;
  double accel = kDefaultAccel;
  double jerk = kDefaultJerk;
  PathFormat format = PathFormat::kAuto;  // kAuto: by the file's extension, else its first character
  // Where the program starts, pulses per axis: empty for the file's own
  // start (a JSON "start", else 0); given (a board's REF_POS), it replaces
  // that: G91 moves count from it and the first move leaves from it.
  std::vector<int64_t> start;
};

// A parsed path in pulses. Each move's feed is its speed along the path in
// pulses/s: the feed in mm/s times the move's length in pulses over its
// length in mm (the same factor as pulses_per_mm when every axis has the
// same). The path limits and a move's jerks are the mm values at the
// smallest pulses_per_mm (no axis passes its share when the axes differ);
// axis_limits at each axis's own.
struct PathProgram {
  size_t axes = 0;
  std::vector<double> pulses_per_mm;
  std::vector<int64_t> start;                    // pulses per axis
  std::vector<scurve::PathMove> moves;           // absolute targets (pulses), feed (pulses/s), source_line, jerks
  scurve::PathLimits limits;                     // pulses/s, pulses/s^2, pulses/s^3
  std::vector<scurve::AxisLimits> axis_limits;   // empty, or one per axis (0: unbounded)
  scurve::PathSource source = scurve::PathSource::kLine;  // G-code: file lines; JSON: point indices
};

PathProgram parse_path_json(const std::string& text, const PathFileOptions& options = {});
PathProgram parse_path_gcode(const std::string& text, const PathFileOptions& options = {});
// By options.format; kAuto: ".json" is JSON, ".gcode" ".nc" ".ngc" ".gc"
// ".g" ".tap" G-code, else JSON when the first character that is not
// white space is '{'.
PathProgram parse_path_text(const std::string& text, const std::string& file_name,
                            const PathFileOptions& options = {});
// Reads and parses the file: the program, or one line naming the file and
// the place ("FILE=p.gcode: cannot read", "p.gcode: line 7 col 12 M=3: ...").
std::variant<PathProgram, std::string> load_path_file(const std::string& path, const PathFileOptions& options = {});

// The request plan_path() takes (axes, start, moves, limits, source).
scurve::PathRequest to_path_request(const PathProgram& program);

}  // namespace scurve::cli
