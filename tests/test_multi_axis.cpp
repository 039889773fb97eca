// The multi-axis core (sc_multi_axis_core) against its model in lockstep,
// every clock, on coordinated lines from scurve::plan_line; and what the
// model cannot vouch for itself: the pins of every axis (pulse timing, step
// accounting), every axis on its exact integer target, all axes loading
// every row on the same clock, the reference's distance from the straight
// line, and the stops (CMD.STOP, a limit on one axis) that halt all axes.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "closed_loop_run.h"
#include "multi_run.h"
#include "planner.h"

namespace sc {
namespace {

struct Line {
  std::vector<int64_t> distances;
  double v = 0, a = 0, j = 0;
  std::string what() const {
    std::string s = "distances";
    for (int64_t d : distances) s += " " + std::to_string(d);
    return s + " v " + std::to_string(v) + " a " + std::to_string(a) + " j " + std::to_string(j);
  }
};

scurve::LinePlan plan(const Line& l) {
  scurve::LineRequest r;
  r.distances = l.distances;
  r.v_path = l.v;
  r.a_path = l.a;
  r.j_path = l.j;
  auto p = scurve::plan_line(scurve::Planner{model_clock()}, r, to_host(PulseTiming{}));
  if (auto* e = std::get_if<scurve::Error>(&p)) throw std::runtime_error(e->message);
  return std::get<scurve::LinePlan>(p);
}

// A random line on `axes` axes, both directions, short enough for the
// default suite (tens of milliseconds at 20 MHz).
Line random_line(std::mt19937_64& rng, size_t axes) {
  Line l;
  std::uniform_real_distribution<double> u(0, 1);
  const double scale = std::pow(10.0, 1 + 2.4 * u(rng));  // 10 .. 2500 pulses
  bool any = false;
  for (size_t i = 0; i < axes; ++i) {
    int64_t d = int64_t(std::llround(scale * u(rng))) * (u(rng) < 0.5 ? -1 : 1);
    if (u(rng) < 0.1) d = 0;
    any = any || d != 0;
    l.distances.push_back(d);
  }
  if (!any) l.distances[0] = 1 + int64_t(scale);
  double len = 0;
  for (int64_t d : l.distances) len += double(d) * double(d);
  len = std::sqrt(len);
  l.v = std::max(20000 + 130000 * u(rng), len / 0.03);
  l.v = std::min(l.v, 150000.0);
  l.a = 2e6 + 2e7 * u(rng);
  l.j = 2e8 + 5e9 * u(rng);
  return l;
}

void expect_exact(const Line& l, const MultiRunResult& r) {
  const std::string what = l.what();
  EXPECT_EQ(r.mismatches, 0u) << what;
  EXPECT_GT(r.compared, 0u) << what;
  for (const std::string& e : r.errors) ADD_FAILURE() << what << ": " << e;
  for (size_t a = 0; a < r.axes; ++a) {
    EXPECT_EQ(r.ref_pos[a], l.distances[a]) << what << " axis " << a;
    EXPECT_EQ(r.pin_steps[a], l.distances[a]) << what << " axis " << a;
    EXPECT_TRUE(r.done[a]) << what << " axis " << a;
    EXPECT_FALSE(r.reversed[a]) << what << " axis " << a;
  }
  EXPECT_LT(r.max_line_deviation, 0.01) << what;
}

void random_lines(size_t axes, int count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  double worst = 0;
  uint64_t clocks = 0;
  double wall = 0;
  for (int i = 0; i < count; ++i) {
    const Line l = random_line(rng, axes);
    const MultiRunResult r = run_multi(line_rows(plan(l)), MultiRunOptions{});
    expect_exact(l, r);
    worst = std::max(worst, r.max_line_deviation);
    clocks += r.clocks;
    wall += r.wall_seconds;
    if (::testing::Test::HasFailure()) return;
  }
  ::testing::Test::RecordProperty("max_line_deviation_pulses", std::to_string(worst));
  ::testing::Test::RecordProperty("lockstep_clocks_per_second", std::to_string(double(clocks) / wall));
  std::printf("%d random %zu-axis lines: max line deviation %.3g pulses, %.3g clocks, %.3g M clocks/s lockstep\n",
              count, axes, worst, double(clocks), double(clocks) / wall / 1e6);
}

TEST(MultiAxisLockstep, TwoAxisLinesEndEveryAxisOnItsTargetWithSharedRowsOnTheLine) {
  const Line l{{12000, -5000}, 120000, 1e7, 2e9};
  const MultiRunResult r = run_multi(line_rows(plan(l)), MultiRunOptions{});
  expect_exact(l, r);
}

TEST(MultiAxisLockstep, HundredRandomTwoAxisLinesMatchAndEndExactly) { random_lines(2, 100, 21); }

TEST(MultiAxisLockstep, ThirtyRandomThreeAxisLinesMatchAndEndExactly) { random_lines(3, 30, 31); }

TEST(MultiAxisLockstep, AnAxisThatDoesNotMoveStaysAtRestWhileTheOthersRun) {
  const Line l{{0, 4000, -3000}, 100000, 8e6, 1e9};
  const MultiRunResult r = run_multi(line_rows(plan(l)), MultiRunOptions{});
  expect_exact(l, r);
}

// Opposite DIR on the two axes, one of which must turn DIR at START: both
// executors start on the same clock all the same (the row checks would see
// a skew), and a second line in the other directions does it again.
TEST(MultiAxisLockstep, AxesThatTurnDirAtStartStillStartTogether) {
  const Line l{{-700, 900}, 60000, 5e6, 1e9};
  MultiRunOptions o;
  o.timing.setup = 400;  // a long DIR setup: a skew would show for hundreds of clocks
  const MultiRunResult r = run_multi(line_rows(plan(l)), o);
  expect_exact(l, r);
}

MultiRunOptions stop_options(const Line& l, uint64_t at) {
  MultiRunOptions o;
  auto codes = line_stop_codes(l.distances, l.j, l.a, model_clock());
  if (auto* e = std::get_if<scurve::Error>(&codes)) throw std::runtime_error(e->message);
  o.stop = std::get<std::vector<scurve::StopLimitCodes>>(codes);
  o.stop_at = at;
  return o;
}

void expect_stopped_together(const Line& l, const MultiRunResult& r, uint64_t max_skew) {
  const std::string what = l.what();
  EXPECT_EQ(r.mismatches, 0u) << what;
  for (const std::string& e : r.errors) ADD_FAILURE() << what << ": " << e;
  uint64_t first = UINT64_MAX, last = 0;
  for (size_t a = 0; a < r.axes; ++a) {
    EXPECT_EQ(int64_t(r.ref_pos[a]), r.pin_steps[a]) << what << " axis " << a << ": pins and reference differ";
    EXPECT_FALSE(r.done[a]) << what << " axis " << a << ": a stopped move is not done";
    EXPECT_FALSE(r.reversed[a]) << what << " axis " << a;
    EXPECT_LE(std::abs(int64_t(r.ref_pos[a])), std::abs(l.distances[a])) << what << " axis " << a;
    if (l.distances[a] == 0) continue;
    EXPECT_NE(r.stop_clock[a], UINT64_MAX) << what << " axis " << a << " never stopped";
    first = std::min(first, r.stop_clock[a]);
    last = std::max(last, r.stop_clock[a]);
  }
  EXPECT_LE(last - first, max_skew) << what;
}

// CMD.STOP at random clocks of random lines, each axis with its share of
// the path's stop limits: every axis stops on the same clock, under
// control, without reversing, its count exact, and the tool stays near the
// line (reported).
TEST(MultiAxisLockstep, StopInTheMiddleOfALineStopsEveryAxisTogetherAlongTheLine) {
  std::mt19937_64 rng(41);
  double worst = 0;
  for (int i = 0; i < 12; ++i) {
    const Line l = random_line(rng, 2 + i % 2);
    const scurve::LinePlan p = plan(l);
    const uint64_t at = 1 + rng() % std::max<uint64_t>(2, p.total_clocks - 1);
    const MultiRunResult r = run_multi(line_rows(p), stop_options(l, at));
    expect_stopped_together(l, r, 0);
    worst = std::max(worst, r.max_line_deviation);
  }
  ::testing::Test::RecordProperty("stop_max_line_deviation_pulses", std::to_string(worst));
  std::printf("12 stopped lines: max line deviation %.3g pulses\n", worst);
}

// A limit switch on one axis (soft: a controlled stop; hard: at once) stops
// every axis: the others within two clocks of it.
TEST(MultiAxisLockstep, ALimitOnOneAxisStopsAllAxes) {
  for (bool hard : {false, true}) {
    const Line l{{3000, 2000}, 100000, 1e7, 2e9};
    MultiRunOptions o = stop_options(l, UINT64_MAX / 2);
    o.stop_at.reset();
    o.limit_at = plan(l).total_clocks / 2;
    o.limit_axis = 1;
    o.limit_hard = hard;
    o.check_sync = false;
    const MultiRunResult r = run_multi(line_rows(plan(l)), o);
    EXPECT_EQ(r.mismatches, 0u) << "hard " << hard;
    for (const std::string& e : r.errors) ADD_FAILURE() << "hard " << hard << ": " << e;
    for (size_t a = 0; a < 2; ++a) {
      EXPECT_EQ(int64_t(r.ref_pos[a]), r.pin_steps[a]) << "hard " << hard << " axis " << a;
      EXPECT_FALSE(r.done[a]) << "hard " << hard << " axis " << a;
      EXPECT_LT(r.ref_pos[a], l.distances[a]) << "hard " << hard << " axis " << a << " ran to its end";
      EXPECT_GT(r.ref_pos[a], 0) << "hard " << hard << " axis " << a;
      if (!hard) {
        EXPECT_NE(r.stop_clock[a], UINT64_MAX) << "axis " << a;
      }
    }
    if (!hard) {
      EXPECT_GE(r.stop_clock[0], r.stop_clock[1]);
      EXPECT_LE(r.stop_clock[0] - r.stop_clock[1], 2u);
    }
  }
}

// A START toward a limit active on one axis is refused by every axis:
// nothing arms, nothing moves.
TEST(MultiAxisLockstep, AStartTowardALimitOnOneAxisIsRefusedByAll) {
  const Line l{{1500, -800}, 80000, 1e7, 2e9};
  MultiRunOptions o;
  o.limit_at = 0;
  o.limit_axis = 1;
  o.measure_line = false;
  const MultiRunResult r = run_multi(line_rows(plan(l)), o);
  EXPECT_EQ(r.mismatches, 0u);
  EXPECT_GT(r.compared, 0u);
  for (size_t a = 0; a < 2; ++a) {
    EXPECT_EQ(r.ref_pos[a], 0) << "axis " << a;
    EXPECT_EQ(r.pin_steps[a], 0) << "axis " << a;
    EXPECT_FALSE(r.done[a]) << "axis " << a;
  }
  EXPECT_LT(r.clocks, 10u);
}

// A random path request: 2 to 4 lines from 0, every axis +-600 pulses a
// line, a random feed (and with blends a random corner tolerance).
scurve::PathRequest random_path_request(std::mt19937_64& rng, size_t axes, scurve::Junction junction) {
  scurve::PathRequest req;
  req.axes = axes;
  req.limits = {40000 + 100000 * double(rng() % 1000) / 1000, 1e7, 2e9};
  req.junction = junction;
  if (junction == scurve::Junction::kBlend) req.tolerance = 0.5 + double(rng() % 500) / 10;
  std::vector<int64_t> at(axes, 0);
  const int moves = 2 + int(rng() % 3);
  for (int k = 0; k < moves; ++k) {
    scurve::PathMove m;
    for (size_t a = 0; a < axes; ++a) at[a] += int64_t(rng() % 1201) - 600;
    m.target_pulses = at;
    m.feed = req.limits.v;
    m.source_line = k + 1;
    req.moves.push_back(m);
  }
  return req;
}

// Random paths of 2 to 4 lines (scurve::plan_path: one row stream, each line
// from the fraction the last one left), with exact stops or blended
// junctions (a random corner tolerance): in lockstep every move's last row
// ends where the plan puts it on every axis (its integer target with exact
// stops; with a blend the target plus what the next line covered), the path
// on its last target, the pins agree, and the reference stays on the lines
// (exact stops) or within the tolerance of them (blends), every clock.
void random_paths(size_t axes, int count, uint64_t seed, scurve::Junction junction) {
  std::mt19937_64 rng(seed);
  const bool blend = junction == scurve::Junction::kBlend;
  for (int i = 0; i < count; ++i) {
    const scurve::PathRequest req = random_path_request(rng, axes, junction);
    auto p = scurve::plan_path(scurve::Planner{model_clock()}, req, to_host(PulseTiming{}));
    ASSERT_TRUE(std::holds_alternative<scurve::PathPlan>(p)) << std::get<scurve::Error>(p).message;
    const scurve::PathPlan& plan = std::get<scurve::PathPlan>(p);
    MultiRunOptions o;
    o.measure_line = false;
    o.polyline = path_polyline(plan);
    o.contour_adjacent = blend;
    o.check_phases = !blend;
    const MultiRunResult r = run_multi(path_rows(plan), o);
    const std::string what = fmt::format("path {} ({} moves, tolerance {})", i, plan.moves.size(), req.tolerance);
    EXPECT_EQ(r.mismatches, 0u) << what;
    for (const std::string& e : r.errors) ADD_FAILURE() << what << ": " << e;
    ASSERT_EQ(r.move_ends.size(), plan.moves.size()) << what;
    for (size_t k = 0; k < plan.moves.size(); ++k) {
      for (size_t a = 0; a < axes; ++a) {
        const int64_t planned = int64_t(plan.moves[k].end_position[a] >> FracBits);
        EXPECT_EQ(r.move_ends[k].ref_pos[a], planned) << what << " move " << k << " axis " << a;
        if (!blend) {
          EXPECT_EQ(planned, plan.moves[k].target[a]) << what << " move " << k << " axis " << a;
        }
      }
    }
    for (size_t a = 0; a < axes; ++a) {
      EXPECT_EQ(r.ref_pos[a], plan.moves.back().target[a]) << what << " axis " << a;
      EXPECT_EQ(r.pin_steps[a], int64_t(r.ref_pos[a])) << what << " axis " << a;
    }
    EXPECT_LT(r.contour_max, blend ? req.tolerance * (1 + 1e-9) + 1e-6 : 0.01) << what;
    if (::testing::Test::HasFailure()) return;
  }
}

TEST(MultiAxisLockstep, RandomTwoAxisPathsWithExactStopsEndEveryMoveOnItsTarget) {
  random_paths(2, 20, 51, scurve::Junction::kExactStop);
}

TEST(MultiAxisLockstep, RandomThreeAxisPathsWithExactStopsEndEveryMoveOnItsTarget) {
  random_paths(3, 8, 61, scurve::Junction::kExactStop);
}

TEST(MultiAxisLockstep, RandomTwoAxisPathsWithBlendedJunctionsEndExactlyWithinTheTolerance) {
  random_paths(2, 20, 53, scurve::Junction::kBlend);
}

TEST(MultiAxisLockstep, RandomThreeAxisPathsWithBlendedJunctionsEndExactlyWithinTheTolerance) {
  random_paths(3, 8, 63, scurve::Junction::kBlend);
}

// Soft-limit windows on every axis, the look-ahead's rows checked by the
// one evaluator the axes share. Windows exactly at the extremes of a path
// (the start and the corners) or wider run it to its end on every target;
// a window cut short on one axis stops every axis on the same clock, at the
// row boundary before the first row that would leave it (no axis loads that
// row: every clock all axes hold the same rows): that axis flags REACH,
// nothing ends done, the rows that ran stayed inside (checked on the
// reference, clock by clock, before any stop ran), the pins agree with
// REF_POS.
MultiLoop servo_loop(const ControllerParams& c);

void soft_window_paths(size_t axes, int count, uint64_t seed, bool servo) {
  std::mt19937_64 rng(seed);
  int cut_runs = 0, start_refusals = 0;
  for (int i = 0; i < count; ++i) {
    const scurve::PathRequest req = random_path_request(rng, axes, scurve::Junction::kExactStop);
    std::vector<int64_t> lo(axes, 0), hi(axes, 0);  // every axis's extremes: the start and the corners
    for (const scurve::PathMove& m : req.moves) {
      for (size_t a = 0; a < axes; ++a) {
        lo[a] = std::min(lo[a], m.target_pulses[a]);
        hi[a] = std::max(hi[a], m.target_pulses[a]);
      }
    }
    auto p = scurve::plan_path(scurve::Planner{model_clock()}, req, to_host(PulseTiming{}));
    ASSERT_TRUE(std::holds_alternative<scurve::PathPlan>(p)) << std::get<scurve::Error>(p).message;
    const scurve::PathPlan& plan = std::get<scurve::PathPlan>(p);
    MultiRunOptions o;
    o.measure_line = false;
    if (servo) o.loop = servo_loop(ControllerParams{});
    for (size_t a = 0; a < axes; ++a) {
      const int64_t margin = (i % 2 == 0) ? 0 : int64_t(rng() % 6);
      o.soft.push_back(SoftWindow{true, int32_t(lo[a] - margin), int32_t(hi[a] + margin)});
    }
    // Every third path inside its windows; the others with one side of one
    // moving axis cut short (the start stays inside).
    const bool cut = i % 3 != 0;
    size_t axis = 0;
    bool upper = true;
    if (cut) {
      axis = size_t(rng() % axes);
      while (hi[axis] == lo[axis]) axis = (axis + 1) % axes;
      upper = hi[axis] > 0 && (lo[axis] == 0 || rng() % 2 == 0);
      const int64_t room = upper ? hi[axis] : -lo[axis];
      const int64_t by = 1 + int64_t(rng() % uint64_t(room));
      if (upper) o.soft[axis].max = int32_t(hi[axis] - by);
      else       o.soft[axis].min = int32_t(lo[axis] + by);
    }
    const MultiRunResult r = run_multi(path_rows(plan), o);
    const std::string what = fmt::format("path {} ({} moves){}", i, plan.moves.size(),
                                         cut ? fmt::format(", axis {} window [{}, {}]", axis, o.soft[axis].min,
                                                           o.soft[axis].max)
                                             : std::string(", inside its windows"));
    EXPECT_EQ(r.mismatches, 0u) << what;
    EXPECT_GT(r.compared, 0u) << what;
    for (const std::string& e : r.errors) ADD_FAILURE() << what << ": " << e;
    for (size_t a = 0; a < axes; ++a) {
      // (in the loop the pins follow the controller: the pin monitor counts
      // them against its step counter)
      if (!servo) {
        EXPECT_EQ(r.pin_steps[a], int64_t(r.ref_pos[a])) << what << " axis " << a;
      }
      EXPECT_GE(r.min_pos_before_stop[a], o.soft[a].min) << what << " axis " << a;
      EXPECT_LE(r.max_pos_before_stop[a], o.soft[a].max) << what << " axis " << a;
    }
    if (!cut) {
      for (size_t a = 0; a < axes; ++a) {
        EXPECT_EQ(r.ref_pos[a], plan.moves.back().target[a]) << what << " axis " << a;
        EXPECT_TRUE(r.done[a]) << what << " axis " << a;
        EXPECT_FALSE(r.reach[a]) << what << " axis " << a;
      }
    } else {
      ++cut_runs;
      EXPECT_TRUE(r.reach[axis]) << what << ": the look-ahead refused no row";
      bool moved = false;
      for (size_t a = 0; a < axes; ++a) {
        EXPECT_FALSE(r.done[a]) << what << " axis " << a;
        moved = moved || r.pin_steps[a] != 0;
      }
      if (!moved) ++start_refusals;
      for (size_t a = 1; a < axes && moved; ++a) {
        EXPECT_EQ(r.stop_clock[a], r.stop_clock[0]) << what << ": axis " << a << " stopped on another clock";
      }
    }
    if (::testing::Test::HasFailure()) return;
  }
  std::printf("%d paths on %zu axes%s: %d cut short (%d refused at START)\n", count, axes, servo ? " (servo)" : "",
              cut_runs, start_refusals);
}

TEST(MultiAxisLockstep, SoftWindowsOnEveryAxisStopAllAxesBeforeARowLeavesOneAndPassPathsInside) {
  soft_window_paths(2, 6, 71, false);
  soft_window_paths(3, 3, 73, false);
}

// Nightly size: 100 random 2-axis and 30 random 3-axis paths, half with
// exact stops and half blended (other seeds than the default suite's).
TEST(MultiAxisPathsLong, HundredTwoAxisAndThirtyThreeAxisPathsInBothJunctionModes) {
  random_paths(2, 50, 151, scurve::Junction::kExactStop);
  random_paths(2, 50, 153, scurve::Junction::kBlend);
  random_paths(3, 15, 161, scurve::Junction::kExactStop);
  random_paths(3, 15, 163, scurve::Junction::kBlend);
}

// ---- the closed-loop capable core (Servo = 1): a servo loop per axis ------

MultiLoop servo_loop(const ControllerParams& c = ControllerParams{}) {
  MultiLoop l;
  l.closed = c.closed_loop;
  ServoConfig cfg;
  const std::string err = to_servo_config(c, l.plant, PulseTiming{}, cfg);
  if (!err.empty()) throw std::runtime_error(err);
  l.ctl = cfg.ctl;
  return l;
}

// Every axis in its own loop on its own plant: RTL = model every clock (the
// controllers' state included), the pins against each step counter, every
// axis's reference on its exact target, the loop settled in position on it
// and the tracking within the single-axis bound.
void expect_closed_loop_line(const Line& l, const MultiRunResult& r) {
  const std::string what = l.what();
  EXPECT_EQ(r.mismatches, 0u) << what;
  EXPECT_GT(r.compared, 0u) << what;
  for (const std::string& e : r.errors) ADD_FAILURE() << what << ": " << e;
  ASSERT_EQ(r.in_pos.size(), r.axes) << what;
  for (size_t a = 0; a < r.axes; ++a) {
    EXPECT_EQ(r.ref_pos[a], l.distances[a]) << what << " axis " << a;
    EXPECT_TRUE(r.done[a]) << what << " axis " << a;
    EXPECT_TRUE(r.in_pos[a]) << what << " axis " << a;
    EXPECT_EQ(r.final_error[a], 0.0) << what << " axis " << a << ": steady-state error";
    EXPECT_EQ(double(r.pin_steps[a]), r.measured_pos[a]) << what << " axis " << a << ": pulses vs encoder";
    EXPECT_LT(r.max_tracking_error[a], kMaxErrorWithFf) << what << " axis " << a;
  }
  EXPECT_LT(r.max_line_deviation, 0.01) << what;
}

// A random line a stepper on the default plant (163 Hz rotor) can follow:
// the single-axis closed-loop tests' range of speeds, both directions.
Line random_servo_line(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  Line l;
  for (int i = 0; i < 2; ++i) {
    l.distances.push_back(int64_t(std::llround(50 + 1450 * u(rng))) * (u(rng) < 0.5 ? -1 : 1));
  }
  l.v = 3000 + 9000 * u(rng);
  l.a = 1e5 + 3e5 * u(rng);
  l.j = 5e6 + 3e7 * u(rng);
  return l;
}

TEST(MultiAxisClosedLoop, RandomTwoAxisLinesInTheLoopMatchSettleAndTrack) {
  std::mt19937_64 rng(71);
  MultiRunOptions o;
  o.loop = servo_loop();
  double worst = 0;
  uint64_t clocks = 0;
  double wall = 0;
  for (int i = 0; i < 5; ++i) {
    const Line l = random_servo_line(rng);
    const MultiRunResult r = run_multi(line_rows(plan(l)), o);
    expect_closed_loop_line(l, r);
    for (double e : r.max_tracking_error) worst = std::max(worst, e);
    clocks += r.compared;
    wall += r.wall_seconds;
  }
  ::testing::Test::RecordProperty("closed_loop_max_tracking_error_pulses", std::to_string(worst));
  std::printf("5 closed-loop lines: max tracking error %.3g pulses, %.3g M clocks at %.3g M clocks/s\n", worst,
              double(clocks) * 1e-6, double(clocks) * 1e-6 / wall);
}

// CMD.STOP in the middle of a line in the loop: every reference stops on
// the same clock along the line, every loop settles in position on its
// reference's integer stop position, the pulses equal the encoder.
TEST(MultiAxisClosedLoop, StopInTheMiddleOfALineStopsBothLoopsTogetherInPosition) {
  std::mt19937_64 rng(75);
  for (int i = 0; i < 2; ++i) {
    const Line l = random_servo_line(rng);
    const scurve::LinePlan p = plan(l);
    MultiRunOptions o = stop_options(l, p.total_clocks / 3 + rng() % (p.total_clocks / 3));
    o.loop = servo_loop();
    const MultiRunResult r = run_multi(line_rows(p), o);
    const std::string what = l.what();
    EXPECT_EQ(r.mismatches, 0u) << what;
    for (const std::string& e : r.errors) ADD_FAILURE() << what << ": " << e;
    ASSERT_EQ(r.in_pos.size(), 2u);
    EXPECT_EQ(r.stop_clock[0], r.stop_clock[1]) << what;
    for (size_t a = 0; a < 2; ++a) {
      EXPECT_NE(r.stop_clock[a], UINT64_MAX) << what << " axis " << a;
      EXPECT_FALSE(r.done[a]) << what << " axis " << a << ": a stopped move is not done";
      EXPECT_TRUE(r.in_pos[a]) << what << " axis " << a;
      EXPECT_EQ(r.final_error[a], 0.0) << what << " axis " << a;
      EXPECT_LT(std::abs(int64_t(r.ref_pos[a])), std::abs(l.distances[a])) << what << " axis " << a;
      EXPECT_FALSE(r.reversed[a]) << what << " axis " << a;
    }
    EXPECT_LT(r.max_line_deviation, 0.01) << what;
  }
}

// A following error on one axis (its limit below the tracking error the
// move needs) stops both: with CL_CFG.FERR_STOP under control along the line
// (the other axis one register stage later, as for a limit), each loop
// settling in position on its reference's stop position; else at once (both
// references freeze on the same clock, the loops stop). The fault stays on
// the axis that had it.
TEST(MultiAxisClosedLoop, AFollowingErrorOnOneAxisStopsBothAxes) {
  for (bool ferr_stop : {true, false}) {
    const Line l{{1200, 900}, 8000, 2e5, 2e7};
    const scurve::LinePlan p = plan(l);
    ControllerParams c;
    c.ferr_stop = ferr_stop;
    MultiRunOptions o = stop_options(l, 0);
    o.stop_at.reset();
    o.loop = servo_loop(c);
    c.ferr_lim = 1.0;
    o.loop->ctl_per_axis = {o.loop->ctl, servo_loop(c).ctl};
    o.check_sync = false;  // axis 1 stops first
    const MultiRunResult r = run_multi(line_rows(p), o);
    const std::string what = ferr_stop ? "ferr_stop" : "ferr abort";
    EXPECT_EQ(r.mismatches, 0u) << what;
    for (const std::string& e : r.errors) ADD_FAILURE() << what << ": " << e;
    ASSERT_EQ(r.ferr.size(), 2u) << what;
    EXPECT_FALSE(r.ferr[0]) << what;
    EXPECT_TRUE(r.ferr[1]) << what;
    for (size_t a = 0; a < 2; ++a) {
      EXPECT_FALSE(r.done[a]) << what << " axis " << a;
      EXPECT_LT(std::abs(int64_t(r.ref_pos[a])), std::abs(l.distances[a])) << what << " axis " << a << " ran on";
      if (ferr_stop) {
        EXPECT_TRUE(r.in_pos[a]) << what << " axis " << a;
        EXPECT_EQ(r.final_error[a], 0.0) << what << " axis " << a;
      }
    }
    if (ferr_stop) {
      EXPECT_NE(r.stop_clock[1], UINT64_MAX) << what;
      EXPECT_GE(r.stop_clock[0], r.stop_clock[1]) << what;
      EXPECT_LE(r.stop_clock[0] - r.stop_clock[1], 2u) << what;
      EXPECT_LT(r.max_line_deviation, 0.01) << what;
    }
  }
}

// Exact stop fine (paper 002): every line STARTs on its own once both loops
// are in position within their window at the corner. Lockstep, every move
// on its exact target, each next line started with the measured position
// within the window of the corner, after at least the in-position hold time.
TEST(MultiAxisClosedLoop, ExactStopFineStartsEachLineOnlyOnceEveryAxisSettledAtTheCorner) {
  scurve::PathRequest req;
  req.axes = 2;
  req.limits = {8000, 2e5, 2e7};
  req.moves = {{{900, 400}, 8000, 1}, {{300, 1100}, 8000, 2}, {{-200, 600}, 8000, 3}};
  auto p = scurve::plan_path(scurve::Planner{model_clock()}, req, to_host(PulseTiming{}));
  ASSERT_TRUE(std::holds_alternative<scurve::PathPlan>(p)) << std::get<scurve::Error>(p).message;
  const scurve::PathPlan& plan = std::get<scurve::PathPlan>(p);
  ControllerParams c;
  c.inpos_win = 1;
  MultiRunOptions o;
  o.measure_line = false;
  o.settle_each_move = true;
  o.polyline = path_polyline(plan);
  o.loop = servo_loop(c);
  const MultiRunResult r = run_multi(path_rows(plan), o);
  EXPECT_EQ(r.mismatches, 0u);
  for (const std::string& e : r.errors) ADD_FAILURE() << e;
  ASSERT_EQ(r.move_ends.size(), 3u);
  for (size_t k = 0; k < 3; ++k) {
    for (size_t a = 0; a < 2; ++a) EXPECT_EQ(r.move_ends[k].ref_pos[a], plan.moves[k].target[a]) << k << " " << a;
  }
  ASSERT_EQ(r.junction_wait.size(), 2u);
  for (size_t k = 0; k < 2; ++k) {
    EXPECT_LE(r.corner_error[k], std::sqrt(2.0) * c.inpos_win) << "corner " << k;
    EXPECT_GE(double(r.junction_wait[k]), c.inpos_hold_s * ClkHz) << "corner " << k;
  }
  for (size_t a = 0; a < 2; ++a) {
    EXPECT_TRUE(r.in_pos[a]) << a;
    EXPECT_LE(std::abs(r.final_error[a]), c.inpos_win) << a;
  }
  EXPECT_LT(r.contour_max, 0.01);
}

// The same core with the loop off runs the open-loop path through the same
// pins: exact, pins = reference, synchronised as the open-loop core.
TEST(MultiAxisClosedLoop, SoftWindowsStopBothLoopsBeforeARowLeavesOne) { soft_window_paths(2, 3, 75, true); }

TEST(MultiAxisClosedLoop, TheServoCoreWithTheLoopOffRunsLinesOpenLoopExactly) {
  std::mt19937_64 rng(73);
  ControllerParams c;
  c.closed_loop = false;
  MultiRunOptions o;
  o.loop = servo_loop(c);
  for (int i = 0; i < 4; ++i) {
    const Line l = random_line(rng, 2);
    expect_exact(l, run_multi(line_rows(plan(l)), o));
  }
}

TEST(MultiAxisModel, AxisCountOutsideOneToMaxAxesIsRefusedNamingIt) {
  EXPECT_THROW(MultiAxisCore(0), std::invalid_argument);
  EXPECT_THROW(MultiAxisCore(MaxAxes + 1), std::invalid_argument);
  try {
    MultiAxisCore m(7);
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("axes=7"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sc
