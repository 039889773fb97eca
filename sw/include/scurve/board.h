// Driving a board from the PC.
//
//   auto line = scurve::open_serial_port({"/dev/ttyUSB1", 115200});  // or an Error naming "port"
//   scurve::UartLink link{*std::get<0>(line), {}};                     // frames, timeouts, retries
//   scurve::Board board{link};
//   auto info = board.identify();            // ID, register map version, axes
//   board.configure(cfg);                    // pulse timing, stop limits, mode, controller
//   board.load_move(plan);  board.start();   // all rows acknowledged before START
//   auto st = board.wait_idle(30.0);         // BoardStatus: positions, phase, FIFO, faults
//
// A board on the multi-axis map (the two-axis sc_board_xy_top) talks in
// 2-byte address frames (LinkOptions::addr_bits = MultiRegAddrW; or ask the
// board: detect_addr_bits) and is driven as an AxisGroup: a Board per axis
// window for what is per axis, the group window for the shared row stream.
//
//   scurve::AxisGroup xy{link};
//   xy.identify();  xy.configure(cfg);        // every axis the same settings
//   auto r = xy.run_path(path_plan, 60.0);    // rows of every axis, the FIFO topped up
//
// The UART bridge protocol is docs/regmap.md "UART bridge protocol". Every
// function returns the one error type of the host library; its `parameter`
// says where the trouble lies: "port" (the line: no such device, no board
// answering, a garbled exchange that retries could not mend) or "board" (the
// board answered and reported a refusal or a fault), or the name of a
// request field that is out of its range.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "scurve/path_planner.h"
#include "scurve/planner.h"
#include "scurve/reg_encode.h"
#include "scurve/register_port.h"
#include "scurve/servo_config.h"
#include "scurve/stream_planner.h"

namespace scurve {

// A byte line to the board: a serial port, or a test's in-process line.
class ByteChannel {
 public:
  virtual ~ByteChannel() = default;
  virtual std::optional<Error> send(const std::vector<uint8_t>& bytes) = 0;
  // Appends what arrives to `out` until it holds `n` bytes or `timeout`
  // seconds have passed. An Error only when the line itself failed (the
  // device went away), not on a timeout.
  virtual std::optional<Error> receive(std::vector<uint8_t>& out, size_t n, double timeout) = 0;
  // Throws away what has arrived and not been read.
  virtual void discard_input() = 0;
};

struct SerialSettings {
  std::string device;  // /dev/ttyUSB1 (the Arty's USB-UART), a pseudo-terminal
  int baud = 115200;   // the board's UART rate, fixed in its bitstream (sc_pkg::UartClksPerBit)
};
// The rates a serial port can be set to.
const std::vector<int>& serial_baud_rates();
// Opens the port raw, 8N1, no flow control. An Error naming "port" (missing,
// not a terminal, no permission) or "baud" (not a rate of
// serial_baud_rates()).
std::variant<std::unique_ptr<ByteChannel>, Error> open_serial_port(const SerialSettings& settings);

struct LinkOptions {
  double timeout = 0.2;  // s from the end of a request to the end of its response
  int retries = 3;       // further tries after a timeout or a garbled exchange
  int baud = 115200;     // the line rate (the quiet gap before a retry is counted in bit times)
  // Byte address bits of the board's map: RegAddrW (the one-axis board,
  // 1-byte word addresses in the frames) or MultiRegAddrW (the multi-axis
  // map, 2-byte word addresses).
  int addr_bits = hw::RegAddrW;
};
// The one place link options are validated: an Error naming "timeout",
// "retries", "baud" or "addr_bits" with the value and the bound.
std::optional<Error> check_link_options(const LinkOptions& o);

struct LinkStats {
  uint64_t accesses = 0;       // register reads and writes asked for
  uint64_t frames = 0;         // request frames sent, retries included
  uint64_t retries = 0;
  uint64_t timeouts = 0;       // no complete answer in time
  uint64_t bad_responses = 0;  // an answer with a wrong sync byte, length or CRC
  uint64_t crc_rejects = 0;    // the board answered 0x80 or 0x81: the request arrived garbled, nothing was done
  uint64_t discarded = 0;      // late bytes drained before a first request or a retry
};

// Register access over the UART bridge. Before the first request and
// before every retry the line is drained until it has been quiet for half
// a timeout, so a late answer is not taken for the next request's (the
// protocol carries no sequence number). A read, and a write that only sets
// its register, is tried again (at most `retries` more times) after a
// timeout or a garbled exchange. A write that acts beyond its register (ROW_PUSH,
// CMD.START) is tried again only when the board answered that the request
// arrived garbled (0x80 CRC error, 0x81 unknown command: nothing was done):
// a lost answer does not tell whether it took effect, so that is an error. A bus error (SLVERR,
// DECERR) is the board's answer and is not retried.
class UartLink : public RegisterPort {
 public:
  UartLink(ByteChannel& line, const LinkOptions& options);
  std::optional<Error> write(uint32_t addr, uint32_t data) override;
  std::variant<uint32_t, Error> read(uint32_t addr) override;
  void wait(double seconds) override;  // sleeps
  const LinkStats& stats() const { return stats_; }

 private:
  std::variant<UartResponse, Error> exchange(uint32_t addr, const uint32_t* data);
  std::optional<Error> resync();
  ByteChannel& line_;
  LinkOptions o_;
  LinkStats stats_;
  bool synced_ = false;  // the line has been drained once
};

struct BoardInfo {
  uint32_t id = 0;              // the ID register
  int version_major = 0;        // register map version of the board
  int version_minor = 0;
  int axes = 0;                 // axes behind the register window (register map 3: one)
  bool closed_loop = false;     // the axis has the closed-loop servo (sc_axi_servo)
};

// One reading of the axis registers.
struct BoardStatus {
  uint32_t ctrl = 0, status = 0, err = 0, fifo_status = 0, irq_status = 0;
  int32_t pulse_count = 0, ref_pos = 0, enc_pos = 0, follow_err = 0, boundary_pos = 0;
  uint32_t move_index = 0;
  bool busy() const;
  bool done() const;
  bool enabled() const;
  bool closed_loop() const;
  Phase phase() const;
  int fifo_level() const;
  // The names of the set ERR flags and of the STATUS faults (FAULT_TABLE,
  // FAULT_OVERRUN, FAULT_FERR, GUARD, ...), in bit order.
  std::vector<std::string> faults() const;
};

// What configure() writes; every value checked in one place (the host
// library's conversions: stop limits, guards, soft limits, controller).
struct BoardConfig {
  PulseTiming timing;
  bool closed_loop = false;                 // CTRL.CLOSED_LOOP (needs the servo axis)
  std::optional<StopLimits> stop;           // STOP_JERK / STOP_ACC in pulses/s^3, pulses/s^2
  std::optional<SoftLimits> soft_limits;    // SOFT_MIN / SOFT_MAX with SW_CFG.SOFT_EN
  std::optional<ServoConfig> servo;         // the controller registers (servo axis)
};

// A stream run: the moves' boundaries as the board reported them.
struct StreamRunReport {
  uint64_t moves = 0;
  uint64_t rows = 0;
  int32_t start_ref = 0;        // REF_POS at the START
  int32_t end_ref = 0;          // REF_POS at rest
  int64_t expected_end = 0;     // start_ref + the sum of the distances
  uint64_t boundaries_checked = 0;  // MOVE_INDEX readings whose BOUNDARY_POS was compared
  BoardStatus final_status;
};

// Which map the board on the line speaks, as LinkOptions::addr_bits: one
// ID read in a multi-axis frame (2-byte address, one try), which the
// multi-axis board answers and the one-axis board's bridge answers 0x80
// (the frame is a byte longer than it expects, so its CRC fails); then, if
// need be, the ID in a one-axis frame with the options' retries. An Error
// naming "port" when neither is answered with an ID.
std::variant<int, Error> detect_addr_bits(ByteChannel& line, const LinkOptions& options);

// One register window of the multi-axis map as a port of its own: the
// one-axis map's addresses moved into axis `axis`'s window, or into the
// group window when `axis` is empty (multi_axis_addr).
class WindowPort : public RegisterPort {
 public:
  WindowPort(RegisterPort& port, std::optional<size_t> axis) : port_(port), axis_(axis) {}
  std::optional<Error> write(uint32_t addr, uint32_t data) override;
  std::variant<uint32_t, Error> read(uint32_t addr) override;
  void wait(double seconds) override { port_.wait(seconds); }

 private:
  RegisterPort& port_;
  std::optional<size_t> axis_;
};

// A stream of rows for Board::stream_rows: row k's register writes (its
// staging words, then its ROW_PUSH last), and the moves' boundaries.
struct RowStream {
  size_t rows = 0;
  std::function<std::vector<RegWrite>(size_t row)> row_writes;
  size_t moves = 0;
  // BOUNDARY_POS of every axis the stream drives, as the board reports them now.
  std::function<std::variant<std::vector<int32_t>, Error>()> read_boundaries;
  // The planned BOUNDARY_POS of every axis once `moves_done` moves (1 ..
  // moves) have ended.
  std::function<std::vector<int64_t>(size_t moves_done)> planned_boundaries;
  // false: return once started (the whole stream must fit the FIFO: else an
  // Error naming "plan", before any row is sent).
  bool wait = true;
};

// The board-level operations on any register port (a UartLink, a
// simulation bench). The axis is the one behind the register window.
class Board {
 public:
  explicit Board(RegisterPort& port, Clock clock = Clock{});
  // ID: the magic 'SC' and a register map this host speaks (the same major
  // version, a minor version at least the host's); else an Error naming
  // "port" (no scurve board) or "board" (another register map).
  std::variant<BoardInfo, Error> identify();
  // Writes the configuration; the axis must be idle.
  std::optional<Error> configure(const BoardConfig& cfg);
  // Empties the FIFO and loads a planned move (rows, POS_FRAC0, the pulse
  // timing of the last configure()); then reads FIFO_STATUS back: the move
  // is loaded only when every row arrived. Does not start.
  std::optional<Error> load_move(const Plan& plan);
  // CMD.START. When its answer is lost after a load, the FIFO level and
  // STATUS.BUSY tell whether it arrived; it is sent again only if not.
  std::optional<Error> start();
  std::optional<Error> stop();     // CMD.STOP: the controlled stop
  std::optional<Error> estop();    // CMD.ESTOP
  // Clears every ERR and IRQ_STATUS flag (after an e-stop: enables again).
  std::optional<Error> clear_faults();
  std::variant<BoardStatus, Error> status();
  // Polls until the axis is idle (done, stopped or refused); an Error
  // naming "timeout" when it is still busy after `timeout` seconds.
  std::variant<BoardStatus, Error> wait_idle(double timeout, double poll = 0.01);
  // Runs planned stream moves (StreamPlanner's, in order, from rest):
  // pushes rows while the FIFO has room, starts once the FIFO is full or
  // holds the whole stream, keeps it topped up, and checks every move
  // boundary it sees (BOUNDARY_POS = the start plus the running sum) and the
  // end (REF_POS = the start plus the sum of the distances). `start_frac`
  // is the stream's start fraction (StreamPlanner's). An axis that goes
  // idle before the last move (a fault, a reset) is an Error naming "board".
  std::variant<StreamRunReport, Error> run_stream(const std::vector<StreamedMove>& moves, u128 start_frac,
                                                  double timeout, double poll = 0.005,
                                                  const std::function<void(const BoardStatus&)>& progress = {});
  const BoardConfig& config() const { return cfg_; }
  Clock clock() const { return clock_; }

  // The stream machinery run_stream is made of, for a group of axes behind
  // one FIFO (AxisGroup): begin_load empties the FIFO and forgets the
  // staging words (the axis idle); stream_rows then fills the FIFO, STARTs,
  // keeps it topped up, checks every move boundary it sees against the
  // plan and waits for rest. It returns the status at rest (every move run,
  // DONE) and counts the boundaries it compared; an axis that goes idle
  // early is an Error naming "board", and on any error while running the
  // axis is stopped (CMD.STOP).
  std::optional<Error> begin_load();
  std::variant<BoardStatus, Error> stream_rows(const RowStream& stream, double timeout, double poll,
                                               const std::function<void(const BoardStatus&)>& progress,
                                               uint64_t& boundaries_checked);
  std::optional<Error> write_pos_frac0(u128 pos_frac0);

 private:
  std::optional<Error> require_idle(const char* what);
  std::optional<Error> write(uint32_t addr, uint32_t data);
  std::variant<uint32_t, Error> read(uint32_t addr);
  std::optional<Error> prepare_rows(u128 pos_frac0);
  // One row's writes: the staging words that differ from what this host
  // last wrote there (the board keeps them across ROW_PUSH), then ROW_PUSH.
  // With the axis idle and `idle_level` rows in the FIFO, a ROW_PUSH whose
  // answer was lost is checked against the FIFO level and sent again if it
  // did not arrive.
  std::optional<Error> push_row(const std::vector<RegWrite>& writes, std::optional<int> idle_level = std::nullopt);
  std::variant<int, Error> fifo_level();
  RegisterPort& port_;
  Clock clock_;
  BoardConfig cfg_;
  std::map<uint32_t, uint32_t> staged_;  // staging register -> the value written; cleared before each load
  int loaded_rows_ = 0;                  // rows loaded for the next START (0: unknown)
};

// A path's run on a group of axes (AxisGroup::run_path).
struct PathRunReport {
  uint64_t moves = 0;
  uint64_t rows = 0;
  std::vector<int32_t> start_ref;        // REF_POS per axis at the START
  std::vector<BoardStatus> final_status; // per axis, at rest
  uint64_t boundaries_checked = 0;       // MOVE_INDEX readings whose BOUNDARY_POS (every axis) was compared
};

// The axes of a multi-axis map (sc_axi_multi_axis): window 0 is the group
// (its writes reach every axis; what the axes share - SEG_CLOCKS, ROW_PUSH,
// CMD.START, CMD.FLUSH - goes only there), window 1 + a is axis a.
class AxisGroup {
 public:
  explicit AxisGroup(RegisterPort& port, Clock clock = Clock{});
  // ID in the group window (the magic and the register map, as
  // Board::identify), then the axes: the windows that answer ID (the map
  // answers DECERR past the last). BoardInfo::closed_loop: every axis has
  // the servo.
  std::variant<BoardInfo, Error> identify();
  size_t axes() const { return axes_.size(); }
  // Axis a's window (its status, its own settings); valid after identify().
  Board& axis(size_t a) { return *axes_.at(a); }
  // The same settings on every axis, through the group window.
  std::optional<Error> configure(const BoardConfig& cfg);
  // Runs a planned path (plan_path with as many axes as the board has,
  // planned from where the axes are: its first move's start must be every
  // axis's REF_POS): POS_FRAC0 per axis, the multi-axis rows streamed
  // through the group window, every move boundary checked on every axis
  // against the plan, and at rest every axis's REF_POS on the last target
  // (and, open loop, PULSE_COUNT the distance from the start). An Error
  // naming "board" for anything the board did differently, "plan" for a
  // plan that does not fit the board. !wait: returns once started, the
  // statuses as they are then (a path of at most a FIFO of rows).
  std::variant<PathRunReport, Error> run_path(const PathPlan& plan, double timeout, double poll = 0.005,
                                              const std::function<void(const BoardStatus&)>& progress = {},
                                              bool wait = true);
  std::variant<std::vector<BoardStatus>, Error> status();
  std::optional<Error> stop() { return group_.stop(); }    // CMD.STOP stops every axis under control
  std::optional<Error> estop() { return group_.estop(); }  // CMD.ESTOP: every axis at once
  std::optional<Error> clear_faults() { return group_.clear_faults(); }
  // Waits until the axes are idle (they run one row stream: they go idle together).
  std::variant<std::vector<BoardStatus>, Error> wait_idle(double timeout, double poll = 0.01);
  Clock clock() const { return clock_; }

 private:
  RegisterPort& port_;
  Clock clock_;
  Board group_;  // on port_ itself: window 0
  std::vector<std::unique_ptr<WindowPort>> axis_ports_;
  std::vector<std::unique_ptr<Board>> axes_;
};

// Exit code of a board command for an error: 1 when the board reported a
// refusal or a fault ("board"), else 2 (bad input, no board, a broken line).
int board_exit_code(const Error& e);

}  // namespace scurve
