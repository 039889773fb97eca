// The move flags every command that plans a move shares (scurve plan / regs /
// sim, sc_bench): one parser, one conversion to the planner's request.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "scurve/cli/user_input.h"
#include "scurve/planner.h"
#include "scurve/reg_encode.h"
#include "scurve/retarget.h"

namespace scurve::cli {

struct MoveFlags {
  int64_t distance = 0;
  bool distance_given = false;
  double v_start = 0, v_cruise = 0, v_end = 0, a_max = 0, j_max = 0;
  std::string profile = "scurve";
  std::vector<double> jerks;  // ts1 ts2 te1 te2
  bool adjust_end_speed = false;
  int pulse_high = PulseTiming{}.high, pulse_low = PulseTiming{}.low;
  int dir_setup = PulseTiming{}.setup, dir_hold = PulseTiming{}.hold;
  double clock_hz = Clock::kDefaultHz;
  // The travel window (MoveRequest::soft_limits): either side alone leaves
  // the other unbounded; neither: no window.
  int64_t start_pos = 0;
  std::optional<int64_t> soft_min, soft_max;
  std::string axis = "x";
  bool json = false;
  std::string json_out;
};

// --distance .. --adjust-end-speed and the window (--start-pos, --soft-min,
// --soft-max, --axis), collected in *move_opts if given, and the pulse
// timing (--pulse-high, --pulse-low, --dir-setup, --dir-hold).
void add_move_flags(CLI::App* app, MoveFlags& f, std::vector<CLI::Option*>* move_opts = nullptr);
// The pulse timing alone (--pulse-high, --pulse-low, --dir-setup, --dir-hold).
void add_timing_flags(CLI::App* app, MoveFlags& f);
// --clock-hz: the board's system clock.
void add_clock_flag(CLI::App* app, MoveFlags& f);
// --json, --json-out.
void add_output_flags(CLI::App* app, MoveFlags& f);

// Empty when the flags make a move; else one line naming the flag: a missing
// --distance, --jerks without an S-curve, --soft-min above --soft-max.
std::string check_move_flags(const MoveFlags& f);
MoveRequest to_request(const MoveFlags& f);
PulseTiming to_timing(const MoveFlags& f);
Clock to_clock(const MoveFlags& f);
// Empty if --clock-hz is usable, else one line naming the flag and the bound.
std::string check_clock_flag(double hz);

// --stop-at, --stop-jerk, --stop-acc: a controlled stop (CMD.STOP) during
// the move, and the stop limits (STOP_JERK, STOP_ACC).
struct StopFlags {
  double at = 0, jerk = 0, acc = 0;
  bool at_given = false, jerk_given = false, acc_given = false;
};
void add_stop_flags(CLI::App* app, StopFlags& f);
// The stop the flags ask for against the planned move: the limits (the
// move's own unless given, move_stop_limits) as register values, and the
// clock of the stop counted from the START clock.
struct StopRequest {
  StopLimits limits;
  StopLimitCodes codes;
  std::optional<uint64_t> at_clock;
};
// The stop, or one line naming the flag, its value and the bound.
std::variant<StopRequest, std::string> resolve_stop_flags(const StopFlags& f, const MoveRequest& request,
                                                          const Plan& plan);

// --retarget-at, --retarget-distance: redirect the running move (RETARGET_ROW,
// ROW_PUSH.REPLACE) to a new distance from its start, decided at a time
// after START (scurve::plan_retarget picks the boundary and plans from it).
struct RetargetFlags {
  double at = 0;
  int64_t distance = 0;
  bool at_given = false, distance_given = false;
};
void add_retarget_flags(CLI::App* app, RetargetFlags& f);
// Without the flags: no retarget. Else the plan, or one line naming the
// flag, its value and the bound (both flags go together).
std::variant<std::optional<RetargetPlan>, std::string> resolve_retarget_flags(const RetargetFlags& f,
                                                                             const MoveRequest& request,
                                                                             const Plan& plan,
                                                                             const PulseTiming& timing);

// Number flags read through the validation layer (decimal notation, finite,
// integer, range); CLI11 reports its message (exit 2).
CLI::Option* real_flag(CLI::App* app, const char* flag, double& target, const std::string& what,
                       double lo = -input::kAnyReal, double hi = input::kAnyReal);
template <typename T>
CLI::Option* int_flag(CLI::App* app, const char* flag, T& target, int64_t lo, int64_t hi, const std::string& what) {
  return app
      ->add_option_function<std::string>(
          flag,
          [&target, flag, lo, hi](const std::string& v) {
            try {
              target = T(input::parse_int(flag + 2, v, lo, hi));
            } catch (const input::Error& e) {
              throw CLI::ValidationError(e.what());
            }
          },
          what)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
}
// A file the command writes, checked when parsed (input::output_path).
CLI::Option* output_file_flag(CLI::App* app, const char* flag, std::string& target, const std::string& what);

// One line "error: <msg>" on stderr; returns 2 (bad input).
int bad_input(const std::string& msg);
// Parses the command line. When parsing ends the program (--help, or a usage
// error reported by bad_input) returns its exit code; empty when the
// command is to run.
std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv);
// Parses flags alone (no program name, no subcommand: the Python bindings'
// keyword arguments) as a command line is parsed; empty when parsed, else
// the one-line error.
std::string parse_flags(CLI::App& app, std::vector<std::string> args);
// The move the flags ask for, planned: the flag checks (check_move_flags,
// check_clock_flag; parameter empty) or the planner's error, or the plan.
std::variant<Plan, Error> plan_flags(const MoveFlags& f);
// Writes j (indented) to path; true if path is empty or the write worked.
bool write_json_file(const std::string& path, const nlohmann::json& j);

}  // namespace scurve::cli
