#include "scurve/cli/board_cli.h"

#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <thread>

#include "scurve/board.h"
#include "scurve/cli/homing_flags.h"
#include "scurve/cli/move_flags.h"
#include "scurve/cli/stream_file.h"
#include "scurve/hw/params.h"

namespace scurve::cli {

nlohmann::json board_status_json(const BoardStatus& s) {
  return {{"ref_pos", s.ref_pos},
          {"enc_pos", s.enc_pos},
          {"pulse_count", s.pulse_count},
          {"follow_err", s.follow_err},
          {"boundary_pos", s.boundary_pos},
          {"move_index", s.move_index},
          {"phase", phase_name(s.phase())},
          {"busy", s.busy()},
          {"done", s.done()},
          {"enabled", s.enabled()},
          {"closed_loop", s.closed_loop()},
          {"fifo_level", s.fifo_level()},
          {"faults", s.faults()},
          {"registers",
           {{"CTRL", s.ctrl}, {"STATUS", s.status}, {"ERR", s.err}, {"FIFO_STATUS", s.fifo_status},
            {"IRQ_STATUS", s.irq_status}}}};
}

nlohmann::json board_info_json(const BoardInfo& i) {
  return {{"id", i.id},
          {"version", fmt::format("{}.{}", i.version_major, i.version_minor)},
          {"axes", i.axes},
          {"closed_loop", i.closed_loop}};
}

nlohmann::json link_json(const LinkStats& l) {
  return {{"accesses", l.accesses}, {"frames", l.frames},           {"retries", l.retries},
          {"timeouts", l.timeouts}, {"bad_responses", l.bad_responses}, {"crc_rejects", l.crc_rejects},
          {"discarded", l.discarded}};
}

namespace {

// REF_POS now (the start of a move or stream).
std::variant<int32_t, Error> ref_pos(Board& board) {
  auto st = board.status();
  if (const Error* e = std::get_if<Error>(&st)) return *e;
  return std::get<BoardStatus>(st).ref_pos;
}

}  // namespace

std::variant<nlohmann::json, Error> run_move_on_board(Board& board, MoveFlags f, bool closed_loop, bool wait,
                                                      double timeout) {
  auto r0 = ref_pos(board);
  if (const Error* e = std::get_if<Error>(&r0)) return *e;
  const int32_t start_ref = std::get<int32_t>(r0);
  f.start_pos = start_ref;  // the window is checked from where the axis is
  auto planned = plan_flags(f);
  if (const Error* e = std::get_if<Error>(&planned)) {
    return Error{e->parameter.empty() ? "move" : e->parameter, e->message};
  }
  const Plan& plan = std::get<Plan>(planned);
  const MoveRequest request = to_request(f);
  BoardConfig cfg;
  cfg.timing = to_timing(f);
  cfg.closed_loop = closed_loop;
  cfg.stop = move_stop_limits(request, to_clock(f));
  cfg.soft_limits = request.soft_limits;
  if (auto e = board.configure(cfg)) return *e;
  if (auto e = board.load_move(plan)) return *e;
  if (auto e = board.start()) return *e;
  nlohmann::json j = {{"action", "run"}, {"distance", request.distance}, {"start_ref", start_ref},
                      {"duration_s", plan.duration_s}};
  if (!wait) {
    j["started"] = true;
    return j;
  }
  auto st = board.wait_idle(timeout);
  if (const Error* e = std::get_if<Error>(&st)) return *e;
  const BoardStatus& b = std::get<BoardStatus>(st);
  // The board's own account against the plan: the reference moved by the
  // distance and, open loop, the pulses on the pin are the distance.
  std::vector<std::string> problems = b.faults();
  const int64_t moved = int64_t(b.ref_pos) - start_ref;
  if (moved != request.distance) {
    problems.push_back(fmt::format("REF_POS moved {} (planned {})", moved, request.distance));
  }
  if (!closed_loop && b.pulse_count != request.distance) {
    problems.push_back(fmt::format("PULSE_COUNT {} (planned {})", b.pulse_count, request.distance));
  }
  if (!b.done()) problems.push_back("not DONE");
  j["pass"] = problems.empty();
  j["problems"] = problems;
  j["status"] = board_status_json(b);
  return j;
}

std::variant<nlohmann::json, Error> run_stream_on_board(
    Board& board, const std::string& file, const PulseTiming& timing, bool closed_loop, double timeout,
    const std::function<void(const BoardStatus&, size_t moves)>& progress) {
  auto loaded = load_stream_file(file);
  if (const std::string* e = std::get_if<std::string>(&loaded)) return Error{"FILE", *e};
  StreamRequest req = std::get<StreamRequest>(loaded);
  auto r0 = ref_pos(board);
  if (const Error* e = std::get_if<Error>(&r0)) return *e;
  req.limits.start_position = std::get<int32_t>(r0);  // the window is checked from where the axis is
  auto planned = plan_whole_stream(board.clock(), timing, req.limits, req.moves);
  if (const Error* e = std::get_if<Error>(&planned)) {
    return Error{e->parameter.empty() ? "moves" : e->parameter, e->message};
  }
  const auto& moves = std::get<std::vector<StreamedMove>>(planned);
  BoardConfig cfg;
  cfg.timing = timing;
  cfg.closed_loop = closed_loop;
  cfg.stop = StopLimits{req.limits.j_max, req.limits.a_max};
  cfg.soft_limits = req.limits.soft_limits;
  if (auto e = board.configure(cfg)) return *e;
  auto run = board.run_stream(moves, kOne / 2, timeout, 0.005, [&](const BoardStatus& b) {
    if (progress) progress(b, moves.size());
  });
  if (const Error* e = std::get_if<Error>(&run)) return *e;
  const StreamRunReport& r = std::get<StreamRunReport>(run);
  return nlohmann::json{{"action", "stream"},
                        {"moves", r.moves},
                        {"rows", r.rows},
                        {"start_ref", r.start_ref},
                        {"end_ref", r.end_ref},
                        {"expected_end", r.expected_end},
                        {"boundaries_checked", r.boundaries_checked},
                        {"pass", true},
                        {"status", board_status_json(r.final_status)}};
}

std::variant<nlohmann::json, Error> run_path_on_board(AxisGroup& group, const BoardPathRequest& request,
                                                      const std::function<void(const BoardStatus&, size_t moves)>&
                                                          progress) {
  auto st = group.status();
  if (const Error* e = std::get_if<Error>(&st)) return *e;
  PathFileOptions fo = request.options;
  if (fo.axes == 0) fo.axes = group.axes();  // G-code: as many axes as the board has
  // The program starts where the axes are: REF_POS is the machine position.
  fo.start.clear();
  for (const BoardStatus& s : std::get<std::vector<BoardStatus>>(st)) fo.start.push_back(s.ref_pos);
  if (request.options.axes != 0 && request.options.axes != group.axes()) {
    return Error{"axes", fmt::format("axes={}: the board has {}", request.options.axes, group.axes())};
  }
  auto loaded = load_path_file(request.file, fo);
  if (const std::string* e = std::get_if<std::string>(&loaded)) return Error{"FILE", *e};
  const PathProgram& prog = std::get<PathProgram>(loaded);
  PathRequest req = to_path_request(prog);
  if (request.tolerance_mm > 0) {
    req.junction = Junction::kBlend;
    req.tolerance = request.tolerance_mm * *std::min_element(prog.pulses_per_mm.begin(), prog.pulses_per_mm.end());
  }
  auto planned = plan_path(Planner{group.clock()}, req, request.timing);
  if (const Error* e = std::get_if<Error>(&planned)) return *e;
  const PathPlan& plan = std::get<PathPlan>(planned);
  if (plan.moves.empty()) {
    return Error{"FILE", fmt::format("FILE={}: every move is to where the axes already are", request.file)};
  }
  BoardConfig cfg;
  cfg.timing = request.timing;
  cfg.closed_loop = request.closed_loop;
  cfg.stop = StopLimits{req.limits.j, req.limits.a};
  if (auto e = group.configure(cfg)) return *e;
  auto run = group.run_path(
      plan, request.timeout, 0.005,
      [&](const BoardStatus& b) {
        if (progress) progress(b, plan.moves.size());
      },
      request.wait);
  if (const Error* e = std::get_if<Error>(&run)) return *e;
  const PathRunReport& r = std::get<PathRunReport>(run);
  nlohmann::json axes = nlohmann::json::array();
  for (size_t a = 0; a < group.axes(); ++a) {
    axes.push_back({{"start_ref", r.start_ref[a]},
                    {"target", plan.moves.back().target[a]},
                    {"status", board_status_json(r.final_status[a])}});
  }
  return nlohmann::json{{"action", "path"},
                        {"moves", r.moves},
                        {"rows", r.rows},
                        {"junction", req.junction == Junction::kBlend ? "blend" : "exact-stop"},
                        {"duration_s", plan.duration_s},
                        {"path_length", plan.path_length},
                        {"max_line_deviation", plan.max_line_deviation},
                        {"boundaries_checked", r.boundaries_checked},
                        {"started", true},
                        {"pass", request.wait},  // not waited for: started, nothing checked yet
                        {"axes", axes}};
}

namespace {

std::string status_table(const BoardStatus& s) {
  const std::vector<std::string> f = s.faults();
  return fmt::format(
      "REF_POS {}  ENC_POS {}  PULSE_COUNT {}  FOLLOW_ERR {}\n"
      "phase {}  {}{}  {}  FIFO {}  moves {}  BOUNDARY_POS {}\n"
      "faults: {}\n",
      s.ref_pos, s.enc_pos, s.pulse_count, s.follow_err, phase_name(s.phase()),
      s.busy() ? "busy" : "idle", s.done() ? ", done" : "", s.enabled() ? "enabled" : "disabled", s.fifo_level(),
      s.move_index, s.boundary_pos, f.empty() ? "none" : fmt::format("{}", fmt::join(f, ", ")));
}

class BoardCommandImpl : public BoardCommand {
 public:
  explicit BoardCommandImpl(CLI::App& app) {
    cmd_ = app.add_subcommand("board", "drive a board (or the virtual board) over its UART");
    cmd_->require_subcommand(1);
    cmd_->add_option("--port", port_, "the board's serial device (/dev/ttyUSB1, the virtual board's pty)")
        ->required();
    int_flag(cmd_, "--baud", link_.baud, 1, 100'000'000, "line rate of the board's UART (default 115200)");
    real_flag(cmd_, "--timeout-ms", timeout_ms_, "wait for each answer, ms (default 200)");
    int_flag(cmd_, "--retries", link_.retries, 0, 1'000'000,
             "tries again after a timeout or a garbled answer (default 3)");
    real_flag(cmd_, "--clock-hz", clock_hz_, "the board's system clock, Hz (default 20e6)");
    cmd_->add_flag("--json", json_, "JSON on stdout");
    cmd_->add_option("--map", map_,
                     "the board's register map: auto (default: asks the board), axis (the one-axis board, 1-byte "
                     "address frames), multi (the multi-axis map of the two-axis board, 2-byte frames)")
        ->check(CLI::IsMember({"auto", "axis", "multi"}));

    info_ = sub("info", "identify the board: ID, register map version, axes, closed loop");
    status_ = sub("status", "one reading of the axis: positions, phase, FIFO, faults");
    run_ = sub("run", "plan a move, load it, start it, wait for the end and check it");
    add_move_flags(run_, move_);
    run_->add_flag("--closed-loop", closed_loop_, "run it closed loop (the servo axis)");
    run_->add_flag("--no-wait", no_wait_, "return once started");
    real_flag(run_, "--timeout", run_timeout_, "seconds the move may take (default 120)", 0, 1e6);
    stream_ = sub("stream", "plan a stream file with look-ahead junctions and run it, the FIFO kept topped up");
    stream_->add_option("FILE", stream_file_, "stream file (docs/streaming.md)")->required();
    add_timing_flags(stream_, stream_timing_);
    stream_->add_flag("--closed-loop", closed_loop_, "run it closed loop (the servo axis)");
    real_flag(stream_, "--timeout", run_timeout_, "seconds the stream may take (default 120)", 0, 1e6);
    path_cmd_ = sub("path", "multi-axis board: plan a path file (JSON points or G-code) from where the axes are and "
                        "run it, the FIFO kept topped up, every axis checked on its targets");
    path_cmd_->add_option("FILE", path_req_.file, "path file: .json points or G-code (docs/multiaxis.md \"Path files\")")
        ->required();
    path_cmd_->add_option("--pulses-per-mm", path_req_.options.pulses_per_mm,
                      "pulses per mm, one per axis (default: the file's, else 100)")
        ->expected(1, 4);
    real_flag(path_cmd_, "--feed-limit", path_req_.options.feed_limit, "G-code: highest feed and G0's, mm/s (default 100)",
              0, 1e6);
    real_flag(path_cmd_, "--accel", path_req_.options.accel, "G-code: path acceleration, mm/s^2 (default 1000)", 0, 1e9);
    real_flag(path_cmd_, "--jerk", path_req_.options.jerk, "G-code: path jerk, mm/s^3 (default 10000)", 0, 1e12);
    real_flag(path_cmd_, "--blend", path_req_.tolerance_mm,
              "blend the corners within this distance of each corner point, mm (default 0: exact stops)", 0, 1e6);
    add_timing_flags(path_cmd_, path_timing_);
    path_cmd_->add_flag("--closed-loop", closed_loop_, "every axis closed loop (servo axes)");
    path_cmd_->add_flag("--no-wait", no_wait_, "return once started (a path of at most a FIFO of rows)");
    real_flag(path_cmd_, "--timeout", run_timeout_, "seconds the path may take (default 120)", 0, 1e6);
    stop_ = sub("stop", "controlled stop (CMD.STOP), then wait for rest");
    estop_ = sub("estop", "e-stop (CMD.ESTOP): the axis stops at once and is disabled until `clear`");
    clear_ = sub("clear", "clear every ERR and IRQ_STATUS flag (after an e-stop or a fault)");
    home_ = sub("home", "home the axis: seek the home switch, back off slowly, latch the release, set the zero");
    add_homing_flags(home_, home_flags_);
    add_timing_flags(home_, home_timing_);
    watch_ = sub("watch", "a live status line: position, speed, phase, FIFO level, faults");
    real_flag(watch_, "--interval", watch_interval_, "seconds between readings (default 0.2)", 0.001, 3600);
    int_flag(watch_, "--count", watch_count_, 0, 1'000'000'000, "readings, then exit (default 0: until Ctrl-C)");
  }

  bool run(int* rc) const override {
    if (!*cmd_) return false;
    *rc = run_selected();
    return true;
  }

 private:
  CLI::App* sub(const char* name, const char* what) {
    CLI::App* c = cmd_->add_subcommand(name, what);
    c->fallthrough();  // --port and the link flags may come after the action
    return c;
  }

  // One line on stderr, the exit code for it.
  static int fail(const Error& e) {
    std::cerr << "error: " << input::printable(e.message) << "\n";
    return board_exit_code(e);
  }

  int run_selected() const {
    LinkOptions lo = link_;
    lo.timeout = timeout_ms_ / 1e3;
    if (auto e = check_link_options(lo)) return fail(*e);
    if (std::string e = check_clock_flag(clock_hz_); !e.empty()) return bad_input(e);
    auto opened = open_serial_port({port_, lo.baud});
    if (const Error* e = std::get_if<Error>(&opened)) return fail(*e);
    std::unique_ptr<ByteChannel> line = std::move(std::get<std::unique_ptr<ByteChannel>>(opened));
    if (map_ == "auto") {
      auto bits = detect_addr_bits(*line, lo);
      if (const Error* e = std::get_if<Error>(&bits)) return fail(*e);
      lo.addr_bits = std::get<int>(bits);
    } else {
      lo.addr_bits = map_ == "multi" ? hw::MultiRegAddrW : hw::RegAddrW;
    }
    UartLink link(*line, lo);
    if (lo.addr_bits == hw::MultiRegAddrW) return run_group(link);
    if (*path_cmd_) {
      return bad_input("board path: the board speaks the one-axis map: run a move with `run` or a stream with "
                       "`stream` (path needs the multi-axis map of a board with several axes)");
    }
    Board board(link, Clock{clock_hz_});
    auto info = board.identify();
    if (const Error* e = std::get_if<Error>(&info)) return fail(*e);
    Session s{board, link, std::get<BoardInfo>(info)};
    if (*info_) return do_info(s);
    if (*status_) return do_status(s);
    if (*run_) return do_run(s);
    if (*stream_) return do_stream(s);
    if (*stop_) return do_stop(s);
    if (*estop_) return do_simple(s, board.estop(), "estop");
    if (*clear_) return do_simple(s, board.clear_faults(), "clear");
    if (*home_) return do_home(s);
    if (*watch_) return do_watch(s);
    return bad_input("board: an action is required");
  }

  struct Session {
    Board& board;
    UartLink& link;
    BoardInfo info;
  };

  // The multi-axis map: the axes as an AxisGroup.
  int run_group(UartLink& link) const {
    AxisGroup group(link, Clock{clock_hz_});
    auto ident = group.identify();
    if (const Error* e = std::get_if<Error>(&ident)) return fail(*e);
    const BoardInfo& info = std::get<BoardInfo>(ident);
    auto out = [&](nlohmann::json j, const std::string& text, int rc) {
      if (json_) {
        j["port"] = port_;
        j["map"] = "multi";
        j["link"] = link_json(link.stats());
        std::cout << j.dump(2) << "\n";
      } else {
        std::cout << text;
      }
      return rc;
    };
    auto statuses = [&](const std::vector<BoardStatus>& st, nlohmann::json& j, std::string& text) {
      j["axes"] = nlohmann::json::array();
      for (size_t a = 0; a < st.size(); ++a) {
        j["axes"].push_back(board_status_json(st[a]));
        text += fmt::format("axis {}:\n{}", a, status_table(st[a]));
      }
    };
    // An action, then every axis's reading.
    auto act_then_status = [&](std::optional<Error> e, const char* what, bool wait) {
      if (e) return fail(*e);
      auto st = wait ? group.wait_idle(run_timeout_) : group.status();
      if (const Error* e2 = std::get_if<Error>(&st)) return fail(*e2);
      nlohmann::json j = {{"action", what}};
      std::string text = fmt::format("{}: {}\n", what, wait ? "at rest" : "done");
      statuses(std::get<std::vector<BoardStatus>>(st), j, text);
      return out(j, text, 0);
    };
    if (*info_) {
      nlohmann::json j = board_info_json(info);
      return out(j,
                 fmt::format("board on {}: ID 0x{:08X}, register map {}.{}, {} axes on the multi-axis map, {}\n",
                             port_, info.id, info.version_major, info.version_minor, info.axes,
                             info.closed_loop ? "closed-loop servo axes" : "open-loop axes"),
                 0);
    }
    if (*status_) return act_then_status(std::nullopt, "status", false);
    if (*stop_) return act_then_status(group.stop(), "stop", true);
    if (*estop_) return act_then_status(group.estop(), "estop", false);
    if (*clear_) return act_then_status(group.clear_faults(), "clear", false);
    if (*path_cmd_) return do_path(group, out);
    if (*watch_) return do_watch_group(group);
    const char* action = *run_ ? "run" : *stream_ ? "stream" : "home";
    return bad_input(fmt::format("board {}: the board has {} axes on the multi-axis map: moves go through `path` "
                                 "(run, stream and home drive the one-axis board)", action, info.axes));
  }

  template <class Out>
  int do_path(AxisGroup& group, Out& out) const {
    BoardPathRequest r = path_req_;
    r.options.axes = 0;  // the board's
    r.timing = to_timing(path_timing_);
    r.closed_loop = closed_loop_;
    r.timeout = run_timeout_;
    r.wait = !no_wait_;
    const bool tty = isatty(2);
    auto progress = [&](const BoardStatus& b, size_t moves) {
      if (tty) std::fprintf(stderr, "\r[path: move %u of %zu, FIFO %d]", b.move_index, moves, b.fifo_level());
    };
    auto res = run_path_on_board(group, r, progress);
    if (tty) std::fputs("\n", stderr);
    if (const Error* e = std::get_if<Error>(&res)) {
      // A file or plan refused: bad input (exit 2); the board's answers: exit 1.
      if (e->parameter == "board" || e->parameter == "port" || e->parameter == "timeout") return fail(*e);
      return bad_input(e->message);
    }
    const nlohmann::json& j = std::get<nlohmann::json>(res);
    if (no_wait_) {
      return out(j, fmt::format("path: started, {} moves, {} rows\n", j["moves"].get<uint64_t>(),
                                j["rows"].get<uint64_t>()), 0);
    }
    std::string text = fmt::format("path: {} moves, {} rows, {:.6f} s planned ({}), {} boundaries checked\n",
                                   j["moves"].get<uint64_t>(), j["rows"].get<uint64_t>(),
                                   j["duration_s"].get<double>(), j["junction"].get<std::string>(),
                                   j["boundaries_checked"].get<uint64_t>());
    for (size_t a = 0; a < j["axes"].size(); ++a) {
      const nlohmann::json& x = j["axes"][a];
      text += fmt::format("axis {}: REF_POS {} -> {} (planned {}), PULSE_COUNT {}, ENC_POS {}\n", a,
                          x["start_ref"].get<int64_t>(), x["status"]["ref_pos"].get<int64_t>(),
                          x["target"].get<int64_t>(), x["status"]["pulse_count"].get<int64_t>(),
                          x["status"]["enc_pos"].get<int64_t>());
    }
    return out(j, text + "PASS\n", 0);
  }

  int do_watch_group(AxisGroup& group) const {
    for (int n = 0; watch_count_ == 0 || n < watch_count_; ++n) {
      if (n > 0) std::this_thread::sleep_for(std::chrono::duration<double>(watch_interval_));
      auto st = group.status();
      if (const Error* e = std::get_if<Error>(&st)) return fail(*e);
      const auto& axes = std::get<std::vector<BoardStatus>>(st);
      if (json_) {
        nlohmann::json j = {{"axes", nlohmann::json::array()}};
        for (const BoardStatus& b : axes) j["axes"].push_back(board_status_json(b));
        std::cout << j.dump() << std::endl;  // JSON Lines
        continue;
      }
      std::string line;
      for (size_t a = 0; a < axes.size(); ++a) {
        const std::vector<std::string> f = axes[a].faults();
        line += fmt::format("{}axis {}: REF_POS {:>11}  ENC_POS {:>11}  {:<14} faults: {}", a ? "  |  " : "", a,
                            axes[a].ref_pos, axes[a].enc_pos, phase_name(axes[a].phase()),
                            f.empty() ? "none" : fmt::format("{}", fmt::join(f, ",")));
      }
      std::cout << line << "\n" << std::flush;
    }
    return 0;
  }

  int emit(const Session& s, nlohmann::json j, const std::string& text, int rc) const {
    if (json_) {
      j["port"] = port_;
      j["link"] = link_json(s.link.stats());
      std::cout << j.dump(2) << "\n";
    } else {
      std::cout << text;
    }
    return rc;
  }

  int do_info(Session& s) const {
    const BoardInfo& i = s.info;
    return emit(s, board_info_json(i),
                fmt::format("board on {}: ID 0x{:08X}, register map {}.{}, {} axis, {}\n", port_, i.id,
                            i.version_major, i.version_minor, i.axes,
                            i.closed_loop ? "closed-loop servo axis" : "open-loop axis"),
                0);
  }

  int do_status(Session& s) const {
    auto st = s.board.status();
    if (const Error* e = std::get_if<Error>(&st)) return fail(*e);
    const BoardStatus& b = std::get<BoardStatus>(st);
    return emit(s, board_status_json(b), status_table(b), 0);
  }

  int do_simple(Session& s, std::optional<Error> e, const char* what) const {
    if (e) return fail(*e);
    auto st = s.board.status();
    if (const Error* e2 = std::get_if<Error>(&st)) return fail(*e2);
    const BoardStatus& b = std::get<BoardStatus>(st);
    return emit(s, {{"action", what}, {"status", board_status_json(b)}},
                fmt::format("{}: done\n{}", what, status_table(b)), 0);
  }

  int do_stop(Session& s) const {
    if (auto e = s.board.stop()) return fail(*e);
    auto st = s.board.wait_idle(run_timeout_);
    if (const Error* e = std::get_if<Error>(&st)) return fail(*e);
    const BoardStatus& b = std::get<BoardStatus>(st);
    return emit(s, {{"action", "stop"}, {"status", board_status_json(b)}}, "stop: at rest\n" + status_table(b), 0);
  }

  int do_run(Session& s) const {
    MoveFlags f = move_;
    f.clock_hz = clock_hz_;
    auto r = run_move_on_board(s.board, f, closed_loop_, !no_wait_, run_timeout_);
    if (const Error* e = std::get_if<Error>(&r)) return fail(*e);
    const nlohmann::json& j = std::get<nlohmann::json>(r);
    if (no_wait_) return emit(s, j, fmt::format("run: started, {} pulses\n", j["distance"].get<int64_t>()), 0);
    const bool pass = j["pass"].get<bool>();
    std::string text = fmt::format("run: {} pulses in {:.6f} s planned\n", j["distance"].get<int64_t>(),
                                   j["duration_s"].get<double>());
    auto st = s.board.status();
    if (const Error* e = std::get_if<Error>(&st)) return fail(*e);
    text += status_table(std::get<BoardStatus>(st));
    if (!pass) {
      const auto problems = j["problems"].get<std::vector<std::string>>();
      std::cerr << "error: run: " << fmt::format("{}", fmt::join(problems, "; ")) << "\n";
    }
    return emit(s, j, text + (pass ? "PASS\n" : "FAIL\n"), pass ? 0 : 1);
  }

  int do_stream(Session& s) const {
    const bool tty = isatty(2);
    auto progress = [&](const BoardStatus& b, size_t moves) {
      if (tty) std::fprintf(stderr, "\r[stream: move %u of %zu, FIFO %d]", b.move_index, moves, b.fifo_level());
    };
    auto r = run_stream_on_board(s.board, stream_file_, to_timing(stream_timing_), closed_loop_, run_timeout_,
                                 progress);
    if (tty) std::fputs("\n", stderr);
    if (const Error* e = std::get_if<Error>(&r)) return fail(*e);
    const nlohmann::json& j = std::get<nlohmann::json>(r);
    return emit(s, j,
                fmt::format("stream: {} moves, {} rows: REF_POS {} -> {} (planned {}), {} boundaries checked\nPASS\n",
                            j["moves"].get<uint64_t>(), j["rows"].get<uint64_t>(), j["start_ref"].get<int64_t>(),
                            j["end_ref"].get<int64_t>(), j["expected_end"].get<int64_t>(),
                            j["boundaries_checked"].get<uint64_t>()),
                0);
  }

  int do_home(Session& s) const {
    // The default latch speed keeps the zero exact for the board's own
    // debounce (SW_CFG.DEBOUNCE) and a clean switch.
    auto sw = s.link.read(hw::RegSwCfg);
    if (const Error* e = std::get_if<Error>(&sw)) return fail(*e);
    const uint32_t debounce = std::get<uint32_t>(sw) >> hw::SwDebounceLsb;
    const Clock clock{clock_hz_};
    const double default_latch =
        std::min(home_flags_.seek_speed, std::floor(exact_latch_speed(debounce, 0, clock) / 2));
    auto req = to_homing_request(home_, home_flags_, default_latch);
    if (const Error* e = std::get_if<Error>(&req)) return bad_input(e->message);
    const HomingRequest& r = std::get<HomingRequest>(req);
    const PulseTiming timing = to_timing(home_timing_);
    if (auto e = check_homing_request(r, timing, clock)) return bad_input(e->message);
    auto st = s.board.status();
    if (const Error* e = std::get_if<Error>(&st)) return fail(*e);
    BoardConfig cfg;
    cfg.timing = timing;
    cfg.closed_loop = std::get<BoardStatus>(st).closed_loop();  // homes in the axis's mode
    cfg.stop = StopLimits{r.j_max, r.a_max};
    if (auto e = s.board.configure(cfg)) return fail(*e);
    auto out = home(s.link, r, timing, clock);
    if (const Error* e = std::get_if<Error>(&out)) return fail(*e);
    const HomingResult& h = std::get<HomingResult>(out);
    return emit(s,
                {{"action", "home"},
                 {"home_ref", h.home_ref},
                 {"release_ref", h.release_ref},
                 {"on_index", h.on_index},
                 {"index_enc", h.index_enc},
                 {"seek_stop", h.seek_stop},
                 {"backoff_stop", h.backoff_stop},
                 {"seek_skipped", h.seek_skipped},
                 {"offset", h.offset},
                 {"latch_speed", r.latch_speed}},
                fmt::format("home: zero at REF_POS {} ({}), machine position {} there; at rest at REF_POS {}\n",
                            h.home_ref, h.on_index ? "the encoder index" : "the switch release", h.offset,
                            h.backoff_stop),
                0);
  }

  int do_watch(Session& s) const {
    using clk = std::chrono::steady_clock;
    const bool tty = isatty(1);
    std::optional<std::pair<clk::time_point, int32_t>> last;
    for (int n = 0; watch_count_ == 0 || n < watch_count_; ++n) {
      if (n > 0) std::this_thread::sleep_for(std::chrono::duration<double>(watch_interval_));
      auto st = s.board.status();
      if (const Error* e = std::get_if<Error>(&st)) {
        if (tty) std::cout << "\n";
        return fail(*e);
      }
      const BoardStatus& b = std::get<BoardStatus>(st);
      const auto now = clk::now();
      // Speed from two readings of REF_POS (host time between them).
      double speed = 0;
      if (last) speed = double(int32_t(uint32_t(b.ref_pos) - uint32_t(last->second))) /
                        std::chrono::duration<double>(now - last->first).count();
      last = {now, b.ref_pos};
      const std::vector<std::string> f = b.faults();
      if (json_) {
        nlohmann::json j = board_status_json(b);
        j["speed"] = speed;
        std::cout << j.dump() << std::endl;  // JSON Lines
        continue;
      }
      const std::string line = fmt::format(
          "REF_POS {:>11}  ENC_POS {:>11}  speed {:>10.0f} p/s  {:<14} FIFO {:>2}  move {:>5}  faults: {}", b.ref_pos,
          b.enc_pos, speed, phase_name(b.phase()), b.fifo_level(), b.move_index,
          f.empty() ? "none" : fmt::format("{}", fmt::join(f, ",")));
      std::cout << (tty ? "\r" : "") << line << (tty ? "\033[K" : "\n") << std::flush;
    }
    if (tty && !json_) std::cout << "\n";
    return 0;
  }

  CLI::App* cmd_ = nullptr;
  CLI::App *info_ = nullptr, *status_ = nullptr, *run_ = nullptr, *stream_ = nullptr, *stop_ = nullptr;
  CLI::App *estop_ = nullptr, *clear_ = nullptr, *home_ = nullptr, *watch_ = nullptr, *path_cmd_ = nullptr;
  std::string port_;
  LinkOptions link_;
  double timeout_ms_ = 200;
  double clock_hz_ = Clock::kDefaultHz;
  bool json_ = false;
  MoveFlags move_, stream_timing_, home_timing_;
  bool closed_loop_ = false, no_wait_ = false;
  double run_timeout_ = 120;
  std::string stream_file_;
  std::string map_ = "auto";
  BoardPathRequest path_req_;
  MoveFlags path_timing_;
  HomingFlags home_flags_;
  double watch_interval_ = 0.2;
  int watch_count_ = 0;
};

}  // namespace

std::unique_ptr<BoardCommand> add_board_command(CLI::App& app) { return std::make_unique<BoardCommandImpl>(app); }

}  // namespace scurve::cli
