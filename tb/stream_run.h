// A stream of moves (scurve::StreamPlanner: look-ahead junction speeds,
// exact endpoints) run on the open-loop core: the host pushes a row in
// every clock the FIFO has room, START after the first rows, to the end at
// rest. RTL and model in lockstep (or either alone, or the model's
// fast-forward), the pin monitor on every pulse, every move boundary checked
// against the planner's running sum of distances and its clock.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <string>
#include <variant>
#include <vector>

#include "planner.h"
#include "scurve/cli/stream_file.h"
#include "scurve/stream_planner.h"
#include "sim_run.h"

namespace sc {

using scurve::cli::parse_stream_json;
using scurve::cli::StreamRequest;

// Planned moves, their rows as FIFO words (the last row of the last move
// ends the stream) and each move's end position (the running sum).
struct PlannedStream {
  std::vector<scurve::StreamedMove> moves;
  std::deque<Row> rows;
  std::deque<int64_t> move_ends;
  // Appends one planned move's rows and end position (not the move).
  void add(const scurve::StreamedMove& m, bool last_of_stream);
};
// Plans the moves, the last one to rest; an error names the move and the bound.
std::variant<PlannedStream, scurve::Error> plan_stream(const StreamRequest& request, const PulseTiming& timing);

struct StreamMoveReport {
  uint64_t index = 0;
  int64_t distance = 0;
  double v_in = 0, v_out = 0;                   // planned junction speeds, pulses/s
  uint64_t planned_start = 0, planned_end = 0;  // clocks from the first row's first clock
  uint64_t end_clock = 0;                       // measured: the clock MOVE_DONE rose, from START
  int64_t end_position = 0;                     // BOUNDARY_POS at MOVE_DONE
  int64_t expected_end_position = 0;            // the running sum of the distances
  bool reached = false;
};

struct StreamRunResult {
  SimEngine engine = SimEngine::Lockstep;
  std::vector<StreamMoveReport> moves;
  uint64_t rows = 0;
  uint64_t clocks = 0;       // START to done
  int64_t pulses = 0;        // net STEP pulses on the pins
  double duration_s = 0;     // START to done
  double planned_s = 0;      // the planner's duration of the stream
  double stop_each_s = 0;    // the same moves, each alone from rest to rest
  uint64_t mismatches = 0, matched_clocks = 0;
  std::string first_mismatch;
  std::vector<std::string> pin_errors;
  double wall_s = 0, clocks_per_s = 0;
  // The closed-loop axis (`scurve stream --closed-loop`): the encoder's
  // tracking of the reference and where it ended.
  bool closed_loop = false;
  double max_error = 0, rmse = 0;  // pulses
  int64_t final_error = 0;         // sum of the distances - encoder position, pulses
  bool in_position = false;
  std::vector<std::string> failures;
  bool pass() const { return failures.empty(); }
};

// The report of a planned stream before it runs: each move's planned
// junction speeds, clocks and end position, the planned duration and that
// of the same moves stopping at every junction.
StreamRunResult stream_report(const PlannedStream& stream, const StreamRequest& request, const PulseTiming& timing);
// Every boundary at its planned clock: the same offset (the arming after
// START) for every move reached, so no row was stretched or cut; a failure
// per move that is off.
void check_boundary_clocks(StreamRunResult& r);

// Runs `stream` with the stop limits of an underrun (executor LSBs).
StreamRunResult run_stream(const PlannedStream& stream, const StreamRequest& request, const PulseTiming& timing,
                           SimEngine engine, uint64_t stop_jerk, uint64_t stop_acc,
                           const std::function<void(double)>& progress = {});

}  // namespace sc
