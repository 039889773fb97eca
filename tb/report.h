// JSON and table renderings of plans and simulation results (CLI, regress).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "planner.h"
#include "sim_run.h"

namespace sc {

nlohmann::json plan_to_json(const Plan& p);
std::string plan_to_table(const Plan& p);
nlohmann::json sim_to_json(const SimResult& r);
std::string sim_table(const std::vector<SimResult>& rs);

}  // namespace sc
