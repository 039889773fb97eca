// The planner's error messages state true facts: the distance it says a
// move needs is the shortest one it accepts, and values appear as given.
#include <gtest/gtest.h>

#include <random>
#include <regex>
#include <string>

#include "planner.h"

using namespace sc;

namespace {

const PlanError* error_of(const PlanResult& r) { return std::get_if<PlanError>(&r); }

}  // namespace

TEST(PlannerErrors, NeededDistanceIsTheShortestAcceptedDistance) {
  std::mt19937_64 g(77);
  std::uniform_real_distribution<double> u(0, 1);
  int checked = 0;
  for (int i = 0; i < 400 && checked < 60; ++i) {
    MoveRequest r;
    r.v_start = u(g) < 0.5 ? 0 : 1000 * u(g);
    r.v_cruise = 100 + 5000 * u(g);
    r.v_end = r.v_cruise * (1 + 30 * u(g));  // an end speed far above: needs a long move
    r.a_max = 1e3 + 1e6 * u(g);
    r.j_max = r.a_max * (1 + 100 * u(g));
    r.distance = 1 + int64_t(50 * u(g));
    const PlanResult p = plan_move(r, PulseTiming{});
    const PlanError* e = error_of(p);
    if (!e) continue;
    std::smatch m;
    if (!std::regex_search(e->message, m, std::regex("needs distance >= (\\d+)"))) continue;
    const int64_t need = std::stoll(m[1]);
    MoveRequest at = r, below = r;
    at.distance = need;
    below.distance = need - 1;
    EXPECT_TRUE(std::holds_alternative<Plan>(plan_move(at, PulseTiming{}))) << e->message;
    EXPECT_NE(error_of(plan_move(below, PulseTiming{})), nullptr) << e->message;
    ++checked;
  }
  EXPECT_GE(checked, 20);
}

TEST(PlannerErrors, ReportedCaseNamesItsTrueMinimum) {
  MoveRequest r;
  r.v_start = 0;
  r.v_cruise = 112.40568534959323;
  r.v_end = 174115.73120520223;
  r.a_max = 864790.1615411609;
  r.j_max = 8349448.036026655;
  r.distance = 549;
  const PlanResult p = plan_move(r, PulseTiming{});
  const PlanError* e = error_of(p);
  ASSERT_NE(e, nullptr);
  EXPECT_NE(e->message.find("needs distance >= 26551 pulses"), std::string::npos) << e->message;
  EXPECT_NE(e->message.find("v_end=174115.73120520223"), std::string::npos) << e->message;
}

TEST(PlannerErrors, ValuesAreShownAsGiven) {
  MoveRequest r;
  r.distance = 100;
  r.v_start = 200000.0001;
  r.v_cruise = 1000;
  r.a_max = 1000;
  r.j_max = 10000;
  const PlanResult p = plan_move(r, PulseTiming{});
  const PlanError* e = error_of(p);
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(e->parameter, "v_start");
  EXPECT_NE(e->message.find("v_start=200000.0001"), std::string::npos) << e->message;
}
