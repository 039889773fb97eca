// Results files (`scurve regress --merge FILE...`): read back with every
// field typed, or refused with one line; what is read renders as a summary,
// JUnit XML and JSON again.
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "fuzz_check.h"
#include "regress.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(data, data + size);
  } catch (const nlohmann::json::exception&) {
    return 0;
  }
  using namespace sc::regress;
  std::vector<TestResult> results;
  try {
    results = results_from_json(j);
  } catch (const nlohmann::json::exception& e) {
    fuzz::require(false, "unchecked JSON access", e.what());
  } catch (const std::exception& e) {
    fuzz::one_line_message(e.what());
    return 0;
  }
  (void)summary_table(results);
  (void)junit_xml(results, "fuzz");
  const nlohmann::json again = results_json(results, "merged");
  (void)again.dump();
  // What results_json writes, results_from_json reads.
  const std::vector<TestResult> back = results_from_json(again);
  fuzz::require(back.size() == results.size(), "results do not read back", std::to_string(back.size()));
  return 0;
}
