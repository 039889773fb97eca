// Closed-loop runs: one planned move through sc_servo_axis (Verilated RTL
// and/or the bit-exact model, compared every clock) with the plant model
// outside the DUT, and the tracking metrics of DESIGN.md.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "fst_output.h"
#include "lockstep.h"
#include "plant.h"
#include "planner.h"
#include "scurve/servo_config.h"
#include "servo_axis.h"
#include "stop_check.h"
#include "stream_run.h"

namespace sc {

// Controller settings in physical units (host library, sw/);
// to_servo_config() turns them into the fixed-point cfg_* words of
// sc_servo_axis at the model's clock.
using ControllerParams = scurve::ControllerParams;

// Error message (empty = ok) for parameters that cannot be encoded.
std::string to_servo_config(const ControllerParams& p, const PlantConfig& plant, const PulseTiming& t,
                            ServoConfig& out);

enum class ClEngine { Lockstep, RtlOnly, ModelOnly };
const char* cl_engine_name(ClEngine e);

// The bound on the max tracking error |P* - 1/2 - P| (pulses) that a run
// must keep to pass, from paper 000's Table 3 (the hardware's max errors on
// its four groups: 15.6, 7.3, 25.3, 13.9 pulses). With feed-forward the
// smallest, 7.3: every run we make with it stays within 3.8 (paper group 2
// in lockstep; 3.0 on the short test moves at every control rate), so
// tracking twice as bad as our worst fails. Without feed-forward the loop
// builds the whole velocity from the error (11.7 on the short test move,
// 23.7 on paper group 1): the largest, 25.3.
inline constexpr double kMaxErrorWithFf = 7.3;
inline constexpr double kMaxErrorWithoutFf = 25.3;
inline double default_max_error_limit(const scurve::ControllerParams& c) {
  return c.ff ? kMaxErrorWithFf : kMaxErrorWithoutFf;
}

struct ClosedLoopOptions {
  ClEngine engine = ClEngine::Lockstep;
  ControllerParams ctl{};
  PlantConfig plant{};
  PulseTiming timing{};
  double tail_s = 0.1;               // quiet time after done (residual vibration)
  uint32_t weight_every = 10;        // weight samples every N control periods
  size_t max_mismatches = 1;
  std::string fst_path;
  uint64_t fst_from = 0, fst_to = kDefaultFstWindow;  // input::Error when the FST cannot be written
  std::function<void(double)> progress;
  // A controlled stop (CMD.STOP) this many clocks after the START clock: the
  // reference stops under the stop limits (checked on the model's executor
  // by the stop monitor), the controller settles on the integer position
  // where it came to rest, and the axis ends in position and not done.
  std::optional<uint64_t> stop_at;
  uint64_t stop_jerk = StopJerkReset, stop_acc = StopAccReset;  // executor LSBs
  // Test hook: called with the model before every clock (fault injection).
  std::function<void(uint64_t, ServoAxis&)> inject;
  // Max tracking error (pulses) above which the run fails; unset: the
  // default for the controller (default_max_error_limit), 0: no bound.
  std::optional<double> max_error_limit;
};

struct WeightSample {
  double t = 0;  // s since start
  double w[4] = {0, 0, 0, 0};   // w_p1 w_p2 w_v1 w_v2 (real)
  double wn[4] = {0, 0, 0, 0};  // normalised
  double e_p = 0;               // pulses
};

struct ClosedLoopResult {
  std::string name;
  ClEngine engine = ClEngine::Lockstep;
  int64_t distance = 0;
  uint64_t clocks = 0, total_clocks = 0;
  double duration_s = 0;          // start to done (in position)
  double ref_duration_s = 0;      // start to reference done
  double settle_time_s = 0;       // reference done to in position
  double max_error = 0;           // max |P* - 1/2 - P|, pulses, start to done
  double rmse = 0;
  double relative_error = 0;      // rmse / L
  int64_t final_error = 0;        // L - P after the tail, pulses
  int64_t pulses = 0;             // net STEP pulses (pins)
  double peak_jerk_enc = 0, peak_acc_enc = 0;  // from the encoder (filtered)
  double peak_jerk_ref = 0, peak_acc_ref = 0;  // same filter on the reference
  double residual_vib = 0;        // peak-to-peak rotor angle after done, pulses
  double residual_enc = 0;        // max |P - L| on the encoder after done, counts
  bool in_pos = false, fault_ferr = false, fault_overrun = false;
  uint64_t enc_illegal = 0, glitches = 0, slips = 0;
  uint64_t mismatches = 0, matched_clocks = 0;
  std::string first_mismatch;
  std::vector<std::string> pin_errors;  // pulse timing and step accounting
  StopReport stop;                      // ClosedLoopOptions::stop_at
  std::vector<StreamMoveReport> moves;  // every MOVE_DONE: its clock from START and boundary position
  uint64_t rows_left = 0;               // rows the host still held at the end
  int64_t target = 0;                   // where the axis must end: the distance, or where the stop left it
  std::vector<WeightSample> weights;
  double wall_s = 0, clocks_per_s = 0;
  std::vector<std::string> failures;
  bool pass() const { return failures.empty(); }
};

ClosedLoopResult run_closed_loop(const Plan& plan, const ClosedLoopOptions& opt);
// A planned stream on the closed-loop axis (`scurve stream --closed-loop`):
// the first rows before START, the rest pushed in every clock the FIFO has
// room; every boundary checked against the running sum and its planned
// clock (the same offset for every move), the axis in position at the sum
// at the end. Reported as the open-loop stream runner reports, with the
// tracking figures.
StreamRunResult run_closed_loop_stream(const PlannedStream& stream, const StreamRequest& request,
                                       const ClosedLoopOptions& opt);

// Field-by-field rendering of the outputs (mismatch reports).
SignalValues render_servo(const ServoOutputs& o);

// One weights CSV per run, all whole or none: each is written to
// "<path>.part", and the files are renamed into place only once every one
// of them is complete, so a full disk or a file-size limit leaves no file
// (neither a truncated one nor some runs' files). Empty on success, else
// "<file>: <reason>".
struct WeightsCsv {
  std::string path;
  const std::vector<WeightSample>* samples;
};
std::string write_weights_csvs(const std::vector<WeightsCsv>& files);

}  // namespace sc
