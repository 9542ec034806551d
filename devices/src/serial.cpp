// The robot links: the serial port over termios, TCP, and the emulators' pseudo-terminals and TCP
// listener (serial.hpp).
#include <algorithm>
#include <antkit/devices/serial.hpp>
#include <antkit/devices/stop_signals.hpp>
#include <antkit/kernel/input_error.hpp>
#include <arpa/inet.h>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <fstream>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <stdlib.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <sys/stat.h>
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
  throw InputError("baud rate", "unsupported baud rate " + std::to_string(baud));
}

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

// EINTR: a stop signal ends the wait, any other signal just retries it.
void interrupted(const std::string& name) {
  if (StopSignals::requested())
    throw LinkError(LinkError::Kind::Interrupted, name + ": interrupted by a stop signal");
}

// ---- the port held exclusively (serial.hpp) ----

// The PID of a process other than (self, self_fd) that has `device` open with a lock on it (an OFD
// lock shows in the fdinfo of the holder's descriptor, as "lock: ... OFDLCK ..."), or -1.
long lock_holder(const struct stat& device, int self_fd) {
  DIR* proc = ::opendir("/proc");
  if (proc == nullptr) return -1;
  const long self = static_cast<long>(::getpid());
  long found = -1;
  while (const dirent* e = ::readdir(proc)) {
    char* end = nullptr;
    const long pid = std::strtol(e->d_name, &end, 10);
    if (end == e->d_name || *end != '\0' || pid <= 0) continue;
    const std::string base = "/proc/" + std::string(e->d_name);
    DIR* fds = ::opendir((base + "/fd").c_str());
    if (fds == nullptr) continue;
    while (const dirent* f = ::readdir(fds)) {
      if (f->d_name[0] == '.') continue;
      if (pid == self && std::atoi(f->d_name) == self_fd) continue;
      struct stat st {};
      if (::stat((base + "/fd/" + f->d_name).c_str(), &st) != 0) continue;
      if (st.st_dev != device.st_dev || st.st_ino != device.st_ino) continue;
      std::ifstream info(base + "/fdinfo/" + f->d_name);
      std::string line;
      while (std::getline(info, line))
        if (line.rfind("lock:", 0) == 0) found = pid;
      if (found > 0) break;
    }
    ::closedir(fds);
    if (found > 0) break;
  }
  ::closedir(proc);
  return found;
}

[[noreturn]] void port_busy(const std::string& path, long pid) {
  throw InputError("port", "'" + path + "' is busy: port busy" +
                               (pid > 0 ? ", held by process " + std::to_string(pid) : ""));
}

// An OFD write lock on the whole device (serial.hpp says why OFD). A kernel without OFD locks
// (EINVAL) leaves TIOCEXCL alone to hold the port.
void lock_port(int fd, const std::string& path) {
  struct flock lk {};
  lk.l_type = F_WRLCK;
  lk.l_whence = SEEK_SET;
  if (::fcntl(fd, F_OFD_SETLK, &lk) == 0) return;
  const int err = errno;
  if (err != EAGAIN && err != EACCES) return;
  struct flock who {};
  who.l_type = F_WRLCK;
  who.l_whence = SEEK_SET;
  long pid = -1;
  // A classic (per-process) lock's holder is named by GETLK; an OFD holder shows as -1.
  if (::fcntl(fd, F_OFD_GETLK, &who) == 0 && who.l_type != F_UNLCK && who.l_pid > 0)
    pid = who.l_pid;
  struct stat st {};
  if (pid <= 0 && ::fstat(fd, &st) == 0) pid = lock_holder(st, fd);
  port_busy(path, pid);
}

// ---- TCP ----

struct AddrInfo {
  addrinfo* list = nullptr;
  AddrInfo() = default;
  AddrInfo(const AddrInfo&) = delete;
  AddrInfo& operator=(const AddrInfo&) = delete;
  ~AddrInfo() {
    if (list != nullptr) ::freeaddrinfo(list);
  }
};

void resolve(const TcpEndpoint& at, const std::string& where, bool passive, AddrInfo& out) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = AI_NUMERICSERV | (passive ? AI_PASSIVE : 0);
  const std::string service = std::to_string(at.port);
  const int rc = ::getaddrinfo(at.host.c_str(), service.c_str(), &hints, &out.list);
  if (rc != 0 || out.list == nullptr)
    throw InputError(where, "cannot resolve host '" + at.host + "': " +
                                (rc == EAI_SYSTEM ? std::strerror(errno) : ::gai_strerror(rc)));
}

// Waits for a non-blocking connect: 0 connected, else the errno (ETIMEDOUT on the deadline).
int finish_connect(int fd, Clock::time_point deadline, const std::string& name) {
  for (;;) {
    pollfd p{fd, POLLOUT, 0};
    const int r = ::poll(&p, 1, remaining_ms(deadline));
    if (r < 0 && errno == EINTR) {
      interrupted(name);
      continue;
    }
    if (r < 0) return errno;
    if (r == 0) return ETIMEDOUT;
    int err = 0;
    socklen_t len = sizeof err;
    if (::getsockopt(fd, SOL_SOCKET, SO_ERROR, &err, &len) != 0) return errno;
    return err;
  }
}

void set_socket_options(int fd) {
  const int one = 1;
  ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  ::setsockopt(fd, SOL_SOCKET, SO_KEEPALIVE, &one, sizeof one);
}

std::uint16_t bound_port(int fd) {
  sockaddr_storage a{};
  socklen_t len = sizeof a;
  if (::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len) != 0) return 0;
  if (a.ss_family == AF_INET) return ntohs(reinterpret_cast<sockaddr_in*>(&a)->sin_port);
  if (a.ss_family == AF_INET6) return ntohs(reinterpret_cast<sockaddr_in6*>(&a)->sin6_port);
  return 0;
}

void set_port(sockaddr* a, std::uint16_t port) {
  if (a->sa_family == AF_INET) reinterpret_cast<sockaddr_in*>(a)->sin_port = htons(port);
  if (a->sa_family == AF_INET6) reinterpret_cast<sockaddr_in6*>(a)->sin6_port = htons(port);
}

} // namespace

bool is_tcp_port(std::string_view path) noexcept {
  return path.substr(0, kTcpScheme.size()) == kTcpScheme;
}

std::string TcpEndpoint::text() const {
  const bool v6 = host.find(':') != std::string::npos;
  return (v6 ? "[" + host + "]" : host) + ":" + std::to_string(port);
}

TcpEndpoint parse_tcp_endpoint(std::string_view text, const std::string& where, bool any_port) {
  const auto bad = [&](const std::string& why) {
    return InputError(where, "'" + std::string(text) + "' is not a TCP address: " + why +
                                 " (expected HOST:PORT, e.g. 127.0.0.1:10020 or [::1]:10020)");
  };
  TcpEndpoint at;
  std::size_t colon = 0;
  if (!text.empty() && text[0] == '[') {
    const auto close = text.find(']');
    if (close == std::string_view::npos) throw bad("an IPv6 address without its ']'");
    at.host = std::string(text.substr(1, close - 1));
    if (at.host.empty()) throw bad("an empty host");
    for (const char c : at.host)
      if (!(std::isxdigit(static_cast<unsigned char>(c)) || c == ':' || c == '.'))
        throw bad("an IPv6 address holds hex digits, ':' and '.' only");
    if (close + 1 >= text.size() || text[close + 1] != ':') throw bad("no ':PORT' after ']'");
    colon = close + 1;
  } else {
    colon = text.rfind(':');
    if (colon == std::string_view::npos) throw bad("no ':PORT'");
    at.host = std::string(text.substr(0, colon));
    if (at.host.empty()) throw bad("an empty host");
    if (at.host.size() > 253) throw bad("a host name longer than 253 characters");
    for (const char c : at.host)
      if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_'))
        throw bad(c == ':' ? "an IPv6 address must be in brackets"
                           : "a host holds letters, digits, '.', '-' and '_' only");
  }
  const std::string_view digits = text.substr(colon + 1);
  std::uint32_t port = 0;
  if (digits.empty() || digits.size() > 5) throw bad("the port must be a number 1-65535");
  for (const char c : digits) {
    if (c < '0' || c > '9') throw bad("the port must be a number 1-65535");
    port = port * 10 + static_cast<std::uint32_t>(c - '0');
  }
  if (port > 65535 || (port == 0 && !any_port))
    throw bad(any_port ? "the port must be a number 0-65535 (0: any free port)"
                       : "the port must be a number 1-65535");
  at.port = static_cast<std::uint16_t>(port);
  return at;
}

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

SerialPort SerialPort::connect(const TcpEndpoint& to, std::size_t max_line,
                               std::chrono::milliseconds timeout) {
  const std::string name = std::string(kTcpScheme) + to.text();
  AddrInfo addrs;
  resolve(to, "port", false, addrs);
  const auto deadline = Clock::now() + timeout;
  int last = ECONNREFUSED;
  for (const addrinfo* a = addrs.list; a != nullptr; a = a->ai_next) {
    const int fd =
        ::socket(a->ai_family, a->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, a->ai_protocol);
    if (fd < 0) {
      last = errno;
      continue;
    }
    SerialPort port(fd, name, max_line); // closes fd on every way out
    int err = 0;
    if (::connect(fd, a->ai_addr, a->ai_addrlen) != 0)
      err = errno == EINPROGRESS ? finish_connect(fd, deadline, name) : errno;
    if (err == 0) {
      set_socket_options(fd);
      return port;
    }
    last = err;
    if (err == ETIMEDOUT) break; // the whole timeout is spent
  }
  const std::string what =
      last == ECONNREFUSED ? "connection refused"
      : last == ETIMEDOUT  ? "connection timed out after " + std::to_string(timeout.count()) + " ms"
                           : std::string(std::strerror(last));
  throw LinkError(LinkError::Kind::Disconnected, to.text() + ": " + what);
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

// ---- the TCP listener ----

TcpListener::TcpListener(int fd, TcpEndpoint at, int family)
    : fd_(fd), at_(std::move(at)), family_(family), listening_(true) {}

TcpListener TcpListener::listen(const TcpEndpoint& at, const std::string& where) {
  AddrInfo addrs;
  resolve(at, where, true, addrs);
  const addrinfo* a = addrs.list;
  const auto fail_bind = [&](int err) {
    return InputError(where, "cannot listen on " + at.text() + ": " + std::strerror(err));
  };
  std::uint16_t port = at.port;
  if (port == 0) {
    // Any free port, chosen by the kernel on a probe socket and then bound by number: only an
    // explicitly bound port survives pause() (serial.hpp).
    const int probe = ::socket(a->ai_family, a->ai_socktype | SOCK_CLOEXEC, a->ai_protocol);
    if (probe < 0) throw fail_bind(errno);
    const int err = ::bind(probe, a->ai_addr, a->ai_addrlen) == 0 ? 0 : errno;
    port = err == 0 ? bound_port(probe) : 0;
    ::close(probe);
    if (err != 0) throw fail_bind(err);
  }
  const int fd =
      ::socket(a->ai_family, a->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, a->ai_protocol);
  if (fd < 0) throw fail_bind(errno);
  const int one = 1;
  // A restarted emulator can take its port back while the last session's connection waits out
  // TIME_WAIT.
  ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  sockaddr_storage addr{};
  std::memcpy(&addr, a->ai_addr, a->ai_addrlen);
  set_port(reinterpret_cast<sockaddr*>(&addr), port);
  if (::bind(fd, reinterpret_cast<sockaddr*>(&addr), a->ai_addrlen) != 0 || ::listen(fd, 1) != 0) {
    const int err = errno;
    ::close(fd);
    throw fail_bind(err);
  }
  TcpEndpoint real = at;
  real.port = bound_port(fd);
  return TcpListener(fd, std::move(real), a->ai_family);
}

TcpListener::TcpListener(TcpListener&& o) noexcept
    : fd_(std::exchange(o.fd_, -1)), at_(std::move(o.at_)), family_(o.family_),
      listening_(o.listening_) {}

TcpListener& TcpListener::operator=(TcpListener&& o) noexcept {
  if (this != &o) {
    close();
    fd_ = std::exchange(o.fd_, -1);
    at_ = std::move(o.at_);
    family_ = o.family_;
    listening_ = o.listening_;
  }
  return *this;
}

TcpListener::~TcpListener() {
  close();
}

void TcpListener::close() noexcept {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  listening_ = false;
}

std::optional<SerialPort> TcpListener::accept(std::chrono::milliseconds timeout,
                                              std::size_t max_line) {
  if (!listening_) resume(); // throws when closed
  const auto deadline = Clock::now() + timeout;
  const std::string name = "tcp:" + at_.text();
  for (;;) {
    sockaddr_storage peer{};
    socklen_t len = sizeof peer;
    const int c =
        ::accept4(fd_, reinterpret_cast<sockaddr*>(&peer), &len, SOCK_NONBLOCK | SOCK_CLOEXEC);
    if (c >= 0) {
      set_socket_options(c);
      char host[INET6_ADDRSTRLEN] = "?";
      std::uint16_t port = 0;
      if (peer.ss_family == AF_INET) {
        const auto* p4 = reinterpret_cast<const sockaddr_in*>(&peer);
        ::inet_ntop(AF_INET, &p4->sin_addr, host, sizeof host);
        port = ntohs(p4->sin_port);
      } else if (peer.ss_family == AF_INET6) {
        const auto* p6 = reinterpret_cast<const sockaddr_in6*>(&peer);
        ::inet_ntop(AF_INET6, &p6->sin6_addr, host, sizeof host);
        port = ntohs(p6->sin6_port);
      }
      return SerialPort(c, "client " + TcpEndpoint{host, port}.text() + " of " + name, max_line);
    }
    const int err = errno;
    if (err == EINTR) {
      interrupted(name);
      continue;
    }
    // A client that reset before we took it is no client; try again.
    if (err == ECONNABORTED || err == EPROTO) continue;
    if (err != EAGAIN && err != EWOULDBLOCK) fail(name, "accept", err);
    const int wait = remaining_ms(deadline);
    if (wait == 0) return std::nullopt;
    pollfd p{fd_, POLLIN, 0};
    const int r = ::poll(&p, 1, wait);
    if (r < 0 && errno == EINTR) {
      interrupted(name);
      continue;
    }
    if (r < 0) fail(name, "poll", errno);
    if (r == 0) return std::nullopt;
  }
}

void TcpListener::pause() noexcept {
  if (fd_ < 0 || !listening_) return;
  // connect(AF_UNSPEC) takes a Linux listening socket out of LISTEN (tcp_disconnect) with its
  // explicitly bound port kept, so connects are refused until listen() again; clients already in
  // the backlog are reset. Where that fails, the socket is closed and bound again on resume().
  sockaddr unspec{};
  unspec.sa_family = AF_UNSPEC;
  if (::connect(fd_, &unspec, sizeof unspec) != 0) {
    ::close(fd_);
    fd_ = -2; // closed by pause(): resume() binds a new socket
  }
  listening_ = false;
}

void TcpListener::resume() {
  if (listening_) return;
  if (fd_ == -2) {
    fd_ = -1;
    *this = listen(at_, "listen address");
    return;
  }
  if (fd_ < 0) throw LinkError(LinkError::Kind::System, at_.text() + ": the listener is closed");
  if (::listen(fd_, 1) != 0) fail("tcp:" + at_.text(), "listen", errno);
  listening_ = true;
}

} // namespace antkit::devices
