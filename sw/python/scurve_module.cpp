// Python bindings of the host library: `import scurve`.
//
// The keyword arguments are the CLI's flags (distance=..., v_cruise=...,
// clock_hz=...: --distance, --v-cruise, --clock-hz) and go through the same
// parser and validation layer as a command line, so a request means the same
// and fails with the same one-line message from Python as from `scurve plan`.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <fmt/format.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scurve/board.h"
#include "scurve/cli/board_cli.h"
#include "scurve/cli/move_flags.h"
#include "scurve/cli/plan_report.h"
#include "scurve/cli/regs_cli.h"
#include "scurve/hw/regmap.h"
#include "scurve/planner.h"
#include "scurve/reg_encode.h"

namespace py = pybind11;
using namespace scurve;

namespace {

// A number as the command line would carry it: ints as digits, floats in
// the shortest form that reads back to the same value (repr).
std::string flag_value(const py::handle& v) {
  if (py::isinstance<py::bool_>(v)) throw py::type_error("a switch takes True or False, not a value list");
  if (py::isinstance<py::str>(v)) return v.cast<std::string>();
  return py::repr(v).cast<std::string>();
}

// Keyword arguments -> flags of `app`: name_with_underscores ->
// --name-with-dashes; True gives the switch, False leaves it out; a list or
// tuple gives several values (jerks=[...]). An unknown name is a TypeError,
// as for any Python function.
std::vector<std::string> flag_args(const CLI::App& app, const char* fn, const py::kwargs& kw) {
  std::vector<std::string> args;
  for (const auto& [key, value] : kw) {
    std::string name = key.cast<std::string>();
    std::string flag = "--" + name;
    for (char& c : flag) c = c == '_' ? '-' : c;
    if (!app.get_option_no_throw(flag)) {
      throw py::type_error(std::string(fn) + "() got an unexpected keyword argument '" + name + "'");
    }
    if (py::isinstance<py::bool_>(value)) {
      if (value.cast<bool>()) args.push_back(flag);
      continue;
    }
    args.push_back(flag);
    if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
      for (const py::handle& item : value) args.push_back(flag_value(item));
    } else {
      args.push_back(flag_value(value));
    }
  }
  return args;
}

py::object to_python(const nlohmann::json& j) { return py::module_::import("json").attr("loads")(j.dump()); }

py::object g_error;  // scurve.Error

[[noreturn]] void raise(const std::string& parameter, const std::string& message) {
  py::object e = g_error(message);
  e.attr("parameter") = parameter;
  PyErr_SetObject(g_error.ptr(), e.ptr());
  throw py::error_already_set();
}

// The move of the keyword arguments, planned (or scurve.Error); with `regs`
// also the flags of `scurve regs`.
Plan plan_kwargs(const char* fn, const py::kwargs& kw, cli::MoveFlags& f, cli::RegsCliFlags* regs = nullptr) {
  CLI::App app;
  cli::add_move_flags(&app, f);
  cli::add_clock_flag(&app, f);
  if (regs) cli::add_regs_flags(&app, *regs);
  if (std::string e = cli::parse_flags(app, flag_args(app, fn, kw)); !e.empty()) raise("", e);
  auto r = cli::plan_flags(f);
  if (auto* e = std::get_if<Error>(&r)) raise(e->parameter, e->message);
  return std::get<Plan>(std::move(r));
}

// A board over its UART: the driver of `scurve board`, the same checks and
// the same errors (as scurve.Error, .parameter "port" for the line, "board"
// for the board's refusals and faults).
class PyBoard {
 public:
  PyBoard(const std::string& port, int baud, double timeout_ms, int retries, double clock_hz) : clock_hz_(clock_hz) {
    LinkOptions o;
    o.baud = baud;
    o.timeout = timeout_ms / 1e3;
    o.retries = retries;
    if (auto e = check_link_options(o)) raise(e->parameter, e->message);
    if (std::string e = cli::check_clock_flag(clock_hz); !e.empty()) raise("clock_hz", e);
    auto opened = open_serial_port({port, baud});
    if (auto* e = std::get_if<Error>(&opened)) raise(e->parameter, e->message);
    line_ = std::move(std::get<std::unique_ptr<ByteChannel>>(opened));
    link_ = std::make_unique<UartLink>(*line_, o);
    board_ = std::make_unique<Board>(*link_, Clock{clock_hz});
    auto info = board_->identify();
    if (auto* e = std::get_if<Error>(&info)) raise(e->parameter, e->message);
    info_ = std::get<BoardInfo>(info);
  }

  py::object info() const { return to_python(cli::board_info_json(info_)); }
  py::object link() const { return to_python(cli::link_json(link_->stats())); }

  py::object status() {
    auto st = board_->status();
    if (auto* e = std::get_if<Error>(&st)) raise(e->parameter, e->message);
    return to_python(cli::board_status_json(std::get<BoardStatus>(st)));
  }

  py::object run(bool wait, double timeout, bool closed_loop, const py::kwargs& kw) {
    CLI::App app;
    cli::MoveFlags f;
    cli::add_move_flags(&app, f);
    if (std::string e = cli::parse_flags(app, flag_args(app, "run", kw)); !e.empty()) raise("", e);
    f.clock_hz = clock_hz_;
    auto r = cli::run_move_on_board(*board_, f, closed_loop, wait, timeout);
    if (auto* e = std::get_if<Error>(&r)) raise(e->parameter, e->message);
    const nlohmann::json& j = std::get<nlohmann::json>(r);
    if (j.contains("pass") && !j["pass"].get<bool>()) {
      raise("board", fmt::format("run: {}", fmt::join(j["problems"].get<std::vector<std::string>>(), "; ")));
    }
    return to_python(j);
  }

  py::object stream(const std::string& file, double timeout, bool closed_loop, const py::kwargs& kw) {
    CLI::App app;
    cli::MoveFlags f;
    cli::add_timing_flags(&app, f);
    if (std::string e = cli::parse_flags(app, flag_args(app, "stream", kw)); !e.empty()) raise("", e);
    auto r = cli::run_stream_on_board(*board_, file, cli::to_timing(f), closed_loop, timeout);
    if (auto* e = std::get_if<Error>(&r)) raise(e->parameter, e->message);
    return to_python(std::get<nlohmann::json>(r));
  }

  py::object stop(double timeout) {
    if (auto e = board_->stop()) raise(e->parameter, e->message);
    auto st = board_->wait_idle(timeout);
    if (auto* e = std::get_if<Error>(&st)) raise(e->parameter, e->message);
    return to_python(cli::board_status_json(std::get<BoardStatus>(st)));
  }
  void estop() {
    if (auto e = board_->estop()) raise(e->parameter, e->message);
  }
  void clear() {
    if (auto e = board_->clear_faults()) raise(e->parameter, e->message);
  }

 private:
  double clock_hz_;
  std::unique_ptr<ByteChannel> line_;
  std::unique_ptr<UartLink> link_;
  std::unique_ptr<Board> board_;
  BoardInfo info_;
};

}  // namespace

PYBIND11_MODULE(scurve, m) {
  m.doc() = "S-curve servo core host library: plan moves, encode registers and UART frames";
  g_error = py::reinterpret_borrow<py::object>(PyErr_NewExceptionWithDoc(
      "scurve.Error",
      "A request the planner or the validation layer refuses; str() is the CLI's one-line message, "
      ".parameter the request field when the planner names one.",
      PyExc_ValueError, nullptr));
  m.attr("Error") = g_error;

  m.def(
      "plan",
      [](const py::kwargs& kw) {
        cli::MoveFlags f;
        const Plan p = plan_kwargs("plan", kw, f);
        return to_python(cli::plan_to_json(p, cli::to_request(f)));
      },
      "Plan a move: keyword arguments as the flags of `scurve plan` (distance, v_start, v_cruise, v_end, "
      "a_max, j_max, profile, jerks, adjust_end_speed, start_pos, soft_min, soft_max, axis, pulse_high, pulse_low, "
      "dir_setup, dir_hold, clock_hz). "
      "Returns the dict `scurve plan --json` prints; raises scurve.Error.");

  m.def(
      "regs",
      [](const py::kwargs& kw) {
        cli::MoveFlags f;
        cli::RegsCliFlags rf;
        const Plan p = plan_kwargs("regs", kw, f, &rf);
        auto r = cli::regs_to_json(rf, cli::to_request(f), p, cli::to_timing(f));
        if (auto* e = std::get_if<Error>(&r)) raise(e->parameter, e->message);
        return to_python(std::get<nlohmann::json>(r));
      },
      "Plan a move and return its register writes as `scurve regs --json` prints them: "
      "[{'addr', 'reg', 'data'}] (and 'frame' with uart=True); keyword arguments as for plan plus "
      "uart, no_start, closed_loop, guard, stop_at, stop_jerk, stop_acc.");

  m.def(
      "register_map",
      [] {
        static const char* const access_names[] = {"RO", "RW", "WO", "W1C"};
        py::dict regs;
        for (const hw::regmap::Reg& r : hw::regmap::kRegs) {
          py::dict fields;
          for (int i = 0; i < r.nfields; ++i) {
            fields[r.fields[i].name] = py::dict(py::arg("lsb") = r.fields[i].lsb, py::arg("width") = r.fields[i].width,
                                                py::arg("reset") = r.fields[i].reset);
          }
          regs[r.name] = py::dict(py::arg("addr") = r.addr, py::arg("access") = access_names[int(r.access)],
                                  py::arg("mask") = r.mask, py::arg("reset") = r.reset, py::arg("servo") = r.servo,
                                  py::arg("fields") = fields);
        }
        return regs;
      },
      "The host register map (generated from rtl/sc_pkg.sv, as docs/regmap.md): {name: {'addr', 'access', "
      "'mask', 'reset', 'servo', 'fields': {name: {'lsb', 'width', 'reset'}}}}; 'servo' registers answer DECERR "
      "in sc_axi_axis.");
  m.def(
      "phase_names",
      [] {
        py::dict names;
        for (int code = 0; code <= int(Phase::PhStop); ++code) names[py::int_(code)] = phase_name(Phase(code));
        return names;
      },
      "STATUS.PHASE codes and their names as plan() reports them: {0: 'idle', 1: 'acc-jerk-up', ...}.");

  m.def(
      "uart_write_frame",
      [](uint32_t addr, uint32_t data) {
        FrameResult r = uart_write_frame(addr, data);
        if (auto* e = std::get_if<Error>(&r)) raise(e->parameter, e->message);
        const auto& bytes = std::get<std::vector<uint8_t>>(r);
        return py::bytes(reinterpret_cast<const char*>(bytes.data()), bytes.size());
      },
      py::arg("addr"), py::arg("data"), "The UART bridge's frame that writes data to addr.");
  m.def(
      "uart_read_frame",
      [](uint32_t addr) {
        FrameResult r = uart_read_frame(addr);
        if (auto* e = std::get_if<Error>(&r)) raise(e->parameter, e->message);
        const auto& bytes = std::get<std::vector<uint8_t>>(r);
        return py::bytes(reinterpret_cast<const char*>(bytes.data()), bytes.size());
      },
      py::arg("addr"), "The UART bridge's frame that reads addr.");

  py::class_<PyBoard>(m, "Board",
                      "A board (or `scurve virtual-board`) over its UART: Board(port, baud=115200, timeout_ms=200, "
                      "retries=3, clock_hz=20e6) opens the port and identifies the board; every method raises "
                      "scurve.Error as `scurve board` exits 1 or 2.")
      .def(py::init<const std::string&, int, double, int, double>(), py::arg("port"), py::arg("baud") = 115200,
           py::arg("timeout_ms") = 200.0, py::arg("retries") = 3, py::arg("clock_hz") = Clock::kDefaultHz)
      .def("info", &PyBoard::info, "ID, register map version, axes, closed loop: the dict of `board info --json`")
      .def("status", &PyBoard::status, "One reading: the dict of `board status --json`")
      .def("link", &PyBoard::link, "The link's counters: frames, retries, timeouts, ...")
      .def("run", &PyBoard::run, py::arg("wait") = true, py::arg("timeout") = 120.0, py::arg("closed_loop") = false,
           "Plan a move (keyword arguments as for plan), load it, start it and, with wait, wait and check it: the "
           "dict of `board run --json`; a check that fails raises scurve.Error")
      .def("stream", &PyBoard::stream, py::arg("file"), py::arg("timeout") = 120.0, py::arg("closed_loop") = false,
           "Run a stream file (pulse timing keyword arguments as for plan): the dict of `board stream --json`")
      .def("stop", &PyBoard::stop, py::arg("timeout") = 120.0, "CMD.STOP, then wait for rest: the final status")
      .def("estop", &PyBoard::estop, "CMD.ESTOP")
      .def("clear", &PyBoard::clear, "Clear every ERR and IRQ_STATUS flag");
}
