// A POSIX serial port (termios) as the board's byte line.
#include <errno.h>
#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include <chrono>
#include <cstring>

#include "scurve/board.h"

namespace scurve {

namespace {

struct Rate {
  int baud;
  speed_t code;
};
constexpr Rate kRates[] = {{9600, B9600},     {19200, B19200},   {38400, B38400},     {57600, B57600},
                           {115200, B115200}, {230400, B230400}, {460800, B460800},   {921600, B921600},
                           {1000000, B1000000}, {2000000, B2000000}, {3000000, B3000000}};

class SerialPort : public ByteChannel {
 public:
  explicit SerialPort(int fd, std::string device) : fd_(fd), device_(std::move(device)) {}
  ~SerialPort() override { ::close(fd_); }
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;

  std::optional<Error> send(const std::vector<uint8_t>& bytes) override {
    size_t done = 0;
    while (done < bytes.size()) {
      const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0 && errno == EAGAIN) {
        pollfd p{fd_, POLLOUT, 0};
        if (::poll(&p, 1, 1000) <= 0) return failure("cannot write (the line is blocked)");
        continue;
      }
      if (n <= 0) return failure(fmt::format("write failed: {}", std::strerror(errno)));
      done += size_t(n);
    }
    return std::nullopt;
  }

  std::optional<Error> receive(std::vector<uint8_t>& out, size_t n, double timeout) override {
    using clk = std::chrono::steady_clock;
    const auto end = clk::now() + std::chrono::duration_cast<clk::duration>(std::chrono::duration<double>(timeout));
    while (out.size() < n) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - clk::now()).count();
      if (left < 0) return std::nullopt;
      pollfd p{fd_, POLLIN, 0};
      const int r = ::poll(&p, 1, int(left) + 1);
      if (r < 0 && errno == EINTR) continue;
      if (r < 0) return failure(fmt::format("poll failed: {}", std::strerror(errno)));
      if (r == 0) continue;
      if (p.revents & (POLLERR | POLLNVAL)) return failure("the device reports an error (unplugged?)");
      uint8_t buf[256];
      const ssize_t got = ::read(fd_, buf, std::min(sizeof buf, n - out.size()));
      if (got < 0 && (errno == EINTR || errno == EAGAIN)) continue;
      // A pseudo-terminal whose other end closed reads EIO or 0 (hang-up).
      if (got < 0 && errno == EIO) return failure("the other end closed the line");
      if (got < 0) return failure(fmt::format("read failed: {}", std::strerror(errno)));
      if (got == 0) {
        if (p.revents & POLLHUP) return failure("the other end closed the line");
        continue;
      }
      out.insert(out.end(), buf, buf + got);
    }
    return std::nullopt;
  }

  void discard_input() override { ::tcflush(fd_, TCIFLUSH); }

 private:
  Error failure(const std::string& what) const { return Error{"port", fmt::format("port={}: {}", device_, what)}; }
  int fd_;
  std::string device_;
};

}  // namespace

const std::vector<int>& serial_baud_rates() {
  static const std::vector<int> rates = [] {
    std::vector<int> v;
    for (const Rate& r : kRates) v.push_back(r.baud);
    return v;
  }();
  return rates;
}

std::variant<std::unique_ptr<ByteChannel>, Error> open_serial_port(const SerialSettings& s) {
  const Rate* rate = nullptr;
  for (const Rate& r : kRates) {
    if (r.baud == s.baud) rate = &r;
  }
  if (!rate) {
    return Error{"baud", fmt::format("baud={}: not a serial rate (one of {})", s.baud,
                                     fmt::join(serial_baud_rates(), ", "))};
  }
  if (s.device.empty()) return Error{"port", "port='': required (the board's serial device, e.g. /dev/ttyUSB1)"};
  struct stat st {};
  if (::stat(s.device.c_str(), &st) != 0) {
    return Error{"port", fmt::format("port={}: {}", s.device, std::strerror(errno))};
  }
  if (!S_ISCHR(st.st_mode)) return Error{"port", fmt::format("port={}: not a terminal device", s.device)};
  const int fd = ::open(s.device.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return Error{"port", fmt::format("port={}: {}", s.device, std::strerror(errno))};
  termios t{};
  if (!::isatty(fd) || ::tcgetattr(fd, &t) != 0) {
    ::close(fd);
    return Error{"port", fmt::format("port={}: not a terminal device", s.device)};
  }
  ::cfmakeraw(&t);
  t.c_cflag &= ~tcflag_t(CSTOPB | PARENB | CRTSCTS);
  t.c_cflag |= CS8 | CLOCAL | CREAD;
  t.c_iflag &= ~tcflag_t(IXON | IXOFF | IXANY);
  t.c_cc[VMIN] = 0;
  t.c_cc[VTIME] = 0;
  if (::cfsetispeed(&t, rate->code) != 0 || ::cfsetospeed(&t, rate->code) != 0 || ::tcsetattr(fd, TCSANOW, &t) != 0) {
    const std::string why = std::strerror(errno);
    ::close(fd);
    return Error{"port", fmt::format("port={}: cannot set {} 8N1: {}", s.device, s.baud, why)};
  }
  ::tcflush(fd, TCIOFLUSH);
  return std::unique_ptr<ByteChannel>(std::make_unique<SerialPort>(fd, s.device));
}

}  // namespace scurve
