// Scenario files (`scurve sim --closed-loop --scenario FILE`): any bytes are
// either applied (every number within its parameter's range) or refused
// with one line naming the key.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_check.h"
#include "scenario_json.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  sc::ControllerInput ctl;
  sc::PlantConfig plant;
  const std::string err = sc::apply_scenario_json(text, ctl, plant);
  if (!err.empty()) {
    fuzz::one_line_message(err);
    return 0;
  }
  for (size_t i = 0; i < sc::controller_params().size(); ++i) {
    if (!ctl.given[i]) continue;
    const auto& p = sc::controller_params()[i];
    const double v = p.get(ctl.values);
    fuzz::require(v >= p.lo && v <= p.hi, "controller value out of range", p.key);
  }
  for (const auto& p : sc::plant_params()) {
    const double v = p.get(plant);
    fuzz::require(v == v, "plant value nan", p.key);
  }
  return 0;
}
