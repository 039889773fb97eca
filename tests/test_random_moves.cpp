// Endpoint exact by construction, proven over many seeded random requests:
// every accepted request, executed by the model's closed-form fast-forward,
// emits exactly |distance| steps, ends half a pulse past the last one and
// stays within every limit; every rejected request gets a one-line error that
// names a parameter (never an internal error).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

#include "planner.h"
#include "profile_exec.h"
#include "random_moves.h"

using namespace sc;

namespace {

// Execute the table on the bit-exact executor model with fast_forward().
struct ExecOutcome {
  int32_t steps = 0;
  u128 frac = 0;
  uint64_t clocks = 0;
  bool finished = false;
};
ExecOutcome execute_fast(const Plan& p) {
  ProfileExec ex;
  load_and_start(ex, p.segments, p.pos_frac0);
  ExecOutcome o;
  const int32_t p0 = ex.state().pint;
  // A finished executor stops fast_forward early; total_clocks + 1 covers
  // the clock that clears the last step request.
  ex.fast_forward(p.total_clocks + 1);
  o.steps = ex.state().pint - p0;
  o.frac = ex.state().frac;
  o.finished = ex.state().finished && !ex.state().run;
  return o;
}

void run_campaign(uint64_t seed, int moves) {
  std::mt19937_64 g(seed);
  std::map<std::string, int> rejected_by;
  int accepted = 0;
  for (int i = 0; i < moves; ++i) {
    const scurve::test::RandomRequest rr = scurve::test::random_request(g, model_clock());
    const MoveRequest& r = rr.req;
    const PulseTiming timing = to_model(rr.timing);
    const PlanResult res = plan_move(r, timing);
    if (const auto* e = std::get_if<PlanError>(&res)) {
      ASSERT_NE(e->parameter, "internal") << "seed " << seed << " move " << i << ": " << e->message;
      ASSERT_FALSE(e->parameter.empty());
      ASSERT_NE(e->message.find(e->parameter), std::string::npos) << e->message;
      ASSERT_EQ(e->message.find('\n'), std::string::npos);
      ++rejected_by[e->parameter];
      continue;
    }
    ++accepted;
    const Plan& p = std::get<Plan>(res);
    const ExecOutcome o = execute_fast(p);
    ASSERT_TRUE(o.finished) << "seed " << seed << " move " << i;
    ASSERT_EQ(o.steps, r.distance) << "seed " << seed << " move " << i;
    ASSERT_EQ(o.frac, kOne >> 1) << "ends mid-pulse; seed " << seed << " move " << i;
    // Limits, over every clock of the table (closed form, exact extremes).
    const int dir = r.distance < 0 ? -1 : 1;
    const TableReport rep = run_table(p.segments, p.pos_frac0, dir);
    ASSERT_GE(rep.min_signed_vel, 0) << "seed " << seed << " move " << i;
    const double v_cap = std::min(std::max({r.v_cruise, r.v_start, p.v_end_used}), step_rate_limit(timing));
    ASSERT_LE(vel_to_phys(rep.peak_vel), v_cap * (1 + 1e-12)) << "seed " << seed << " move " << i;
    ASSERT_LE(acc_to_phys(rep.peak_acc), r.a_max * (1 + 1e-12)) << "seed " << seed << " move " << i;
    if (r.kind == ProfileKind::SCurve) {
      ASSERT_LE(jerk_to_phys(rep.peak_jerk), scurve::test::jerk_cap(r) * (1 + 1e-12)) << "seed " << seed << " move " << i;
    }
  }
  // The campaign must exercise both outcomes substantially.
  EXPECT_GT(accepted, moves / 2);
  int rejected = 0;
  for (const auto& [param, n] : rejected_by) rejected += n;
  ::testing::Test::RecordProperty("accepted", accepted);
  ::testing::Test::RecordProperty("rejected", rejected);
  std::printf("seed %llu: %d moves, %d accepted, %d rejected (", static_cast<unsigned long long>(seed), moves,
              accepted, rejected);
  for (const auto& [param, n] : rejected_by) std::printf(" %s:%d", param.c_str(), n);
  std::printf(" )\n");
}

}  // namespace

// 100,000 moves in four seeded shards (ctest runs them in parallel).
TEST(RandomMoves, HundredThousandFastForwardShard0) { run_campaign(1001, 25000); }
TEST(RandomMoves, HundredThousandFastForwardShard1) { run_campaign(1002, 25000); }
TEST(RandomMoves, HundredThousandFastForwardShard2) { run_campaign(1003, 25000); }
TEST(RandomMoves, HundredThousandFastForwardShard3) { run_campaign(1004, 25000); }
