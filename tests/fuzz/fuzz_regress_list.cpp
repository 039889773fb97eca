// Regression lists (`scurve regress --list FILE`): any bytes are expanded
// into tests whose names are safe file names, or refused with one line
// naming the field; never an unchecked JSON access (a raw nlohmann error).
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "fuzz_check.h"
#include "regress.h"
#include "scurve/cli/user_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  nlohmann::json list;
  try {
    list = nlohmann::json::parse(data, data + size);
  } catch (const nlohmann::json::exception&) {
    return 0;  // "not JSON": reported by the caller with the parser's message
  }
  using namespace sc::regress;
  try {
    // A small draw budget: the planner under ASan and coverage tracing takes
    // about 15 ms a draw, and the bound itself is what is checked here.
    const std::vector<TestCase> tests = expand_list(list, {}, {"long"}, 200);
    for (const TestCase& t : tests) {
      fuzz::require(!t.name.empty() && t.name[0] != '.' && t.name.find('/') == std::string::npos, "unsafe name",
                    t.name);
      fuzz::require(!t.argv.empty(), "empty argv", t.name);
      (void)shell_command(t.argv);
    }
    if (!tests.empty()) (void)select_shard(tests, 1, 2);
  } catch (const nlohmann::json::exception& e) {
    fuzz::require(false, "unchecked JSON access", e.what());
  } catch (const std::exception& e) {
    fuzz::one_line_message(e.what());
  }
  return 0;
}
