// Helpers shared by the path planner's tests (test_path.cpp,
// test_path_blend.cpp).
#pragma once

#include <gtest/gtest.h>

#include "scurve/path_planner.h"

namespace scurve::test {

// The integer pulse of an exact position (LSB, kOne per pulse), rounded down.
inline i128 floor_pulses(i128 pos) {
  const i128 one = i128(kOne);
  return pos >= 0 ? pos / one : -((-pos + one - 1) / one);
}

// plan_path with the default planner and pulse timing; a refusal is a test
// failure (naming its parameter) and an empty plan.
inline PathPlan plan_or_fail(const PathRequest& r) {
  const PathResult p = plan_path(Planner{}, r, PulseTiming{});
  if (const Error* e = std::get_if<Error>(&p)) {
    ADD_FAILURE() << e->parameter << ": " << e->message;
    return {};
  }
  return std::get<PathPlan>(p);
}

}  // namespace scurve::test
