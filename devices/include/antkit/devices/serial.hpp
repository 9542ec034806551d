#pragma once
// A POSIX serial link over termios, and pseudo-terminals for the firmware emulators.
//
// SerialPort: raw mode (cfmakeraw), the given baud rate and framing, CLOCAL | CREAD, no flow
// control, non-blocking I/O driven by poll() with timeouts, and line framing over a bounded input
// buffer: a robot's reply ends at LF (its CR LF is kept so the codec can check it, PROTOCOLS.md); a
// firmware reading commands ends a line at CR or LF and skips empty lines. A hang-up (EOF, EIO,
// POLLHUP, POLLERR) is LinkError Disconnected; a stop signal interrupting a wait is Interrupted.
#include <antkit/devices/line_settings.hpp>
#include <chrono>
#include <cstddef>
#include <cstdint>
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
  // Throws kernel::InputError("--port", ...) when `path` cannot be opened or is not a terminal.
  static SerialPort open(const std::string& path, const LineSettings& settings,
                         std::size_t max_line = 512);
  // Adopts an open fd (a pty master); does not change its termios.
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

} // namespace antkit::devices
