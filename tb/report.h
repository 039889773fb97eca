// JSON and table renderings of simulation results (CLI, regress); plans:
// scurve/cli/plan_report.h.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "planner.h"
#include "sim_run.h"
#include "stream_run.h"

namespace sc {

// A controlled stop (`--stop-at`): null when none was requested; one table
// line (empty when none was requested).
nlohmann::json stop_to_json(const StopReport& s);
std::string stop_line(const std::string& name, const StopReport& s);

nlohmann::json sim_to_json(const SimResult& r);
std::string sim_table(const std::vector<SimResult>& rs);
nlohmann::json stream_to_json(const StreamRunResult& r);
std::string stream_table(const StreamRunResult& r);

}  // namespace sc
