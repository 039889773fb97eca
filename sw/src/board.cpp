#include "scurve/board.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <cmath>
#include <thread>

#include "scurve/hw/params.h"
#include "scurve/hw/regmap.h"

namespace scurve {

namespace {

constexpr uint32_t bit(int b) { return uint32_t(1) << b; }

// The quiet gap before a retry: longer than the bridge's inter-byte timeout
// (UartTimeoutBits), so the board has dropped any partial frame.
constexpr int kRetryGapBits = hw::UartTimeoutBits + 10;
constexpr double kMaxTimeout = 60.0;  // s
constexpr int kMaxRetries = 20;

// "REF_POS (0x028)"; in an axis window of the multi-axis map "axis 1 REF_POS (0x828)".
std::string reg_label(uint32_t addr) {
  const uint32_t window = addr >> hw::RegAddrW;
  const std::string name = reg_name(addr & ((uint32_t(1) << hw::RegAddrW) - 1));
  if (window == 0) return fmt::format("{} (0x{:03X})", name, addr);
  return fmt::format("axis {} {} (0x{:03X})", window - 1, name, addr);
}

const char* bus_status_name(uint8_t s) {
  switch (s) {
    case 1: return "EXOKAY";
    case 2: return "SLVERR";
    case 3: return "DECERR";
    default: return "an unknown status";
  }
}

// A field of the generated register table (the name must exist).
const hw::regmap::Field& field_of(const char* reg, const char* field) {
  for (const hw::regmap::Reg& r : hw::regmap::kRegs) {
    for (int i = 0; std::string(r.name) == reg && i < r.nfields; ++i) {
      if (std::string(r.fields[i].name) == field) return r.fields[i];
    }
  }
  throw std::logic_error(fmt::format("no field {}.{} in the register map", reg, field));
}

// Names of the set bits of a register's one-bit fields, in bit order.
void flag_names(const char* reg, uint32_t value, std::vector<std::string>& out, uint32_t only = ~0u) {
  for (const hw::regmap::Reg& r : hw::regmap::kRegs) {
    if (std::string(r.name) != reg) continue;
    for (int i = 0; i < r.nfields; ++i) {
      const hw::regmap::Field& f = r.fields[i];
      if (f.width == 1 && (value & only & bit(f.lsb))) out.push_back(fmt::format("{}.{}", reg, f.name));
    }
  }
}

}  // namespace

// ---- link ------------------------------------------------------------------------

std::optional<Error> check_link_options(const LinkOptions& o) {
  if (!std::isfinite(o.timeout) || o.timeout <= 0 || o.timeout > kMaxTimeout) {
    return Error{"timeout", fmt::format("timeout={} s: needs a number in (0, {}]", o.timeout, kMaxTimeout)};
  }
  if (o.retries < 0 || o.retries > kMaxRetries) {
    return Error{"retries", fmt::format("retries={}: needs 0 .. {}", o.retries, kMaxRetries)};
  }
  bool known = false;
  for (int b : serial_baud_rates()) known = known || b == o.baud;
  if (!known) {
    return Error{"baud", fmt::format("baud={}: not a serial rate (one of {})", o.baud,
                                     fmt::join(serial_baud_rates(), ", "))};
  }
  if (o.addr_bits != hw::RegAddrW && o.addr_bits != hw::MultiRegAddrW) {
    return Error{"addr_bits", fmt::format("addr_bits={}: needs {} (the one-axis map) or {} (the multi-axis map)",
                                          o.addr_bits, hw::RegAddrW, hw::MultiRegAddrW)};
  }
  return std::nullopt;
}

std::variant<int, Error> detect_addr_bits(ByteChannel& line, const LinkOptions& options) {
  if (auto e = check_link_options(options)) return *e;
  LinkOptions multi = options;
  multi.addr_bits = hw::MultiRegAddrW;
  multi.retries = 0;
  UartLink probe(line, multi);
  auto id = probe.read(hw::RegId);
  const uint32_t magic = uint32_t(hw::RegIdMagic);
  if (const uint32_t* v = std::get_if<uint32_t>(&id); v && (*v >> hw::IdMagicLsb) == magic) return hw::MultiRegAddrW;
  LinkOptions single = options;
  single.addr_bits = hw::RegAddrW;
  UartLink link(line, single);
  auto id1 = link.read(hw::RegId);
  if (const Error* e = std::get_if<Error>(&id1)) return *e;
  return hw::RegAddrW;
}

UartLink::UartLink(ByteChannel& line, const LinkOptions& options) : line_(line), o_(options) {}

std::optional<Error> UartLink::resync() {
  // Late answers to earlier requests (a slow board, one that was stopped, a
  // previous program's) must not be taken for the next request's: wait
  // until the line has been quiet for half a timeout (at least the frame
  // gap, after which the bridge has dropped a partial request).
  const double quiet = std::max(double(kRetryGapBits) / o_.baud, o_.timeout / 2);
  line_.discard_input();
  for (int i = 0; i < 1000; ++i) {
    std::vector<uint8_t> late;
    if (auto e = line_.receive(late, 4096, quiet)) return e;
    if (late.empty()) break;
    stats_.discarded += late.size();
  }
  synced_ = true;
  return std::nullopt;
}

void UartLink::wait(double seconds) {
  if (seconds > 0) std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
}

std::variant<UartResponse, Error> UartLink::exchange(uint32_t addr, const uint32_t* data) {
  ++stats_.accesses;
  const bool is_read = data == nullptr;
  const FrameResult frame =
      is_read ? uart_read_frame(addr, o_.addr_bits) : uart_write_frame(addr, *data, o_.addr_bits);
  if (const Error* e = std::get_if<Error>(&frame)) return *e;
  const uint32_t reg = addr & ((uint32_t(1) << hw::RegAddrW) - 1);  // in any window
  const bool repeatable = is_read || !(reg == uint32_t(hw::RegRowPush) ||
                                       (reg == uint32_t(hw::RegCmd) && (*data & bit(hw::CmdStartBit))));
  const std::string what = is_read ? fmt::format("a read of {}", reg_label(addr))
                                   : fmt::format("a write of 0x{:08X} to {}", *data, reg_label(addr));
  std::string last;          // what went wrong with the last try
  bool maybe_done = false;   // a try may have taken effect (its answer was lost or garbled)
  for (int attempt = 0; attempt <= o_.retries; ++attempt) {
    if (attempt > 0) ++stats_.retries;
    if (attempt > 0 || !synced_) {
      if (auto e = resync()) return *e;
    }
    ++stats_.frames;
    if (auto e = line_.send(std::get<std::vector<uint8_t>>(frame))) return *e;
    // Sync and status first: they say how long the rest is.
    std::vector<uint8_t> rsp;
    if (auto e = line_.receive(rsp, 2, o_.timeout)) return *e;
    size_t len = 3;
    if (rsp.size() == 2 && rsp[0] == uint8_t(hw::UartRspSync) && is_read && rsp[1] < uint8_t(hw::UartStCrcErr)) len = 7;
    if (rsp.size() == 2 && rsp[0] == uint8_t(hw::UartRspSync)) {
      if (auto e = line_.receive(rsp, len, o_.timeout)) return *e;
    }
    if (rsp.empty() || (rsp.size() < len && rsp[0] == uint8_t(hw::UartRspSync))) {
      ++stats_.timeouts;
      last = rsp.empty() ? "no answer" : fmt::format("an answer cut short ({} of {} bytes)", rsp.size(), len);
      maybe_done = true;
      if (!repeatable) break;
      continue;
    }
    const UartResponse r = parse_uart_response(rsp, is_read);
    if (!r.ok) {
      ++stats_.bad_responses;
      last = fmt::format("a garbled answer ({})", r.error);
      maybe_done = true;
      if (!repeatable) break;
      continue;
    }
    // The bridge did nothing with a request it answers 0x80 or 0x81: safe
    // to send again whatever it is (line noise can garble the command byte).
    if (r.status == uint8_t(hw::UartStCrcErr)) {
      ++stats_.crc_rejects;
      last = "the board received it garbled (CRC error)";
      continue;
    }
    if (r.status == uint8_t(hw::UartStBadCmd)) {
      ++stats_.crc_rejects;
      last = "the board did not know the command (garbled on the line, or no scurve UART bridge)";
      continue;
    }
    return r;
  }
  if (!repeatable && maybe_done) {
    return Error{"port", fmt::format("{}: {}; not sent again, since it may have taken effect", what, last)};
  }
  return Error{"port", fmt::format("{}: {} after {} tries of {} ms each", what, last, o_.retries + 1,
                                   std::lround(o_.timeout * 1e3))};
}

std::optional<Error> UartLink::write(uint32_t addr, uint32_t data) {
  auto r = exchange(addr, &data);
  if (const Error* e = std::get_if<Error>(&r)) return *e;
  const UartResponse& rsp = std::get<UartResponse>(r);
  if (rsp.status != 0) {
    return Error{"board", fmt::format("write of 0x{:08X} to {}: the board answered {}", data, reg_label(addr),
                                      bus_status_name(rsp.status))};
  }
  return std::nullopt;
}

std::variant<uint32_t, Error> UartLink::read(uint32_t addr) {
  auto r = exchange(addr, nullptr);
  if (const Error* e = std::get_if<Error>(&r)) return *e;
  const UartResponse& rsp = std::get<UartResponse>(r);
  if (rsp.status != 0) {
    return Error{"board", fmt::format("read of {}: the board answered {}", reg_label(addr),
                                      bus_status_name(rsp.status))};
  }
  return rsp.data;
}

// ---- status ------------------------------------------------------------------------

bool BoardStatus::busy() const { return status & bit(hw::StatusBusyBit); }
bool BoardStatus::done() const { return status & bit(hw::StatusDoneBit); }
bool BoardStatus::enabled() const { return ctrl & bit(hw::CtrlEnableBit); }
bool BoardStatus::closed_loop() const { return ctrl & bit(hw::CtrlClosedBit); }
Phase BoardStatus::phase() const {
  return Phase((status >> hw::StatusPhaseLsb) & ((1u << hw::PhaseW) - 1));
}
int BoardStatus::fifo_level() const {
  static const hw::regmap::Field& level = field_of("FIFO_STATUS", "LEVEL");
  return int((fifo_status >> level.lsb) & ((1u << level.width) - 1));
}

std::vector<std::string> BoardStatus::faults() const {
  std::vector<std::string> out;
  flag_names("ERR", err, out);
  const uint32_t status_faults = bit(hw::StatusFaultTableBit) | bit(hw::StatusFaultOverrunBit) |
                                 bit(hw::StatusFaultFerrBit) | bit(hw::StatusUnderrunBit) |
                                 bit(hw::StatusDiscontBit) | bit(hw::StatusGuardBit);
  flag_names("STATUS", status, out, status_faults);
  return out;
}

int board_exit_code(const Error& e) { return e.parameter == "board" ? 1 : 2; }

// ---- board -------------------------------------------------------------------------

Board::Board(RegisterPort& port, Clock clock) : port_(port), clock_(clock) {}

std::optional<Error> Board::write(uint32_t addr, uint32_t data) { return port_.write(addr, data); }
std::variant<uint32_t, Error> Board::read(uint32_t addr) { return port_.read(addr); }

std::variant<BoardInfo, Error> Board::identify() {
  auto id = read(hw::RegId);
  if (const Error* e = std::get_if<Error>(&id)) return *e;
  BoardInfo info;
  info.id = std::get<uint32_t>(id);
  const uint32_t magic = (info.id >> hw::IdMagicLsb) & 0xFFFFu;
  const uint32_t version = (info.id >> hw::IdVersionLsb) & 0xFFFFu;
  const uint32_t want_magic = uint32_t(hw::RegIdMagic);
  if (magic != want_magic) {
    return Error{"port", fmt::format("ID=0x{:08X}: not an scurve board (the magic is 0x{:04X}, expected 0x{:04X})",
                                     info.id, magic, want_magic)};
  }
  info.version_major = int(version >> 8);
  info.version_minor = int(version & 0xFF);
  const int host_major = hw::RegMapVersion >> 8, host_minor = hw::RegMapVersion & 0xFF;
  if (info.version_major != host_major || info.version_minor < host_minor) {
    return Error{"board", fmt::format("register map {}.{} on the board; this host speaks {}.{} (the same major "
                                      "version and at least its minor one): update the bitstream or the host",
                                      info.version_major, info.version_minor, host_major, host_minor)};
  }
  // Register map 3 has one axis per register window.
  info.axes = 1;
  // The controller registers answer only on the servo axis (DECERR on the
  // open-loop axis); CL_CFG is read-write and harmless to read.
  auto cl = read(hw::RegClCfg);
  if (const Error* e = std::get_if<Error>(&cl)) {
    if (e->parameter != "board") return *e;
    // The refused read left ERR.BAD_ACCESS set: clear it.
    if (auto w = write(hw::RegErr, bit(hw::ErrBadAddrBit))) return *w;
  } else {
    info.closed_loop = true;
  }
  return info;
}

std::optional<Error> Board::require_idle(const char* what) {
  auto st = read(hw::RegStatus);
  if (const Error* e = std::get_if<Error>(&st)) return *e;
  if (std::get<uint32_t>(st) & bit(hw::StatusBusyBit)) {
    return Error{"board", fmt::format("{}: the axis is moving (stop it first)", what)};
  }
  return std::nullopt;
}

std::optional<Error> Board::configure(const BoardConfig& cfg) {
  std::vector<RegWrite> w;
  // Every value through the host library's conversions (their Errors name the field).
  if (cfg.stop) {
    const StopLimitsResult s = encode_stop_limits(cfg.stop->jerk, cfg.stop->acc, clock_);
    if (const Error* e = std::get_if<Error>(&s)) return *e;
    const auto& sw = std::get<std::vector<RegWrite>>(s);
    w.insert(w.end(), sw.begin(), sw.end());
  }
  if (cfg.soft_limits) {
    const SoftLimitWritesResult s = encode_soft_limits(*cfg.soft_limits);
    if (const Error* e = std::get_if<Error>(&s)) return *e;
    const auto& sw = std::get<std::vector<RegWrite>>(s);
    w.insert(w.end(), sw.begin(), sw.end());
  }
  if (cfg.servo) {
    const auto sw = encode_servo_config(*cfg.servo);
    w.insert(w.end(), sw.begin(), sw.end());
  }
  if (auto e = require_idle("configure")) return e;
  const uint32_t ctrl = bit(hw::CtrlEnableBit) | (cfg.closed_loop ? bit(hw::CtrlClosedBit) : 0u);
  w.insert(w.begin(), {uint32_t(hw::RegCtrl), ctrl});
  w.insert(w.begin() + 1, {uint32_t(hw::RegPulseTime), (uint32_t(cfg.timing.high) << hw::PulseHighLsb) |
                                                           (uint32_t(cfg.timing.low) << hw::PulseLowLsb)});
  w.insert(w.begin() + 2, {uint32_t(hw::RegDirTime), (uint32_t(cfg.timing.setup) << hw::DirSetupLsb) |
                                                          (uint32_t(cfg.timing.hold) << hw::DirHoldLsb)});
  for (const RegWrite& x : w) {
    if (auto e = write(x.addr, x.data)) return e;
  }
  if (cfg.closed_loop) {
    // The open-loop axis ignores CTRL.CLOSED_LOOP: a closed-loop request must read back.
    auto c = read(hw::RegCtrl);
    if (const Error* e = std::get_if<Error>(&c)) return *e;
    if (!(std::get<uint32_t>(c) & bit(hw::CtrlClosedBit))) {
      return Error{"closed_loop", "closed_loop: the board's axis has no closed loop (CTRL.CLOSED_LOOP reads 0)"};
    }
  }
  cfg_ = cfg;
  return std::nullopt;
}

std::variant<int, Error> Board::fifo_level() {
  auto fs = read(hw::RegFifoStatus);
  if (const Error* e = std::get_if<Error>(&fs)) return *e;
  BoardStatus s;
  s.fifo_status = std::get<uint32_t>(fs);
  return s.fifo_level();
}

std::optional<Error> Board::push_row(const std::vector<RegWrite>& writes, std::optional<int> idle_level) {
  for (const RegWrite& x : writes) {
    const bool push = (x.addr & ((uint32_t(1) << hw::RegAddrW) - 1)) == uint32_t(hw::RegRowPush);
    if (!push) {
      auto it = staged_.find(x.addr);
      if (it != staged_.end() && it->second == x.data) continue;
    }
    auto e = write(x.addr, x.data);
    // A ROW_PUSH whose answer was lost, while the axis is idle: the FIFO
    // level tells whether it arrived (one more row) or not (send it again).
    for (int again = 0; e && push && idle_level && e->parameter == "port" && again < 3; ++again) {
      auto level = fifo_level();
      if (std::holds_alternative<Error>(level)) break;
      if (std::get<int>(level) == *idle_level + 1) {
        e.reset();
      } else if (std::get<int>(level) == *idle_level) {
        e = write(x.addr, x.data);
      } else {
        break;
      }
    }
    if (e) {
      staged_.clear();  // a failed write leaves the register unknown
      return e;
    }
    if (!push) staged_[x.addr] = x.data;
  }
  return std::nullopt;
}

std::optional<Error> Board::begin_load() {
  staged_.clear();  // another host, or a reset, may have written the staging registers
  if (auto e = require_idle("load")) return e;
  if (auto e = write(hw::RegCmd, bit(hw::CmdFlushBit))) return e;
  const uint32_t ctrl = bit(hw::CtrlEnableBit) | (cfg_.closed_loop ? bit(hw::CtrlClosedBit) : 0u);
  return write(hw::RegCtrl, ctrl);
}

std::optional<Error> Board::write_pos_frac0(u128 pos_frac0) {
  const u128 f = mask_bits(pos_frac0, hw::FracBits);
  for (int i = 0; i < 3; ++i) {
    if (auto e = write(uint32_t(hw::RegPosFrac0 + 4 * i), uint32_t(f >> (32 * i)))) return e;
  }
  return std::nullopt;
}

std::optional<Error> Board::prepare_rows(u128 pos_frac0) {
  if (auto e = begin_load()) return e;
  return write_pos_frac0(pos_frac0);
}

std::optional<Error> Board::load_move(const Plan& plan) {
  if (plan.segments.size() > size_t(hw::RowFifoDepth)) {
    return Error{"plan", fmt::format("plan: {} rows do not fit the FIFO of {}", plan.segments.size(),
                                     hw::RowFifoDepth)};
  }
  if (auto e = prepare_rows(plan.pos_frac0)) return e;
  const std::vector<RowFlags> flags = move_row_flags(plan.segments);
  for (size_t i = 0; i < plan.segments.size(); ++i) {
    if (auto e = push_row(encode_row(plan.segments[i], flags[i]), int(i))) return e;
  }
  auto level = fifo_level();
  if (const Error* e = std::get_if<Error>(&level)) return *e;
  if (size_t(std::get<int>(level)) != plan.segments.size()) {
    return Error{"board", fmt::format("load: the FIFO holds {} rows after loading {} (a row was lost): not started",
                                      std::get<int>(level), plan.segments.size())};
  }
  loaded_rows_ = int(plan.segments.size());
  return std::nullopt;
}

std::optional<Error> Board::start() {
  auto e = write(hw::RegCmd, bit(hw::CmdStartBit));
  // Its answer lost: still idle with every loaded row in the FIFO means the
  // START never arrived (send it again); anything else means it runs.
  for (int again = 0; e && e->parameter == "port" && loaded_rows_ > 0 && again < 3; ++again) {
    auto st = read(hw::RegStatus);
    auto level = fifo_level();
    if (std::holds_alternative<Error>(st) || std::holds_alternative<Error>(level)) break;
    if ((std::get<uint32_t>(st) & bit(hw::StatusBusyBit)) || std::get<int>(level) != loaded_rows_) {
      e.reset();
    } else {
      e = write(hw::RegCmd, bit(hw::CmdStartBit));
    }
  }
  loaded_rows_ = 0;
  return e;
}
std::optional<Error> Board::stop() { return write(hw::RegCmd, bit(hw::CmdStopBit)); }
std::optional<Error> Board::estop() { return write(hw::RegCmd, bit(hw::CmdEstopBit)); }

std::optional<Error> Board::clear_faults() {
  if (auto e = write(hw::RegErr, ~0u)) return e;
  return write(hw::RegIrqStatus, ~0u);
}

std::variant<BoardStatus, Error> Board::status() {
  BoardStatus s;
  struct Item {
    uint32_t addr;
    uint32_t* u;
    int32_t* i;
  };
  const Item items[] = {
      {uint32_t(hw::RegCtrl), &s.ctrl, nullptr},
      {uint32_t(hw::RegStatus), &s.status, nullptr},
      {uint32_t(hw::RegErr), &s.err, nullptr},
      {uint32_t(hw::RegFifoStatus), &s.fifo_status, nullptr},
      {uint32_t(hw::RegIrqStatus), &s.irq_status, nullptr},
      {uint32_t(hw::RegPulseCount), nullptr, &s.pulse_count},
      {uint32_t(hw::RegRefPos), nullptr, &s.ref_pos},
      {uint32_t(hw::RegEncPos), nullptr, &s.enc_pos},
      {uint32_t(hw::RegFollowErr), nullptr, &s.follow_err},
      {uint32_t(hw::RegBoundaryPos), nullptr, &s.boundary_pos},
      {uint32_t(hw::RegMoveIndex), &s.move_index, nullptr},
  };
  for (const Item& it : items) {
    auto r = read(it.addr);
    if (const Error* e = std::get_if<Error>(&r)) return *e;
    if (it.u) *it.u = std::get<uint32_t>(r);
    if (it.i) *it.i = int32_t(std::get<uint32_t>(r));
  }
  return s;
}

std::variant<BoardStatus, Error> Board::wait_idle(double timeout, double poll) {
  using clk = std::chrono::steady_clock;
  const auto t0 = clk::now();
  for (;;) {
    auto st = read(hw::RegStatus);
    if (const Error* e = std::get_if<Error>(&st)) return *e;
    if (!(std::get<uint32_t>(st) & bit(hw::StatusBusyBit))) return status();
    if (std::chrono::duration<double>(clk::now() - t0).count() > timeout) {
      return Error{"timeout", fmt::format("timeout={} s: the axis is still moving", timeout)};
    }
    port_.wait(poll);
  }
}

std::variant<BoardStatus, Error> Board::stream_rows(const RowStream& stream, double timeout, double poll,
                                                    const std::function<void(const BoardStatus&)>& progress,
                                                    uint64_t& boundaries_checked) {
  if (!stream.wait && stream.rows > size_t(hw::RowFifoDepth)) {
    return Error{"plan", fmt::format("plan: {} rows do not fit the FIFO of {} (a stream that is not waited for must)",
                                     stream.rows, hw::RowFifoDepth)};
  }
  size_t pushed = 0;
  bool running = false;  // before START the FIFO level tells whether a row arrived
  auto push = [&](int room) -> std::optional<Error> {
    for (; room > 0 && pushed < stream.rows; --room, ++pushed) {
      const std::optional<int> idle_level = running ? std::nullopt : std::optional<int>(int(pushed));
      if (auto e = push_row(stream.row_writes(pushed), idle_level)) return e;
    }
    return std::nullopt;
  };
  if (auto e = push(hw::RowFifoDepth)) return *e;
  auto level = fifo_level();
  if (const Error* e = std::get_if<Error>(&level)) return *e;
  if (size_t(std::get<int>(level)) != pushed) {
    return Error{"board", fmt::format("stream: the FIFO holds {} rows after loading {} (a row was lost): not started",
                                      std::get<int>(level), pushed)};
  }
  loaded_rows_ = int(pushed);
  if (auto e = start()) return *e;
  running = true;
  if (!stream.wait) return status();
  BoardStatus s;

  using clk = std::chrono::steady_clock;
  const auto t0 = clk::now();
  auto abort = [&](Error e) -> Error {
    (void)stop();  // best effort: never leave the axis running on a broken stream
    return e;
  };
  // While rows remain, each round reads FIFO_STATUS and STATUS only (the
  // line is the bottleneck: about 1 ms a register access at 115200 baud)
  // and fills the room; the move boundaries are read between rounds.
  for (;;) {
    auto st = read(hw::RegStatus);
    if (const Error* e = std::get_if<Error>(&st)) return abort(*e);
    s.status = std::get<uint32_t>(st);
    if (!s.busy()) break;
    if (pushed < stream.rows) {
      auto f = read(hw::RegFifoStatus);
      if (const Error* e = std::get_if<Error>(&f)) return abort(*e);
      s.fifo_status = std::get<uint32_t>(f);
      if (auto e = push(hw::RowFifoDepth - s.fifo_level())) return abort(*e);
    } else {
      port_.wait(poll);
    }
    auto mi = read(hw::RegMoveIndex);
    if (const Error* e = std::get_if<Error>(&mi)) return abort(*e);
    auto bp = stream.read_boundaries();
    if (const Error* e = std::get_if<Error>(&bp)) return abort(*e);
    s.move_index = std::get<uint32_t>(mi);
    const std::vector<int32_t>& seen = std::get<std::vector<int32_t>>(bp);
    if (!seen.empty()) s.boundary_pos = seen[0];
    // BOUNDARY_POS holds the boundary of the last move ended (MOVE_INDEX of
    // them); a move may end between the reads, so a boundary is checked
    // when a second MOVE_INDEX read agrees.
    auto mi2 = read(hw::RegMoveIndex);
    if (const Error* e = std::get_if<Error>(&mi2)) return abort(*e);
    if (std::get<uint32_t>(mi2) == s.move_index && s.move_index > 0 && s.move_index <= stream.moves) {
      const std::vector<int64_t> want = stream.planned_boundaries(s.move_index);
      for (size_t a = 0; a < seen.size() && a < want.size(); ++a) {
        if (int64_t(seen[a]) != int64_t(int32_t(uint32_t(want[a])))) {
          return abort(Error{"board", fmt::format("stream: move {} ended at BOUNDARY_POS {}{}, planned {}",
                                                  s.move_index, seen[a],
                                                  seen.size() > 1 ? fmt::format(" on axis {}", a) : "", want[a])});
        }
      }
      ++boundaries_checked;
    }
    if (progress) progress(s);
    if (std::chrono::duration<double>(clk::now() - t0).count() > timeout) {
      return abort(Error{"timeout", fmt::format("timeout={} s: the stream is still running", timeout)});
    }
  }
  auto fin = status();
  if (const Error* e = std::get_if<Error>(&fin)) return *e;
  s = std::get<BoardStatus>(fin);
  const std::vector<std::string> f = s.faults();
  if (s.move_index != stream.moves || pushed != stream.rows || !s.done()) {
    return Error{"board", fmt::format("stream: the axis went idle after move {} of {} ({} of {} rows sent){}{}",
                                      s.move_index, stream.moves, pushed, stream.rows,
                                      f.empty() ? ": no fault flag (a reset?)" : ": ",
                                      fmt::join(f, ", "))};
  }
  return s;
}

std::variant<StreamRunReport, Error> Board::run_stream(const std::vector<StreamedMove>& moves, u128 start_frac,
                                                       double timeout, double poll,
                                                       const std::function<void(const BoardStatus&)>& progress) {
  StreamRunReport rep;
  rep.moves = moves.size();
  if (moves.empty()) return Error{"moves", "moves: the stream is empty"};
  // Every row with its ROW_PUSH flags, in order.
  std::vector<std::pair<const Segment*, RowFlags>> rows;
  for (size_t m = 0; m < moves.size(); ++m) {
    const std::vector<RowFlags> f = move_row_flags(moves[m].segments, m + 1 == moves.size());
    for (size_t i = 0; i < moves[m].segments.size(); ++i) rows.emplace_back(&moves[m].segments[i], f[i]);
  }
  rep.rows = rows.size();
  if (auto e = prepare_rows(start_frac)) return *e;
  auto ref0 = read(hw::RegRefPos);
  if (const Error* e = std::get_if<Error>(&ref0)) return *e;
  rep.start_ref = int32_t(std::get<uint32_t>(ref0));
  rep.expected_end = int64_t(rep.start_ref) + moves.back().end_position;

  RowStream stream;
  stream.rows = rows.size();
  stream.row_writes = [&](size_t k) { return encode_row(*rows[k].first, rows[k].second); };
  stream.moves = moves.size();
  stream.read_boundaries = [&]() -> std::variant<std::vector<int32_t>, Error> {
    auto bp = read(hw::RegBoundaryPos);
    if (const Error* e = std::get_if<Error>(&bp)) return *e;
    return std::vector<int32_t>{int32_t(std::get<uint32_t>(bp))};
  };
  stream.planned_boundaries = [&](size_t done) {
    return std::vector<int64_t>{int64_t(rep.start_ref) + moves[done - 1].end_position};
  };
  auto fin = stream_rows(stream, timeout, poll, progress, rep.boundaries_checked);
  if (const Error* e = std::get_if<Error>(&fin)) return *e;
  const BoardStatus& s = std::get<BoardStatus>(fin);
  rep.final_status = s;
  rep.end_ref = s.ref_pos;
  if (int64_t(s.ref_pos) != int32_t(uint32_t(rep.expected_end))) {
    return Error{"board", fmt::format("stream: REF_POS {} at the end, planned {}", s.ref_pos, rep.expected_end)};
  }
  return rep;
}

// ---- the multi-axis map -----------------------------------------------------------

std::optional<Error> WindowPort::write(uint32_t addr, uint32_t data) {
  return port_.write(multi_axis_addr(axis_, addr), data);
}

std::variant<uint32_t, Error> WindowPort::read(uint32_t addr) { return port_.read(multi_axis_addr(axis_, addr)); }

// The group window is window 0: the one-axis addresses as they are (and the
// row writes, which name each axis's window, pass through unchanged).
AxisGroup::AxisGroup(RegisterPort& port, Clock clock) : port_(port), clock_(clock), group_(port, clock) {}

std::variant<BoardInfo, Error> AxisGroup::identify() {
  auto group = group_.identify();
  if (const Error* e = std::get_if<Error>(&group)) return *e;
  BoardInfo info = std::get<BoardInfo>(group);
  axis_ports_.clear();
  axes_.clear();
  info.closed_loop = true;
  for (size_t a = 0; a < size_t(hw::MaxAxes); ++a) {
    // Past the last axis the map answers DECERR (no register file sees it).
    auto id = port_.read(multi_axis_addr(a, hw::RegId));
    if (const Error* e = std::get_if<Error>(&id)) {
      if (e->parameter != "board") return *e;
      break;
    }
    axis_ports_.push_back(std::make_unique<WindowPort>(port_, a));
    axes_.push_back(std::make_unique<Board>(*axis_ports_.back(), clock_));
    auto ai = axes_.back()->identify();
    if (const Error* e = std::get_if<Error>(&ai)) return *e;
    info.closed_loop = info.closed_loop && std::get<BoardInfo>(ai).closed_loop;
  }
  if (axes_.empty()) return Error{"board", "the multi-axis map answers ID in its group window but in no axis window"};
  info.axes = int(axes_.size());
  return info;
}

std::optional<Error> AxisGroup::configure(const BoardConfig& cfg) {
  if (axes_.empty()) return Error{"board", "configure: identify the axes first"};
  // A group write reaches every axis's register file (the axes run one
  // stream: idle together); a group read answers axis 0's register.
  return group_.configure(cfg);
}

std::variant<std::vector<BoardStatus>, Error> AxisGroup::status() {
  std::vector<BoardStatus> out;
  for (auto& a : axes_) {
    auto st = a->status();
    if (const Error* e = std::get_if<Error>(&st)) return *e;
    out.push_back(std::get<BoardStatus>(st));
  }
  return out;
}

std::variant<std::vector<BoardStatus>, Error> AxisGroup::wait_idle(double timeout, double poll) {
  auto st = group_.wait_idle(timeout, poll);
  if (const Error* e = std::get_if<Error>(&st)) return *e;
  return status();
}

std::variant<PathRunReport, Error> AxisGroup::run_path(const PathPlan& plan, double timeout, double poll,
                                                       const std::function<void(const BoardStatus&)>& progress,
                                                       bool wait) {
  const size_t n = axes_.size();
  if (n == 0) return Error{"board", "run_path: identify the axes first"};
  if (plan.axes.size() != n) {
    return Error{"plan", fmt::format("plan: {} axes planned, the board has {}", plan.axes.size(), n)};
  }
  if (plan.moves.empty() || plan.axes[0].rows.empty()) return Error{"plan", "plan: no move (nothing to run)"};
  PathRunReport rep;
  rep.moves = plan.moves.size();
  rep.rows = plan.axes[0].rows.size();
  for (size_t a = 0; a < n; ++a) {
    if (plan.axes[a].rows.size() != rep.rows || plan.axes[a].flags.size() != rep.rows) {
      return Error{"plan", fmt::format("plan: axis {} has {} rows, axis 0 {}", a, plan.axes[a].rows.size(),
                                       rep.rows)};
    }
  }
  auto st0 = status();
  if (const Error* e = std::get_if<Error>(&st0)) return *e;
  for (size_t a = 0; a < n; ++a) {
    const BoardStatus& s = std::get<std::vector<BoardStatus>>(st0)[a];
    if (s.busy()) return Error{"board", fmt::format("path: axis {} is moving (stop it first)", a)};
    rep.start_ref.push_back(s.ref_pos);
    if (int64_t(s.ref_pos) != plan.moves.front().start.at(a)) {
      return Error{"plan", fmt::format("plan: axis {} starts at {}, the board's REF_POS is {} (plan from where the "
                                       "axes are)", a, plan.moves.front().start.at(a), s.ref_pos)};
    }
  }
  if (auto e = group_.begin_load()) return *e;
  for (size_t a = 0; a < n; ++a) {
    if (auto e = axes_[a]->write_pos_frac0(plan.axes[a].pos_frac0)) return *e;
  }
  // Move m's boundary: every axis's integer part of its exact position
  // where the move's MOVE_END row ends.
  RowStream stream;
  stream.rows = size_t(rep.rows);
  stream.row_writes = [&](size_t k) {
    std::vector<Segment> rows;
    for (size_t a = 0; a < n; ++a) rows.push_back(plan.axes[a].rows[k]);
    return encode_multi_row(rows, plan.axes[0].flags[k]);
  };
  stream.moves = plan.moves.size();
  stream.read_boundaries = [&]() -> std::variant<std::vector<int32_t>, Error> {
    std::vector<int32_t> out;
    for (size_t a = 0; a < n; ++a) {
      auto bp = port_.read(multi_axis_addr(a, hw::RegBoundaryPos));
      if (const Error* e = std::get_if<Error>(&bp)) return *e;
      out.push_back(int32_t(std::get<uint32_t>(bp)));
    }
    return out;
  };
  stream.planned_boundaries = [&](size_t done) {
    std::vector<int64_t> out;
    for (size_t a = 0; a < n; ++a) out.push_back(int64_t(plan.moves[done - 1].end_position[a] >> hw::FracBits));
    return out;
  };
  stream.wait = wait;
  auto fin = group_.stream_rows(stream, timeout, poll, progress, rep.boundaries_checked);
  if (const Error* e = std::get_if<Error>(&fin)) return *e;
  auto st = status();
  if (const Error* e = std::get_if<Error>(&st)) return *e;
  rep.final_status = std::get<std::vector<BoardStatus>>(st);
  if (!wait) return rep;
  const bool open_loop = !group_.config().closed_loop;
  for (size_t a = 0; a < n; ++a) {
    const BoardStatus& s = rep.final_status[a];
    const int64_t target = plan.moves.back().target.at(a);
    if (int64_t(s.ref_pos) != int32_t(uint32_t(target))) {
      return Error{"board", fmt::format("path: axis {} REF_POS {} at the end, planned {}", a, s.ref_pos, target)};
    }
    const int64_t distance = target - rep.start_ref[a];
    if (open_loop && int64_t(s.pulse_count) != distance) {
      return Error{"board", fmt::format("path: axis {} PULSE_COUNT {} at the end, planned {}", a, s.pulse_count,
                                        distance)};
    }
    if (!s.done()) return Error{"board", fmt::format("path: axis {} is not DONE at the end", a)};
  }
  return rep;
}

}  // namespace scurve
