// JSON and table renderings of simulation results (CLI, regress); plans:
// scurve/cli/plan_report.h.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "planner.h"
#include "sim_run.h"

namespace sc {

nlohmann::json sim_to_json(const SimResult& r);
std::string sim_table(const std::vector<SimResult>& rs);

}  // namespace sc
