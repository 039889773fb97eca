// Throughput benchmark: simulated clocks per second of CPU time, and the ratio to
// real time (20 M clocks/s), for each engine on the same move. Run with
//   build/bin/bench_sim --benchmark_out=bench.json --benchmark_out_format=json
// Rates use the thread's CPU time (robust to other processes time-slicing
// the machine; on a quiet machine it equals wall time).
// The move: paper group 1's speeds (1500 -> 3000 -> 0 pulses/s) over 12,000
// pulses with a = 2000, j = 10000: about 5.9 s = 118 M clocks of motion.
#include <benchmark/benchmark.h>

#include "planner.h"
#include "sim_run.h"

namespace {

using namespace sc;

const Plan& bench_plan() {
  static const Plan plan = [] {
    MoveRequest r;
    r.distance = 12000;
    r.v_start = 1500;
    r.v_cruise = 3000;
    r.v_end = 0;
    r.a_max = 2000;
    r.j_max = 10000;
    return std::get<Plan>(plan_move(r, PulseTiming{}));
  }();
  return plan;
}

void run(benchmark::State& state, SimEngine engine) {
  SimOptions opt;
  opt.engine = engine;
  uint64_t clocks = 0;
  bool pass = true;
  for (auto _ : state) {
    const SimResult r = run_move(bench_plan(), PulseTiming{}, Limits4Check{}, opt);
    clocks += r.total_clocks;
    pass = pass && r.pass();
  }
  if (!pass) state.SkipWithError("simulation failed its checks");
  state.counters["clk_per_s"] = benchmark::Counter(double(clocks), benchmark::Counter::kIsRate);
  state.counters["x_realtime"] =
      benchmark::Counter(double(clocks) / double(ClkHz), benchmark::Counter::kIsRate);
}

void BM_Lockstep(benchmark::State& s) { run(s, SimEngine::Lockstep); }
void BM_RtlOnly(benchmark::State& s) { run(s, SimEngine::RtlOnly); }
void BM_ModelOnly(benchmark::State& s) { run(s, SimEngine::ModelOnly); }
void BM_ModelFastForward(benchmark::State& s) { run(s, SimEngine::ModelFast); }

BENCHMARK(BM_Lockstep)->Unit(benchmark::kSecond)->Iterations(2);
BENCHMARK(BM_RtlOnly)->Unit(benchmark::kSecond)->Iterations(2);
BENCHMARK(BM_ModelOnly)->Unit(benchmark::kSecond)->Iterations(2);
BENCHMARK(BM_ModelFastForward)->Unit(benchmark::kMillisecond)->Iterations(20);

}  // namespace

BENCHMARK_MAIN();
