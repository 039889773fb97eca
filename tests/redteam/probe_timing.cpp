// Planning time: adversarial requests (adjust_end_speed bisection x
// geometric plateau walk) and a random search for the slowest request.
#include <random>

#include "rt_util.h"

using namespace sc;
using scurve::test::log_uniform;

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::stoi(argv[1]) : 2000;
  auto show = [](const MoveRequest& r, const PulseTiming& t) {
    rt::Outcome o = rt::run(r, t, 0);
    std::printf("%8.1f ms  %s  -> %s\n", o.plan_ms, rt::describe(r, t).c_str(),
                o.accepted ? "accepted" : o.err.message.c_str());
    return o.plan_ms;
  };
  MoveRequest r;
  PulseTiming t{1, 1, 0, 0};
  r.distance = 1; r.v_start = 0; r.v_cruise = 1e7; r.v_end = 1e7; r.a_max = 1e8; r.j_max = 1e11; r.adjust_end_speed = true;
  show(r, t);
  r.distance = 1000; show(r, t);
  r.distance = 100000; show(r, t);
  r.v_start = 1e7; r.v_end = 0; r.distance = 3; show(r, t);
  r.v_start = 1e7; r.v_end = 0; r.distance = 3000; show(r, t);
  r.v_start = 0; r.v_end = 1e7; r.a_max = 0.01; r.j_max = 10; r.distance = 2147483646; show(r, t);
  // random search biased to adjust_end_speed and far-apart speeds
  std::mt19937_64 g(7);
  double worst = 0;
  MoveRequest wr; PulseTiming wt;
  for (int i = 0; i < n; ++i) {
    PulseTiming tt; tt.high = uint16_t(1 + g() % 100); tt.low = uint16_t(1 + g() % 100);
    const double vl = step_rate_limit(tt);
    MoveRequest q;
    q.distance = int64_t(std::llround(log_uniform(g, 1, 2e9))) * (g() % 2 ? 1 : -1);
    q.v_start = g() % 2 ? 0.0 : log_uniform(g, 1e-3, vl);
    q.v_cruise = g() % 3 ? vl : log_uniform(g, 1e-3, vl);
    q.v_end = g() % 2 ? vl : log_uniform(g, 1e-3, vl);
    q.a_max = log_uniform(g, 0.01, 1e8);
    q.j_max = log_uniform(g, 10, 1e11);
    if (g() % 4 == 0) { std::array<double, 4> js; for (auto& x : js) x = log_uniform(g, 10, 1e11); q.jerks = js; }
    if (g() % 5 == 0) q.kind = ProfileKind::Trapezoid;
    q.adjust_end_speed = true;
    const auto t0 = std::chrono::steady_clock::now();
    (void)plan_move(q, tt);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (ms > worst) { worst = ms; wr = q; wt = tt; }
  }
  std::printf("random (%d, adjust_end_speed): worst %.1f ms\n", n, worst);
  show(wr, wt);
}
