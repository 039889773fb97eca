// `scurve sim --closed-loop`: flags, dispatch, tables and JSON for the
// closed-loop runs (kept out of scurve_main.cpp, which only forwards).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "closed_loop_run.h"
#include "planner.h"

namespace CLI {
class App;
}

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

struct ClosedLoopCli {
  bool enabled = false;
  bool compare = false;
  ControllerInput ctl{};
  PlantConfig plant{};
  std::string plant_kind = "stepper";
  std::string weights_csv;
  std::string scenario;  // JSON file with plant/controller keys
  double tail_s = 0.1;
  std::string fst_path;  // FST waveform of the RTL (one run, engines lockstep and rtl)
  uint64_t fst_from = 0, fst_to = 0;
};

void add_closed_loop_flags(CLI::App* sim, ClosedLoopCli& f);

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

// Runs every job (name, request) in closed loop; prints the results table,
// the paper's Table 3 layout for paper groups, and with compare the
// controller comparison; json_out: also write the JSON result to this file.
// Returns the exit code (0 pass, 1 fail, 2 bad input).
int run_closed_loop_cli(ClosedLoopCli f, const std::vector<std::pair<std::string, MoveRequest>>& jobs,
                        const PulseTiming& timing, const std::string& engine, unsigned n_threads, bool json,
                        const std::string& json_out = {});

// Paper 000 Table 3 (hardware): max error, RMSE, relative error (%), per group.
struct PaperRow {
  double max_error, rmse, relative_pct;
};
inline constexpr PaperRow kPaperTable3[4] = {
    {15.6, 1.83, 0.0061}, {7.3, 0.653, 0.0022}, {25.3, 2.34, 0.0448}, {13.9, 1.68, 0.0056}};

std::string closed_loop_table(const std::vector<ClosedLoopResult>& r);
std::string table3_layout(const std::vector<ClosedLoopResult>& r);  // rows named groupN
std::string comparison_table(const std::vector<ClosedLoopResult>& r);

// Applies a JSON scenario ({"plant": {...}, "controller": {...}}); error text or "".
std::string apply_scenario_json(const std::string& text, ControllerInput& c, PlantConfig& p);

}  // namespace sc
