// TCP links (serial.hpp): endpoint parsing, the client's connect and the emulators' listener.
#include "serial_internal.hpp"

#include <antkit/devices/serial.hpp>
#include <antkit/kernel/input_error.hpp>
#include <arpa/inet.h>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>
#include <utility>

namespace antkit::devices {

using namespace serial_detail;
using kernel::InputError;

namespace {

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
