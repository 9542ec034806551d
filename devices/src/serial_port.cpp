// The serial port over termios (serial.hpp): opening and setting up the line, writing, and reading
// lines and bytes under a deadline; the wait helpers the TCP link shares (serial_internal.hpp).
#include "serial_internal.hpp"

#include <algorithm>
#include <antkit/devices/serial.hpp>
#include <antkit/devices/stop_signals.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>
#include <utility>

namespace antkit::devices {

namespace serial_detail {

int remaining_ms(Clock::time_point deadline) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
  return left.count() < 0 ? 0 : static_cast<int>(left.count());
}

[[noreturn]] void fail(const std::string& name, const char* what, int err) {
  if (err == EIO || err == EPIPE || err == ENXIO || err == ECONNRESET || err == ENOTCONN ||
      err == ECONNABORTED || err == ETIMEDOUT)
    throw LinkError(LinkError::Kind::Disconnected,
                    name + ": disconnected (" + what + ": " + std::strerror(err) + ")");
  throw LinkError(LinkError::Kind::System, name + ": " + what + ": " + std::strerror(err));
}

void interrupted(const std::string& name) {
  if (StopSignals::requested())
    throw LinkError(LinkError::Kind::Interrupted, name + ": interrupted by a stop signal");
}

} // namespace serial_detail

using namespace serial_detail;
using kernel::InputError;

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

SerialPort SerialPort::open(const std::string& path, const LineSettings& settings,
                            std::size_t max_line) {
  if (is_tcp_port(path))
    return connect(
        parse_tcp_endpoint(std::string_view(path).substr(kTcpScheme.size()), "port", false),
        max_line);
  const speed_t speed = speed_code(settings.baud);
  const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0 && errno == EBUSY) { // another process set TIOCEXCL
    struct stat st {};
    port_busy(path, ::stat(path.c_str(), &st) == 0 ? lock_holder(st, -1) : -1);
  }
  if (fd < 0) throw InputError("port", "cannot open '" + path + "': " + std::strerror(errno));
  SerialPort port(fd, path, max_line);
  termios t{};
  if (::tcgetattr(fd, &t) != 0)
    throw InputError("port",
                     "'" + path + "' is not a serial port or terminal: " + std::strerror(errno));
  lock_port(fd, path); // before any setting changes: a held port is left as its holder set it
  // Other processes may not open it while we drive the robot; close() clears it again (a pty
  // keeps the flag after its last close while the master is open).
  port.exclusive_ = ::ioctl(fd, TIOCEXCL) == 0;
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
    throw InputError("port", "cannot set up '" + path + "': " + std::strerror(errno));
  ::tcflush(fd, TCIOFLUSH);
  return port;
}

SerialPort::SerialPort(int fd, std::string name, std::size_t max_line)
    : fd_(fd), name_(std::move(name)), max_line_(max_line == 0 ? 1 : max_line) {
  const int flags = ::fcntl(fd_, F_GETFL);
  if (flags >= 0) ::fcntl(fd_, F_SETFL, flags | O_NONBLOCK);
  struct stat st {};
  socket_ = ::fstat(fd_, &st) == 0 && S_ISSOCK(st.st_mode);
}

SerialPort::SerialPort(SerialPort&& o) noexcept
    : fd_(std::exchange(o.fd_, -1)), name_(std::move(o.name_)), max_line_(o.max_line_),
      buffer_(std::move(o.buffer_)), discarding_(o.discarding_), socket_(o.socket_),
      exclusive_(std::exchange(o.exclusive_, false)) {}

SerialPort& SerialPort::operator=(SerialPort&& o) noexcept {
  if (this != &o) {
    close();
    fd_ = std::exchange(o.fd_, -1);
    name_ = std::move(o.name_);
    max_line_ = o.max_line_;
    buffer_ = std::move(o.buffer_);
    discarding_ = o.discarding_;
    socket_ = o.socket_;
    exclusive_ = std::exchange(o.exclusive_, false);
  }
  return *this;
}

SerialPort::~SerialPort() {
  close();
}

void SerialPort::close() noexcept {
  if (fd_ >= 0 && exclusive_) ::ioctl(fd_, TIOCNXCL);
  exclusive_ = false;
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

void SerialPort::write_all(std::string_view bytes, std::chrono::milliseconds timeout) {
  if (fd_ < 0) throw LinkError(LinkError::Kind::Disconnected, name_ + ": closed");
  const auto deadline = Clock::now() + timeout;
  while (!bytes.empty()) {
    // A socket: MSG_NOSIGNAL, so a peer that has gone is EPIPE (Disconnected), not SIGPIPE.
    const ssize_t n = socket_ ? ::send(fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL)
                              : ::write(fd_, bytes.data(), bytes.size());
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
  if (!socket_) ::tcflush(fd_, TCIFLUSH); // a socket has no tty queue: draining below is all

  char chunk[512];
  while (::read(fd_, chunk, sizeof chunk) > 0) {
  }
}

} // namespace antkit::devices
