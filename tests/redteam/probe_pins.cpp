// Lockstep + pin checks for planned moves with unusual pulse timing.
// Each case: plan, run_move (RTL vs model every clock), print verdict.
#include <fmt/format.h>

#include "rt_util.h"
#include "sim_run.h"

using namespace sc;

int main(int argc, char** argv) {
  struct C { const char* name; MoveRequest r; PulseTiming t; };
  auto mk = [](int64_t L, double vs, double vc, double ve, double a, double j) {
    MoveRequest r; r.distance = L; r.v_start = vs; r.v_cruise = vc; r.v_end = ve; r.a_max = a; r.j_max = j; return r;
  };
  std::vector<C> cs;
  cs.push_back({"fwd, vs at rate limit, default timing", mk(1000, 200000, 200000, 0, 1e7, 1e10), PulseTiming{}});
  cs.push_back({"bwd, vs at rate limit, default timing", mk(-1000, 200000, 200000, 0, 1e7, 1e10), PulseTiming{}});
  cs.push_back({"bwd, vs at rate limit, setup 1000", mk(-1000, 200000, 200000, 0, 1e7, 1e10), PulseTiming{50, 50, 1000, 100}});
  cs.push_back({"bwd, vs half rate, setup 1000", mk(-1000, 100000, 100000, 0, 1e7, 1e10), PulseTiming{50, 50, 1000, 100}});
  cs.push_back({"bwd, from rest, h=l=1, setup 65535", mk(-20000, 0, 1e7, 0, 1e8, 1e11), PulseTiming{1, 1, 65535, 0}});
  cs.push_back({"bwd, from rest, default pulse, setup 65535", mk(-20000, 0, 200000, 0, 1e8, 1e11), PulseTiming{50, 50, 65535, 100}});
  cs.push_back({"fwd, h=l=1 at limit", mk(5000, 1e7, 1e7, 1e7, 1e8, 1e11), PulseTiming{1, 1, 0, 0}});
  cs.push_back({"bwd, h=l=1 at limit setup 0", mk(-5000, 1e7, 1e7, 1e7, 1e8, 1e11), PulseTiming{1, 1, 0, 0}});
  cs.push_back({"bwd, h=l=1 at limit setup 1", mk(-5000, 1e7, 1e7, 1e7, 1e8, 1e11), PulseTiming{1, 1, 1, 0}});
  cs.push_back({"bwd, h=65535 l=1", mk(-20, 0, 20e6 / 65536, 0, 1e4, 1e8), PulseTiming{65535, 1, 65535, 65535}});
  cs.push_back({"bwd, h=1 l=65535", mk(-20, 300, 20e6 / 65536, 300, 1e4, 1e8), PulseTiming{1, 65535, 0, 65535}});
  cs.push_back({"bwd, hold 65535 (no effect single move)", mk(-2000, 0, 200000, 0, 1e6, 1e9), PulseTiming{50, 50, 0, 65535}});
  cs.push_back({"a/j<1clk: vs=vc ve=0 (dead stop)", mk(1000, 1000, 1000, 0, 100, 1e10), PulseTiming{}});
  cs.push_back({"bwd, constant speed at rate limit, default timing", mk(-1000, 200000, 200000, 200000, 1e7, 1e10), PulseTiming{}});
  cs.push_back({"bwd, constant 150k, default timing", mk(-1000, 150000, 150000, 150000, 1e7, 1e10), PulseTiming{}});
  cs.push_back({"bwd, paper g2 speeds (3000->1500->0), setup 20000 (1 ms)", mk(-30000, 3000, 1500, 0, 500, 2500), PulseTiming{50, 50, 20000, 100}});
  cs.push_back({"bwd, vs 100k->0, setup 800 (40 us)", mk(-3000, 100000, 100000, 0, 1e7, 1e10), PulseTiming{50, 50, 800, 100}});
  const bool only = argc > 1;
  int fails = 0;
  for (size_t i = 0; i < cs.size(); ++i) {
    if (only && std::stoul(argv[1]) != i) continue;
    const C& c = cs[i];
    PlanResult pr = plan_move(c.r, c.t);
    std::printf("== [%zu] %s\n   %s\n", i, c.name, rt::describe(c.r, c.t).c_str());
    if (auto* e = std::get_if<PlanError>(&pr)) { std::printf("   REJECTED %s\n", e->message.c_str()); continue; }
    const Plan& p = std::get<Plan>(pr);
    Limits4Check l;
    l.v_max = std::max({c.r.v_cruise, c.r.v_start, p.v_end_used});
    l.a_max = c.r.a_max;
    l.j_max = c.r.j_max;
    SimResult s = run_move(p, c.t, l, SimOptions{});
    std::printf("   plan %llu clocks; sim: %s, pulses %lld, mismatches %llu, done-clock %llu (plan end %llu)\n",
                (unsigned long long)p.total_clocks, s.pass() ? "PASS" : "FAIL", (long long)s.pulses,
                (unsigned long long)s.mismatches, (unsigned long long)s.clocks, (unsigned long long)(p.total_clocks));
    for (size_t k = 0; k < s.failures.size() && k < 4; ++k) std::printf("   ! %s\n", s.failures[k].c_str());
    if (!s.pass()) ++fails;
  }
  return fails ? 1 : 0;
}
