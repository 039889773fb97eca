#include "scurve/cli/path_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string_view>
#include <system_error>
#include <utility>

#include "scurve/cli/user_input.h"

namespace scurve::cli {

namespace {

constexpr int64_t kMaxPosition = scurve::PathRequest::kMaxPosition;
using input::kAnyReal;  // a finite number; the sign is checked where it matters

// A move as the file gives it: the feed still in mm/s (its factor to pulses
// needs the move's start), the jerks in mm/s^3.
struct FileMove {
  std::vector<int64_t> target;
  double feed_mm_s = 0;
  int source_line = 0;
  std::optional<std::array<double, 4>> jerks_mm_s3;  // Ts1, Ts2, Te1, Te2 along the path; unset: symmetric
};

// mm -> pulses, rounded once per absolute position.
int64_t to_pulses(const std::string& param, const std::string& value, double mm, double pulses_per_mm) {
  const double p = mm * pulses_per_mm;
  if (!std::isfinite(p) || std::fabs(p) >= double(kMaxPosition) + 0.5) {
    throw input::Error(param, value,
                       fmt::format("{:.10g} mm is {:.10g} pulses at {:.10g} pulses/mm: beyond the position range "
                                   "+-{} pulses (+-{:.10g} mm)",
                                   mm, p, pulses_per_mm, kMaxPosition, double(kMaxPosition) / pulses_per_mm));
  }
  return std::llround(p);
}

std::string positive_rule(const char* unit) {
  return std::string("must be a finite number > 0") + (*unit ? " " : "") + unit;
}

void check_positive(const std::string& param, double v, const char* unit) {
  if (!std::isfinite(v) || v <= 0) throw input::Error(param, fmt::format("{}", v), positive_rule(unit));
}

double json_positive(const std::string& param, const nlohmann::json& v, const char* unit) {
  const double d = input::json_real(param, v, -kAnyReal, kAnyReal);
  if (d <= 0) throw input::Error(param, input::shown(v), positive_rule(unit));
  return d;
}

// A line's four jerks along the path (paper 002's Ts1, Ts2, Te1, Te2, as
// scurve::LineRequest::jerks), mm/s^3: each > 0 and at most the path's
// jerk limit, the line's j_path.
std::array<double, 4> json_jerks(const std::string& param, const nlohmann::json& v, double jerk_limit) {
  const nlohmann::json& a = input::json_array(param, v);
  if (a.size() != 4) {
    throw input::Error(param, input::shown(v),
                       fmt::format("needs 4 jerks (Ts1 Ts2 speeding up, Te1 Te2 slowing down) in mm/s^3, has {}",
                                   a.size()));
  }
  std::array<double, 4> j{};
  for (size_t k = 0; k < 4; ++k) {
    const std::string at = fmt::format("{}[{}]", param, k);
    j[k] = json_positive(at, a[k], "mm/s^3");
    if (j[k] > jerk_limit) {
      throw input::Error(at, input::shown(a[k]), fmt::format("must be <= limits.jerk={} mm/s^3", jerk_limit));
    }
  }
  return j;
}

// Pulses per mm of every axis: the given list, else the default.
// PathFileOptions::start: one position per axis, within the planner's range.
std::vector<int64_t> given_start(const std::vector<int64_t>& start, size_t axes) {
  if (start.size() != axes) {
    throw input::Error("start", fmt::format("{} values", start.size()), fmt::format("needs {} (one per axis)", axes));
  }
  for (size_t i = 0; i < axes; ++i) {
    if (std::llabs(start[i]) > scurve::PathRequest::kMaxPosition) {
      throw input::Error(fmt::format("start[{}]", i), fmt::format("{}", start[i]),
                         fmt::format("must be within +-{} pulses", scurve::PathRequest::kMaxPosition));
    }
  }
  return start;
}

std::vector<double> pulses_per_mm_of(const PathFileOptions& o, size_t axes) {
  if (o.pulses_per_mm.empty()) return std::vector<double>(axes, PathFileOptions::kDefaultPulsesPerMm);
  if (o.pulses_per_mm.size() != axes) {
    throw input::Error("pulses_per_mm", fmt::format("{} values", o.pulses_per_mm.size()),
                       fmt::format("needs one per axis ({})", axes));
  }
  for (size_t i = 0; i < axes; ++i) check_positive(fmt::format("pulses_per_mm[{}]", i), o.pulses_per_mm[i], "");
  return o.pulses_per_mm;
}

// The file's moves in the library's units. The feed along the path scales
// by the move's length in pulses over its length in mm (pulses_per_mm when
// the axes have the same); the path limits and a move's jerks by the
// smallest pulses_per_mm (so jerks within the jerk limit in mm stay within
// it in pulses).
PathProgram finish(size_t axes, std::vector<double> ppm, std::vector<int64_t> start, std::vector<FileMove> moves,
                   double feed_limit, double accel, double jerk) {
  PathProgram p;
  p.axes = axes;
  const double ppm_min = *std::min_element(ppm.begin(), ppm.end());
  p.limits = scurve::PathLimits{feed_limit * ppm_min, accel * ppm_min, jerk * ppm_min};
  std::vector<int64_t> at = start;
  for (FileMove& m : moves) {
    double pulses2 = 0, mm2 = 0;
    for (size_t i = 0; i < axes; ++i) {
      const double d = double(m.target[i] - at[i]);
      pulses2 += d * d;
      mm2 += (d / ppm[i]) * (d / ppm[i]);
    }
    const double scale = mm2 > 0 ? std::sqrt(pulses2 / mm2) : ppm_min;
    scurve::PathMove pm{m.target, m.feed_mm_s * scale, m.source_line};
    if (m.jerks_mm_s3) {
      pm.jerks.emplace();
      for (size_t k = 0; k < 4; ++k) (*pm.jerks)[k] = (*m.jerks_mm_s3)[k] * ppm_min;
    }
    p.moves.push_back(std::move(pm));
    at = std::move(m.target);
  }
  p.pulses_per_mm = std::move(ppm);
  p.start = std::move(start);
  return p;
}

// ---- JSON ----------------------------------------------------------------------

// Line and column (1-based) of a 1-based byte position, as nlohmann counts.
std::pair<size_t, size_t> line_col(const std::string& text, size_t byte) {
  const size_t at = std::min(byte > 0 ? byte - 1 : 0, text.size());
  const size_t line = 1 + size_t(std::count(text.begin(), text.begin() + std::ptrdiff_t(at), '\n'));
  const size_t nl = at == 0 ? std::string::npos : text.rfind('\n', at - 1);
  return {line, nl == std::string::npos ? at + 1 : at - nl};
}

std::string line_text(const std::string& text, size_t line) {
  size_t begin = 0;
  for (size_t l = 1; l < line && begin != std::string::npos; ++l) {
    begin = text.find('\n', begin);
    if (begin != std::string::npos) ++begin;
  }
  if (begin == std::string::npos || begin >= text.size()) return "";
  std::string s = text.substr(begin, text.find('\n', begin) - begin);
  s.erase(0, std::min(s.find_first_not_of(" \t"), s.size()));
  if (s.size() > 60) s = s.substr(0, 57) + "...";
  return s;
}

nlohmann::json parse_json_text(const std::string& text) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    const auto [line, col] = line_col(text, e.byte);
    throw input::Error(fmt::format("line {} col {} JSON", line, col), line_text(text, line),
                       std::string("not JSON: ") + e.what());
  } catch (const nlohmann::json::out_of_range& e) {
    // A number beyond double ("number overflow parsing '1e999'"): no byte
    // position, so the place of its first occurrence.
    const std::string what = e.what();
    const size_t q0 = what.find('\''), q1 = what.rfind('\'');
    const std::string token = q0 != std::string::npos && q1 > q0 ? what.substr(q0 + 1, q1 - q0 - 1) : "";
    const size_t at = token.empty() ? std::string::npos : text.find(token);
    if (at == std::string::npos) throw input::Error("path", "file", "not a finite number: " + what);
    const auto [line, col] = line_col(text, at + 1);
    throw input::Error(fmt::format("line {} col {} JSON", line, col), token, "not a finite number: " + what);
  } catch (const nlohmann::json::exception& e) {
    throw input::Error("path", "file", std::string("not JSON: ") + e.what());
  }
}

std::vector<int64_t> json_position(const std::string& param, const nlohmann::json& v, const std::vector<double>& ppm) {
  const nlohmann::json& a = input::json_array(param, v);
  if (a.size() != ppm.size()) {
    throw input::Error(param, input::shown(v),
                       fmt::format("needs {} coordinates (one per axis), has {}", ppm.size(), a.size()));
  }
  std::vector<int64_t> p(ppm.size());
  for (size_t i = 0; i < ppm.size(); ++i) {
    const std::string at = fmt::format("{}[{}]", param, i);
    p[i] = to_pulses(at, input::shown(a[i]), input::json_real(at, a[i], -kAnyReal, kAnyReal), ppm[i]);
  }
  return p;
}

// ---- G-code --------------------------------------------------------------------

struct Word {
  char letter = 0;      // upper case
  std::string number;   // as written
  double value = 0;
  size_t col = 0;       // 1-based column of the letter
};

std::string place(int line, size_t col) { return fmt::format("line {} col {}", line, col); }
std::string param(int line, const Word& w) { return fmt::format("line {} col {} {}", line, w.col, w.letter); }

const char* const kSubset = "the subset is G0 G1 G21 G90 G91, X Y Z F, N line numbers";

// The words of one line; comments, white space and a leading '%' dropped.
std::vector<Word> gcode_words(std::string_view s, int line) {
  std::vector<Word> words;
  bool percent = false;
  size_t i = 0;
  const auto blank = [](char c) { return c == ' ' || c == '\t'; };
  while (i < s.size()) {
    const char c = s[i];
    if (blank(c)) {
      ++i;
    } else if (c == ';') {
      break;
    } else if (c == '(') {
      const size_t close = s.find(')', i);
      if (close == std::string_view::npos) {
        throw input::Error(place(line, i + 1) + " comment", std::string(s.substr(i, 40)),
                           "not closed by ')' on the same line");
      }
      i = close + 1;
    } else if (c == '%' && words.empty() && !percent) {
      percent = true;  // program start/end marker: only comments may follow
      ++i;
    } else if (std::isalpha(static_cast<unsigned char>(c)) && !percent) {
      Word w;
      w.letter = char(std::toupper(static_cast<unsigned char>(c)));
      w.col = i + 1;
      ++i;
      while (i < s.size() && blank(s[i])) ++i;
      const size_t begin = i;
      if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
      size_t digits = 0, points = 0;
      while (i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.')) {
        (s[i] == '.' ? points : digits) += 1;
        ++i;
      }
      w.number = std::string(s.substr(begin, i - begin));
      if (digits == 0 || points > 1) {
        throw input::Error(param(line, w), w.number.empty() ? "''" : w.number,
                           "needs a number after the letter (digits, at most one '.')");
      }
      // from_chars: the same digits in any locale; no '+' there.
      std::string_view num(w.number);
      if (num[0] == '+') num.remove_prefix(1);
      const auto [end, ec] = std::from_chars(num.data(), num.data() + num.size(), w.value);
      if (ec != std::errc() || end != num.data() + num.size() || !std::isfinite(w.value)) {
        throw input::Error(param(line, w), w.number, "must be a finite number");
      }
      words.push_back(std::move(w));
    } else {
      throw input::Error(place(line, i + 1) + " text", std::string(s.substr(i, 20)),
                         std::string(percent ? "only comments may follow '%'"
                                             : "not G-code: expected a word (a letter and a number), "
                                               "a comment or ';'"));
    }
  }
  return words;
}

bool integer_valued(const Word& w, double lo, double hi) {
  return w.value == std::floor(w.value) && w.value >= lo && w.value <= hi;
}

}  // namespace

PathProgram parse_path_json(const std::string& text, const PathFileOptions& o) {
  using namespace input;
  const nlohmann::json j = parse_json_text(text);
  json_object("path", j);
  json_known_keys("path", j, {"_comment", "axes", "pulses_per_mm", "limits", "axis_limits", "start", "points"});
  for (const char* k : {"axes", "limits", "points"}) {
    if (!j.contains(k)) throw input::Error(k, "missing", "required");
  }
  const size_t axes = size_t(json_int("axes", j["axes"], 1, int64_t(scurve::LineRequest::kMaxAxes)));
  if (o.axes != 0 && o.axes != axes) {
    throw input::Error("axes", std::to_string(axes), fmt::format("the file's axes, but {} were asked for", o.axes));
  }
  std::vector<double> ppm;
  if (j.contains("pulses_per_mm")) {
    const nlohmann::json& a = json_array("pulses_per_mm", j["pulses_per_mm"]);
    if (a.size() != axes) {
      throw input::Error("pulses_per_mm", shown(a), fmt::format("needs one value per axis ({})", axes));
    }
    for (size_t i = 0; i < axes; ++i) ppm.push_back(json_positive(fmt::format("pulses_per_mm[{}]", i), a[i], ""));
    if (!o.pulses_per_mm.empty() && o.pulses_per_mm != ppm) {
      throw input::Error("pulses_per_mm", shown(a), "differs from the pulses per mm given with the file");
    }
  } else {
    ppm = pulses_per_mm_of(o, axes);
  }

  const nlohmann::json& l = json_object("limits", j["limits"]);
  json_known_keys("limits", l, {"feed", "accel", "jerk"});
  for (const char* k : {"feed", "accel", "jerk"}) {
    if (!l.contains(k)) throw input::Error(std::string("limits.") + k, "missing", "required");
  }
  const double feed_limit = json_positive("limits.feed", l["feed"], "mm/s");
  const double accel = json_positive("limits.accel", l["accel"], "mm/s^2");
  const double jerk = json_positive("limits.jerk", l["jerk"], "mm/s^3");

  std::vector<scurve::AxisLimits> axis_limits;
  if (j.contains("axis_limits")) {
    const nlohmann::json& a = json_array("axis_limits", j["axis_limits"]);
    if (a.size() != axes) {
      throw input::Error("axis_limits", shown(a), fmt::format("needs one object per axis ({})", axes));
    }
    for (size_t i = 0; i < axes; ++i) {
      const std::string at = fmt::format("axis_limits[{}]", i);
      const nlohmann::json& x = json_object(at, a[i]);
      json_known_keys(at, x, {"v_max", "a_max", "j_max"});
      scurve::AxisLimits al;  // a missing limit stays 0: unbounded
      if (x.contains("v_max")) al.v_max = json_positive(at + ".v_max", x["v_max"], "mm/s") * ppm[i];
      if (x.contains("a_max")) al.a_max = json_positive(at + ".a_max", x["a_max"], "mm/s^2") * ppm[i];
      if (x.contains("j_max")) al.j_max = json_positive(at + ".j_max", x["j_max"], "mm/s^3") * ppm[i];
      axis_limits.push_back(al);
    }
  }

  std::vector<int64_t> start =
      j.contains("start") ? json_position("start", j["start"], ppm) : std::vector<int64_t>(axes, 0);
  if (!o.start.empty()) start = given_start(o.start, axes);
  const nlohmann::json& pts = json_array("points", j["points"]);
  if (pts.empty()) throw input::Error("points", "[]", "needs at least one point");
  std::vector<FileMove> moves;
  for (size_t k = 0; k < pts.size(); ++k) {
    const std::string at = fmt::format("points[{}]", k);
    FileMove m;
    m.source_line = int(k);
    m.feed_mm_s = feed_limit;
    if (pts[k].is_object()) {
      json_known_keys(at, pts[k], {"to", "feed", "jerks"});
      if (!pts[k].contains("to")) throw input::Error(at + ".to", "missing", "required");
      m.target = json_position(at + ".to", pts[k]["to"], ppm);
      if (pts[k].contains("feed")) m.feed_mm_s = json_positive(at + ".feed", pts[k]["feed"], "mm/s");
      if (pts[k].contains("jerks")) m.jerks_mm_s3 = json_jerks(at + ".jerks", pts[k]["jerks"], jerk);
    } else if (pts[k].is_array()) {
      m.target = json_position(at, pts[k], ppm);
    } else {
      throw input::Error(at, shown(pts[k]),
                         "must be [x, y, ...] or {\"to\": [x, y, ...], \"feed\": mm/s, \"jerks\": [mm/s^3 x 4]}");
    }
    moves.push_back(std::move(m));
  }
  PathProgram p = finish(axes, ppm, start, std::move(moves), feed_limit, accel, jerk);
  p.axis_limits = std::move(axis_limits);
  p.source = scurve::PathSource::kPoint;
  return p;
}

PathProgram parse_path_gcode(const std::string& text, const PathFileOptions& o) {
  const size_t axes = o.axes == 0 ? 2 : o.axes;
  if (axes > 3) {
    throw input::Error("axes", std::to_string(axes), "G-code names X, Y and Z: needs 1 to 3 axes");
  }
  const std::vector<double> ppm = pulses_per_mm_of(o, axes);
  check_positive("feed_limit", o.feed_limit, "mm/s");
  check_positive("accel", o.accel, "mm/s^2");
  check_positive("jerk", o.jerk, "mm/s^3");

  // Modal state: the motion (G0/G1), the distance mode, the feed (mm/s) and
  // the absolute position in mm, from which every target is rounded once.
  std::optional<int> motion;
  bool absolute = true;
  std::optional<double> feed_mm_s;
  const std::vector<int64_t> start =
      o.start.empty() ? std::vector<int64_t>(axes, 0) : given_start(o.start, axes);
  std::vector<double> pos_mm(axes, 0.0);
  for (size_t i = 0; i < axes; ++i) pos_mm[i] = double(start[i]) / ppm[i];
  std::vector<FileMove> moves;

  int line = 0;
  size_t begin = 0;
  while (begin <= text.size()) {
    size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    std::string_view s(text.data() + begin, end - begin);
    begin = end + 1;
    ++line;
    if (!s.empty() && s.back() == '\r') s.remove_suffix(1);
    const std::vector<Word> words = gcode_words(s, line);

    // One word of each kind (one per modal group for G) per line.
    const Word* g_motion = nullptr;
    const Word* g_distance = nullptr;
    const Word* f_word = nullptr;
    std::vector<const Word*> coord(axes, nullptr);
    const auto once = [&](const Word*& slot, const Word& w) {
      if (slot) {
        throw input::Error(param(line, w), w.number,
                           fmt::format("conflicts with {}{} at col {} on the same line", slot->letter, slot->number,
                                       slot->col));
      }
      slot = &w;
    };
    for (size_t k = 0; k < words.size(); ++k) {
      const Word& w = words[k];
      const std::string word = std::string(1, w.letter) + w.number;
      switch (w.letter) {
        case 'N':
          if (k != 0) throw input::Error(param(line, w), w.number, "a line number N must be the line's first word");
          if (!integer_valued(w, 0, 1e9)) throw input::Error(param(line, w), w.number, "must be an integer >= 0");
          break;
        case 'G': {
          // A code is written as digits alone ("G1", "G01"); "G1.5" or "G-1" is another code.
          const bool plain = std::all_of(w.number.begin(), w.number.end(),
                                         [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
          if (plain && (w.value == 0 || w.value == 1)) {
            once(g_motion, w);
          } else if (plain && (w.value == 90 || w.value == 91)) {
            once(g_distance, w);
          } else if (plain && w.value == 21) {
            // mm: the only units
          } else if (plain && w.value == 20) {
            throw input::Error(param(line, w), w.number, "inch units (G20) are not supported: positions are mm (G21)");
          } else {
            throw input::Error(param(line, w), w.number, fmt::format("unsupported word {}: {}", word, kSubset));
          }
          break;
        }
        case 'F':
          once(f_word, w);
          if (w.value <= 0) throw input::Error(param(line, w), w.number, "must be a feed > 0 mm/min");
          break;
        case 'X':
        case 'Y':
        case 'Z': {
          const size_t axis = size_t(w.letter - 'X');
          if (axis >= axes) {
            const std::string names = std::string("X Y Z").substr(0, 2 * axes - 1);
            throw input::Error(param(line, w), w.number,
                               fmt::format("no {} axis: the path's axes are {}; --axes {} adds it", w.letter, names,
                                           axis + 1));
          }
          once(coord[axis], w);
          break;
        }
        default:
          throw input::Error(param(line, w), w.number, fmt::format("unsupported word {}: {}", word, kSubset));
      }
    }

    if (g_distance) absolute = g_distance->value == 90;
    if (f_word) feed_mm_s = f_word->value / 60.0;  // mm/min, the G-code convention
    if (g_motion) motion = int(g_motion->value);
    const Word* first_coord = nullptr;
    for (const Word* c : coord) {
      if (c && (!first_coord || c->col < first_coord->col)) first_coord = c;
    }
    if (!first_coord) continue;  // modal settings only
    if (!motion) {
      throw input::Error(param(line, *first_coord), first_coord->number,
                         "no motion mode in effect: G0 or G1 must come first");
    }
    if (*motion == 1 && !feed_mm_s) {
      const Word& at = g_motion ? *g_motion : *first_coord;
      throw input::Error(param(line, at), at.number, "G1 needs a feed: an F word (mm/min) on this line or before");
    }
    FileMove m;
    m.source_line = line;
    m.feed_mm_s = *motion == 0 ? o.feed_limit : *feed_mm_s;  // G0: rapid, the path's feed limit
    m.target.resize(axes);
    for (size_t i = 0; i < axes; ++i) {
      if (coord[i]) pos_mm[i] = absolute ? coord[i]->value : pos_mm[i] + coord[i]->value;
      const std::string at = coord[i] ? param(line, *coord[i]) : fmt::format("line {} {}", line, "XYZ"[i]);
      m.target[i] = to_pulses(at, coord[i] ? coord[i]->number : fmt::format("{}", pos_mm[i]), pos_mm[i], ppm[i]);
    }
    moves.push_back(std::move(m));
  }
  if (moves.empty()) throw input::Error("moves", "none", "the file has no G0/G1 move");
  return finish(axes, ppm, start, std::move(moves), o.feed_limit, o.accel, o.jerk);
}

PathProgram parse_path_text(const std::string& text, const std::string& file_name, const PathFileOptions& o) {
  PathFormat f = o.format;
  if (f == PathFormat::kAuto) {
    std::string ext = std::filesystem::path(file_name).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".json") {
      f = PathFormat::kJson;
    } else if (ext == ".gcode" || ext == ".nc" || ext == ".ngc" || ext == ".gc" || ext == ".g" || ext == ".tap") {
      f = PathFormat::kGCode;
    } else {
      const size_t first = text.find_first_not_of(" \t\r\n");
      f = first != std::string::npos && text[first] == '{' ? PathFormat::kJson : PathFormat::kGCode;
    }
  }
  return f == PathFormat::kJson ? parse_path_json(text, o) : parse_path_gcode(text, o);
}

std::variant<PathProgram, std::string> load_path_file(const std::string& path, const PathFileOptions& o) {
  std::ifstream in(path, std::ios::binary);
  if (!std::filesystem::is_regular_file(path) || !in) {
    return fmt::format("FILE={}: cannot read", input::printable(path));
  }
  std::stringstream ss;
  ss << in.rdbuf();
  try {
    return parse_path_text(ss.str(), path, o);
  } catch (const input::Error& e) {
    return fmt::format("{}: {}", input::printable(path), e.what());
  }
}

scurve::PathRequest to_path_request(const PathProgram& p) {
  scurve::PathRequest r;
  r.axes = p.axes;
  r.start = p.start;
  r.moves = p.moves;
  r.limits = p.limits;
  r.axis_limits = p.axis_limits;
  r.source = p.source;
  return r;
}

}  // namespace scurve::cli
