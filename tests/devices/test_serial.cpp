// The serial link over real pseudo-terminals (devices/serial.hpp): termios set-up, line framing,
// timeouts with partial bytes, the bounded buffer, hang-ups and stop signals.
#include "scratch_dir.hpp"

#include <antkit/devices/serial.hpp>
#include <antkit/devices/stop_signals.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <fstream>
#include <rapidcheck/catch.h>
#include <termios.h>
#include <thread>
#include <unistd.h>

namespace devices = antkit::devices;
using namespace std::chrono_literals;
using devices::LineEnd;
using devices::LinkError;

namespace {

devices::LineSettings line(std::uint32_t baud, std::uint8_t stop_bits) {
  devices::LineSettings s;
  s.baud = baud;
  s.stop_bits = stop_bits;
  return s;
}

void send(devices::Pty& pty, std::string_view bytes) {
  pty.master().write_all(bytes, 100ms);
}

} // namespace

TEST_CASE("open() puts the tty in raw mode at the requested baud rate and framing", "[devices]") {
  for (const auto& [baud, stop, code] : {std::tuple{9600u, 2, B9600}, std::tuple{9600u, 1, B9600},
                                         std::tuple{115200u, 1, B115200}}) {
    auto pty = devices::Pty::open();
    auto port =
        devices::SerialPort::open(pty.slave_path(), line(baud, static_cast<std::uint8_t>(stop)));
    termios t{};
    REQUIRE(::tcgetattr(port.fd(), &t) == 0);
    CHECK((t.c_cflag & CSIZE) == CS8);
    CHECK(((t.c_cflag & CSTOPB) != 0) == (stop == 2));
    CHECK((t.c_cflag & PARENB) == 0);
    CHECK((t.c_cflag & (CLOCAL | CREAD)) == (CLOCAL | CREAD));
    CHECK((t.c_lflag & (ICANON | ECHO)) == 0);
    CHECK((t.c_iflag & (ICRNL | IXON)) == 0);
    CHECK((t.c_oflag & OPOST) == 0);
    CHECK(::cfgetospeed(&t) == static_cast<speed_t>(code));
  }
  CHECK(devices::parse_framing("8N2", 9600, "--framing").stop_bits == 2);
  CHECK(devices::parse_framing("7E1", 9600, "--framing").parity == devices::Parity::Even);
  CHECK(devices::parse_framing("8N1", 9600, "--framing").framing() == "8N1");
  for (const char* bad : {"", "8N", "9N1", "8X1", "8N3", "8n1", "8N1 "})
    CHECK_THROWS_AS(devices::parse_framing(bad, 9600, "--framing"), antkit::kernel::InputError);
  CHECK(devices::parse_baud("115200", "--baud") == 115200);
  for (const char* bad : {"", "0", "12345", "9600x", "-9600", "99999999999"})
    CHECK_THROWS_AS(devices::parse_baud(bad, "--baud"), antkit::kernel::InputError);
}

TEST_CASE("open() refuses a missing path and a file that is not a terminal", "[devices]") {
  try {
    devices::SerialPort::open("/nonexistent/ttyX", line(9600, 1));
    FAIL("opened a missing path");
  } catch (const antkit::kernel::InputError& e) {
    CHECK(e.where() == "port");
    CHECK(std::string(e.what()).find("/nonexistent/ttyX") != std::string::npos);
  }
  const antkit::test::ScratchDir dir("not-a-tty");
  const std::string file = (dir / "not-a-tty").string();
  std::ofstream(file) << "x";
  CHECK_THROWS_AS(devices::SerialPort::open(file, line(9600, 1)), antkit::kernel::InputError);
}

TEST_CASE("read_line assembles lines across writes and splits several in one write", "[devices]") {
  auto pty = devices::Pty::open();
  auto port = devices::SerialPort::open(pty.slave_path(), line(9600, 2));
  std::thread writer([&pty] {
    for (const char c : std::string("n,1,2,3\r\n")) {
      send(pty, std::string(1, c));
      std::this_thread::sleep_for(1ms);
    }
  });
  auto r = port.read_line(1000ms);
  writer.join();
  CHECK(r.complete);
  CHECK(r.bytes == "n,1,2,3\r\n");
  send(pty, "d\r\nh,5,6\r\nlast");
  r = port.read_line(200ms);
  CHECK((r.complete && r.bytes == "d\r\n"));
  r = port.read_line(200ms);
  CHECK((r.complete && r.bytes == "h,5,6\r\n"));
  // A timeout hands over the partial bytes (consumed) and says it is not complete.
  r = port.read_line(30ms);
  CHECK(!r.complete);
  CHECK(r.bytes == "last");
  CHECK(port.buffered() == 0);
}

TEST_CASE("a firmware's lines end at CR or LF, and empty lines are skipped", "[devices]") {
  auto pty = devices::Pty::open();
  auto port = devices::SerialPort::open(pty.slave_path(), line(115200, 1));
  // What the client sends arrives at the master: commands ended by CR, LF or CR LF.
  port.write_all("N\rD,1,2\n\r\n\rH\r\n", 100ms);
  auto& master = pty.master();
  std::vector<std::string> got;
  for (int i = 0; i < 3; ++i) {
    const auto r = master.read_line(200ms, LineEnd::CrOrLf);
    REQUIRE(r.complete);
    got.push_back(r.bytes);
  }
  CHECK(got == std::vector<std::string>{"N\r", "D,1,2\n", "H\r\n"});
  CHECK(!master.read_line(20ms, LineEnd::CrOrLf).complete);
  // A robot's reply ends at LF only: a lone CR stays inside the line.
  send(pty, "a\rb\r\n");
  const auto r = port.read_line(200ms);
  CHECK((r.complete && r.bytes == "a\rb\r\n"));
}

TEST_CASE("an over-long line is cut, the rest dropped, and the next line comes through",
          "[devices]") {
  auto pty = devices::Pty::open();
  auto port = devices::SerialPort::open(pty.slave_path(), line(9600, 2), 16);
  send(pty, std::string(40, 'x') + "\r\nd\r\n");
  auto r = port.read_line(200ms);
  CHECK(r.overflow);
  CHECK(!r.complete);
  CHECK(r.bytes.size() == 16);
  CHECK(port.buffered() <= 16 + 512);
  r = port.read_line(200ms);
  CHECK((r.complete && r.bytes == "d\r\n"));
}

TEST_CASE("a hang-up is a disconnect, for reads and writes", "[devices]") {
  // (Linux drops what the slave had not yet read when the master closes, so a line is only safe
  // once read: the link reads each reply before it sends the next command.)
  auto pty = devices::Pty::open();
  auto port = devices::SerialPort::open(pty.slave_path(), line(9600, 2));
  send(pty, "d\r\n");
  const auto r = port.read_line(200ms);
  CHECK((r.complete && r.bytes == "d\r\n"));
  pty.hang_up();
  try {
    port.read_line(200ms);
    FAIL("read after a hang-up");
  } catch (const LinkError& e) {
    CHECK(e.kind() == LinkError::Kind::Disconnected);
  }
  try {
    port.write_all("N\r", 100ms);
    FAIL("wrote after a hang-up");
  } catch (const LinkError& e) {
    CHECK(e.kind() == LinkError::Kind::Disconnected);
  }
}

TEST_CASE("a stop signal interrupts a wait", "[devices]") {
  auto pty = devices::Pty::open();
  auto port = devices::SerialPort::open(pty.slave_path(), line(9600, 2));
  devices::StopSignals::Scope scope;
  const pthread_t reader = ::pthread_self();
  std::thread t([reader] {
    std::this_thread::sleep_for(30ms);
    ::pthread_kill(reader, SIGINT);
  });
  const auto start = std::chrono::steady_clock::now();
  try {
    port.read_line(5000ms);
    FAIL("no interruption");
  } catch (const LinkError& e) {
    CHECK(e.kind() == LinkError::Kind::Interrupted);
  }
  t.join();
  CHECK(std::chrono::steady_clock::now() - start < 2000ms);
  CHECK(devices::StopSignals::signal() == SIGINT);
  devices::StopSignals::reset();
  CHECK(!devices::StopSignals::requested());
}

TEST_CASE("flush_input drops what was received", "[devices]") {
  auto pty = devices::Pty::open();
  auto port = devices::SerialPort::open(pty.slave_path(), line(9600, 2));
  send(pty, "junk\r\nmore junk");
  std::this_thread::sleep_for(20ms);
  port.flush_input();
  CHECK(port.buffered() == 0);
  send(pty, "d\r\n");
  const auto r = port.read_line(200ms);
  CHECK((r.complete && r.bytes == "d\r\n"));
}

TEST_CASE("any byte stream, in any chunks, comes out as the same lines", "[devices][property]") {
  auto pty = devices::Pty::open();
  auto port = devices::SerialPort::open(pty.slave_path(), line(115200, 1), 4096);
  rc::prop("read_line(Lf) re-cuts the stream at its LFs", [&] {
    const auto bytes = *rc::gen::container<std::string>(rc::gen::inRange<char>(1, 127));
    const std::string stream = bytes + "\n";
    std::size_t at = 0;
    while (at < stream.size()) {
      const auto n = *rc::gen::inRange<std::size_t>(1, stream.size() - at + 1);
      send(pty, std::string_view(stream).substr(at, n));
      at += n;
    }
    std::string joined;
    while (joined.size() < stream.size()) {
      const auto r = port.read_line(500ms);
      RC_ASSERT(r.complete);
      RC_ASSERT(r.bytes.back() == '\n');
      RC_ASSERT(r.bytes.find('\n') == r.bytes.size() - 1);
      joined += r.bytes;
    }
    RC_ASSERT(joined == stream);
  });
}

// ---- the port held exclusively (issue 26: one process per robot) ----
#include <antkit/devices/emulator.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <atomic>

TEST_CASE("a second open of a held pty is refused: port busy, with the holder's PID", "[devices]") {
  auto pty = devices::Pty::open();
  auto first = devices::SerialPort::open(pty.slave_path(), line(9600, 2));
  // The OFD lock is per open, so a second open in the same process conflicts too.
  try {
    (void)devices::SerialPort::open(pty.slave_path(), line(9600, 2));
    FAIL("opened twice");
  } catch (const antkit::kernel::InputError& e) {
    const std::string what = e.what();
    INFO(what);
    CHECK(e.where() == "port");
    CHECK(what.find("port busy") != std::string::npos);
    CHECK(what.find("held by process " + std::to_string(::getpid())) != std::string::npos);
  }
  // The first open still works, and once it is closed the port is free again.
  send(pty, "d\r\n");
  CHECK(first.read_line(500ms).bytes == "d\r\n");
  first.close();
  auto again = devices::SerialPort::open(pty.slave_path(), line(9600, 2));
  CHECK(again.fd() >= 0);
}

TEST_CASE("a second TCP client of serve_tcp cannot share the session", "[devices]") {
  auto listener =
      devices::TcpListener::listen(devices::parse_tcp_endpoint("127.0.0.1:0", "test", true));
  const std::string spec = listener.port_spec();
  devices::FirmwareEmulator emulator(
      devices::RobotKind::Khepera,
      antkit::geometry::build_arena_spec("circle:d=8").arena.walls_fx());
  std::atomic<bool> stop{false};
  std::thread serving([&] { emulator.serve(listener, &stop, false); });
  const auto ask = [](devices::SerialPort& port, std::string_view command) {
    port.write_all(command, 1000ms);
    return port.read_line(5000ms).bytes;
  };
  {
    auto first = devices::SerialPort::open(spec, devices::LineSettings{});
    CHECK(ask(first, "D,1,1\r") == "d\r\n"); // the first client's session is under way
    // While it is connected, a second client is refused at once.
    try {
      (void)devices::SerialPort::open(spec, devices::LineSettings{});
      FAIL("a second client connected");
    } catch (const LinkError& e) {
      CHECK(e.kind() == LinkError::Kind::Disconnected);
      CHECK(std::string(e.what()).find("connection refused") != std::string::npos);
    }
    CHECK(ask(first, "E\r") == "e,1,1\r\n"); // its session is untouched
  }
  // The first has gone: the next client is the next session, from the start.
  bool served = false;
  for (int i = 0; i < 200 && !served; ++i) {
    try {
      auto next = devices::SerialPort::open(spec, devices::LineSettings{});
      CHECK(ask(next, "E\r") == "e,0,0\r\n");
      served = true;
    } catch (const LinkError&) { // the emulator has not yet seen the first one go
      std::this_thread::sleep_for(10ms);
    }
  }
  CHECK(served);
  stop = true;
  serving.join();
  CHECK(emulator.sessions() == 2);
}

#include <sys/stat.h>
#include <sys/wait.h>

TEST_CASE("TIOCEXCL: a non-root second open is EBUSY, said as port busy, and close() frees the pty",
          "[devices]") {
  // Root bypasses TIOCEXCL: the check runs as an unprivileged user (nobody) in a child process when
  // the test runs as root, as itself otherwise. Exit codes say what failed.
  auto pty = devices::Pty::open();
  pty.close_slave_keeper(); // the master alone keeps the pty, as a serving emulator does
  const std::string path = pty.slave_path();
  if (::geteuid() == 0) ::chmod(path.c_str(), 0666);
  const pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) ::_exit(10);
    try {
      auto first = devices::SerialPort::open(path, line(9600, 2));
      try {
        (void)devices::SerialPort::open(path, line(9600, 2));
        ::_exit(11); // opened twice
      } catch (const antkit::kernel::InputError& e) {
        const std::string what = e.what();
        if (what.find("port busy") == std::string::npos) ::_exit(12);
        if (what.find("held by process " + std::to_string(::getpid())) == std::string::npos)
          ::_exit(13);
      }
      first.close(); // clears TIOCEXCL, which a pty slave would otherwise keep
      auto again = devices::SerialPort::open(path, line(9600, 2));
    } catch (...) {
      ::_exit(14);
    }
    ::_exit(0);
  }
  int status = 0;
  REQUIRE(::waitpid(pid, &status, 0) == pid);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
}
