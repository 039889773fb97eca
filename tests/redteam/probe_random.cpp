// Random campaign: planner guarantees (exact endpoint, limits, no internal
// error, one-line errors, planning time) + time-optimality against an
// independent double-precision reference.  Usage: probe_random SEED N
#include <map>
#include <random>

#include "ref_time.h"
#include "rt_util.h"

using namespace sc;
using scurve::test::log_uniform;

int main(int argc, char** argv) {
  const uint64_t seed = argc > 1 ? std::stoull(argv[1]) : 1;
  const int n = argc > 2 ? std::stoi(argv[2]) : 10000;
  const int mode = argc > 3 ? std::stoi(argv[3]) : 0;  // 0 wide, 1 realistic (a/j ratio sane)
  std::mt19937_64 g(seed);
  std::uniform_int_distribution<int> coin(0, 99);
  int acc = 0, rej = 0, bad = 0, slow = 0, fast = 0, slowplan = 0;
  double worst_plan_ms = 0;
  std::map<std::string, int> rejected_by;
  for (int i = 0; i < n; ++i) {
    PulseTiming t;
    const int tc = coin(g);
    if (tc < 40) { t.high = uint16_t(1 + g() % 200); t.low = uint16_t(1 + g() % 200); }
    else if (tc < 70) { t.high = uint16_t(1 + g() % 65535); t.low = uint16_t(1 + g() % 65535); }
    else { t.high = uint16_t(1 + g() % 4); t.low = uint16_t(1 + g() % 4); }
    t.setup = uint16_t(g() % 65536);
    t.hold = uint16_t(g() % 65536);
    const double vlim = step_rate_limit(t);
    auto speed = [&](bool zero) {
      const int c = coin(g);
      if (zero && c < 30) return 0.0;
      if (c < 40) return vlim;
      return log_uniform(g, std::min(1e-3, vlim), vlim);
    };
    MoveRequest r;
    r.distance = int64_t(std::llround(log_uniform(g, 1, 2147483646.0)));
    if (coin(g) < 50) r.distance = -r.distance;
    r.v_start = speed(true);
    r.v_cruise = speed(false);
    r.v_end = coin(g) < 15 ? r.v_start : speed(true);
    r.a_max = log_uniform(g, 0.01, 1e8);
    if (mode == 1) r.j_max = r.a_max * log_uniform(g, 0.1, 1e5);
    else r.j_max = log_uniform(g, 10, 1e11);
    r.kind = coin(g) < 15 ? ProfileKind::Trapezoid : ProfileKind::SCurve;
    if (coin(g) < 20) {
      std::array<double, 4> js;
      for (auto& x : js) x = mode == 1 ? std::min(1e11, std::max(10.0, r.a_max * log_uniform(g, 0.1, 1e5))) : log_uniform(g, 10, 1e11);
      r.jerks = js;
    }
    r.adjust_end_speed = coin(g) < 15;
    rt::Outcome o = rt::run(r, t, 2'000'000);
    worst_plan_ms = std::max(worst_plan_ms, o.plan_ms);
    if (o.plan_ms > 100) ++slowplan;
    if (!o.accepted) {
      ++rej;
      ++rejected_by[o.err.parameter];
      if (!o.problems.empty()) { ++bad; std::printf("BAD  %s\n     %s [%s] %.1f ms %s\n", rt::describe(r, t).c_str(), o.problems.c_str(), o.err.parameter.c_str(), o.plan_ms, o.err.message.c_str()); }
      continue;
    }
    ++acc;
    // end velocity reached?
    const double ve_req = o.plan.v_end_used;
    const double ve_err = std::fabs(o.plan.v_end_actual - ve_req);
    const double ve_tol = std::max(1e-6 * std::max(1.0, ve_req), r.a_max / 20e6 * 1.0000001);
    if (ve_err > ve_tol) o.problems += "end speed " + std::to_string(o.plan.v_end_actual) + " != " + std::to_string(ve_req) + "; ";
    if (!o.problems.empty()) {
      ++bad;
      std::printf("BAD  %s\n     %s (plan %.1f ms, rows %zu, %.6g s)\n", rt::describe(r, t).c_str(), o.problems.c_str(), o.plan_ms, o.plan.segments.size(), o.plan.duration_s);
      continue;
    }
    // time optimality
    const double j4[4] = {r.jerks ? (*r.jerks)[0] : r.j_max, r.jerks ? (*r.jerks)[1] : r.j_max,
                          r.jerks ? (*r.jerks)[2] : r.j_max, r.jerks ? (*r.jerks)[3] : r.j_max};
    const double p0 = double(r.distance > 0 ? o.plan.pos_frac0 : kOne - o.plan.pos_frac0) / double(kOne);
    const double L = double(std::llabs(r.distance)) + 0.5 - p0;
    rt::RefPlan rp = rt::ref_plan(L, r.v_start, r.v_cruise, ve_req, r.a_max, j4, r.kind == ProfileKind::Trapezoid, vlim);
    if (!rp.ok) continue;
    const double ratio = o.plan.duration_s / rp.T;
    const double slack = 3.0 * o.plan.segments.size() / 20e6 / rp.T;  // a few clocks of rounding
    if (ratio > 1.01 + slack) {
      ++slow;
      if (slow <= 30) std::printf("SLOW %.4fx  %s\n     plan %.6g s vp %.9g | ref %.6g s vp %.9g\n", ratio, rt::describe(r, t).c_str(), o.plan.duration_s, o.plan.v_plateau, rp.T, rp.vp);
    } else if (ratio < 0.99 - slack) {
      ++fast;
      if (fast <= 30) std::printf("FAST %.4fx  %s\n     plan %.6g s vp %.9g | ref %.6g s vp %.9g\n", ratio, rt::describe(r, t).c_str(), o.plan.duration_s, o.plan.v_plateau, rp.T, rp.vp);
    }
  }
  std::printf("seed %llu: %d requests, %d accepted, %d rejected (", (unsigned long long)seed, n, acc, rej);
  for (auto& [k, v] : rejected_by) std::printf(" %s:%d", k.c_str(), v);
  std::printf(" ), %d bad, %d slower >1%%, %d faster >1%%, %d plans >100ms, worst plan %.1f ms\n", bad, slow, fast, slowplan, worst_plan_ms);
}
