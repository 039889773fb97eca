// `scurve board --port DEV info|status|run|stream|path|stop|estop|clear|home|watch`:
// a board (or the virtual board's pseudo-terminal) driven over its UART; the
// one-axis board, or the two-axis board on the multi-axis map (`path`).
// Exit codes: 0 ok, 1 the board reported a refusal or a fault (or a check
// of what it did failed), 2 bad input, no board, a broken line.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <variant>

#include "scurve/board.h"
#include "scurve/cli/move_flags.h"
#include "scurve/cli/path_file.h"

namespace scurve::cli {

class BoardCommand {
 public:
  virtual ~BoardCommand() = default;
  // Runs `board` if it was selected; false otherwise.
  virtual bool run(int* exit_code) const = 0;
};

std::unique_ptr<BoardCommand> add_board_command(CLI::App& app);

// What `scurve board` and the Python bindings share: JSON of a reading, of
// ID, of the link's counters; a planned move run on the board (configure:
// pulse timing, the move's own stop limits, its window; load; start; unless
// !wait, wait and check REF_POS, PULSE_COUNT open loop, DONE, no fault:
// "pass" and "problems" in the report); a stream file run on the board. An
// Error names the place (see scurve/board.h; a refused plan names its field).
nlohmann::json board_status_json(const BoardStatus& s);
nlohmann::json board_info_json(const BoardInfo& i);
nlohmann::json link_json(const LinkStats& l);
std::variant<nlohmann::json, Error> run_move_on_board(Board& board, MoveFlags f, bool closed_loop, bool wait,
                                                      double timeout);
std::variant<nlohmann::json, Error> run_stream_on_board(
    Board& board, const std::string& file, const PulseTiming& timing, bool closed_loop, double timeout,
    const std::function<void(const BoardStatus&, size_t moves)>& progress = {});
// A path file (scurve/cli/path_file.h) on a multi-axis board: planned from
// where the axes are (the file's own start is not used), with exact stops or
// blends within `tolerance_mm` of each corner (0: exact stops), the path's jerk and
// acceleration as every axis's stop limits; run (AxisGroup::run_path) and
// reported per axis. A file or plan the planner refuses is an Error naming
// "FILE" or the planner's field.
struct BoardPathRequest {
  std::string file;
  PathFileOptions options;
  double tolerance_mm = 0;  // > 0: blended junctions (in pulses: times the smallest pulses_per_mm)
  PulseTiming timing;
  bool closed_loop = false;
  double timeout = 120;
  bool wait = true;  // false: return once started (a path of at most a FIFO of rows)
};
std::variant<nlohmann::json, Error> run_path_on_board(AxisGroup& group, const BoardPathRequest& request,
                                                      const std::function<void(const BoardStatus&, size_t moves)>&
                                                          progress = {});

}  // namespace scurve::cli
