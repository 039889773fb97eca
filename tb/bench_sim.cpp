// Throughput benchmark: simulated clocks per second of CPU time, and the ratio to
// real time (20 M clocks/s), for each engine on the same move. Run with
//   build/bin/bench_sim --benchmark_out=bench.json --benchmark_out_format=json
// Rates use the thread's CPU time (robust to other processes time-slicing
// the machine; on a quiet machine it equals wall time).
// The move: paper group 1's speeds (1500 -> 3000 -> 0 pulses/s) over 12,000
// pulses with a = 2000, j = 10000: about 5.9 s = 118 M clocks of motion.
// The stream (BM_Stream*): 40 moves of 2,000-6,000 pulses in both
// directions at 20,000-60,000 pulses/s with look-ahead junction speeds, the
// host pushing a row whenever the FIFO has room (about 34 M clocks).
// The two-axis line (BM_TwoAxisLine*): 20,000 and -12,000 pulses on the
// multi-axis core at 40,000 pulses/s along the path (about 13 M clocks).
#include <benchmark/benchmark.h>

#include <random>
#include <utility>

#include "multi_run.h"
#include "planner.h"
#include "sim_run.h"
#include "stream_run.h"

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

// Runs `once` (simulated clocks, checks passed) per iteration and reports
// simulated clocks per CPU second and the ratio to real time.
template <class Run>
void measure(benchmark::State& state, Run once) {
  uint64_t clocks = 0;
  bool pass = true;
  for (auto _ : state) {
    const auto [n, ok] = once();
    clocks += n;
    pass = pass && ok;
  }
  if (!pass) state.SkipWithError("the simulation failed its checks");
  state.counters["clk_per_s"] = benchmark::Counter(double(clocks), benchmark::Counter::kIsRate);
  state.counters["x_realtime"] =
      benchmark::Counter(double(clocks) / double(ClkHz), benchmark::Counter::kIsRate);
}

void run(benchmark::State& state, SimEngine engine) {
  SimOptions opt;
  opt.engine = engine;
  measure(state, [&] {
    const SimResult r = run_move(bench_plan(), PulseTiming{}, Limits4Check{}, opt);
    return std::pair{r.total_clocks, r.pass()};
  });
}

const StreamRequest& bench_stream_request() {
  static const StreamRequest req = [] {
    StreamRequest r;
    r.limits = scurve::StreamLimits(2e6, 4e8, 60000);
    std::mt19937_64 g(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 40; ++i) {
      const int dir = i % 7 < 4 ? 1 : -1;
      r.moves.push_back({dir * int64_t(2000 + 4000 * u(g)), 20000 + 40000 * u(g), 60000});
    }
    return r;
  }();
  return req;
}

void run_stream_bench(benchmark::State& state, SimEngine engine) {
  const StreamRequest& req = bench_stream_request();
  const auto planned = plan_stream(req, PulseTiming{});
  const auto codes = scurve::stop_limit_codes(req.limits.j_max, req.limits.a_max);
  if (!std::holds_alternative<PlannedStream>(planned) || !std::holds_alternative<scurve::StopLimitCodes>(codes)) {
    state.SkipWithError("the stream does not plan");
    return;
  }
  const scurve::StopLimitCodes& c = std::get<scurve::StopLimitCodes>(codes);
  measure(state, [&] {
    const StreamRunResult r = run_stream(std::get<PlannedStream>(planned), req, PulseTiming{}, engine, c.jerk, c.acc);
    return std::pair{r.clocks, r.pass()};
  });
}

void run_two_axis_line(benchmark::State& state, bool rtl) {
  static const MultiRows rows = [] {
    scurve::LineRequest r;
    r.distances = {20000, -12000};
    r.v_path = 40000;
    r.a_path = 2e6;
    r.j_path = 4e8;
    return line_rows(std::get<scurve::LinePlan>(scurve::plan_line(scurve::Planner{model_clock()}, r,
                                                                   to_host(PulseTiming{}))));
  }();
  MultiRunOptions opt;
  opt.rtl = rtl;
  opt.measure_line = false;
  measure(state, [&] {
    const MultiRunResult r = run_multi(rows, opt);
    return std::pair{r.clocks, r.ok() && r.ref_pos[0] == 20000 && r.ref_pos[1] == -12000};
  });
}

void BM_Lockstep(benchmark::State& s) { run(s, SimEngine::Lockstep); }
void BM_RtlOnly(benchmark::State& s) { run(s, SimEngine::RtlOnly); }
void BM_ModelOnly(benchmark::State& s) { run(s, SimEngine::ModelOnly); }
void BM_ModelFastForward(benchmark::State& s) { run(s, SimEngine::ModelFast); }
void BM_StreamLockstep(benchmark::State& s) { run_stream_bench(s, SimEngine::Lockstep); }
void BM_StreamRtlOnly(benchmark::State& s) { run_stream_bench(s, SimEngine::RtlOnly); }
void BM_TwoAxisLineLockstep(benchmark::State& s) { run_two_axis_line(s, true); }
void BM_TwoAxisLineModelOnly(benchmark::State& s) { run_two_axis_line(s, false); }

BENCHMARK(BM_Lockstep)->Unit(benchmark::kSecond)->Iterations(2);
BENCHMARK(BM_RtlOnly)->Unit(benchmark::kSecond)->Iterations(2);
BENCHMARK(BM_ModelOnly)->Unit(benchmark::kSecond)->Iterations(2);
BENCHMARK(BM_ModelFastForward)->Unit(benchmark::kMillisecond)->Iterations(20);
BENCHMARK(BM_StreamLockstep)->Unit(benchmark::kSecond)->Iterations(2);
BENCHMARK(BM_StreamRtlOnly)->Unit(benchmark::kSecond)->Iterations(2);
BENCHMARK(BM_TwoAxisLineLockstep)->Unit(benchmark::kSecond)->Iterations(2);
BENCHMARK(BM_TwoAxisLineModelOnly)->Unit(benchmark::kSecond)->Iterations(2);

}  // namespace

BENCHMARK_MAIN();
