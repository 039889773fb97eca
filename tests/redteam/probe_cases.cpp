// Hand-picked edge cases: print each outcome.
#include "rt_util.h"

using namespace sc;

int main() {
  struct C { const char* name; MoveRequest r; PulseTiming t; };
  auto mk = [](int64_t L, double vs, double vc, double ve, double a, double j) {
    MoveRequest r; r.distance = L; r.v_start = vs; r.v_cruise = vc; r.v_end = ve; r.a_max = a; r.j_max = j; return r;
  };
  std::vector<C> cs;
  PulseTiming d{};
  cs.push_back({"paper g1", mk(30000, 1500, 3000, 0, 500, 2500), d});
  cs.push_back({"jerk >> 2e7*a, rest-to-rest", mk(1000, 0, 1000, 0, 100, 1e10), d});
  cs.push_back({"jerk >> 2e7*a, vs=vc, ve=0", mk(1000, 1000, 1000, 0, 100, 1e10), d});
  cs.push_back({"jerk >> 2e7*a, vs=0 vc ve", mk(100000, 0, 1000, 1000, 100, 1e10), d});
  cs.push_back({"jerk = 2e7*a exactly", mk(1000, 0, 1000, 0, 100, 2e9), d});
  cs.push_back({"jerk = 1e7*a", mk(1000, 0, 1000, 0, 100, 1e9), d});
  cs.push_back({"tiny ve, huge jerk", mk(1000, 0, 1000, 1e-4, 1e8, 1e11), d});
  cs.push_back({"tiny vs, ve 0", mk(1000, 1e-4, 1e-4, 0, 1e8, 1e11), d});
  cs.push_back({"max distance", mk((int64_t(1) << 31) - 2, 0, 200000, 0, 1e8, 1e11), d});
  cs.push_back({"max distance slow", mk((int64_t(1) << 31) - 2, 0, 1000, 0, 1e3, 1e5), d});
  cs.push_back({"min a, min j", mk(10, 0, 1, 0, 0.01, 10), d});
  cs.push_back({"min a, min j long", mk(100000, 0, 10, 0, 0.01, 10), d});
  cs.push_back({"distance 1", mk(1, 0, 200000, 0, 1e8, 1e11), d});
  cs.push_back({"distance -1", mk(-1, 0, 200000, 0, 1e8, 1e11), d});
  cs.push_back({"distance 1 slow", mk(1, 0, 1, 0, 0.01, 10), d});
  cs.push_back({"vs at limit, ve at limit, L=1", mk(1, 200000, 200000, 200000, 1e8, 1e11), d});
  cs.push_back({"vs at limit, stop L=1", mk(1, 200000, 200000, 0, 1e8, 1e11), d});
  PulseTiming fast{1, 1, 0, 0};
  cs.push_back({"h=l=1, vs=1e7", mk(-5, 1e7, 1e7, 1e7, 1e8, 1e11), fast});
  cs.push_back({"h=l=1, rest", mk(-123456, 0, 1e7, 0, 1e8, 1e11), fast});
  PulseTiming slow{65535, 65535, 65535, 65535};
  cs.push_back({"h=l=65535", mk(-10, 0, 20e6 / 131070, 0, 1e3, 1e5), slow});
  cs.push_back({"trapezoid tiny", mk(3, 0, 1000, 0, 1e8, 0), d});
  cs.back().r.kind = ProfileKind::Trapezoid;
  cs.push_back({"vs > vc short", mk(200, 3000, 100, 0, 500, 2500), d});
  cs.push_back({"ve > vc", mk(30000, 0, 1500, 3000, 500, 2500), d});
  cs.push_back({"adjust ve", mk(5000, 0, 3000, 3000, 500, 2500), d});
  cs.back().r.adjust_end_speed = true;
  cs.push_back({"adjust ve up when braking", mk(100, 3000, 3000, 0, 500, 2500), d});
  cs.back().r.adjust_end_speed = true;
  cs.push_back({"asym extreme", mk(50000, 0, 5000, 0, 1e4, 1e5), d});
  cs.back().r.jerks = std::array<double, 4>{10, 1e11, 1e11, 10};
  cs.push_back({"asym extreme 2", mk(50000, 0, 5000, 0, 1e4, 1e5), d});
  cs.back().r.jerks = std::array<double, 4>{1e11, 10, 10, 1e11};
  for (auto& c : cs) {
    rt::Outcome o = rt::run(c.r, c.t);
    std::printf("== %s: %s\n   %s\n", c.name, rt::describe(c.r, c.t).c_str(),
                o.accepted ? "ACCEPTED" : ("REJECTED [" + o.err.parameter + "] " + o.err.message).c_str());
    if (o.accepted)
      std::printf("   plan %.2f ms, rows %zu, clocks %llu (%.4f s), steps %lld, peak v %.6g a %.6g j %.6g, end_v %.6g, v_end_actual %.6g, plateau %.6g\n",
                  o.plan_ms, o.plan.segments.size(), (unsigned long long)o.plan.total_clocks, o.plan.duration_s,
                  (long long)o.steps, o.peak_v, o.peak_a, o.peak_j, o.end_v, o.plan.v_end_actual, o.plan.v_plateau);
    else std::printf("   plan %.2f ms\n", o.plan_ms);
    if (!o.problems.empty()) std::printf("   PROBLEMS: %s\n", o.problems.c_str());
  }
}
