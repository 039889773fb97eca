#include "scurve/cli/user_input.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <system_error>

#include <unistd.h>

namespace scurve::input {

std::string printable(std::string_view text) {
  std::string out;
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f) {
      out += fmt::format("\\x{:02x}", u);
    } else {
      out += c;
    }
  }
  return out;
}

Error::Error(std::string parameter, std::string value, const std::string& why)
    : std::invalid_argument(fmt::format("{}={}: {}", printable(parameter), printable(value), printable(why))),
      parameter_(std::move(parameter)),
      value_(std::move(value)) {}

namespace {

std::string bounds(int64_t lo, int64_t hi) { return fmt::format("an integer in [{}, {}]", lo, hi); }
std::string bounds(double lo, double hi) {
  if (lo <= -1e299 && hi >= 1e299) return "a finite number";  // the range is checked elsewhere
  return fmt::format("a finite number in [{}, {}]", lo, hi);
}

bool decimal_integer(std::string_view t) {
  size_t i = (!t.empty() && (t[0] == '-' || t[0] == '+')) ? 1 : 0;
  if (i == t.size()) return false;
  if (t[i] == '0' && i + 1 < t.size()) return false;  // 010 is not ten, nor eight
  for (; i < t.size(); ++i) {
    if (t[i] < '0' || t[i] > '9') return false;
  }
  return true;
}

// Digits, one optional point, an optional decimal exponent; leading zeros
// of the integer part rejected as for integers.
bool decimal_real(std::string_view t) {
  size_t i = (!t.empty() && (t[0] == '-' || t[0] == '+')) ? 1 : 0;
  const size_t int_start = i;
  while (i < t.size() && t[i] >= '0' && t[i] <= '9') ++i;
  const size_t int_digits = i - int_start;
  if (int_digits > 1 && t[int_start] == '0') return false;
  size_t frac_digits = 0;
  if (i < t.size() && t[i] == '.') {
    ++i;
    while (i < t.size() && t[i] >= '0' && t[i] <= '9') ++i, ++frac_digits;
  }
  if (int_digits + frac_digits == 0) return false;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    if (i < t.size() && (t[i] == '-' || t[i] == '+')) ++i;
    const size_t exp_start = i;
    while (i < t.size() && t[i] >= '0' && t[i] <= '9') ++i;
    if (i == exp_start) return false;
  }
  return i == t.size();
}

}  // namespace

bool is_decimal_integer(std::string_view t) {
  const bool negative = !t.empty() && t[0] == '-';
  if (negative) t.remove_prefix(1);
  if (t.empty() || (t[0] == '0' && (t.size() > 1 || negative))) return false;  // "01", "-0"
  for (char c : t) {
    if (c < '0' || c > '9') return false;
  }
  return true;
}

int64_t parse_int(const std::string& param, std::string_view text, int64_t lo, int64_t hi) {
  const std::string given(text);
  if (text.empty()) throw Error(param, "''", "required, " + bounds(lo, hi));
  if (!decimal_integer(text)) throw Error(param, given, "must be " + bounds(lo, hi) + " in decimal notation");
  if (text[0] == '+') text.remove_prefix(1);
  int64_t v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec == std::errc::result_out_of_range || end != text.data() + text.size() || v < lo || v > hi) {
    throw Error(param, given, "must be " + bounds(lo, hi));
  }
  return v;
}

double parse_real(const std::string& param, std::string_view text, double lo, double hi) {
  const std::string given(text);
  if (text.empty()) throw Error(param, "''", "required, " + bounds(lo, hi));
  if (!decimal_real(text)) throw Error(param, given, "must be " + bounds(lo, hi) + " in decimal notation");
  const double v = std::strtod(given.c_str(), nullptr);  // the grammar above is strtod's decimal subset
  if (!std::isfinite(v) || v < lo || v > hi) throw Error(param, given, "must be " + bounds(lo, hi));
  return v;
}

std::string parse_name(const std::string& param, std::string_view text, size_t max_len) {
  const std::string given(text);
  const std::string rule = fmt::format("1 to {} characters of A-Z a-z 0-9 _ - .", max_len);
  if (text.empty()) throw Error(param, "''", "required, " + rule);
  const bool chars_ok = std::all_of(text.begin(), text.end(), [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
           c == '.';
  });
  if (!chars_ok || text.size() > max_len) throw Error(param, given, "must be " + rule);
  return given;
}

std::string shown(const nlohmann::json& v) {
  std::string s = v.dump();
  if (s.size() > 60) s = s.substr(0, 57) + "...";
  return s;
}

int64_t json_int(const std::string& param, const nlohmann::json& v, int64_t lo, int64_t hi) {
  if (v.is_number_integer()) {
    if (v.is_number_unsigned() && v.get<uint64_t>() > uint64_t(INT64_MAX)) {
      throw Error(param, shown(v), "must be " + bounds(lo, hi));
    }
    const int64_t x = v.get<int64_t>();
    if (x < lo || x > hi) throw Error(param, shown(v), "must be " + bounds(lo, hi));
    return x;
  }
  if (v.is_number_float()) {
    const double d = v.get<double>();
    // 1e3 is an integer written in exponent form; 1.5 and 1e30 are not ours.
    if (std::isfinite(d) && d == std::floor(d) && d >= double(lo) && d <= double(hi)) return int64_t(d);
  }
  throw Error(param, shown(v), "must be " + bounds(lo, hi));
}

double json_real(const std::string& param, const nlohmann::json& v, double lo, double hi) {
  if (!v.is_number()) throw Error(param, shown(v), "must be " + bounds(lo, hi));
  const double d = v.get<double>();
  if (!std::isfinite(d) || d < lo || d > hi) throw Error(param, shown(v), "must be " + bounds(lo, hi));
  return d;
}

bool json_bool(const std::string& param, const nlohmann::json& v) {
  if (!v.is_boolean()) throw Error(param, shown(v), "must be true or false");
  return v.get<bool>();
}

std::string json_string(const std::string& param, const nlohmann::json& v) {
  if (!v.is_string()) throw Error(param, shown(v), "must be a string");
  return v.get<std::string>();
}

const nlohmann::json& json_object(const std::string& param, const nlohmann::json& v) {
  if (!v.is_object()) throw Error(param, shown(v), "must be a JSON object");
  return v;
}

const nlohmann::json& json_array(const std::string& param, const nlohmann::json& v) {
  if (!v.is_array()) throw Error(param, shown(v), "must be a JSON array");
  return v;
}

void json_known_keys(const std::string& param, const nlohmann::json& obj, const std::vector<std::string_view>& allowed) {
  json_object(param, obj);
  for (const auto& [k, v] : obj.items()) {
    if (std::find(allowed.begin(), allowed.end(), k) != allowed.end()) continue;
    std::string list;
    for (std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    throw Error(param + "." + k, shown(v), "unknown key (known: " + list + ")");
  }
}

void json_known_keys(const std::string& param, const nlohmann::json& obj, std::initializer_list<std::string_view> allowed) {
  json_known_keys(param, obj, std::vector<std::string_view>(allowed));
}

void output_path(const std::string& param, const std::string& path) {
  namespace fs = std::filesystem;
  if (path.empty()) throw Error(param, "''", "required: a file name");
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (fs::exists(st) && !fs::is_regular_file(st)) {
    throw Error(param, path, fs::is_directory(st) ? "is a directory, not a file" : "exists and is not a regular file");
  }
  fs::path dir = fs::path(path).parent_path();
  if (dir.empty()) dir = ".";
  const fs::file_status dst = fs::status(dir, ec);
  if (!fs::exists(dst)) throw Error(param, path, "directory " + dir.string() + " does not exist");
  if (!fs::is_directory(dst)) throw Error(param, path, dir.string() + " is not a directory");
  // The file is written as "<path>.part" and renamed: both need the directory writable.
  if (::access(dir.c_str(), W_OK | X_OK) != 0) throw Error(param, path, "directory " + dir.string() + " is not writable");
  if (fs::exists(st) && ::access(path.c_str(), W_OK) != 0) throw Error(param, path, "file is not writable");
}

}  // namespace scurve::input
