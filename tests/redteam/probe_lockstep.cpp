// Random planned moves through RTL+model lockstep with pin checks.
// Usage: probe_lockstep SEED N SETUPMAX MAXCLOCKS
#include <map>
#include <random>

#include "rt_util.h"
#include "sim_run.h"

using namespace sc;
using scurve::test::log_uniform;

int main(int argc, char** argv) {
  const uint64_t seed = argc > 1 ? std::stoull(argv[1]) : 1;
  const int n = argc > 2 ? std::stoi(argv[2]) : 100;
  const int setup_max = argc > 3 ? std::stoi(argv[3]) : 65535;
  const uint64_t max_clocks = argc > 4 ? std::stoull(argv[4]) : 3'000'000;
  std::mt19937_64 g(seed);
  int runs = 0, fails = 0, tries = 0;
  uint64_t clocks = 0;
  std::map<std::string, int> kinds;
  while (runs < n && tries < 200 * n) {
    ++tries;
    PulseTiming t;
    const int tc = int(g() % 10);
    if (tc < 4) { t.high = uint16_t(1 + g() % 8); t.low = uint16_t(1 + g() % 8); }
    else if (tc < 8) { t.high = uint16_t(1 + g() % 300); t.low = uint16_t(1 + g() % 300); }
    else { t.high = uint16_t(1 + g() % 65535); t.low = uint16_t(1 + g() % 65535); }
    t.setup = uint16_t(g() % (setup_max + 1));
    t.hold = uint16_t(g() % 65536);
    const double vl = step_rate_limit(t);
    auto speed = [&](bool z) { int c = int(g() % 10); if (z && c < 3) return 0.0; if (c < 5) return vl; return log_uniform(g, std::min(1.0, vl), vl); };
    MoveRequest r;
    r.distance = int64_t(std::llround(log_uniform(g, 1, 50000))) * (g() % 2 ? -1 : 1);
    r.v_start = speed(true); r.v_cruise = speed(false); r.v_end = g() % 5 == 0 ? r.v_start : speed(true);
    r.a_max = vl * log_uniform(g, 1, 1e4);
    r.j_max = std::min(1e11, r.a_max * log_uniform(g, 1, 1e5));
    if (g() % 5 == 0) r.kind = ProfileKind::Trapezoid;
    if (g() % 5 == 0) { std::array<double, 4> js; for (auto& x : js) x = std::min(1e11, r.a_max * log_uniform(g, 1, 1e5)); r.jerks = js; r.j_max = std::max({js[0], js[1], js[2], js[3]}); }
    r.adjust_end_speed = g() % 5 == 0;
    if (r.a_max > 1e8) continue;
    PlanResult pr = plan_move(r, t);
    if (!std::holds_alternative<Plan>(pr)) continue;
    const Plan& p = std::get<Plan>(pr);
    if (p.total_clocks > max_clocks) continue;
    Limits4Check l;
    l.v_max = std::max({r.v_cruise, r.v_start, p.v_end_used});
    l.a_max = r.a_max;
    if (r.kind == ProfileKind::SCurve) l.j_max = r.j_max;
    SimResult s = run_move(p, t, l, SimOptions{});
    ++runs;
    clocks += s.total_clocks;
    if (!s.pass()) {
      ++fails;
      std::string k = s.failures[0].substr(s.failures[0].find(':') == std::string::npos ? 0 : 0, 40);
      for (auto& f : s.failures) {
        std::string kk = f.find("mismatch") != std::string::npos ? "mismatch"
                         : f.find("pulses") == 0 ? "pulse count"
                         : f.find("cruise: pulse interval") != std::string::npos ? "cruise interval varies"
                         : f.find("duty trend") != std::string::npos ? "duty trend"
                         : f.find("DIR setup") != std::string::npos ? "DIR setup"
                         : f.find("DIR hold") != std::string::npos ? "DIR hold"
                         : f.find("STEP low") != std::string::npos ? "STEP low"
                         : f.find("STEP high") != std::string::npos ? "STEP high"
                         : f.find("after done") != std::string::npos ? "pulse after done"
                         : f.find("peak") == 0 ? f.substr(0, 18) : f.substr(0, 30);
        ++kinds[kk];
      }
      if (fails <= 12) {
        std::printf("FAIL %s\n", rt::describe(r, t).c_str());
        for (size_t k2 = 0; k2 < s.failures.size() && k2 < 3; ++k2) std::printf("   ! %s\n", s.failures[k2].c_str());
      }
    }
  }
  std::printf("seed %llu: %d lockstep runs (%llu clocks), %d failed:", (unsigned long long)seed, runs, (unsigned long long)clocks, fails);
  for (auto& [k, v] : kinds) std::printf(" [%s]:%d", k.c_str(), v);
  std::printf("\n");
}
