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
};
// The one place link options are validated: an Error naming "timeout",
// "retries" or "baud" with the value and the bound.
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

 private:
  std::optional<Error> write(uint32_t addr, uint32_t data);
  std::variant<uint32_t, Error> read(uint32_t addr);
  std::optional<Error> require_idle(const char* what);
  std::optional<Error> prepare_rows(u128 pos_frac0);
  // One row: the staging words that differ from what this host last wrote
  // there (the board keeps them across ROW_PUSH), then ROW_PUSH. With the
  // axis idle and `idle_level` rows in the FIFO, a ROW_PUSH whose answer was
  // lost is checked against the FIFO level and sent again if it did not
  // arrive.
  std::optional<Error> push_row(const Segment& row, RowFlags flags, std::optional<int> idle_level = std::nullopt);
  std::variant<int, Error> fifo_level();
  RegisterPort& port_;
  Clock clock_;
  BoardConfig cfg_;
  std::map<uint32_t, uint32_t> staged_;  // staging register -> the value written; cleared before each load
  int loaded_rows_ = 0;                  // rows loaded for the next START (0: unknown)
};

// Exit code of a board command for an error: 1 when the board reported a
// refusal or a fault ("board"), else 2 (bad input, no board, a broken line).
int board_exit_code(const Error& e);

}  // namespace scurve
