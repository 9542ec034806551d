#pragma once
// The robot links: a POSIX serial port over termios, a TCP client, and the emulators' servers
// (pseudo-terminals, and a TCP listener).
//
// SerialPort: raw mode (cfmakeraw), the given baud rate and framing, CLOCAL | CREAD, no flow
// control, non-blocking I/O driven by poll() with timeouts, and line framing over a bounded input
// buffer: a robot's reply ends at LF (its CR LF is kept so the codec can check it, PROTOCOLS.md); a
// firmware reading commands ends a line at CR or LF and skips empty lines. A hang-up (EOF, EIO,
// POLLHUP, POLLERR) is LinkError Disconnected; a stop signal interrupting a wait is Interrupted.
//
// The port is held exclusively (issue 26: one process per robot). A tty or pty is opened with
// ioctl(TIOCEXCL) -- a later open() by anyone but root fails with EBUSY; close() clears it with
// TIOCNXCL, since a pty slave keeps the flag after its last close while its master is open (an
// emulator's next session could not open it; a holder killed by SIGKILL leaves it so) -- and an
// open file description lock (fcntl F_OFD_SETLK, a write lock on the whole device). Why OFD locks
// and not classic fcntl (F_SETLK) locks or flock(): a classic lock belongs to the process, so a
// second open of the device in the same process (the tests, an embedding program) would be granted
// it; an OFD lock belongs to the open file description, so two opens conflict in one process as
// between two (checked on a /dev/pts slave, Linux 6.x). It is advisory: it binds programs that ask,
// as antkit does, and TIOCEXCL covers the rest for non-root users (root bypasses TIOCEXCL).
// F_OFD_GETLK reports pid -1 for an OFD holder, so the holder's PID is found by the /proc/PID/fd
// entries that are the same device and whose /proc/PID/fdinfo lists a lock; a classic-lock holder's
// PID comes from F_OFD_GETLK itself. A held port: kernel::InputError("port", "'PATH' is busy:
// port busy, held by process PID") (just "port busy" when the PID cannot be found, e.g. /proc not
// readable); an open() failing with EBUSY says "port busy" too.
//
// TCP (`--port tcp:HOST:PORT`, HOST a name, an IPv4 address or [an IPv6 address]): a connect with a
// timeout (kConnectTimeout), TCP_NODELAY (a command is a few bytes: no Nagle delay) and
// SO_KEEPALIVE, then the same SerialPort over the socket: line settings (baud, framing) do not
// apply and are ignored; flush_input drains the socket (no tcflush). End of file, ECONNRESET and
// EPIPE are LinkError Disconnected, as a tty hang-up is; writes use send(MSG_NOSIGNAL), so a closed
// peer cannot kill the process with SIGPIPE. A malformed spec or a host that does not resolve is
// kernel::InputError("port", ...) (exit 2); nothing listening, or a server that already has its
// one client (the Webots relay, `antkit emulate --listen`), is LinkError(Disconnected, "HOST:PORT:
// connection refused"); no answer within the timeout is LinkError(Disconnected, "...: connection
// timed out").
//
// TcpListener: the emulators' TCP side (`antkit emulate ... --listen HOST:PORT`), one client at a
// time. While a client is connected the listener stops listening (pause()), so a second client's
// connect is refused at once -- the same failure a second client of the Webots relay meets, and one
// the client sees before it sends anything, rather than a connection that opens and then closes; it
// listens again (resume()) when the client has gone. The port stays bound meanwhile: a Linux
// listening socket is taken out of LISTEN by connect(AF_UNSPEC) (tcp_disconnect) and keeps an
// explicitly bound port, so port 0 is resolved to a free port once and then bound by number.
#include <antkit/devices/line_settings.hpp>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace antkit::devices {

// "8N1" / "8N2" / "7E1" ...: data bits 5-8, parity N/E/O, stop bits 1-2. Throws
// kernel::InputError(where, ...).
LineSettings parse_framing(std::string_view text, std::uint32_t baud, const std::string& where);
// A standard termios rate (1200 ... 921600). Throws kernel::InputError(where, ...).
std::uint32_t parse_baud(std::string_view text, const std::string& where);

class LinkError : public std::runtime_error {
public:
  enum class Kind : std::uint8_t { Timeout, Disconnected, Overflow, Interrupted, System };
  LinkError(Kind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  [[nodiscard]] Kind kind() const noexcept { return kind_; }

private:
  Kind kind_;
};
std::string_view link_error_name(LinkError::Kind kind) noexcept;

// `tcp:HOST:PORT` ports (see above).
inline constexpr std::string_view kTcpScheme = "tcp:";
inline constexpr std::chrono::milliseconds kConnectTimeout{5000};
[[nodiscard]] bool is_tcp_port(std::string_view path) noexcept;

struct TcpEndpoint {
  std::string host; // a name or an address, without the brackets of an IPv6 address
  std::uint16_t port = 0;
  // "HOST:PORT", with brackets around an IPv6 address.
  [[nodiscard]] std::string text() const;
  friend bool operator==(const TcpEndpoint&, const TcpEndpoint&) = default;
};
// "HOST:PORT" (without the scheme): HOST a name or IPv4 address (letters, digits, '.', '-', '_') or
// an IPv6 address in brackets, PORT a decimal 1-65535 (0 too when any_port: a listener's "any free
// port"). Throws kernel::InputError(where, ...) naming what is wrong.
TcpEndpoint parse_tcp_endpoint(std::string_view text, const std::string& where, bool any_port);

enum class LineEnd : std::uint8_t { Lf, CrOrLf };

// One read_line: the line with its terminator when complete; on a timeout the partial bytes
// (consumed); overflow when max_line bytes came without a terminator (the rest of that line is
// then discarded up to its terminator).
struct ReadResult {
  std::string bytes;
  bool complete = false;
  bool overflow = false;
};

class SerialPort {
public:
  // A tty or pty path (held exclusively), or `tcp:HOST:PORT` (settings ignored); see above.
  // Throws kernel::InputError("port", ...) when `path` cannot be opened, is not a terminal, is
  // busy, or is a malformed or unresolvable TCP spec; LinkError Disconnected when a TCP connection
  // is refused or times out.
  static SerialPort open(const std::string& path, const LineSettings& settings,
                         std::size_t max_line = 512);
  static SerialPort connect(const TcpEndpoint& to, std::size_t max_line = 512,
                            std::chrono::milliseconds timeout = kConnectTimeout);
  // Adopts an open fd (a pty master, a socket); does not change its termios.
  SerialPort(int fd, std::string name, std::size_t max_line = 512);
  SerialPort(SerialPort&& other) noexcept;
  SerialPort& operator=(SerialPort&& other) noexcept;
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;
  ~SerialPort();

  void write_all(std::string_view bytes, std::chrono::milliseconds timeout);
  ReadResult read_line(std::chrono::milliseconds timeout, LineEnd end = LineEnd::Lf);
  // Exactly n bytes (binary payloads such as a camera frame after its header line), the buffered
  // ones first; on a timeout the bytes that came (fewer than n), consumed.
  std::string read_bytes(std::size_t n, std::chrono::milliseconds timeout);
  void flush_input();
  void close() noexcept;
  [[nodiscard]] int fd() const noexcept { return fd_; }
  [[nodiscard]] bool is_socket() const noexcept { return socket_; }
  [[nodiscard]] const std::string& name() const noexcept { return name_; }
  [[nodiscard]] std::size_t buffered() const noexcept { return buffer_.size(); }

private:
  // Takes a complete line out of buffer_ into out (true), or nothing.
  bool take_line(LineEnd end, ReadResult& out);
  // Appends what has arrived (at most `limit` bytes) to buffer_, waiting for it until the
  // deadline: false on a timeout. Throws LinkError (a hang-up, an end of file, a stop signal).
  bool receive(std::chrono::steady_clock::time_point deadline, std::size_t limit);
  int fd_ = -1;
  std::string name_;
  std::size_t max_line_;
  std::string buffer_;
  bool discarding_ = false; // inside an over-long line, up to its terminator
  bool socket_ = false;     // a TCP link: send(MSG_NOSIGNAL), no tcflush
  bool exclusive_ = false;  // TIOCEXCL set by open(), cleared by close()
};

class Pty {
public:
  static Pty open();
  Pty(Pty&&) noexcept = default;
  Pty& operator=(Pty&&) noexcept = default;
  ~Pty();
  [[nodiscard]] const std::string& slave_path() const noexcept { return slave_path_; }
  SerialPort& master() noexcept { return master_; }
  void close_slave_keeper() noexcept;
  void hang_up() noexcept;

private:
  Pty(SerialPort master, std::string slave_path, int keeper);
  SerialPort master_;
  std::string slave_path_;
  int keeper_ = -1;
};

class TcpListener {
public:
  // Binds `at` (port 0: a free port, chosen here) and listens with a backlog of 1. Throws
  // kernel::InputError(where, ...) when the host does not resolve or the address cannot be bound.
  static TcpListener listen(const TcpEndpoint& at, const std::string& where = "listen address");
  TcpListener(TcpListener&& other) noexcept;
  TcpListener& operator=(TcpListener&& other) noexcept;
  TcpListener(const TcpListener&) = delete;
  TcpListener& operator=(const TcpListener&) = delete;
  ~TcpListener();

  // The bound address with its real port, and `tcp:HOST:PORT` for a client's --port.
  [[nodiscard]] const TcpEndpoint& endpoint() const noexcept { return at_; }
  [[nodiscard]] std::string port_spec() const { return std::string(kTcpScheme) + at_.text(); }
  // The next client, waiting at most `timeout`: nothing on a timeout. A stop signal ends the wait
  // with LinkError Interrupted.
  std::optional<SerialPort> accept(std::chrono::milliseconds timeout, std::size_t max_line = 512);
  // Stops listening, the port kept: connects are refused until resume() (see above).
  void pause() noexcept;
  void resume();
  void close() noexcept;

private:
  TcpListener(int fd, TcpEndpoint at, int family);
  int fd_ = -1;
  TcpEndpoint at_;
  int family_ = 0;
  bool listening_ = false;
};

} // namespace antkit::devices
