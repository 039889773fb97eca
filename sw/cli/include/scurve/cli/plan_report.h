// JSON and table renderings of a plan (times and physical units at the
// plan's clock rate).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "scurve/planner.h"

namespace scurve::cli {

nlohmann::json plan_to_json(const Plan& p);
std::string plan_to_table(const Plan& p);
// The same with the request's window: when it has soft limits or a nonzero
// start position, also "start_position" and "target_position" (pulses), and
// with soft limits "soft_limits": {"axis", "min", "max"} (null: unbounded);
// the table gets a line with the same.
nlohmann::json plan_to_json(const Plan& p, const MoveRequest& request);
std::string plan_to_table(const Plan& p, const MoveRequest& request);
// The clock rate as JSON: an integer when it is a whole number of Hz.
nlohmann::json clock_to_json(Clock c);

}  // namespace scurve::cli
