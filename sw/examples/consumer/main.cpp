// Plans paper 000 group 1 for a board clocked at 25 MHz, re-executes the
// table and prints the register writes that load it.
#include <cstdio>
#include <variant>

#include <scurve/planner.h>
#include <scurve/reg_encode.h>

int main() {
  scurve::MoveRequest req;
  req.distance = 30000;
  req.v_start = 1500;
  req.v_cruise = 3000;
  req.v_end = 0;
  req.a_max = 500;
  req.j_max = 2500;
  const scurve::Clock clock{25e6};
  const scurve::PlanResult r = scurve::Planner(clock).plan(req, scurve::PulseTiming{});
  if (const auto* e = std::get_if<scurve::Error>(&r)) {
    std::fprintf(stderr, "error: %s\n", e->message.c_str());
    return 2;
  }
  const scurve::Plan& plan = std::get<scurve::Plan>(r);
  const scurve::TableReport rep = scurve::run_table(plan.segments, plan.pos_frac0, 1);
  const auto writes = scurve::encode_move(plan, scurve::PulseTiming{});
  std::printf("rows %zu  clocks %llu at %.0f Hz  duration %.6f s  steps %lld of %lld  writes %zu\n",
              plan.segments.size(), static_cast<unsigned long long>(plan.total_clocks), plan.clock.hz,
              plan.duration_s, static_cast<long long>(rep.steps), static_cast<long long>(req.distance),
              writes.size());
  return rep.steps == req.distance ? 0 : 1;
}
