// `scurve sim --closed-loop`: flags, dispatch, tables and JSON for the
// closed-loop runs (kept out of scurve_main.cpp, which only forwards).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "closed_loop_run.h"
#include "planner.h"
#include "scenario_json.h"
#include "scurve/cli/move_flags.h"

namespace CLI {
class App;
}

namespace sc {

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
// The controller's flags (--controller and one per controller_params()
// row), in `group`: shared by `scurve sim --closed-loop` and `scurve path`.
void add_controller_flags(CLI::App* cmd, ControllerInput& ctl, const std::string& group);

// Runs every job (name, request) in closed loop; prints the results table,
// the paper's Table 3 layout for paper groups, and with compare the
// controller comparison; json_out: also write the JSON result to this file;
// stop: `--stop-at` and the stop limits, resolved against each planned move.
// Returns the exit code (0 pass, 1 fail, 2 bad input).
int run_closed_loop_cli(ClosedLoopCli f, const std::vector<std::pair<std::string, MoveRequest>>& jobs,
                        const PulseTiming& timing, const std::string& engine, unsigned n_threads, bool json,
                        const std::string& json_out = {}, const scurve::cli::StopFlags& stop = {});

// Paper 000 Table 3 (hardware): max error, RMSE, relative error (%), per group.
struct PaperRow {
  double max_error, rmse, relative_pct;
};
inline constexpr PaperRow kPaperTable3[4] = {
    {15.6, 1.83, 0.0061}, {7.3, 0.653, 0.0022}, {25.3, 2.34, 0.0448}, {13.9, 1.68, 0.0056}};
// The runner's tracking-error bounds are the smallest and the largest of them.
static_assert(kPaperTable3[1].max_error == kMaxErrorWithFf && kPaperTable3[2].max_error == kMaxErrorWithoutFf);

std::string closed_loop_table(const std::vector<ClosedLoopResult>& r);
std::string table3_layout(const std::vector<ClosedLoopResult>& r);  // rows named groupN
std::string comparison_table(const std::vector<ClosedLoopResult>& r);


}  // namespace sc
