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
#include <thread>

#include "scurve/cli/move_flags.h"
#include "scurve/cli/user_input.h"
#include "scurve/hw/params.h"

namespace sc {

namespace {

constexpr int kPinClocksPerClock = 5;  // the board's 100 MHz pin clock over its 20 MHz system clock

}  // namespace

VirtualBoard::VirtualBoard(const VirtualBoardConfig& cfg)
    : cfg_(cfg), plant_(cfg.plant, double(ClkHz)),
      line_(kPinClocksPerClock * scurve::hw::UartClksPerBit) {
  if (cfg.home_at) home_.emplace(*cfg.home_at, cfg.home_dir, 0, false, cfg.seed);
  if (cfg.limit_neg_at) lim_neg_.emplace(*cfg.limit_neg_at, -1, 0, false, cfg.seed + 1);
  if (cfg.limit_pos_at) lim_pos_.emplace(*cfg.limit_pos_at, 1, 0, false, cfg.seed + 2);
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

void VirtualBoard::clock(bool reset_n) {
  const int64_t pos = plant_.commanded();
  uint8_t sw = 0;
  if (lim_neg_ && lim_neg_->pin(pos)) sw |= 1;
  if (lim_pos_ && lim_pos_->pin(pos)) sw |= 2;
  if (home_ && home_->pin(pos)) sw |= 4;
  RtlBoard::Pins p;
  for (int i = 0; i < kPinClocksPerClock; ++i) {
    rtl_.tick100(line_.tx_level(), reset_n, false, plant_.enc_a(), plant_.enc_b(), sw, plant_.enc_z());
    p = rtl_.pins();
    line_.clock(p.uart_tx);
  }
  plant_.clock(p.step, p.dir);
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
    // Short steps while bytes move (answers go out promptly), 1 ms otherwise.
    const uint64_t step = (n > 0 || vb.line_busy()) ? 2000 : 20000;
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
  std::cerr << fmt::format("virtual board: {} clocks ({:.3f} s of board time) in {:.3f} s, position {}, encoder {}, {} "
                           "host bytes corrupted\n",
                           vb.clocks(), double(vb.clocks()) / hz, wall_s, vb.position(), vb.encoder(),
                           vb.corrupted());
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
