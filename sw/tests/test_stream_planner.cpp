// StreamPlanner and Planner::plan_from: moves streamed back to back. The rows
// of a whole stream are executed as one continuous closed-form execution (the
// position fraction carried), independent of how they were planned.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>

#include "scurve/stream_planner.h"

using namespace scurve;

namespace {

const StreamLimits kLimits{500, 2500, 3000};

int64_t floor_pulses(i128 pos) {
  const i128 one = i128(kOne);
  return int64_t(pos >= 0 ? pos / one : -((-pos + one - 1) / one));
}

// One continuous execution of every row of a stream, checked move by move.
class StreamExecution {
 public:
  StreamExecution(Clock clock, const StreamLimits& l, u128 start_frac = kOne / 2)
      : clock_(clock), pos_(i128(start_frac)) {
    a_max_ = int64_t(std::floor(l.a_max * acc_lsb_per_unit(clock)));
    j_max_ = int64_t(std::floor(l.j_max * jerk_lsb_per_unit(clock)));
  }

  // Executes one move's rows from where the previous one ended. v_junction:
  // the junction limit of the move that follows (checked on the end speed).
  void run(const StreamedMove& m) {
    ASSERT_EQ(m.index, moves_);
    ASSERT_EQ(m.start_clock, clocks_);
    ASSERT_EQ(m.start.velocity, v_);
    ASSERT_EQ(m.start.frac, u128(pos_ - i128(floor_pulses(pos_)) * i128(kOne)));
    ASSERT_FALSE(m.segments.empty());
    const int dir = m.distance < 0 ? -1 : 1;
    // A direction change happens only at rest.
    if (v_ != 0) ASSERT_EQ(v_ < 0, dir < 0) << "move " << m.index << " reverses at a nonzero junction";
    for (const Segment& s : m.segments) {
      // Junction continuity: each row continues the previous row exactly.
      ASSERT_EQ(s.vel0, v_) << "move " << m.index;
      ASSERT_EQ(s.acc0, a_) << "move " << m.index;
      ASSERT_GT(s.clocks, 0u);
      pos_ += pos_gain(s.vel0, s.acc0, s.jerk, s.clocks);
      v_ = vel_after(s.vel0, s.acc0, s.jerk, s.clocks);
      a_ = int64_t(acc_after(s.acc0, s.jerk, s.clocks));
      clocks_ += s.clocks;
    }
    ASSERT_EQ(a_, 0) << "move " << m.index << " ends accelerating";
    sum_ += m.distance;
    // Exactly the running sum of distances in steps: the end lies in the
    // one-pulse window [sum, sum + 1) of the step rule floor(position).
    ASSERT_EQ(floor_pulses(pos_), sum_) << "move " << m.index;
    ASSERT_EQ(m.end_position, sum_);
    ASSERT_EQ(m.end.velocity, v_);
    ASSERT_EQ(m.end.frac, u128(pos_ - i128(sum_) * i128(kOne)));
    ASSERT_EQ(m.end_clock, clocks_);
    ASSERT_NEAR(std::abs(vel_to_phys(v_, clock_)), m.v_out, 1e-9 * (1 + m.v_out));
    // Limits, and no reversal inside the move: the planner's own re-check
    // run independently on the move's rows.
    const TableReport rep = run_table(m.segments, m.start.frac, dir);
    ASSERT_TRUE(rep.ok) << rep.error;
    ASSERT_EQ(rep.steps, m.distance);
    ASSERT_GE(rep.min_signed_vel, 0) << "move " << m.index << " reverses";
    ASSERT_LE(rep.peak_acc, a_max_) << "move " << m.index;
    ASSERT_LE(rep.peak_jerk, j_max_) << "move " << m.index;
    peak_vel_ = std::max(peak_vel_, rep.peak_vel);
    ++moves_;
  }

  void expect_at_rest() const { EXPECT_EQ(v_, 0); }
  uint64_t moves() const { return moves_; }
  uint64_t clocks() const { return clocks_; }
  i128 peak_vel() const { return peak_vel_; }
  int64_t position() const { return sum_; }

 private:
  Clock clock_;
  i128 pos_;
  i128 v_ = 0;
  int64_t a_ = 0;
  int64_t a_max_ = 0, j_max_ = 0;
  int64_t sum_ = 0;
  uint64_t clocks_ = 0;
  uint64_t moves_ = 0;
  i128 peak_vel_ = 0;
};

// Streams `moves` through a planner, executing what it hands out as it goes;
// checks each move's speed against its own cruise and junction limits.
void stream_and_check(StreamPlanner& sp, StreamExecution& ex, const std::vector<StreamMove>& moves) {
  uint64_t checked = 0;
  const auto drain = [&] {
    for (const StreamedMove& m : sp.take_ready()) {
      ex.run(m);
      if (::testing::Test::HasFatalFailure()) return;
      const StreamMove& req = moves[m.index];
      const double v_cap = req.v_cruise;
      ASSERT_LE(m.v_in, v_cap * (1 + 1e-12));
      ASSERT_LE(m.v_out, v_cap * (1 + 1e-12));
      if (m.index + 1 < moves.size()) {
        const StreamMove& next = moves[m.index + 1];
        ASSERT_LE(m.v_out, std::min(next.v_cruise, next.v_junction_max) * (1 + 1e-12));
        if ((next.distance < 0) != (req.distance < 0)) ASSERT_EQ(m.end.velocity, 0);
      } else {
        ASSERT_EQ(m.end.velocity, 0) << "the stream ends at rest";
      }
      ++checked;
    }
  };
  for (const StreamMove& m : moves) {
    auto e = sp.append(m);
    ASSERT_FALSE(e) << e->message;
    drain();
    if (::testing::Test::HasFatalFailure()) return;
  }
  auto e = sp.flush();
  ASSERT_FALSE(e) << e->message;
  drain();
  ASSERT_EQ(checked, moves.size());
  ex.expect_at_rest();
}

std::vector<StreamMove> random_moves(std::mt19937_64& g, size_t n, double v_max) {
  std::uniform_int_distribution<int64_t> dist(1, 100000);
  std::uniform_int_distribution<int> coin(0, 99);
  std::uniform_real_distribution<double> frac(0.0, 1.0);
  std::vector<StreamMove> moves(n);
  int dir = 1;
  for (StreamMove& m : moves) {
    if (coin(g) < 20) dir = -dir;
    // Mostly short moves, so junction speeds are limited by the look-ahead.
    const int64_t d = coin(g) < 60 ? 1 + int64_t(std::pow(frac(g), 3) * 2000) : dist(g);
    m.distance = dir * d;
    m.v_cruise = std::max(1.0, v_max * std::pow(frac(g), 2));
    m.v_junction_max = coin(g) < 10 ? 0.0 : v_max * frac(g);
  }
  return moves;
}

void run_random_stream(size_t n, uint64_t seed) {
  std::mt19937_64 g(seed);
  const Clock clock{};
  const StreamLimits limits{2000, 20000, 20000};
  const auto moves = random_moves(g, n, limits.v_max);
  StreamPlanner sp(clock, PulseTiming{}, limits);
  StreamExecution ex(clock, limits);
  const auto t0 = std::chrono::steady_clock::now();
  stream_and_check(sp, ex, moves);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LE(vel_to_phys(ex.peak_vel(), clock), limits.v_max * (1 + 1e-12));
  std::printf("[stream] %zu random moves planned and executed in %.1f s; stream %.1f s long, end at %lld pulses\n", n,
              secs, double(ex.clocks()) / clock.hz, (long long)ex.position());
}

}  // namespace

TEST(StreamPlanner, EveryMoveEndsExactlyOnTheRunningSumOfDistances) {
  const Clock clock{};
  const std::vector<StreamMove> moves = {{1000, 3000, 3000}, {1, 3000, 3000},     {250, 2000, 3000},
                                         {-40, 3000, 3000},  {-7000, 3000, 1500}, {3, 100, 3000},
                                         {12345, 3000, 3000}, {2, 3000, 3000}};
  StreamPlanner sp(clock, PulseTiming{}, kLimits);
  StreamExecution ex(clock, kLimits);
  stream_and_check(sp, ex, moves);
  EXPECT_EQ(ex.position(), 1000 + 1 + 250 - 40 - 7000 + 3 + 12345 + 2);
}

TEST(StreamPlanner, RandomStreamOf100kMovesIsExactAndWithinLimits) { run_random_stream(100000, 1); }

#ifdef SCURVE_LONG_TESTS  // its own executable, labelled long
TEST(StreamPlannerLong, RandomStreamOf1MMovesIsExactAndWithinLimits) { run_random_stream(1000000, 2); }
#endif

TEST(StreamPlanner, JunctionIsZeroAtDirectionChangesAndAtTheEnd) {
  StreamPlanner sp(Clock{}, PulseTiming{}, kLimits);
  for (int64_t d : {5000, 5000, -5000, -5000, 5000}) ASSERT_FALSE(sp.append({d, 3000, 3000}));
  ASSERT_FALSE(sp.flush());
  const auto moves = sp.take_ready();
  ASSERT_EQ(moves.size(), 5u);
  EXPECT_GT(moves[0].v_out, 0);  // same direction: the look-ahead keeps speed
  EXPECT_EQ(moves[1].v_out, 0);
  EXPECT_EQ(moves[1].end.velocity, 0);
  EXPECT_GT(moves[2].v_out, 0);
  EXPECT_EQ(moves[3].end.velocity, 0);
  EXPECT_EQ(moves[4].end.velocity, 0);
  EXPECT_EQ(moves[4].v_out, 0);
}

TEST(StreamPlanner, EachJunctionAllowsStoppingWithinTheQueuedDistance) {
  // After every append, a copy of the planner (a value) ended right there
  // must stop within the queued moves, exactly.
  std::mt19937_64 g(3);
  const Clock clock{};
  const StreamLimits limits{2000, 20000, 20000};
  const auto moves = random_moves(g, 400, limits.v_max);
  StreamPlanner sp(clock, PulseTiming{}, limits);
  StreamExecution ex(clock, limits);
  std::vector<StreamedMove> handed_out;
  for (const StreamMove& m : moves) {
    ASSERT_FALSE(sp.append(m));
    for (StreamedMove& r : sp.take_ready()) handed_out.push_back(std::move(r));
    StreamPlanner stop_here = sp;
    ASSERT_FALSE(stop_here.flush());
    StreamExecution replay = ex;
    for (const StreamedMove& r : handed_out) replay.run(r);
    for (const StreamedMove& r : stop_here.take_ready()) replay.run(r);
    ASSERT_FALSE(HasFatalFailure());
    replay.expect_at_rest();
    for (const StreamedMove& r : handed_out) ex.run(r);
    handed_out.clear();
  }
}

TEST(StreamPlanner, AppendingNeverRaisesAFrozenJunction) {
  // Frozen: the junctions of moves handed out, including the entry of the
  // first queued move (the exact end state of the last one handed out).
  std::mt19937_64 g(4);
  const StreamLimits limits{2000, 20000, 20000};
  const auto moves = random_moves(g, 3000, limits.v_max);
  StreamPlanner sp(Clock{}, PulseTiming{}, limits);
  std::map<uint64_t, double> shown;  // move index -> last look-ahead speed into it
  uint64_t next_planned = 0;
  double frozen_exit = 0;
  uint64_t lowered = 0, raised = 0;
  for (const StreamMove& m : moves) {
    ASSERT_FALSE(sp.append(m));
    for (const StreamedMove& r : sp.take_ready()) {
      ASSERT_EQ(r.index, next_planned++);
      EXPECT_EQ(r.v_in, frozen_exit) << "move " << r.index << " entered faster than its frozen junction";
      frozen_exit = r.v_out;
    }
    const auto j = sp.queued_junctions();
    EXPECT_EQ(j.front(), frozen_exit);
    EXPECT_EQ(j.back(), 0.0);
    for (size_t k = 0; k + 1 < j.size(); ++k) {
      const uint64_t idx = next_planned + k;
      if (shown.count(idx)) {
        lowered += j[k] < shown[idx];
        raised += j[k] > shown[idx];
      }
      shown[idx] = j[k];
    }
  }
  // Queued (not frozen) junctions mostly rise as the queue grows; a short
  // jerk-limited braking can need more room to a higher exit, so some drop.
  std::printf("[stream] queued junctions over 3000 appends: %llu raised, %llu lowered\n",
              (unsigned long long)raised, (unsigned long long)lowered);
  EXPECT_GT(raised, lowered);
}

TEST(StreamPlanner, LookaheadStreamIsFasterThanStoppingAtEveryJunction) {
  const Clock clock{};
  std::mt19937_64 g(5);
  std::uniform_int_distribution<int64_t> dist(50, 3000);
  std::vector<StreamMove> fluid, stopping;
  for (int i = 0; i < 200; ++i) {
    const int64_t d = dist(g);
    fluid.push_back({d, 3000, 3000});
    stopping.push_back({d, 3000, 0});
  }
  const auto duration = [&](const std::vector<StreamMove>& moves) {
    StreamPlanner sp(clock, PulseTiming{}, kLimits);
    StreamExecution ex(clock, kLimits);
    stream_and_check(sp, ex, moves);
    return double(ex.clocks()) / clock.hz;
  };
  const double t_fluid = duration(fluid), t_stop = duration(stopping);
  std::printf("[stream] 200 moves one way: %.2f s with look-ahead, %.2f s stopping at every junction\n", t_fluid,
              t_stop);
  RecordProperty("lookahead_s", std::to_string(t_fluid));
  RecordProperty("stopping_s", std::to_string(t_stop));
  EXPECT_LT(t_fluid, t_stop);
}

TEST(StreamPlannerErrors, EachBadParameterIsNamedWithValueAndBound) {
  StreamPlanner sp(Clock{}, PulseTiming{}, kLimits);
  const auto expect_error = [&](StreamMove m, const char* param, const char* text) {
    auto e = sp.append(m);
    ASSERT_TRUE(e) << param;
    EXPECT_EQ(e->parameter, param);
    EXPECT_NE(e->message.find(text), std::string::npos) << e->message;
  };
  expect_error({0, 1000, 1000}, "distance", "distance=0: must be non-zero");
  expect_error({int64_t(1) << 40, 1000, 1000}, "distance", "exceeds the limit +-2147483646");
  expect_error({10, NAN, 1000}, "v_cruise", "v_cruise=nan: must be a finite number");
  expect_error({10, INFINITY, 1000}, "v_cruise", "must be a finite number");
  expect_error({10, 0, 1000}, "v_cruise", "v_cruise=0: must be >= 0.001 pulses/s");
  expect_error({10, 3500, 1000}, "v_cruise", "v_cruise=3500: exceeds the limit v_max=3000 pulses/s");
  expect_error({10, 1000, -1}, "v_junction_max", "v_junction_max=-1: must be >= 0 pulses/s");
  expect_error({10, 1000, NAN}, "v_junction_max", "must be a finite number");
  expect_error({10, 1000, 3001}, "v_junction_max", "exceeds the limit v_max=3000");
  EXPECT_EQ(sp.queued(), 0u) << "a refused move is not queued";

  StreamPlanner bad_acc(Clock{}, PulseTiming{}, {-5, 2500, 3000});
  auto e = bad_acc.append({10, 1000, 1000});
  ASSERT_TRUE(e);
  EXPECT_EQ(e->parameter, "a_max");
  StreamPlanner bad_v(Clock{}, PulseTiming{}, {500, 2500, 1e6});
  e = bad_v.append({10, 1000, 1000});
  ASSERT_TRUE(e);
  EXPECT_EQ(e->parameter, "v_max");
  EXPECT_NE(e->message.find("exceeds the limit step-rate limit=200000"), std::string::npos) << e->message;
}

// ---- soft limits (the travel window) of a stream ---------------------------

namespace {

StreamLimits windowed_limits(int64_t start, std::optional<int64_t> min_pos, std::optional<int64_t> max_pos) {
  StreamLimits l = kLimits;
  l.soft_limits = SoftLimits{"x", min_pos, max_pos};
  l.start_position = start;
  return l;
}

// Every row a stream hands out from here on, to compare two streams.
std::vector<Segment> flushed_rows(StreamPlanner sp) {
  std::vector<Segment> rows;
  EXPECT_FALSE(sp.flush());
  for (const StreamedMove& m : sp.take_ready()) rows.insert(rows.end(), m.segments.begin(), m.segments.end());
  return rows;
}

}  // namespace

TEST(StreamSoftLimits, RefusedAppendNamesTheMoveAndLeavesTheStreamUnchanged) {
  const Clock clock{};
  const StreamLimits limits = windowed_limits(200, 0, 10000);
  StreamPlanner sp(clock, PulseTiming{}, limits);
  ASSERT_FALSE(sp.append({5000, 3000, 3000}));
  ASSERT_FALSE(sp.append({3000, 3000, 3000}));
  const StreamPlanner before = sp;
  const auto junctions = sp.queued_junctions();
  const size_t queued = sp.queued();

  auto e = sp.append({2000, 3000, 3000});  // 200 + 5000 + 3000 + 2000 = 10200
  ASSERT_TRUE(e);
  EXPECT_EQ(e->parameter, "soft_limits.max_pos");
  EXPECT_EQ(e->message,
            "axis x: move 2: target position 10200 is beyond soft limit max=10000 pulses (start 8200, distance +2000)");
  e = sp.append({-8201, 3000, 3000});
  ASSERT_TRUE(e);
  EXPECT_EQ(e->parameter, "soft_limits.min_pos");
  EXPECT_EQ(e->message,
            "axis x: move 2: target position -1 is beyond soft limit min=0 pulses (start 8200, distance -8201)");
  EXPECT_EQ(sp.queued(), queued);
  EXPECT_EQ(sp.queued_junctions(), junctions);
  EXPECT_EQ(sp.position(), before.position());
  EXPECT_EQ(flushed_rows(sp), flushed_rows(before)) << "a refused append changed the stream";

  // Later appends still work, up to the limit exactly, and take the next index.
  ASSERT_FALSE(sp.append({1800, 3000, 3000}));   // 10000: on the limit
  ASSERT_FALSE(sp.append({-10000, 3000, 3000}));  // 0: on the other limit
  ASSERT_FALSE(sp.flush());
  StreamExecution ex(clock, limits);
  for (const StreamedMove& m : sp.take_ready()) ex.run(m);
  ASSERT_FALSE(HasFatalFailure());
  EXPECT_EQ(ex.moves(), 4u);
  EXPECT_EQ(ex.position(), -200) << "positions count from the stream's start";
  ex.expect_at_rest();
}

TEST(StreamSoftLimits, StreamStartingBeyondALimitMayOnlyComeBack) {
  StreamPlanner sp(Clock{}, PulseTiming{}, windowed_limits(-500, 0, 10000));
  auto e = sp.append({-1, 3000, 3000});
  ASSERT_TRUE(e);
  EXPECT_EQ(e->parameter, "start_position");
  EXPECT_NE(e->message.find("axis x: move 0: start position -500 is already beyond soft limit min=0"),
            std::string::npos)
      << e->message;
  ASSERT_FALSE(sp.append({300, 3000, 3000}));  // -200: closer, still outside
  ASSERT_FALSE(sp.append({300, 3000, 3000}));  // 100: inside
  e = sp.append({-101, 3000, 3000});           // back out: refused
  ASSERT_TRUE(e);
  EXPECT_EQ(e->parameter, "soft_limits.min_pos");
  ASSERT_FALSE(sp.flush());
  EXPECT_EQ(sp.take_ready().size(), 2u);
}

TEST(StreamSoftLimits, BadWindowIsRefusedByEveryAppendNamingTheField) {
  StreamPlanner sp(Clock{}, PulseTiming{}, windowed_limits(0, 5, 1));
  auto e = sp.append({10, 1000, 1000});
  ASSERT_TRUE(e);
  EXPECT_EQ(e->parameter, "soft_limits.min_pos");
  EXPECT_NE(e->message.find("min=5 is above max=1"), std::string::npos) << e->message;
  StreamLimits far = kLimits;
  far.start_position = PlannerLimits::kMaxPosition + 1;
  StreamPlanner sp2(Clock{}, PulseTiming{}, far);
  e = sp2.append({10, 1000, 1000});
  ASSERT_TRUE(e);
  EXPECT_EQ(e->parameter, "start_position");
}

TEST(StreamSoftLimits, RunningSumNeverLeavesTheWindowOverRandomStreams) {
  // Random streams inside random windows: each append is accepted iff its
  // end (start + running sum) is inside the window; the accepted moves are
  // planned and executed as one stream, exact and without reversal inside a
  // move (so the ends are the extremes).
  const Clock clock{};
  std::mt19937_64 g(20261204);
  std::uniform_int_distribution<int64_t> width(2000, 400000);
  uint64_t appended = 0, refused = 0;
  for (int stream = 0; stream < 20; ++stream) {
    const int64_t lo = std::uniform_int_distribution<int64_t>(-1000000, 1000000)(g);
    const int64_t hi = lo + width(g);
    const int64_t start = std::uniform_int_distribution<int64_t>(lo, hi)(g);
    StreamLimits limits{2000, 20000, 20000};
    limits.soft_limits = SoftLimits{"y", lo, hi};
    limits.start_position = start;
    StreamPlanner sp(clock, PulseTiming{}, limits);
    StreamExecution ex(clock, limits);
    int64_t pos = start;  // absolute, of the accepted moves
    for (const StreamMove& m : random_moves(g, 300, limits.v_max)) {
      const int64_t target = pos + m.distance;
      const bool inside = target >= lo && target <= hi;
      auto e = sp.append(m);
      ASSERT_EQ(!e, inside) << "stream " << stream << ": target " << target << " in [" << lo << ", " << hi
                            << "]: " << (e ? e->message : "accepted");
      if (e) {
        ++refused;
        EXPECT_NE(e->message.find("axis y: move " + std::to_string(sp.queued() + ex.moves())), std::string::npos)
            << e->message;
        continue;
      }
      ++appended;
      pos = target;
      for (const StreamedMove& r : sp.take_ready()) {
        ex.run(r);
        ASSERT_FALSE(HasFatalFailure());
        const int64_t at = start + r.end_position;
        ASSERT_TRUE(at >= lo && at <= hi) << "move " << r.index << " ends at " << at;
      }
    }
    ASSERT_FALSE(sp.flush());
    for (const StreamedMove& r : sp.take_ready()) {
      ex.run(r);
      ASSERT_FALSE(HasFatalFailure());
      const int64_t at = start + r.end_position;
      ASSERT_TRUE(at >= lo && at <= hi) << "move " << r.index << " ends at " << at;
    }
    ex.expect_at_rest();
    EXPECT_EQ(start + ex.position(), pos);
  }
  std::printf("[stream soft limits] 20 random streams: %llu moves appended, %llu refused\n",
              (unsigned long long)appended, (unsigned long long)refused);
  EXPECT_GT(refused, appended / 20);
}

TEST(PlanFrom, ContinuesAnExactStateIntoTheEndWindow) {
  const Planner planner;
  MoveRequest req;
  req.distance = 7777;
  req.v_cruise = 3000;
  req.v_end = 1234.5;
  req.a_max = 500;
  req.j_max = 2500;
  JunctionState start;
  start.velocity = i128(std::floor(800.25 * vel_lsb_per_unit(Clock{}))) + 12345;  // not a round speed
  start.frac = kOne - 1;                                                           // right before a step
  const PlanResult r = planner.plan_from(start, req, PulseTiming{});
  ASSERT_TRUE(std::holds_alternative<Plan>(r)) << std::get<Error>(r).message;
  const Plan& p = std::get<Plan>(r);
  EXPECT_EQ(p.segments.front().vel0, start.velocity);
  EXPECT_EQ(p.segments.front().acc0, 0);
  const TableReport rep = run_table(p.segments, start.frac, 1);
  EXPECT_EQ(rep.steps, 7777);
  EXPECT_GE(rep.end_pos, i128(7777) * i128(kOne));
  EXPECT_LT(rep.end_pos, i128(7778) * i128(kOne));
  EXPECT_EQ(p.end_state.frac, u128(rep.end_pos - i128(7777) * i128(kOne)));
  EXPECT_EQ(p.end_state.velocity, i128(std::floor(1234.5 * vel_lsb_per_unit(Clock{}))));
}

TEST(PlanFrom, ReversalNeedsJunctionSpeedZero) {
  MoveRequest req;
  req.distance = -100;
  req.v_cruise = 3000;
  req.a_max = 500;
  req.j_max = 2500;
  JunctionState start;
  start.velocity = 1000;
  const PlanResult r = Planner().plan_from(start, req, PulseTiming{});
  ASSERT_TRUE(std::holds_alternative<Error>(r));
  EXPECT_EQ(std::get<Error>(r).parameter, "start_velocity");
  EXPECT_NE(std::get<Error>(r).message.find("junction speed 0"), std::string::npos);
}
