// Closed-loop settings from flags and scenario files: the parameter tables
// (range, integer-ness, meaning of each plant and controller number) shared
// by `scurve sim --closed-loop` flags and the scenario JSON, and the
// scenario reader. Links without Verilator or SystemC.
#pragma once

#include <string>
#include <vector>

#include "closed_loop_run.h"

namespace sc {

// Controller settings as given (flags, then the scenario's "controller"
// object): the ones not given take scurve::controller_defaults() at the
// control rate, so the default gains suit the rate (docs/closed_loop.md).
struct ControllerInput {
  ControllerParams values{};
  std::vector<bool> given;  // by controller_params() index
  ControllerInput();
  void set(size_t param, double v);
  ControllerParams resolve() const;
};

// A number a user can give as a flag and as a scenario key: one table per
// target (plant, controller), so both ways in share the range, the
// integer-ness and the meaning, and go through the validation layer.
template <class Target>
struct NumberParam {
  const char* flag;  // without "--"
  const char* key;   // in the scenario's "plant" / "controller" object
  double lo, hi;
  bool integer;
  const char* what;  // meaning and unit (the flag's help)
  void (*set)(Target&, double);
  double (*get)(const Target&);
};
using PlantParam = NumberParam<PlantConfig>;
using ControllerParam = NumberParam<ControllerParams>;
const std::vector<PlantParam>& plant_params();
const std::vector<ControllerParam>& controller_params();

// Applies a JSON scenario ({"plant": {...}, "controller": {...}}); error text or "".
std::string apply_scenario_json(const std::string& text, ControllerInput& c, PlantConfig& p);

}  // namespace sc
