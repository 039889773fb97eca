// Host planner throughput:
//   * single-move planning: the median time per plan() over a fixed random
//     set of accepted requests (counter median_us, net_median_us without the
//     timer's own cost; the framework's time is the mean over the set;
//     max_us the slowest request), and per plan_from() from an exact start
//     state,
//   * stream planning with look-ahead: moves planned per second (counter
//     moves_per_s), appending, handing out and finally flushing the stream.
// Run: bin/bench_planner --benchmark_out=bench.json --benchmark_out_format=json
// Times are the thread's CPU time, robust to other processes on the machine.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <random>
#include <vector>

#include "../tests/random_moves.h"
#include "scurve/planner.h"
#include "scurve/stream_planner.h"

namespace {

using namespace scurve;

double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// The timer's own cost: the median of an empty interval. The thread CPU
// clock is a system call on some machines (about 1 us), which every
// per-plan time below includes.
double timer_overhead() {
  static const double t = [] {
    std::vector<double> d(2001);
    for (double& x : d) {
      const double t0 = thread_cpu_seconds();
      x = thread_cpu_seconds() - t0;
    }
    std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
    return d[d.size() / 2];
  }();
  return t;
}

// Per-plan times of a set of requests planned in turn (call k plans request
// k mod n). median_us: the median per-plan time, net_median_us the same less
// the timer's own cost (timer_us); max_us: the slowest request (the median of
// its repetitions: a single call can take a page fault or an interrupt of the
// loaded machine), max_call_us the slowest single call.
void report_per_plan(benchmark::State& state, std::vector<double>& per_plan, size_t n_requests) {
  if (per_plan.empty()) return;
  const double worst_call = *std::max_element(per_plan.begin(), per_plan.end());
  std::vector<std::vector<double>> by_request(n_requests);
  for (size_t i = 0; i < per_plan.size(); ++i) by_request[i % n_requests].push_back(per_plan[i]);
  double worst = 0;
  for (std::vector<double>& t : by_request) {
    if (t.empty()) continue;
    std::nth_element(t.begin(), t.begin() + t.size() / 2, t.end());
    worst = std::max(worst, t[t.size() / 2]);
  }
  std::nth_element(per_plan.begin(), per_plan.begin() + per_plan.size() / 2, per_plan.end());
  const double median = per_plan[per_plan.size() / 2];
  state.counters["median_us"] = median * 1e6;
  state.counters["net_median_us"] = (median - timer_overhead()) * 1e6;
  state.counters["timer_us"] = timer_overhead() * 1e6;
  state.counters["max_us"] = worst * 1e6;
  state.counters["max_call_us"] = worst_call * 1e6;
}

// 1000 random requests the planner accepts (the generator of the unit tests).
const std::vector<test::RandomRequest>& accepted_requests() {
  static const std::vector<test::RandomRequest> set = [] {
    std::mt19937_64 g(11);
    std::vector<test::RandomRequest> out;
    const Planner planner;
    while (out.size() < 1000) {
      test::RandomRequest rr = test::random_request(g, Clock{});
      if (std::holds_alternative<Plan>(planner.plan(rr.req, rr.timing))) out.push_back(rr);
    }
    return out;
  }();
  return set;
}

void BM_PlanSingleMove(benchmark::State& state) {
  const auto& set = accepted_requests();
  const Planner planner;
  std::vector<double> per_plan;
  per_plan.reserve(1 << 16);
  size_t i = 0;
  for (auto _ : state) {
    const auto& rr = set[i++ % set.size()];
    const double t0 = thread_cpu_seconds();
    PlanResult r = planner.plan(rr.req, rr.timing);
    const double t1 = thread_cpu_seconds();
    benchmark::DoNotOptimize(r);
    if (per_plan.size() < per_plan.capacity()) per_plan.push_back(t1 - t0);
  }
  report_per_plan(state, per_plan, set.size());
}
BENCHMARK(BM_PlanSingleMove)->MinTime(2.0);

// The same requests planned from an exact start state (plan_from, as the
// stream plans each move): start speed v_start in LSB, a random fraction.
// Times plan(k) for k = 0, 1, ... over a set of n requests (thread CPU
// time per call) and reports the per-plan distribution and the share
// accepted.
template <class PlanFn>
void time_each_plan(benchmark::State& state, size_t n, PlanFn plan) {
  std::vector<double> per_plan;
  per_plan.reserve(1 << 16);
  size_t i = 0, accepted = 0;
  for (auto _ : state) {
    const size_t k = i++ % n;
    const double t0 = thread_cpu_seconds();
    PlanResult r = plan(k);
    const double t1 = thread_cpu_seconds();
    accepted += std::holds_alternative<Plan>(r);
    benchmark::DoNotOptimize(r);
    if (per_plan.size() < per_plan.capacity()) per_plan.push_back(t1 - t0);
  }
  report_per_plan(state, per_plan, n);
  state.counters["accepted"] = i ? double(accepted) / double(i) : 0.0;
}

void BM_PlanFromExactState(benchmark::State& state) {
  const auto& set = accepted_requests();
  const Planner planner;
  std::mt19937_64 g(13);
  std::vector<JunctionState> starts;
  for (const auto& rr : set) {
    const int dir = rr.req.distance < 0 ? -1 : 1;
    JunctionState st;
    st.velocity = dir * i128(std::floor(rr.req.v_start * vel_lsb_per_unit(Clock{})));
    st.frac = (u128(g()) << 16) & (kOne - 1);
    starts.push_back(st);
  }
  time_each_plan(state, set.size(), [&](size_t k) { return planner.plan_from(starts[k], set[k].req, set[k].timing); });
}
BENCHMARK(BM_PlanFromExactState)->MinTime(2.0);

// The same starts with an acceleration (plan_from_state, a move retargeted on
// the fly): up to the acceleration limit, either sign, small enough that
// ending it at the jerk limit keeps the speed within 0 .. v_start + its own.
void BM_PlanFromStateWithAcceleration(benchmark::State& state) {
  const auto& set = accepted_requests();
  const Planner planner;
  std::mt19937_64 g(14);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<ExactState> starts;
  for (const auto& rr : set) {
    const int dir = rr.req.distance < 0 ? -1 : 1;
    const Clock c{};
    ExactState st;
    const double v = std::floor(rr.req.v_start * vel_lsb_per_unit(c));
    st.velocity = dir * i128(v);
    const double j = std::floor(rr.req.j_max * jerk_lsb_per_unit(c));
    const double a_max = std::floor(rr.req.a_max * acc_lsb_per_unit(c));
    const double a = std::min(a_max, std::sqrt(2.0 * j * std::max(v, 1.0))) * u(g);
    st.acceleration = int64_t(a) * (u(g) < 0.5 ? 1 : -1) * dir;
    st.frac = (u128(g()) << 16) & (kOne - 1);
    starts.push_back(st);
  }
  time_each_plan(state, set.size(),
                 [&](size_t k) { return planner.plan_from_state(starts[k], set[k].req, set[k].timing); });
}
BENCHMARK(BM_PlanFromStateWithAcceleration)->MinTime(2.0);

// Streams of the unit tests' mix: 20 % direction changes, 60 % short moves
// (1..2000 pulses) limited by the look-ahead, the rest up to 100000 pulses.
std::vector<StreamMove> random_stream(size_t n, double v_max, bool short_only) {
  std::mt19937_64 g(12);
  std::uniform_int_distribution<int64_t> dist(1, 100000);
  std::uniform_int_distribution<int> coin(0, 99);
  std::uniform_real_distribution<double> frac(0.0, 1.0);
  std::vector<StreamMove> moves(n);
  int dir = 1;
  for (StreamMove& m : moves) {
    if (coin(g) < 20) dir = -dir;
    const int64_t d = short_only || coin(g) < 60 ? 1 + int64_t(std::pow(frac(g), 3) * 2000) : dist(g);
    m.distance = dir * d;
    m.v_cruise = std::max(1.0, v_max * std::pow(frac(g), 2));
    m.v_junction_max = coin(g) < 10 ? 0.0 : v_max * frac(g);
  }
  return moves;
}

void stream_moves(benchmark::State& state, bool short_only) {
  const StreamLimits limits{2000, 20000, 20000};
  const auto moves = random_stream(10000, limits.v_max, short_only);
  uint64_t planned = 0;
  const double t0 = thread_cpu_seconds();
  for (auto _ : state) {
    StreamPlanner sp(Clock{}, PulseTiming{}, limits);
    for (const StreamMove& m : moves) {
      if (sp.append(m)) state.SkipWithError("append failed");
      planned += sp.take_ready().size();
    }
    if (sp.flush()) state.SkipWithError("flush failed");
    planned += sp.take_ready().size();
  }
  state.counters["moves_per_s"] = benchmark::Counter(double(planned), benchmark::Counter::kIsRate);
  state.counters["us_per_move"] = planned ? (thread_cpu_seconds() - t0) / double(planned) * 1e6 : 0.0;
}

void BM_StreamMixedMoves(benchmark::State& state) { stream_moves(state, false); }
void BM_StreamShortMoves(benchmark::State& state) { stream_moves(state, true); }
BENCHMARK(BM_StreamMixedMoves)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_StreamShortMoves)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
