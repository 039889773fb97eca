// Streamed moves through the row FIFO: the executor model over very long
// streams (fast-forward), RTL and model in lockstep over random streams with
// random host append timing (late appends underrun), and the continuity
// guard. Expected positions come from the host stream planner (closed form),
// not from the executor: after move k the boundary position is the sum of
// the first k distances.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <deque>
#include <random>

#include "closed_loop_run.h"
#include "lockstep.h"
#include "pin_monitor.h"
#include "planner.h"
#include "rtl_core.h"
#include "scurve/reg_encode.h"
#include "scurve/stream_planner.h"
#include "stream_run.h"

using namespace sc;

namespace {

// Random moves: both directions, short and long, random cruise and
// junction limits (a junction limit of 0 forces a stop).
std::vector<scurve::StreamMove> random_moves(std::mt19937_64& g, size_t n, double v_max, int64_t max_distance) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<scurve::StreamMove> moves(n);
  int dir = 1;
  for (scurve::StreamMove& m : moves) {
    if (u(g) < 0.2) dir = -dir;
    const int64_t d = 1 + int64_t(std::pow(u(g), 3) * double(max_distance - 1));
    m.distance = dir * d;
    m.v_cruise = std::max(1.0, v_max * (0.05 + 0.95 * u(g)));
    m.v_junction_max = u(g) < 0.1 ? 0.0 : v_max * u(g);
  }
  return moves;
}

// Plans `moves` (tb/stream_run.h): their rows, the last move ending the
// stream, and each move's end position (the running sum, from the planner).
PlannedStream plan_moves(const std::vector<scurve::StreamMove>& moves, const scurve::StreamLimits& limits) {
  auto r = plan_stream(StreamRequest{limits, moves}, PulseTiming{});
  if (const scurve::Error* e = std::get_if<scurve::Error>(&r)) {
    ADD_FAILURE() << e->message;
    return {};
  }
  EXPECT_EQ(std::get<PlannedStream>(r).moves.size(), moves.size());
  return std::get<PlannedStream>(std::move(r));
}

// Streams a planner's output through the executor model, keeping the FIFO
// topped up and jumping each row in closed form; checks every move boundary.
void stream_through_model(size_t n_moves, uint64_t seed) {
  std::mt19937_64 g(seed);
  const scurve::StreamLimits limits{2000, 20000, 20000};
  const auto moves = random_moves(g, n_moves, limits.v_max, 100000);
  scurve::StreamPlanner sp(scurve::Clock{}, scurve::PulseTiming{}, limits);
  ProfileExec ex;
  PlannedStream q;  // rows not yet pushed, move ends not yet reached
  std::deque<Row>& pending = q.rows;
  std::deque<int64_t>& ends = q.move_ends;
  uint64_t moves_done = 0, clocks = 0;
  bool started = false;
  auto check_boundary = [&] {
    const ProfileExec::State& s = ex.state();
    if (!s.move_done) return;
    ASSERT_FALSE(ends.empty());
    ASSERT_EQ(int64_t(s.bpos), ends.front()) << "move " << moves_done;
    ASSERT_EQ(s.move_idx, uint32_t(moves_done + 1));
    ends.pop_front();
    ++moves_done;
  };
  auto clock = [&](const ProfileExec::Inputs& in) {
    ex.step(in);
    ++clocks;
    check_boundary();
  };
  // Runs the executor until it needs more rows (FIFO near empty) or is idle.
  auto run = [&](bool draining) {
    while (!::testing::Test::HasFatalFailure()) {
      while (!pending.empty() && !ex.fifo_full()) {
        ProfileExec::Inputs in;
        in.row_push = true;
        in.row = pending.front();
        pending.pop_front();
        clock(in);
      }
      if (!started) {
        ProfileExec::Inputs in;
        in.start = true;
        in.pos_frac0 = kOne / 2;
        clock(in);
        started = true;
      }
      if (!ex.state().run) return;
      if (!draining && ex.fifo_level() < 2) return;
      const uint64_t left = ex.state().left;
      ex.fast_forward(left);  // to and including this row's last clock
      clocks += left;
      check_boundary();
      ASSERT_FALSE(ex.state().underrun) << "underrun after move " << moves_done;
      ASSERT_FALSE(ex.state().discont) << "discontinuity after move " << moves_done;
    }
  };
  for (const scurve::StreamMove& m : moves) {
    auto e = sp.append(m);
    ASSERT_FALSE(e) << e->message;
    for (const scurve::StreamedMove& r : sp.take_ready()) q.add(r, false);
    if (pending.size() > 64) run(false);
    if (::testing::Test::HasFatalFailure()) return;
  }
  auto e = sp.flush();
  ASSERT_FALSE(e) << e->message;
  for (const scurve::StreamedMove& r : sp.take_ready()) q.add(r, false);
  run(true);
  if (::testing::Test::HasFatalFailure()) return;
  EXPECT_EQ(moves_done, n_moves);
  EXPECT_TRUE(ends.empty());
  EXPECT_FALSE(ex.state().run);
  EXPECT_TRUE(ex.state().finished) << "the stream ends at rest: no STREAM_END row needed";
  EXPECT_EQ(int64_t(ex.state().pint), sp.position());
  ::testing::Test::RecordProperty("moves", std::to_string(moves_done));
  ::testing::Test::RecordProperty("clocks", std::to_string(clocks));
}

}  // namespace

TEST(StreamModel, HundredThousandStreamedMovesEndExactlyOnTheRunningSum) { stream_through_model(100000, 11); }

TEST(StreamModelLong, MillionStreamedMovesEndExactlyOnTheRunningSum) { stream_through_model(1000000, 12); }

namespace {

struct StreamRunStats {
  uint64_t clocks = 0, moves_done = 0, underruns = 0, rows = 0;
  uint64_t rest_ends = 0;  // the FIFO ran dry at a junction at rest: the stream ended there
};

// RTL and model in lockstep over one stream of random moves; the host
// appends rows at random times (a push every `push_gap` clocks on average)
// and now and then stalls for `stall` clocks: a stall while moving
// underruns, the axis stops, and the host starts the rest of the moves as a
// new stream from rest; a stall over a junction at rest ends the stream
// there, and the host starts the rest the same way.
StreamRunStats lockstep_stream(std::mt19937_64& g, size_t n_moves, double push_rate, uint64_t stall) {
  const scurve::StreamLimits limits{2e6, 5e9, 150000};
  PulseTiming t;
  t.high = uint16_t(2 + g() % 20);
  t.low = uint16_t(2 + g() % 20);
  t.setup = uint16_t(g() % 60);
  t.hold = uint16_t(g() % 60);
  RtlCore rtl;
  rtl.reset();
  AxisCore model;
  LockstepChecker chk;
  PinRules rules{t};
  rules.profile_phases = false;  // several moves: no single-move duty contract
  rules.accounting = StepAccounting::ReferencePosition;
  PinMonitor pins(rules);
  StreamRunStats st;
  CoreInputs in;
  in.enable = true;
  in.cfg = t;
  in.pos_frac0 = kOne / 2;  // read when the executor starts, after the arming
  // An underrun stops under control within the stream's own limits.
  in.stop_jerk = uint64_t(limits.j_max * kTwoPowFrac / (double(ClkHz) * ClkHz * ClkHz));
  in.stop_acc = uint64_t(limits.a_max * kTwoPowFrac / (double(ClkHz) * ClkHz));
  auto tick = [&](const CoreInputs& ci) {
    rtl.step(ci);
    model.step(ci);
    const CoreOutputs& o = rtl.outputs();
    chk.compare(st.clocks, o, model.outputs());
    pins.on_clock(st.clocks, o);
    ++st.clocks;
  };
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<scurve::StreamMove> moves = random_moves(g, n_moves, limits.v_max, 400);
  size_t next_move = 0;
  int64_t origin = 0;  // integer position at the current stream's START
  while (next_move < moves.size() && !chk.should_stop()) {
    // A new stream from rest: the remaining moves.
    std::vector<scurve::StreamMove> rest(moves.begin() + long(next_move), moves.end());
    PlannedStream q = plan_moves(rest, limits);
    if (::testing::Test::HasFatalFailure()) return st;
    origin = model.outputs().ref_pos_int;
    // Preload a few rows, then START.
    const size_t preload = std::min<size_t>(q.rows.size(), 1 + g() % RowFifoDepth);
    for (size_t i = 0; i < preload; ++i) {
      CoreInputs w = in;
      w.row_push = true;
      w.row = q.rows.front();
      q.rows.pop_front();
      tick(w);
      ++st.rows;
    }
    CoreInputs s = in;
    s.start = true;
    tick(s);
    uint64_t moves_in_stream = 0;
    int64_t last_end = 0;  // the last move done, from the stream's origin
    uint64_t stall_left = 0;
    uint64_t guard = 0;
    while (!chk.should_stop() && ++guard < 50'000'000) {
      CoreInputs ci = in;
      if (stall_left > 0) {
        --stall_left;
      } else if (!q.rows.empty() && !model.outputs().fifo_full && u(g) < push_rate) {
        ci.row_push = true;
        ci.row = q.rows.front();
        q.rows.pop_front();
        ++st.rows;
        if (stall > 0 && u(g) < 0.02) stall_left = stall;
      }
      tick(ci);
      const CoreOutputs& o = model.outputs();
      if (o.move_done) {
        EXPECT_EQ(int64_t(o.boundary_pos), origin + q.move_ends.front()) << "move " << next_move + moves_in_stream;
        last_end = q.move_ends.front();
        EXPECT_EQ(o.move_idx, uint32_t(moves_in_stream + 1));
        q.move_ends.pop_front();
        ++moves_in_stream;
        ++st.moves_done;
      }
      if (!o.busy && !o.move_done) break;
    }
    const CoreOutputs& o = model.outputs();
    EXPECT_FALSE(o.discont) << "the planner's rows continue exactly";
    const bool owed = !q.rows.empty() || !q.move_ends.empty();
    next_move += moves_in_stream;
    if (o.underrun) {
      ++st.underruns;
      EXPECT_TRUE(owed) << "an underrun needs rows still owed";
      EXPECT_EQ(o.fifo_level, 0);
    } else if (owed) {
      // The FIFO ran dry at a boundary where the plan is at rest (a junction
      // at speed zero): the stream ends there as planned, exactly on the
      // boundary of the last move done, and the host starts the rest anew.
      ++st.rest_ends;
      if (moves_in_stream == 0) {
        ADD_FAILURE() << "the stream ended at rest before its first move was done";
        return st;
      }
      EXPECT_TRUE(o.done);
      EXPECT_TRUE(o.ref_vel == 0);
      EXPECT_EQ(o.fifo_level, 0);
      EXPECT_EQ(int64_t(o.ref_pos_int), origin + (moves_in_stream ? last_end : 0))
          << "a stream that runs dry at rest ends on a move boundary";
      continue;
    } else {
      EXPECT_TRUE(o.done);
      break;
    }
    // The interrupted move is planned again, whole, from where the stop left
    // the axis (the next stream's origin).
    CoreInputs flush = in;
    flush.fifo_flush = true;
    tick(flush);
    for (int i = 0; i < 200; ++i) tick(in);
  }
  for (int i = 0; i < 2000; ++i) tick(in);
  pins.finish(st.clocks);
  EXPECT_TRUE(chk.errors().empty()) << chk.finish();
  for (const std::string& e : pins.errors()) ADD_FAILURE() << e;
  EXPECT_EQ(pins.net_steps(), int64_t(model.outputs().ref_pos_int)) << "every reference step on the pins";
  return st;
}

void lockstep_streams(int streams, size_t max_moves, uint64_t seed) {
  std::mt19937_64 g(seed);
  StreamRunStats total;
  for (int i = 0; i < streams; ++i) {
    const double rate = i % 3 == 0 ? 1.0 : std::pow(10.0, -3.0 * double(g() % 1000) / 1000.0);
    const uint64_t stall = i % 2 == 0 ? 0 : 20000 + g() % 200000;
    const size_t n = 20 + g() % (max_moves - 19);
    const StreamRunStats s = lockstep_stream(g, n, rate, stall);
    if (::testing::Test::HasFailure()) {
      ADD_FAILURE() << "stream " << i << " (" << n << " moves, push rate " << rate << ", stall " << stall << ")";
      return;
    }
    total.clocks += s.clocks;
    total.moves_done += s.moves_done;
    total.underruns += s.underruns;
    total.rows += s.rows;
    total.rest_ends += s.rest_ends;
  }
  EXPECT_GT(total.underruns, 0u) << "the campaign must underrun at least once";
  ::testing::Test::RecordProperty("clocks", std::to_string(total.clocks));
  ::testing::Test::RecordProperty("moves", std::to_string(total.moves_done));
  ::testing::Test::RecordProperty("underruns", std::to_string(total.underruns));
  ::testing::Test::RecordProperty("rest_ends", std::to_string(total.rest_ends));
  std::printf("[stream] %d streams, %llu moves, %llu rows, %llu underruns, %llu ends at rest, %llu clocks in lockstep\n",
              streams, (unsigned long long)total.moves_done, (unsigned long long)total.rows,
              (unsigned long long)total.underruns, (unsigned long long)total.rest_ends,
              (unsigned long long)total.clocks);
}

}  // namespace

// Streams on the closed-loop axis (sc_servo_axis, the default controller and
// stepper plant): every move ends on the running sum at the clock the
// open-loop core reaches it (the reference is the same executor), the
// encoder ends on the sum in position; the first stream in lockstep.
TEST(ClosedLoopStream, RandomStreamsEndOnTheRunningSumInPositionAtTheOpenLoopBoundaries) {
  std::mt19937_64 g(31);
  const scurve::StreamLimits limits{20000, 400000, 4000};
  for (int i = 0; i < 3; ++i) {
    const std::vector<scurve::StreamMove> moves = random_moves(g, 3 + g() % 3, limits.v_max, 600);
    const StreamRequest req{limits, moves};
    const PlannedStream ps = plan_moves(moves, limits);
    if (::testing::Test::HasFatalFailure()) return;
    const auto codes = std::get<scurve::StopLimitCodes>(scurve::stop_limit_codes(limits.j_max, limits.a_max));
    const StreamRunResult open = run_stream(ps, req, PulseTiming{}, SimEngine::ModelFast, codes.jerk, codes.acc);
    ClosedLoopOptions o;
    o.engine = i == 0 ? ClEngine::Lockstep : ClEngine::ModelOnly;
    o.tail_s = 0.01;
    o.stop_jerk = codes.jerk;
    o.stop_acc = codes.acc;
    const StreamRunResult closed = run_closed_loop_stream(ps, req, o);
    std::string failures;
    for (const std::string& f : closed.failures) failures += f + "\n";
    ASSERT_TRUE(open.pass());
    ASSERT_TRUE(closed.pass()) << "stream " << i << " (" << moves.size() << " moves):\n" << failures;
    EXPECT_TRUE(closed.in_position);
    EXPECT_EQ(closed.final_error, 0);
    ASSERT_EQ(closed.moves.size(), open.moves.size());
    for (size_t k = 0; k < closed.moves.size(); ++k) {
      EXPECT_TRUE(closed.moves[k].reached) << "move " << k;
      EXPECT_EQ(closed.moves[k].end_position, closed.moves[k].expected_end_position) << "move " << k;
      EXPECT_EQ(closed.moves[k].end_clock, open.moves[k].end_clock) << "move " << k;
    }
    if (o.engine == ClEngine::Lockstep) {
      EXPECT_GT(closed.matched_clocks, 0u);
    }
  }
}

TEST(StreamLockstep, RandomStreamsWithRandomAppendTimingMatchEveryClock) { lockstep_streams(6, 80, 77); }

// The runner of `scurve stream` (tb/stream_run.h) on random streams with
// random pulse timing: every engine passes (boundaries on the running sum
// and at their planned clocks, pins, no underrun with a host that pushes
// whenever there is room) and all four see every MOVE_DONE at the same clock.
TEST(StreamRun, RandomStreamsPassOnEveryEngineWithTheSameBoundaries) {
  std::mt19937_64 g(5);
  for (int i = 0; i < 4; ++i) {
    StreamRequest req;
    req.limits = {2e6, 5e9, 150000};
    req.moves = random_moves(g, 8 + g() % 16, req.limits.v_max, 600);
    PulseTiming t;
    t.high = uint16_t(2 + g() % 20);
    t.low = uint16_t(2 + g() % 20);
    t.setup = uint16_t(g() % 60);
    t.hold = uint16_t(g() % 60);
    auto planned = plan_stream(req, t);
    ASSERT_TRUE(std::holds_alternative<PlannedStream>(planned)) << std::get<scurve::Error>(planned).message;
    const auto& ps = std::get<PlannedStream>(planned);
    const uint64_t j = uint64_t(req.limits.j_max * kTwoPowFrac / (double(ClkHz) * ClkHz * ClkHz));
    const uint64_t a = uint64_t(req.limits.a_max * kTwoPowFrac / (double(ClkHz) * ClkHz));
    std::vector<uint64_t> ends;
    for (SimEngine e : {SimEngine::Lockstep, SimEngine::RtlOnly, SimEngine::ModelOnly, SimEngine::ModelFast}) {
      const StreamRunResult r = run_stream(ps, req, t, e, j, a);
      std::string failures;
      for (const std::string& f : r.failures) failures += f + "\n";
      ASSERT_TRUE(r.pass()) << "stream " << i << " (" << req.moves.size() << " moves) on " << engine_name(e) << ":\n"
                            << failures;
      EXPECT_EQ(r.pulses, ps.move_ends.back());
      std::vector<uint64_t> e_ends;
      for (const StreamMoveReport& m : r.moves) e_ends.push_back(m.end_clock);
      if (ends.empty()) ends = e_ends;
      EXPECT_EQ(e_ends, ends) << "stream " << i << " on " << engine_name(e);
      if (e == SimEngine::Lockstep) {
        EXPECT_GT(r.matched_clocks, 0u);
      }
    }
  }
}

TEST(StreamLockstepLong, TwoHundredStreamsOf20To200MovesMatchEveryClock) { lockstep_streams(200, 200, 78); }
