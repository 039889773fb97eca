#include "stream_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>

#include "lockstep.h"
#include "pin_monitor.h"

namespace sc {

void PlannedStream::add(const scurve::StreamedMove& m, bool last_of_stream) {
  std::vector<Segment> segs;
  for (const scurve::Segment& s : m.segments) segs.push_back(to_model(s));
  for (const Row& r : move_rows(segs, last_of_stream)) rows.push_back(r);
  move_ends.push_back(m.end_position);
}

std::variant<PlannedStream, scurve::Error> plan_stream(const StreamRequest& request, const PulseTiming& timing) {
  auto planned = scurve::plan_whole_stream(model_clock(), to_host(timing), request.limits, request.moves);
  if (const scurve::Error* e = std::get_if<scurve::Error>(&planned)) return *e;
  PlannedStream s;
  s.moves = std::move(std::get<std::vector<scurve::StreamedMove>>(planned));
  for (size_t i = 0; i < s.moves.size(); ++i) s.add(s.moves[i], i + 1 == s.moves.size());
  return s;
}

namespace {

// The same moves each alone from rest to rest: the reference the junction
// speeds are measured against (NaN when one does not plan).
double stop_at_every_junction_s(const StreamRequest& request, const PulseTiming& timing) {
  uint64_t clocks = 0;
  for (const scurve::StreamMove& m : request.moves) {
    MoveRequest r;
    r.distance = m.distance;
    r.v_cruise = m.v_cruise;
    r.a_max = request.limits.a_max;
    r.j_max = request.limits.j_max;
    const PlanResult p = plan_move(r, timing);
    if (!std::holds_alternative<Plan>(p)) return std::numeric_limits<double>::quiet_NaN();
    clocks += std::get<Plan>(p).total_clocks;
  }
  return double(clocks) / ClkHz;
}

}  // namespace

void check_boundary_clocks(StreamRunResult& r) {
  const StreamMoveReport* first = nullptr;
  for (const StreamMoveReport& m : r.moves) {
    if (!m.reached) continue;
    if (!first) first = &m;
    if (m.end_clock - m.planned_end != first->end_clock - first->planned_end) {
      r.failures.push_back(fmt::format("move {} ended at clock {} (planned {}), move {} at {} (planned {}): not the "
                                       "same offset",
                                       m.index, m.end_clock, m.planned_end, first->index, first->end_clock,
                                       first->planned_end));
    }
  }
}

StreamRunResult stream_report(const PlannedStream& stream, const StreamRequest& request, const PulseTiming& timing) {
  StreamRunResult res;
  for (const scurve::StreamedMove& m : stream.moves) {
    StreamMoveReport r;
    r.index = m.index;
    r.distance = m.distance;
    r.v_in = m.v_in;
    r.v_out = m.v_out;
    r.planned_start = m.start_clock;
    r.planned_end = m.end_clock;
    r.expected_end_position = m.end_position;
    res.moves.push_back(r);
  }
  res.planned_s = double(stream.moves.empty() ? 0 : stream.moves.back().end_clock) / ClkHz;
  res.stop_each_s = stop_at_every_junction_s(request, timing);
  return res;
}

StreamRunResult run_stream(const PlannedStream& stream, const StreamRequest& request, const PulseTiming& timing,
                           SimEngine engine, uint64_t stop_jerk, uint64_t stop_acc,
                           const std::function<void(double)>& progress) {
  StreamRunResult res = stream_report(stream, request, timing);
  res.engine = engine;
  const uint64_t planned_clocks = stream.moves.empty() ? 0 : stream.moves.back().end_clock;

  PinRules rules{timing};
  rules.profile_phases = false;  // several moves: no single-move duty contract
  rules.accounting = StepAccounting::ReferencePosition;
  CoreDriver drv(engine, rules);

  CoreInputs in;
  in.enable = true;
  in.cfg = timing;
  in.pos_frac0 = kOne / 2;  // the stream planner's start fraction
  in.stop_jerk = stop_jerk;
  in.stop_acc = stop_acc;
  const auto t0 = std::chrono::steady_clock::now();
  auto tick = [&](const CoreInputs& ci, bool held) { drv.tick(ci, held); };

  std::deque<Row> rows = stream.rows;
  auto push = [&]() {
    CoreInputs w = in;
    w.row_push = true;
    w.row = rows.front();
    rows.pop_front();
    ++res.rows;
    tick(w, false);
  };
  // The first rows, then START.
  for (size_t i = 0; i < RowFifoDepth && !rows.empty() && !drv.stopped(); ++i) push();
  CoreInputs st = in;
  st.start = true;
  if (!drv.stopped()) tick(st, false);
  const uint64_t start_clock = drv.clock();
  const uint64_t slack = 100000 + 8 * (uint64_t(timing.high) + timing.low + timing.setup + timing.hold) *
                                      (stream.moves.size() + 1);
  const uint64_t limit = start_clock + planned_clocks + slack;
  bool inputs_changed = true;  // the last clock's inputs differ from `in`
  size_t next_move = 0;
  while (!drv.stopped() && drv.clock() < limit) {
    if (!rows.empty() && !drv.out().fifo_full) {
      push();
      inputs_changed = true;
    } else {
      uint64_t n = 0;
      if (engine == SimEngine::ModelFast) {
        // Nothing to push until a row ends: jump to the clock before the
        // next event (a step, a row end), stepping that one.
        const uint64_t ev = drv.model().clocks_to_next_event(in);
        if (ev > 1) n = std::min(ev - 1, limit - drv.clock());
      }
      if (n > 1) {
        drv.jump(in, n);
      } else {
        tick(in, !inputs_changed && engine != SimEngine::ModelFast);
      }
      inputs_changed = false;
    }
    if (drv.out().move_done) {
      if (next_move < res.moves.size()) {
        StreamMoveReport& m = res.moves[next_move];
        m.reached = true;
        m.end_clock = drv.clock() - 1 - start_clock;
        m.end_position = drv.out().boundary_pos;
      }
      ++next_move;
    }
    if (drv.out().done || (!drv.out().busy && drv.clock() > start_clock + 4)) break;
    if (progress && (drv.clock() & 0xffffff) == 0) {
      progress(double(drv.clock() - start_clock) / double(planned_clocks + 1));
    }
  }
  const CoreOutputs end = drv.out();
  const uint64_t done_clock = drv.clock();
  // Quiet tail: nothing may move after done.
  const uint64_t tail = 4ull * (uint64_t(timing.high) + timing.low + timing.setup + timing.hold) + 1000;
  for (uint64_t i = 0; i < tail && !drv.stopped(); ++i) tick(in, i > 0 || !inputs_changed);
  drv.pins().finish(drv.clock());
  res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  res.clocks_per_s = res.wall_s > 0 ? double(drv.clock()) / res.wall_s : 0;
  res.clocks = done_clock - start_clock;
  res.duration_s = double(res.clocks) / ClkHz;
  res.pulses = drv.pins().net_steps();
  res.mismatches = drv.checker().mismatches();
  res.matched_clocks = drv.checker().matched();
  if (!drv.checker().errors().empty()) res.first_mismatch = drv.checker().errors().front().to_string();
  res.pin_errors = drv.pins().errors();

  auto fail = [&](std::string s) { res.failures.push_back(std::move(s)); };
  if (res.mismatches) fail(fmt::format("{} lockstep mismatches: {}", res.mismatches, res.first_mismatch));
  if (end.underrun) fail(fmt::format("underrun after {} moves (the host pushes a row in every clock with room)",
                                     next_move));
  if (end.discont) fail(fmt::format("discontinuity after {} moves: the planner's rows must continue", next_move));
  if (end.fault_table) fail("table fault");
  if (!end.done && !end.underrun && !end.discont) fail(fmt::format("not done within {} clocks (hang)", limit));
  if (next_move != res.moves.size()) fail(fmt::format("{} MOVE_DONE for {} moves", next_move, res.moves.size()));
  for (const StreamMoveReport& m : res.moves) {
    if (m.reached && m.end_position != m.expected_end_position) {
      fail(fmt::format("move {} ended at {}, planned {}", m.index, m.end_position, m.expected_end_position));
    }
  }
  check_boundary_clocks(res);
  const int64_t target = stream.move_ends.empty() ? 0 : stream.move_ends.back();
  if (end.done && res.pulses != target) fail(fmt::format("pulses {} != the sum of the distances {}", res.pulses, target));
  if (res.pulses != int64_t(drv.out().ref_pos_int)) {
    fail(fmt::format("pulses {} != reference position {}", res.pulses, drv.out().ref_pos_int));
  }
  if (int64_t(drv.out().pulse_count) != res.pulses) fail(fmt::format("pulse_count_o {} != pins {}", drv.out().pulse_count, res.pulses));
  for (const std::string& e : res.pin_errors) fail(e);
  if (engine == SimEngine::Lockstep && res.matched_clocks == 0) fail("lockstep compared nothing");
  return res;
}

}  // namespace sc
