// One validation layer for values a user or a list author gives (command
// line text, JSON files): decimal notation, finiteness, integer-ness and
// range checked in one place, with one error type whose message names the
// parameter, the value as given and the bound.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace scurve::input {

// Text from a file or the command line made safe for a one-line message:
// control characters (a newline, an escape sequence) become \xNN.
std::string printable(std::string_view text);

// The message is "parameter=value: why", each part through printable().
class Error : public std::invalid_argument {
 public:
  Error(std::string parameter, std::string value, const std::string& why);
  const std::string& parameter() const { return parameter_; }
  const std::string& value() const { return value_; }

 private:
  std::string parameter_, value_;
};

// "-12", "0", "340282366920938463463374607431768211455": an optional '-',
// digits, no leading zeros; any width (traces carry 128-bit values).
bool is_decimal_integer(std::string_view text);

// The bound of a real that any finite value may take (parse_real(p, t,
// -kAnyReal, kAnyReal)): where its range is checked later, by the planner or
// against the value's sign.
inline constexpr double kAnyReal = 1e300;

// Decimal text: an optional sign and digits, no leading zeros (no octal or
// hex reading), within [lo, hi].
int64_t parse_int(const std::string& param, std::string_view text, int64_t lo, int64_t hi);
// Decimal text of a finite real within [lo, hi] (no hex floats, inf or nan).
double parse_real(const std::string& param, std::string_view text, double lo, double hi);
// A name (an axis): 1 to max_len characters of A-Z a-z 0-9 _ - .
std::string parse_name(const std::string& param, std::string_view text, size_t max_len);

// JSON values. `param` names the place ("tests[3].count").
int64_t json_int(const std::string& param, const nlohmann::json& v, int64_t lo, int64_t hi);
double json_real(const std::string& param, const nlohmann::json& v, double lo, double hi);
bool json_bool(const std::string& param, const nlohmann::json& v);
std::string json_string(const std::string& param, const nlohmann::json& v);
const nlohmann::json& json_object(const std::string& param, const nlohmann::json& v);
const nlohmann::json& json_array(const std::string& param, const nlohmann::json& v);
// Fails on a key of `obj` that is not in `allowed` (a typo must not be ignored).
void json_known_keys(const std::string& param, const nlohmann::json& obj, std::initializer_list<std::string_view> allowed);
void json_known_keys(const std::string& param, const nlohmann::json& obj, const std::vector<std::string_view>& allowed);

// A file a tool is asked to write (--json-out, --fst, a trace): fails before
// any work is done when it cannot be one: empty, an existing directory or
// device (/dev/full), a missing or non-directory parent, an unwritable
// directory. The file itself is not created.
void output_path(const std::string& param, const std::string& path);

// A JSON value as the user wrote it, shortened for one-line messages.
std::string shown(const nlohmann::json& v);

}  // namespace scurve::input

// The testbench's tools use the same layer.
namespace sc {
namespace input = scurve::input;
}  // namespace sc
