// The serial link over termios and the emulators' pseudo-terminals (serial.hpp).
#include <algorithm>
#include <antkit/devices/serial.hpp>
#include <antkit/devices/stop_signals.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <stdlib.h>
#include <sys/ioctl.h>
#include <system_error>
#include <termios.h>
#include <unistd.h>
#include <utility>

namespace antkit::devices {

namespace {

using Clock = std::chrono::steady_clock;
using kernel::InputError;

struct Rate {
  std::uint32_t baud;
  speed_t code;
};
constexpr Rate kRates[] = {{1200, B1200},     {2400, B2400},     {4800, B4800},
                           {9600, B9600},     {19200, B19200},   {38400, B38400},
                           {57600, B57600},   {115200, B115200}, {230400, B230400},
                           {460800, B460800}, {921600, B921600}};

speed_t speed_code(std::uint32_t baud) {
  for (const auto& r : kRates)
    if (r.baud == baud) return r.code;
  throw InputError("--baud", "unsupported baud rate " + std::to_string(baud));
}

int remaining_ms(Clock::time_point deadline) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
  return left.count() < 0 ? 0 : static_cast<int>(left.count());
}

[[noreturn]] void fail(const std::string& name, const char* what, int err) {
  if (err == EIO || err == EPIPE || err == ENXIO || err == ECONNRESET)
    throw LinkError(LinkError::Kind::Disconnected,
                    name + ": disconnected (" + what + ": " + std::strerror(err) + ")");
  throw LinkError(LinkError::Kind::System, name + ": " + what + ": " + std::strerror(err));
}

// EINTR: a stop signal ends the wait, any other signal just retries it.
void interrupted(const std::string& name) {
  if (StopSignals::requested())
    throw LinkError(LinkError::Kind::Interrupted, name + ": interrupted by a stop signal");
}

} // namespace

std::string_view link_error_name(LinkError::Kind kind) noexcept {
  switch (kind) {
  case LinkError::Kind::Timeout:
    return "timeout";
  case LinkError::Kind::Disconnected:
    return "disconnected";
  case LinkError::Kind::Overflow:
    return "overflow";
  case LinkError::Kind::Interrupted:
    return "interrupted";
  case LinkError::Kind::System:
    return "system error";
  }
  return "?";
}

std::uint32_t parse_baud(std::string_view text, const std::string& where) {
  std::uint64_t v = 0;
  if (text.empty() || text.size() > 7)
    v = 0;
  else
    for (const char c : text) {
      if (c < '0' || c > '9') {
        v = 0;
        break;
      }
      v = v * 10 + static_cast<std::uint64_t>(c - '0');
    }
  for (const auto& r : kRates)
    if (r.baud == v) return r.baud;
  throw InputError(where, "'" + std::string(text) +
                              "' is not a supported baud rate: expected one of 1200, 2400, 4800, "
                              "9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600");
}

LineSettings parse_framing(std::string_view text, std::uint32_t baud, const std::string& where) {
  LineSettings s;
  s.baud = baud;
  const bool ok = text.size() == 3 && text[0] >= '5' && text[0] <= '8' &&
                  (text[1] == 'N' || text[1] == 'E' || text[1] == 'O') &&
                  (text[2] == '1' || text[2] == '2');
  if (!ok)
    throw InputError(where, "'" + std::string(text) +
                                "' is not a framing: expected data bits 5-8, parity N, E or O, "
                                "stop bits 1 or 2, e.g. 8N1 or 8N2");
  s.data_bits = static_cast<std::uint8_t>(text[0] - '0');
  s.parity = text[1] == 'N' ? Parity::None : text[1] == 'E' ? Parity::Even : Parity::Odd;
  s.stop_bits = static_cast<std::uint8_t>(text[2] - '0');
  return s;
}

SerialPort SerialPort::open(const std::string& path, const LineSettings& settings,
                            std::size_t max_line) {
  const speed_t speed = speed_code(settings.baud);
  const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw InputError("--port", "cannot open '" + path + "': " + std::strerror(errno));
  SerialPort port(fd, path, max_line);
  termios t{};
  if (::tcgetattr(fd, &t) != 0)
    throw InputError("--port",
                     "'" + path + "' is not a serial port or terminal: " + std::strerror(errno));
  ::ioctl(fd, TIOCEXCL); // other processes may not open it while we drive the robot
  ::cfmakeraw(&t);
  t.c_cflag &= ~static_cast<tcflag_t>(CSIZE | CSTOPB | PARENB | PARODD | CRTSCTS);
  t.c_cflag |= CLOCAL | CREAD;
  t.c_cflag |= settings.data_bits == 5   ? CS5
               : settings.data_bits == 6 ? CS6
               : settings.data_bits == 7 ? CS7
                                         : CS8;
  if (settings.stop_bits == 2) t.c_cflag |= CSTOPB;
  if (settings.parity != Parity::None) t.c_cflag |= PARENB;
  if (settings.parity == Parity::Odd) t.c_cflag |= PARODD;
  t.c_iflag &= ~static_cast<tcflag_t>(IXON | IXOFF | IXANY);
  t.c_cc[VMIN] = 0;
  t.c_cc[VTIME] = 0;
  ::cfsetispeed(&t, speed);
  ::cfsetospeed(&t, speed);
  if (::tcsetattr(fd, TCSANOW, &t) != 0)
    throw InputError("--port", "cannot set up '" + path + "': " + std::strerror(errno));
  ::tcflush(fd, TCIOFLUSH);
  return port;
}

SerialPort::SerialPort(int fd, std::string name, std::size_t max_line)
    : fd_(fd), name_(std::move(name)), max_line_(max_line == 0 ? 1 : max_line) {
  const int flags = ::fcntl(fd_, F_GETFL);
  if (flags >= 0) ::fcntl(fd_, F_SETFL, flags | O_NONBLOCK);
}

SerialPort::SerialPort(SerialPort&& o) noexcept
    : fd_(std::exchange(o.fd_, -1)), name_(std::move(o.name_)), max_line_(o.max_line_),
      buffer_(std::move(o.buffer_)), discarding_(o.discarding_) {}

SerialPort& SerialPort::operator=(SerialPort&& o) noexcept {
  if (this != &o) {
    close();
    fd_ = std::exchange(o.fd_, -1);
    name_ = std::move(o.name_);
    max_line_ = o.max_line_;
    buffer_ = std::move(o.buffer_);
    discarding_ = o.discarding_;
  }
  return *this;
}

SerialPort::~SerialPort() {
  close();
}

void SerialPort::close() noexcept {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

void SerialPort::write_all(std::string_view bytes, std::chrono::milliseconds timeout) {
  if (fd_ < 0) throw LinkError(LinkError::Kind::Disconnected, name_ + ": closed");
  const auto deadline = Clock::now() + timeout;
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
    if (n > 0) {
      bytes.remove_prefix(static_cast<std::size_t>(n));
      continue;
    }
    if (n < 0 && errno == EINTR) {
      interrupted(name_);
      continue;
    }
    if (n < 0 && errno != EAGAIN) fail(name_, "write", errno);
    pollfd p{fd_, POLLOUT, 0};
    const int r = ::poll(&p, 1, remaining_ms(deadline));
    if (r < 0 && errno == EINTR) {
      interrupted(name_);
      continue;
    }
    if (r < 0) fail(name_, "poll", errno);
    if (r == 0)
      throw LinkError(LinkError::Kind::Timeout, name_ + ": could not write within " +
                                                    std::to_string(timeout.count()) + " ms");
    if ((p.revents & (POLLHUP | POLLERR)) != 0 && (p.revents & POLLOUT) == 0)
      throw LinkError(LinkError::Kind::Disconnected, name_ + ": disconnected (hang-up)");
  }
}

bool SerialPort::take_line(LineEnd end, ReadResult& out) {
  for (;;) {
    std::size_t i = 0;
    const auto is_end = [end](char c) {
      return c == '\n' || (end == LineEnd::CrOrLf && c == '\r');
    };
    while (i < buffer_.size() && !is_end(buffer_[i])) ++i;
    if (i == buffer_.size()) {
      // No terminator yet: an over-long line is cut here.
      if (discarding_) {
        buffer_.clear();
        return false;
      }
      if (buffer_.size() >= max_line_) {
        out.bytes = buffer_.substr(0, max_line_);
        out.overflow = true;
        buffer_.clear();
        discarding_ = true;
        return true;
      }
      return false;
    }
    std::size_t stop = i + 1;
    // CrOrLf: a CR LF pair is one terminator (a CR then a LF would otherwise make an empty line).
    if (end == LineEnd::CrOrLf && buffer_[i] == '\r' && stop < buffer_.size() &&
        buffer_[stop] == '\n')
      ++stop;
    std::string line = buffer_.substr(0, stop);
    buffer_.erase(0, stop);
    if (discarding_) { // the end of an over-long line: drop it, look for the next
      discarding_ = false;
      continue;
    }
    if (end == LineEnd::CrOrLf && line.find_first_not_of("\r\n") == std::string::npos) continue;
    if (line.size() > max_line_) { // a whole over-long line in one chunk
      out.bytes = line.substr(0, max_line_);
      out.overflow = true;
      return true;
    }
    out.bytes = std::move(line);
    out.complete = true;
    return true;
  }
}

bool SerialPort::receive(Clock::time_point deadline, std::size_t limit) {
  char chunk[65536];
  bool ready = false; // poll said there is something to read
  for (;;) {
    const ssize_t n = ::read(fd_, chunk, std::min(sizeof chunk, limit));
    if (n > 0) {
      buffer_.append(chunk, static_cast<std::size_t>(n));
      return true;
    }
    // A tty in raw mode with VMIN = VTIME = 0 reads 0 bytes when nothing has arrived; only after
    // poll reported input is 0 bytes an end of file.
    if (n == 0 && ready) throw LinkError(LinkError::Kind::Disconnected, name_ + ": end of file");
    if (n < 0 && errno == EINTR) {
      interrupted(name_);
      continue;
    }
    if (n < 0 && errno != EAGAIN) fail(name_, "read", errno);
    const int wait = remaining_ms(deadline);
    if (wait == 0) return false;
    pollfd p{fd_, POLLIN, 0};
    const int r = ::poll(&p, 1, wait);
    if (r < 0 && errno == EINTR) {
      interrupted(name_);
      continue;
    }
    if (r < 0) fail(name_, "poll", errno);
    if (r == 0) return false;
    if ((p.revents & POLLIN) == 0 && (p.revents & (POLLHUP | POLLERR)) != 0)
      throw LinkError(LinkError::Kind::Disconnected, name_ + ": disconnected (hang-up)");
    ready = true;
  }
}

ReadResult SerialPort::read_line(std::chrono::milliseconds timeout, LineEnd end) {
  ReadResult out;
  if (take_line(end, out)) return out;
  if (fd_ < 0) throw LinkError(LinkError::Kind::Disconnected, name_ + ": closed");
  const auto deadline = Clock::now() + timeout;
  while (receive(deadline, 512))
    if (take_line(end, out)) return out;
  // Timeout: hand over what came (and is not part of an over-long line being dropped).
  out.bytes = discarding_ ? std::string() : std::move(buffer_);
  buffer_.clear();
  discarding_ = false;
  return out;
}

std::string SerialPort::read_bytes(std::size_t n, std::chrono::milliseconds timeout) {
  if (fd_ < 0 && buffer_.size() < n)
    throw LinkError(LinkError::Kind::Disconnected, name_ + ": closed");
  const auto deadline = Clock::now() + timeout;
  while (buffer_.size() < n && receive(deadline, n - buffer_.size())) {
  }
  const std::size_t take = std::min(n, buffer_.size());
  std::string out = buffer_.substr(0, take);
  buffer_.erase(0, take);
  return out;
}

void SerialPort::flush_input() {
  buffer_.clear();
  discarding_ = false;
  if (fd_ < 0) return;
  ::tcflush(fd_, TCIFLUSH);
  char chunk[512];
  while (::read(fd_, chunk, sizeof chunk) > 0) {
  }
}

// ---- pseudo-terminals ----

Pty::Pty(SerialPort master, std::string slave_path, int keeper)
    : master_(std::move(master)), slave_path_(std::move(slave_path)), keeper_(keeper) {}

Pty Pty::open() {
  const int m = ::posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (m < 0) throw std::system_error(errno, std::generic_category(), "posix_openpt");
  if (::grantpt(m) != 0 || ::unlockpt(m) != 0) {
    const int err = errno;
    ::close(m);
    throw std::system_error(err, std::generic_category(), "grantpt/unlockpt");
  }
  char name[128] = {};
  if (::ptsname_r(m, name, sizeof name) != 0) {
    const int err = errno;
    ::close(m);
    throw std::system_error(err, std::generic_category(), "ptsname");
  }
  // Raw mode on the pair before any client opens it: no echo, no CR/NL translation.
  const int keeper = ::open(name, O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (keeper < 0) {
    const int err = errno;
    ::close(m);
    throw std::system_error(err, std::generic_category(), "open pty slave");
  }
  termios t{};
  ::tcgetattr(keeper, &t);
  ::cfmakeraw(&t);
  ::tcsetattr(keeper, TCSANOW, &t);
  return Pty(SerialPort(m, std::string("pty master of ") + name), name, keeper);
}

Pty::~Pty() {
  close_slave_keeper();
}

void Pty::close_slave_keeper() noexcept {
  if (keeper_ >= 0) ::close(keeper_);
  keeper_ = -1;
}

void Pty::hang_up() noexcept {
  master_.close();
  close_slave_keeper();
}

} // namespace antkit::devices
