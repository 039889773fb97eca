// Coordinated rows on the multi-axis core (sc_multi_axis_core / MultiAxisCore):
// the host pushes one multi-axis row in every clock the FIFO has room, START
// after the first rows, to the end at rest (or a CMD.STOP at a given clock).
// RTL and model in lockstep (or the model alone), every clock compared; and
// checks that do not mirror the RTL: the pin monitor on every axis, the
// axes' row loads on the same clock, and the reference's distance from the
// straight line measured clock by clock.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "multi_axis_core.h"
#include "plant.h"
#include "scurve/line_planner.h"
#include "scurve/path_planner.h"
#include "scurve/reg_encode.h"

namespace sc {

// One coordinated move's FIFO words: rows[axis][k], the same clocks for every
// axis at each k, and each axis's start fraction.
struct MultiRows {
  std::vector<std::vector<Row>> rows;
  std::vector<u128> pos_frac0;
  // A path's: each move's start fraction per axis (move_frac0[k][axis]), what
  // POS_FRAC0 holds when the move STARTs on its own (settle_each_move).
  std::vector<std::vector<u128>> move_frac0;
  size_t axes() const { return rows.size(); }
};
// The rows of a planned line (the last row ends the stream).
MultiRows line_rows(const scurve::LinePlan& plan);
// The rows of a planned path (every move back to back, its flags).
MultiRows path_rows(const scurve::PathPlan& plan);
// A planned path's polyline in the reference's coordinates (REF_POS starts
// at 0 at the path's start), for MultiRunOptions::polyline: each move's start
// point with the fraction the plan starts it from, the end mid-pulse on the
// last target.
std::vector<std::vector<double>> path_polyline(const scurve::PathPlan& plan);

// The closed-loop capable core (sc_multi_axis_core #(.Servo(1))): every
// axis drives its own plant (the model of tb/plant.h, seed + axis index)
// from STEP/DIR and reads its encoder back, in the loop or (closed = false)
// on the open-loop path of the same core.
struct MultiLoop {
  bool closed = true;
  NeuronConfig ctl{};  // every axis's controller settings (to_servo_config)
  PlantConfig plant{};
  std::vector<NeuronConfig> ctl_per_axis;   // empty: `ctl` on every axis
  std::vector<PlantConfig> plant_per_axis;  // empty: `plant` on every axis
};

struct MultiRunOptions {
  bool rtl = true;  // RTL and model in lockstep; false: the model alone
  std::optional<MultiLoop> loop;  // unset: the open-loop core (Servo = 0)
  PulseTiming timing{};
  // STOP_JERK / STOP_ACC per axis (empty: the registers' reset values).
  std::vector<scurve::StopLimitCodes> stop;
  std::optional<uint64_t> stop_at;  // CMD.STOP this many clocks after START
  // A limit switch: both limits of axis `limit_axis` become active this many
  // clocks after START (0: before it), hard (immediate) or soft (controlled).
  std::optional<uint64_t> limit_at;
  size_t limit_axis = 0;
  bool limit_hard = false;
  // The soft-limit window per axis (SOFT_EN, SOFT_MIN, SOFT_MAX; empty: off
  // on every axis). A window that a row would leave stops every axis.
  std::vector<SoftWindow> soft;
  // Check every clock that all axes load rows together (off where one axis
  // is meant to stop first: a limit on one axis).
  bool check_sync = true;
  // Measure the reference's largest distance from the straight line from
  // its start to where the unstopped move ends (a model pre-pass finds it).
  bool measure_line = true;
  // A path's polyline (vertices per axis, pulses, in reference
  // coordinates): the contour error is the reference's distance from the
  // segment of the move it is in (the move index), every clock.
  std::vector<std::vector<double>> polyline;
  // Exact stop fine (paper 002): every move (rows up to a MOVE_END row) is
  // pushed and STARTed on its own once every axis is done with the last one
  // (closed loop: in position, within its INPOS_WIN for its hold time), so
  // the next line starts only when every axis has settled at the corner.
  // Needs MultiRows::move_frac0 (path_rows).
  bool settle_each_move = false;
  // Blended junctions: the distance from the nearer of the move's segment
  // and the next one (the next move starts before this one ends).
  bool contour_adjacent = false;
  // The pin monitor's duty-phase trends (a row's phase says whether the
  // pulse rate rises or falls): off for blended rows, whose phase is the
  // earlier line's while the next one's acceleration adds to it.
  bool check_phases = true;
  uint64_t max_clocks = 400'000'000;
  std::function<void(double)> progress;  // fraction of the rows pushed, now and then
  // A decimated trace of the reference (MultiRunResult::trace): a sample
  // every trace_every clocks from START, at every move end and at the end;
  // 0: none (the run then costs one compare per clock for it).
  uint64_t trace_every = 0;
};

// The decimated trace, sample by sample (`clock` from START); pos and vel
// hold `axes` values per sample, axis by axis.
struct MultiTrace {
  size_t axes = 0;
  std::vector<uint64_t> clock;
  std::vector<double> pos;      // reference position, pulses (REF_POS plus its fraction)
  std::vector<double> vel;      // reference velocity, pulses/s
  // closed loop: the measured position (encoder) plus 1/2 pulse, pulses: the
  // reference's coordinates (the loop follows P* - 1/2); empty in open loop
  std::vector<double> measured;
  std::vector<double> contour;  // contour error, pulses (0 without a polyline or before the first row)
  size_t size() const { return clock.size(); }
};

// Where a move ended: the clock (from START) its last row ended and REF_POS
// of every axis there.
struct MultiMoveEnd {
  uint64_t clock = 0;
  std::vector<int32_t> ref_pos;
};

struct MultiRunResult {
  size_t axes = 0;
  uint64_t clocks = 0;      // START to every axis idle
  uint64_t compared = 0;    // clocks compared RTL against model
  uint64_t mismatches = 0;
  std::vector<std::string> errors;  // lockstep, pins, synchronisation, timeout
  std::vector<int32_t> ref_pos;     // REF_POS per axis at the end
  std::vector<int64_t> pin_steps;   // net STEP edges per axis (pins)
  std::vector<bool> done;           // DONE per axis at the end
  std::vector<uint64_t> stop_clock;  // per axis: the first clock its stop ran (UINT64_MAX: none)
  std::vector<bool> reversed;       // per axis: the reference velocity changed sign
  std::vector<bool> reach;          // per axis at the end: its look-ahead refused a row
  // Per axis: the lowest and highest REF_POS before any axis's stop ran
  // (the rows that ran, without the stopping distance).
  std::vector<int32_t> min_pos_before_stop, max_pos_before_stop;
  double max_line_deviation = 0;    // pulses, every clock (measure_line)
  double contour_max = 0, contour_rms = 0;  // pulses, from the polyline (options.polyline)
  std::vector<MultiMoveEnd> move_ends;      // one per completed move
  // settle_each_move: per junction the clocks from the move's last row to
  // the next START (the settling), and the measured position's distance
  // from the corner (the reference at rest) at that START, pulses.
  std::vector<uint64_t> junction_wait;
  std::vector<double> corner_error;
  // Peaks of the reference, every clock: along the path (Euclidean) and per
  // axis (pulses/s, /s^2; jerk per axis, /s^3).
  double peak_path_velocity = 0, peak_path_acceleration = 0;
  std::vector<double> peak_velocity, peak_acceleration, peak_jerk;
  MultiTrace trace;  // options.trace_every > 0
  // With options.loop: the measured position (encoder counts / counts per
  // pulse) per axis at the end, the largest tracking error |reference -
  // measured| (pulses, every clock; the reference at rest is its integer
  // position, where the loop settles), the steady-state error at the end
  // (REF_POS - measured, pulses), each axis in position at the end, and the
  // contour error of the measured position from the polyline.
  std::vector<double> measured_pos, max_tracking_error, final_error;
  std::vector<bool> in_pos, ferr;  // in position / following-error fault at the end
  // With options.loop and a polyline, per axis: the largest overshoot of the
  // measured position past the target of the line that moved the axis, in
  // that line's direction (pulses), and the largest as a percentage of the
  // axis's travel on its line (each maximum on its own).
  std::vector<double> overshoot, overshoot_percent;
  double measured_contour_max = 0, measured_contour_rms = 0;
  double wall_seconds = 0;
  bool ok() const { return errors.empty() && mismatches == 0; }
};

MultiRunResult run_multi(const MultiRows& rows, const MultiRunOptions& options);

// Each axis's share of a path's stop limits (jerk and deceleration along
// the path, pulses/s^3 and /s^2) for a line of these distances, as register
// codes at `clock`: with them the axes of a stopped line brake along it. An
// axis that does not move keeps the path's limits (it has nothing to stop).
std::variant<std::vector<scurve::StopLimitCodes>, scurve::Error> line_stop_codes(
    const std::vector<int64_t>& distances, double stop_jerk, double stop_acc, scurve::Clock clock);

}  // namespace sc
