#include "virtual_board.h"

#include <errno.h>
#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <stdexcept>
#include <thread>

#include "scurve/cli/move_flags.h"
#include "scurve/cli/user_input.h"
#include "scurve/hw/params.h"

namespace sc {

namespace {

constexpr int kPinClocksPerClock = 5;  // the board's 100 MHz pin clock over its 20 MHz system clock

}  // namespace

VirtualBoard::VirtualBoard(const VirtualBoardConfig& cfg)
    : cfg_(cfg),
      line_(kPinClocksPerClock * (cfg.axes == 1 ? int(scurve::hw::UartClksPerBit) : RtlBoardXY::kClksPerBit)) {
  if (cfg.axes == 1) {
    rtl_ = std::make_unique<RtlBoard>();
  } else if (cfg.axes == RtlBoardXY::kAxes) {
    rtl_xy_ = std::make_unique<RtlBoardXY>();
  } else {
    throw std::invalid_argument(fmt::format("axes={}: needs 1 or {}", cfg.axes, RtlBoardXY::kAxes));
  }
  for (size_t a = 0; a < cfg.axes; ++a) {
    PlantConfig pc = cfg.plant;
    pc.seed = cfg.plant.seed + 7 * a;
    Axis x{Plant(pc, double(ClkHz)), {}, {}, {}};
    const uint64_t seed = cfg.seed + 3 * a;
    if (cfg.home_at) x.home.emplace(*cfg.home_at, cfg.home_dir, 0, false, seed);
    if (cfg.limit_neg_at) x.lim_neg.emplace(*cfg.limit_neg_at, -1, 0, false, seed + 1);
    if (cfg.limit_pos_at) x.lim_pos.emplace(*cfg.limit_pos_at, 1, 0, false, seed + 2);
    axes_.push_back(std::move(x));
  }
  // The reset synchroniser and the clock stand-in's lock.
  for (int i = 0; i < 40; ++i) clock(true);
}

void VirtualBoard::receive_from_host(const uint8_t* data, size_t n) {
  for (size_t i = 0; i < n; ++i) {
    uint8_t b = data[i];
    ++host_bytes_;
    if (cfg_.corrupt_every > 0 && host_bytes_ % cfg_.corrupt_every == 0) {
      b = uint8_t(b ^ (1u << (host_bytes_ / cfg_.corrupt_every % 8)));
      ++corrupted_;
    }
    line_.send(b);
    if (cfg_.reset_after_bytes > 0 && host_bytes_ == cfg_.reset_after_bytes) reset_pending_ = true;
  }
}

uint8_t VirtualBoard::Axis::switches() {
  const int64_t pos = plant.commanded();
  uint8_t sw = 0;
  if (lim_neg && lim_neg->pin(pos)) sw |= 1;
  if (lim_pos && lim_pos->pin(pos)) sw |= 2;
  if (home && home->pin(pos)) sw |= 4;
  return sw;
}

void VirtualBoard::clock(bool reset_n) {
  if (rtl_) {
    Axis& x = axes_[0];
    const uint8_t sw = x.switches();
    RtlBoard::Pins p;
    for (int i = 0; i < kPinClocksPerClock; ++i) {
      rtl_->tick100(line_.tx_level(), reset_n, false, x.plant.enc_a(), x.plant.enc_b(), sw, x.plant.enc_z());
      p = rtl_->pins();
      line_.clock(p.uart_tx);
    }
    x.plant.clock(p.step, p.dir);
  } else {
    uint8_t sw = 0, a = 0, b = 0, z = 0;
    for (size_t k = 0; k < axes_.size(); ++k) {
      sw = uint8_t(sw | axes_[k].switches() << (3 * k));
      a = uint8_t(a | uint8_t(axes_[k].plant.enc_a()) << k);
      b = uint8_t(b | uint8_t(axes_[k].plant.enc_b()) << k);
      z = uint8_t(z | uint8_t(axes_[k].plant.enc_z()) << k);
    }
    RtlBoardXY::Pins p;
    for (int i = 0; i < kPinClocksPerClock; ++i) {
      rtl_xy_->tick100(line_.tx_level(), false, sw, false, a, b, z, reset_n);
      p = rtl_xy_->pins();
      line_.clock(p.uart_tx);
    }
    for (size_t k = 0; k < axes_.size(); ++k) axes_[k].plant.clock(p.step[k], p.dir[k]);
  }
  ++clocks_;
}

void VirtualBoard::run(uint64_t clocks, std::vector<uint8_t>& to_host) {
  if (reset_pending_) {
    reset_pending_ = false;
    press_reset();
  }
  for (uint64_t i = 0; i < clocks; ++i) clock(true);
  const std::vector<uint8_t> got = line_.take_received();
  to_host.insert(to_host.end(), got.begin(), got.end());
}

void VirtualBoard::press_reset() {
  for (int i = 0; i < 10; ++i) clock(false);
  for (int i = 0; i < 40; ++i) clock(true);
}

std::optional<scurve::Error> VirtualBoardChannel::send(const std::vector<uint8_t>& bytes) {
  b_.receive_from_host(bytes.data(), bytes.size());
  return std::nullopt;
}

std::optional<scurve::Error> VirtualBoardChannel::receive(std::vector<uint8_t>& out, size_t n, double timeout) {
  const uint64_t until = b_.clocks() + uint64_t(std::ceil(timeout * double(ClkHz)));
  for (;;) {
    size_t k = 0;
    for (; k < pending_.size() && out.size() < n; ++k) out.push_back(pending_[k]);
    pending_.erase(pending_.begin(), pending_.begin() + ptrdiff_t(k));
    if (out.size() >= n || b_.clocks() >= until) return std::nullopt;
    b_.run(std::min<uint64_t>(200, until - b_.clocks()), pending_);
  }
}

// ---- the pseudo-terminal ------------------------------------------------------------

namespace {

std::atomic<bool> g_stop{false};
std::atomic<bool> g_reset{false};

extern "C" void on_stop(int) { g_stop = true; }
extern "C" void on_reset(int) { g_reset = true; }

int fail(const std::string& msg) {
  std::cerr << "error: " << scurve::input::printable(msg) << "\n";
  return 2;
}

}  // namespace

int run_virtual_board(const VirtualBoardCliOptions& opt) {
  const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
  if (master < 0 || ::grantpt(master) != 0 || ::unlockpt(master) != 0) {
    return fail(fmt::format("cannot make a pseudo-terminal: {}", std::strerror(errno)));
  }
  const std::string name = ::ptsname(master);
  // Our own handle on the terminal keeps it open between clients (else the
  // master reads EIO once a client closes it) and makes it raw from the start.
  const int slave = ::open(name.c_str(), O_RDWR | O_NOCTTY);
  termios t{};
  if (slave < 0 || ::tcgetattr(slave, &t) != 0) return fail(fmt::format("{}: {}", name, std::strerror(errno)));
  ::cfmakeraw(&t);
  ::tcsetattr(slave, TCSANOW, &t);
  ::fcntl(master, F_SETFL, ::fcntl(master, F_GETFL) | O_NONBLOCK);
  if (!opt.pty_link.empty()) {
    struct stat st {};
    if (::lstat(opt.pty_link.c_str(), &st) == 0) {
      if (!S_ISLNK(st.st_mode)) {
        return fail(fmt::format("pty-link={}: exists and is not a symbolic link", opt.pty_link));
      }
      ::unlink(opt.pty_link.c_str());
    }
    if (::symlink(name.c_str(), opt.pty_link.c_str()) != 0) {
      return fail(fmt::format("pty-link={}: {}", opt.pty_link, std::strerror(errno)));
    }
  }
  std::signal(SIGINT, on_stop);
  std::signal(SIGTERM, on_stop);
  std::signal(SIGUSR1, on_reset);

  VirtualBoard vb(opt.board);
  std::cout << "virtual board on " << name;
  if (!opt.pty_link.empty()) std::cout << " (" << opt.pty_link << ")";
  std::cout << std::endl;

  using clk = std::chrono::steady_clock;
  const auto t0 = clk::now();
  const double hz = double(ClkHz);
  std::vector<uint8_t> out;
  uint8_t buf[512];
  while (!g_stop) {
    if (g_reset.exchange(false)) vb.press_reset();
    const ssize_t n = ::read(master, buf, sizeof buf);
    if (n > 0) vb.receive_from_host(buf, size_t(n));
    // 100 us of board time between looks at the terminal: a request waits
    // at most that long (the host's exchanges, not the simulation, set the
    // rate at which rows reach the FIFO).
    const uint64_t step = 2000;
    vb.run(step, out);
    for (size_t done = 0; done < out.size();) {
      const ssize_t w = ::write(master, out.data() + done, out.size() - done);
      if (w > 0) {
        done += size_t(w);
      } else if (w < 0 && errno != EAGAIN && errno != EINTR) {
        break;  // nobody reads the terminal: the answer is lost, as on a real line
      } else {
        pollfd p{master, POLLOUT, 0};
        ::poll(&p, 1, 10);
      }
    }
    out.clear();
    const double board_s = double(vb.clocks()) / hz;
    const double wall_s = std::chrono::duration<double>(clk::now() - t0).count();
    if (opt.max_seconds > 0 && wall_s > opt.max_seconds) break;
    if (opt.speed > 0 && board_s / opt.speed > wall_s) {
      // Ahead of the wall clock: wait, but keep listening to the host.
      pollfd p{master, POLLIN, 0};
      ::poll(&p, 1, int(std::ceil((board_s / opt.speed - wall_s) * 1e3)));
    }
  }
  const double wall_s = std::chrono::duration<double>(clk::now() - t0).count();
  std::string where;
  for (size_t a = 0; a < vb.axes(); ++a) {
    where += fmt::format("{}position {}, encoder {}, ", vb.axes() > 1 ? fmt::format("axis {}: ", a) : "",
                         vb.position(a), vb.encoder(a));
  }
  std::cerr << fmt::format("virtual board: {} clocks ({:.3f} s of board time) in {:.3f} s, {}{} host bytes corrupted\n",
                           vb.clocks(), double(vb.clocks()) / hz, wall_s, where, vb.corrupted());
  if (!opt.pty_link.empty()) ::unlink(opt.pty_link.c_str());
  ::close(slave);
  ::close(master);
  return 0;
}

void add_virtual_board_command(CLI::App& app, VirtualBoardCli& v) {
  using scurve::cli::int_flag;
  using scurve::cli::real_flag;
  CLI::App* c = app.add_subcommand(
      "virtual-board", "run the Verilated board top with a simulated motor, encoder and switches behind a "
                       "pseudo-terminal: scurve board --port drives it as it drives the Arty");
  v.cmd = c;
  c->add_option("--pty-link", v.opt.pty_link, "a symbolic link to the terminal (replaced when it is one)");
  int_flag(c, "--axes", v.opt.board.axes, 1, int64_t(RtlBoardXY::kAxes),
           "1 (default: the one-axis board, sc_board_top) or 2 (the two-axis board, sc_board_xy_top, on the "
           "multi-axis map; switches on both axes)");
  real_flag(c, "--speed", v.opt.speed, "x real time (default 1; 0: as fast as the simulation runs)", 0, 1000);
  real_flag(c, "--max-seconds", v.opt.max_seconds, "exit after this many wall seconds (default 0: at SIGINT/SIGTERM)",
            0, 1e7);
  int_flag(c, "--index-period", v.index_period, 0, 1'000'000'000,
           "encoder counts per index pulse (default 4000, one revolution; 0: no index)");
  int_flag(c, "--home-at", v.home_at, -1'000'000'000, 1'000'000'000,
           "a home switch, active at and beyond this position (pulses) toward --home-dir");
  int_flag(c, "--home-dir", v.opt.board.home_dir, -1, 1, "the home switch's side: -1 (default) or 1");
  int_flag(c, "--limit-neg-at", v.limit_neg_at, -1'000'000'000, 1'000'000'000,
           "a limit - switch, active at and below this position");
  int_flag(c, "--limit-pos-at", v.limit_pos_at, -1'000'000'000, 1'000'000'000,
           "a limit + switch, active at and above this position");
  int_flag(c, "--corrupt-every", v.opt.board.corrupt_every, 0, 1'000'000'000,
           "line noise: flip one bit of every N-th byte from the host (default 0: none)");
  int_flag(c, "--reset-after-bytes", v.opt.board.reset_after_bytes, 0, int64_t(1) << 62,
           "press the reset button once this many bytes came from the host (default 0: never; SIGUSR1 presses it "
           "too)");
  int_flag(c, "--seed", v.opt.board.seed, 0, int64_t(1) << 62, "seed of the plant");
}

int run_virtual_board_cli(VirtualBoardCli v) {
  if (v.opt.board.home_dir == 0) return fail("--home-dir=0: needs -1 or 1");
  VirtualBoardConfig& b = v.opt.board;
  if (v.cmd->count("--home-at") > 0) b.home_at = v.home_at;
  if (v.cmd->count("--limit-neg-at") > 0) b.limit_neg_at = v.limit_neg_at;
  if (v.cmd->count("--limit-pos-at") > 0) b.limit_pos_at = v.limit_pos_at;
  b.plant.index_period = v.index_period;
  b.plant.seed = b.seed;
  if (!v.opt.pty_link.empty()) {
    try {
      scurve::input::output_path("pty-link", v.opt.pty_link);
    } catch (const scurve::input::Error& e) {
      // An existing symbolic link is replaced; anything else is refused below.
      struct stat st {};
      if (::lstat(v.opt.pty_link.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return fail(e.what());
    }
  }
  return run_virtual_board(v.opt);
}

}  // namespace sc
