// Retarget on the fly: ROW_PUSH.REPLACE makes a row row number k of the
// running stream, dropping the queued rows from k on, in one clock, or is
// refused (nothing changes) once row k is loaded. The executor model at the
// exact boundary clocks; random retargets of running moves in RTL/model
// lockstep with the pin monitor. The expected end positions come from the
// host library's closed forms (the old rows up to boundary k, then the new
// plan's exact end window), not from the executor.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <random>

#include "planner.h"
#include "scurve/reg_encode.h"
#include "sim_run.h"

using namespace sc;

namespace {

const scurve::Clock kClock = model_clock();

scurve::Plan plan_or_fail(const scurve::MoveRequest& r) {
  auto p = scurve::Planner{kClock}.plan(r, scurve::PulseTiming{});
  if (const scurve::Error* e = std::get_if<scurve::Error>(&p)) {
    ADD_FAILURE() << e->message;
    return {};
  }
  return std::get<scurve::Plan>(p);
}

scurve::MoveRequest request(int64_t distance, double v, double a = 2e6, double j = 4e8,
                            scurve::ProfileKind kind = scurve::ProfileKind::SCurve) {
  scurve::MoveRequest r;
  r.kind = kind;
  r.distance = distance;
  r.v_cruise = v;
  r.a_max = a;
  r.j_max = j;
  return r;
}

// The executor's exact state at the start of row k: position in LSBs from
// integer 0 (the start fraction included), velocity and acceleration (row
// k - 1's end: a trapezoid's row k steps from it).
struct Boundary {
  i128 pos = 0;
  i128 vel = 0;
  int64_t acc = 0;
  uint64_t clock = 0;  // clocks from the first row's first clock
};
Boundary boundary_of(const std::vector<scurve::Segment>& rows, u128 frac0, size_t k) {
  Boundary b;
  b.pos = i128(frac0);
  for (size_t i = 0; i < k; ++i) {
    const scurve::Segment& s = rows[i];
    b.pos += scurve::pos_gain(s.vel0, s.acc0, s.jerk, s.clocks);
    b.clock += s.clocks;
  }
  b.vel = rows[k].vel0;
  b.acc = k == 0 ? rows[0].acc0
                 : int64_t(scurve::acc_after(rows[k - 1].acc0, rows[k - 1].jerk, rows[k - 1].clocks));
  return b;
}

i128 floor_pulses(i128 lsb) {
  const i128 one = i128(kOne);
  return lsb >= 0 ? lsb / one : -((-lsb + one - 1) / one);
}

// A plan from boundary `b` (any acceleration) over `distance` more pulses;
// its rows as FIFO words, the last one ending the stream.
std::optional<std::vector<Row>> replan(const Boundary& b, int64_t distance, double v,
                                       scurve::ProfileKind kind = scurve::ProfileKind::SCurve) {
  scurve::ExactState st{b.vel, b.acc, u128(b.pos - floor_pulses(b.pos) * i128(kOne))};
  auto p = scurve::Planner{kClock}.plan_from_state(st, request(distance, v, 2e6, 4e8, kind), scurve::PulseTiming{});
  if (std::holds_alternative<scurve::Error>(p)) return std::nullopt;
  std::vector<Segment> segs;
  for (const scurve::Segment& s : std::get<scurve::Plan>(p).segments) segs.push_back(to_model(s));
  return move_rows(segs, true, b.acc);  // a trapezoid's first row steps from b.acc: ACC_STEP
}

void push(ProfileExec& ex, const Row& r, bool replace = false, uint32_t k = 0) {
  ProfileExec::Inputs w;
  w.row_push = true;
  w.row = r;
  w.row_replace = replace;
  w.retarget_row = k;
  ex.step(w);
}

}  // namespace

TEST(RetargetExec, AReplaceBeforeItsRowLoadsRedirectsTheMoveOneOnTheBoundaryClockIsRefused) {
  const scurve::Plan p = plan_or_fail(request(3000, 40000));
  std::vector<Segment> segs;
  for (const scurve::Segment& s : p.segments) segs.push_back(to_model(s));
  const std::vector<Row> rows = move_rows(segs, true);
  // The first row after the first acceleration phase with a = 0: the cruise.
  size_t k = 1;
  while (k < rows.size() && rows[k].seg.acc0 != 0) ++k;
  ASSERT_LT(k, rows.size() - 1);
  const Boundary b = boundary_of(p.segments, p.pos_frac0, k);
  const auto fresh = replan(b, 2500 - int64_t(floor_pulses(b.pos)), 40000);
  ASSERT_TRUE(fresh.has_value());

  for (int late : {0, 1}) {
    ProfileExec ex;
    load_and_start(ex, segs, p.pos_frac0);
    // Run to the clock where row k - 1 ends (its boundary: row k loads now).
    while (!(ex.state().rows == k && ex.state().left == 1)) ex.step({});
    ASSERT_EQ(ex.state().rows, k);
    if (late) ex.step({});  // one clock later: row k is loaded
    const size_t level = ex.fifo_level();
    // Row k + 0 on its boundary clock (late = 0) or after it is refused.
    push(ex, (*fresh)[0], true, uint32_t(k));
    EXPECT_TRUE(ex.state().refused);
    EXPECT_EQ(ex.fifo_level(), level - (late ? 0 : 1)) << "a refused replace changes nothing";
    EXPECT_EQ(ex.state().rows, k + 1);
    ex.step({});
    EXPECT_FALSE(ex.state().refused) << "one clock";
    while (ex.state().run) ex.step({});
    EXPECT_TRUE(ex.state().finished);
    EXPECT_EQ(ex.state().pint, 3000) << "the old move runs on";
  }

  // One clock before the boundary: accepted; the rest of the old move is
  // dropped and the new rows run, ending exactly where the closed form says.
  ProfileExec ex;
  load_and_start(ex, segs, p.pos_frac0);
  while (!(ex.state().rows == k && ex.state().left == 2)) ex.step({});
  push(ex, (*fresh)[0], true, uint32_t(k));
  EXPECT_FALSE(ex.state().refused);
  EXPECT_EQ(ex.fifo_level(), 1u) << "rows from k on dropped, the new one in their place";
  for (size_t i = 1; i < fresh->size(); ++i) push(ex, (*fresh)[i]);
  while (ex.state().run) ex.step({});
  EXPECT_TRUE(ex.state().finished);
  EXPECT_FALSE(ex.state().underrun || ex.state().discont || ex.state().fault);
  EXPECT_EQ(ex.state().pint, 2500);
}

TEST(RetargetExec, AReplaceIsRefusedWhileIdleStoppingOrBeyondTheQueuedRowsAndCountsTheWholeMovesItLeaves) {
  const scurve::Plan p = plan_or_fail(request(2000, 30000));
  std::vector<Segment> segs;
  for (const scurve::Segment& s : p.segments) segs.push_back(to_model(s));
  const std::vector<Row> rows = move_rows(segs, true);
  {
    ProfileExec ex;  // idle
    push(ex, rows[0], true, 0);
    EXPECT_TRUE(ex.state().refused);
    EXPECT_EQ(ex.fifo_level(), 0u);
  }
  {
    ProfileExec ex;  // beyond the queued rows: a gap would be a hole in the stream
    load_and_start(ex, segs, p.pos_frac0);
    const size_t level = ex.fifo_level();
    push(ex, rows[1], true, uint32_t(ex.state().rows + level + 1));
    EXPECT_TRUE(ex.state().refused);
    EXPECT_EQ(ex.fifo_level(), level);
    // Right behind the queued rows: an append that counts as a replace.
    push(ex, rows[1], true, uint32_t(ex.state().rows + ex.fifo_level()));
    EXPECT_FALSE(ex.state().refused);
    EXPECT_EQ(ex.fifo_level(), level + 1);
  }
  {
    ProfileExec ex;  // the STREAM_END row runs: nothing after it would run
    load_and_start(ex, segs, p.pos_frac0);
    while (ex.state().rows < rows.size()) ex.step({});
    ASSERT_TRUE(ex.state().run);
    push(ex, rows[1], true, uint32_t(ex.state().rows));
    EXPECT_TRUE(ex.state().refused);
    EXPECT_EQ(ex.fifo_level(), 0u);
  }
  {
    ProfileExec ex;  // stopping
    load_and_start(ex, segs, p.pos_frac0);
    for (int i = 0; i < 1000; ++i) ex.step({});
    ProfileExec::Inputs s;
    s.stop = true;
    ex.step(s);
    ASSERT_TRUE(ex.stopping());
    push(ex, rows[1], true, uint32_t(ex.state().rows));
    EXPECT_TRUE(ex.state().refused);
  }
  {
    // The MOVE_END count a HOLD waits on follows a replace: a replace that
    // completes the queued move ends the hold.
    ProfileExec ex;
    Row hold{};
    hold.seg.phase = Phase::PhCruise;
    hold.seg.clocks = 1;
    hold.seg.vel0 = i128(1) << 70;
    hold.flags = kRowHold;
    push(ex, hold);
    ProfileExec::Inputs st;
    st.start = true;
    ex.step(st);
    ex.step({});
    ASSERT_TRUE(ex.holding());
    Row cruise = hold;
    cruise.flags = 0;
    cruise.seg.clocks = 100;
    push(ex, cruise);
    Row last = cruise;
    last.flags = kRowMoveEnd | kRowHold;
    push(ex, last);  // a whole move queued: the hold ends in this clock
    EXPECT_FALSE(ex.holding());
    ProfileExec ex2;
    push(ex2, hold);
    ex2.step(st);
    ex2.step({});
    push(ex2, cruise);
    push(ex2, cruise);
    ASSERT_TRUE(ex2.holding());
    push(ex2, last, true, ex2.state().rows + 1);  // replaces the second cruise row: now whole
    EXPECT_FALSE(ex2.holding());
  }
}

namespace {

struct RetargetCase {
  int64_t distance = 0;
  double v = 0;
  size_t k = 0;          // the row replaced from
  int64_t delta = 0;     // push clock - the clock row k loads (< 0: accepted; not before START)
  int64_t new_end = 0;   // pulses from the start
  scurve::ProfileKind kind = scurve::ProfileKind::SCurve;
};

// One move retargeted while it runs, on the core, RTL and model in
// lockstep; the replace is pushed `delta` clocks from the clock row k loads
// by the plan (the rows' clocks from the clock row 0 loaded). Returns the
// failures; *refused_seen: RETARGET_REFUSED rose.
std::vector<std::string> run_retarget(const RetargetCase& c, SimEngine engine, bool* refused_seen) {
  const scurve::Plan p = plan_or_fail(request(c.distance, c.v, 2e6, 4e8, c.kind));
  std::vector<Segment> segs;
  for (const scurve::Segment& s : p.segments) segs.push_back(to_model(s));
  const std::vector<Row> rows = move_rows(segs, true);
  const Boundary b = boundary_of(p.segments, p.pos_frac0, c.k);
  const auto fresh = replan(b, c.new_end - int64_t(floor_pulses(b.pos)), c.v, c.kind);
  if (!fresh) return {"no plan"};
  // A host one row a clock keeps up only if every new row is queued before
  // the clock it loads (row 0 with the replace, row i > 0 at delta + i + 1;
  // row i loads at the sum of the new rows' clocks before it).
  uint64_t load_at = 0;
  for (size_t i = 1; i < fresh->size(); ++i) {
    load_at += (*fresh)[i - 1].seg.clocks;
    if (c.delta < 0 && c.delta + int64_t(i) + 1 >= int64_t(load_at)) return {"host too slow"};
  }

  PinRules rules{PulseTiming{}};
  rules.profile_phases = false;
  rules.accounting = StepAccounting::ReferencePosition;
  CoreDriver drv(engine, rules);
  CoreInputs in;
  in.enable = true;
  in.pos_frac0 = p.pos_frac0;
  drv.tick(in);
  for (const CoreInputs& ci : load_sequence(rows, p.pos_frac0, in)) drv.tick(ci);
  for (uint64_t i = 0; drv.out().row_count == 0 && i < 100'000; ++i) drv.tick(in, i > 0);
  const uint64_t loads_k = drv.clock() + b.clock;  // the tick that ends here loads row k
  const uint64_t push_at = uint64_t(int64_t(loads_k) + c.delta);
  for (uint64_t i = 0; drv.clock() + 1 < push_at && i < 400'000'000; ++i) drv.tick(in, i > 0);
  const bool late = drv.clock() + 1 >= loads_k;  // the push's clock is row k's or later
  bool refused = false;
  for (size_t i = 0; i < fresh->size(); ++i) {
    CoreInputs w = in;
    w.row_push = true;
    w.row = (*fresh)[i];
    w.row_replace = i == 0;
    w.retarget_row = uint32_t(c.k);
    drv.tick(w);
    refused = refused || drv.out().retarget_refused;
    if (i == 0) {
      drv.tick(in);
      refused = refused || drv.out().retarget_refused;
      if (refused) break;  // the host reads ERR.RETARGET and sends nothing more
    }
  }
  *refused_seen = refused;
  for (uint64_t i = 0; drv.out().busy && i < 400'000'000 && !drv.stopped(); ++i) drv.tick(in, i > 0);
  for (int i = 0; i < 2000; ++i) drv.tick(in, i > 0);
  drv.pins().finish(drv.clock());
  const CoreOutputs& o = drv.out();
  std::vector<std::string> failures;
  auto fail = [&](std::string s) { failures.push_back(std::move(s)); };
  if (refused != late) fail(fmt::format("refused {}, expected {}", refused, late));
  const int64_t want = refused ? c.distance : c.new_end;
  if (!o.done) fail("not done");
  if (o.underrun || o.discont || o.fault_table) fail("underrun, discontinuity or fault");
  if (o.ref_pos_int != want) fail(fmt::format("ended at {}, expected {}", o.ref_pos_int, want));
  if (drv.pins().net_steps() != o.ref_pos_int) fail("pins != reference position");
  if (drv.checker().mismatches()) fail(drv.checker().errors().front().to_string());
  for (const std::string& e : drv.pins().errors()) fail(e);
  return failures;
}

// `cases` random retargets of running moves of one profile kind, in
// lockstep; counts the accepted and refused ones and the accepted ones from
// a boundary where the executor's acceleration is not 0.
struct RetargetCounts {
  int accepted = 0, refused = 0, with_acc = 0;
};
RetargetCounts run_random_retargets(scurve::ProfileKind kind, int cases, uint64_t seed) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  RetargetCounts n_of;
  for (int n = 0; n < cases;) {
    RetargetCase c;
    c.kind = kind;
    const int dir = (g() & 1) ? 1 : -1;
    c.distance = dir * int64_t(1000 + 4000 * u(g));
    c.v = 10000 + 60000 * u(g);
    const scurve::Plan p = plan_or_fail(request(c.distance, c.v, 2e6, 4e8, kind));
    // Boundaries in motion inside the move, at any acceleration.
    std::vector<size_t> ks;
    for (size_t k = 1; k + 1 < p.segments.size(); ++k) {
      if (p.segments[k].vel0 != 0) ks.push_back(k);
    }
    if (ks.empty()) continue;
    c.k = ks[g() % ks.size()];
    static const int64_t kDeltas[] = {-20000, -300, -2, -1, 0, 1, 3, 500};
    c.delta = kDeltas[g() % 8];
    const Boundary b = boundary_of(p.segments, p.pos_frac0, c.k);
    const int64_t here = int64_t(floor_pulses(b.pos));
    c.new_end = here + dir * int64_t(200 + 6000 * u(g));
    bool seen = false;
    const auto f = run_retarget(c, SimEngine::Lockstep, &seen);
    if (f.size() == 1 && (f[0] == "no plan" || f[0] == "host too slow")) continue;
    EXPECT_TRUE(f.empty()) << fmt::format("case {}: distance {} v {} k {} delta {} new end {}: {}", n, c.distance,
                                          c.v, c.k, c.delta, c.new_end, f.empty() ? "" : f.front());
    (seen ? n_of.refused : n_of.accepted) += 1;
    n_of.with_acc += !seen && b.acc != 0;
    ++n;
  }
  return n_of;
}

}  // namespace

TEST(RetargetLockstep, RandomRetargetsOfRunningMovesEndOnTheNewTargetOrAreRefusedAndMatchEveryClock) {
  const RetargetCounts n = run_random_retargets(scurve::ProfileKind::SCurve, 24, 9);
  EXPECT_GT(n.accepted, 4);
  EXPECT_GT(n.refused, 3);
  EXPECT_GT(n.with_acc, 2) << "retargets from boundaries with nonzero acceleration";
}

// A trapezoid's rows step the acceleration: a retarget from a boundary
// inside a ramp starts its new rows with a step from that acceleration
// (ACC_STEP), which the continuity guard takes.
TEST(RetargetLockstep, TrapezoidMovesRetargetFromBoundariesInsideTheirRampsAndEndOnTheNewTarget) {
  const RetargetCounts n = run_random_retargets(scurve::ProfileKind::Trapezoid, 16, 19);
  EXPECT_GT(n.accepted, 4);
  EXPECT_GT(n.refused, 1);
  EXPECT_GT(n.with_acc, 2) << "retargets from boundaries with nonzero acceleration";
}
