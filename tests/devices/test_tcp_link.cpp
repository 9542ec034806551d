// Links over TCP (issue 26): the TCP client behind `--port tcp:HOST:PORT`, the emulators served
// over TCP (serve_tcp, `antkit emulate --listen`), the Khepera in Webots as its own device, and
// runs recorded against a server that behaves as Webots' Khepera relay does (webots_relay.hpp,
// written from PROTOCOLS.md) and against our emulator over TCP, each log replayed.
#include "emulated_robot.hpp"
#include "webots_relay.hpp"

#include <antkit/devices/emulator.hpp>
#include <antkit/devices/protocol.hpp>
#include <antkit/devices/record_loop.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/devices/robot.hpp>
#include <antkit/devices/serial.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <chrono>
#include <filesystem>
#include <netinet/in.h>
#include <sys/socket.h>
#include <thread>

namespace devices = antkit::devices;
using namespace std::chrono_literals;
using antkit::test::TempDir;
using antkit::test::WebotsRelay;
using devices::LineEnd;
using devices::LinkError;
using devices::RobotKind;

namespace {

devices::TcpListener loopback_listener() {
  return devices::TcpListener::listen(devices::parse_tcp_endpoint("127.0.0.1:0", "test", true));
}

// A firmware emulator served over TCP (serve_tcp) from a thread of the test.
class OnTcp {
public:
  OnTcp(RobotKind robot, const std::string& arena, devices::EmulatorOptions options = {})
      : listener_(loopback_listener()),
        emulator_(robot, antkit::geometry::build_arena_spec(arena).arena.walls_fx(), options) {
    thread_ = std::thread([this] { emulator_.serve(listener_, &stop_, false); });
  }
  OnTcp(const OnTcp&) = delete;
  OnTcp& operator=(const OnTcp&) = delete;
  ~OnTcp() { stop(); }
  void stop() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }
  [[nodiscard]] std::string port() const { return listener_.port_spec(); }
  [[nodiscard]] const devices::FirmwareEmulator& emulator() const { return emulator_; }

private:
  devices::TcpListener listener_;
  devices::FirmwareEmulator emulator_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

devices::SerialPort client(const std::string& spec) {
  return devices::SerialPort::open(spec, devices::LineSettings{});
}

// One command and its reply line (the bare "\n" of an unknown command included).
std::string ask(devices::SerialPort& port, std::string_view command) {
  port.write_all(command, 1000ms);
  const auto r = port.read_line(5000ms);
  REQUIRE(r.complete);
  return r.bytes;
}

devices::RecordOptions options_for(RobotKind robot, const std::string& port, std::int64_t steps,
                                   const std::string& out) {
  devices::RecordOptions o;
  o.device = std::string(devices::robot_name(robot));
  o.port = port;
  o.line = devices::describe(robot).line;
  o.controller = devices::make_spec("buffon", 7, {{"visit", 1}}, "test");
  o.steps = steps;
  o.out = out;
  // Generous: a relay step is a real millisecond or two, and the host may be busy.
  o.link.timeout = std::chrono::milliseconds(200);
  o.link.backoff = std::chrono::milliseconds(1);
  o.link.tries = 5;
  return o;
}

} // namespace

TEST_CASE("tcp: specs parse to host and port, and malformed ones are bad input", "[devices]") {
  CHECK(devices::is_tcp_port("tcp:127.0.0.1:10020"));
  CHECK(!devices::is_tcp_port("/dev/ttyUSB0"));
  const auto a = devices::parse_tcp_endpoint("127.0.0.1:10020", "--port", false);
  CHECK(a.host == "127.0.0.1");
  CHECK(a.port == 10020);
  CHECK(a.text() == "127.0.0.1:10020");
  const auto b = devices::parse_tcp_endpoint("[::1]:80", "--port", false);
  CHECK(b.host == "::1");
  CHECK(b.text() == "[::1]:80");
  CHECK(devices::parse_tcp_endpoint("robot-lab.local:1", "--port", false).host ==
        "robot-lab.local");
  CHECK(devices::parse_tcp_endpoint("localhost:0", "--listen", true).port == 0);
  for (const char* bad :
       {"", ":", "host", "host:", ":80", "host:0", "host:65536", "host:80x", "host:-1", "[::1",
        "[::1]80", "[]:80", "::1:80", "a b:80", "host:123456", "[g::1]:80", "ho/st:80"}) {
    INFO(bad);
    CHECK_THROWS_AS(devices::parse_tcp_endpoint(bad, "--port", false), antkit::kernel::InputError);
    CHECK_THROWS_AS(client(std::string("tcp:") + bad), antkit::kernel::InputError);
  }
  try {
    client("tcp:127.0.0.1:99999");
    FAIL("accepted");
  } catch (const antkit::kernel::InputError& e) {
    CHECK(e.where() == "port");
    CHECK(std::string(e.what()).find("1-65535") != std::string::npos);
  }
  // A host that does not resolve is bad input too (.invalid never resolves, RFC 6761).
  CHECK_THROWS_AS(client("tcp:no-such-host.invalid:10020"), antkit::kernel::InputError);
}

TEST_CASE("tcp: the client reads lines across writes and writes to the server", "[devices]") {
  auto listener = loopback_listener();
  auto port = client(listener.port_spec());
  CHECK(port.is_socket());
  auto server = listener.accept(5000ms);
  REQUIRE(server.has_value());
  server->write_all("h,12", 1000ms);
  server->write_all(",34\r", 1000ms);
  server->write_all("\nn,1,2", 1000ms);
  auto r = port.read_line(5000ms);
  CHECK((r.complete && r.bytes == "h,12,34\r\n"));
  server->write_all(",3\r\n", 1000ms);
  r = port.read_line(5000ms);
  CHECK((r.complete && r.bytes == "n,1,2,3\r\n"));
  port.write_all("D,1,2\r", 1000ms);
  const auto c = server->read_line(5000ms, LineEnd::CrOrLf);
  CHECK((c.complete && c.bytes == "D,1,2\r"));
  // flush_input drains a socket (no tty queue to flush).
  server->write_all("junk\r\n", 1000ms);
  server->write_all("b,0,0\r\n", 1000ms);
  CHECK(port.read_line(5000ms).bytes == "junk\r\n");
  std::this_thread::sleep_for(20ms);
  port.flush_input();
  CHECK(port.buffered() == 0);
  server->write_all("d\r\n", 1000ms);
  CHECK(port.read_line(5000ms).bytes == "d\r\n");
}

TEST_CASE("tcp: a peer that closes or resets the connection is a disconnect", "[devices]") {
  SECTION("closed: end of file on read, EPIPE (not SIGPIPE) on write") {
    auto listener = loopback_listener();
    auto port = client(listener.port_spec());
    auto server = listener.accept(5000ms);
    REQUIRE(server.has_value());
    server->close();
    try {
      (void)port.read_line(5000ms);
      FAIL("no disconnect");
    } catch (const LinkError& e) {
      CHECK(e.kind() == LinkError::Kind::Disconnected);
    }
    // Writes to a closed peer end in a reset or EPIPE: Disconnected, and the process lives on.
    bool disconnected = false;
    for (int i = 0; i < 100 && !disconnected; ++i) {
      try {
        port.write_all("N\r", 1000ms);
        std::this_thread::sleep_for(1ms);
      } catch (const LinkError& e) {
        CHECK(e.kind() == LinkError::Kind::Disconnected);
        disconnected = true;
      }
    }
    CHECK(disconnected);
  }
  SECTION("reset: ECONNRESET") {
    auto listener = loopback_listener();
    auto port = client(listener.port_spec());
    auto server = listener.accept(5000ms);
    REQUIRE(server.has_value());
    const linger hard{1, 0}; // close with a RST
    ::setsockopt(server->fd(), SOL_SOCKET, SO_LINGER, &hard, sizeof hard);
    port.write_all("N\r", 1000ms); // unread data at the server makes its close a reset too
    std::this_thread::sleep_for(10ms);
    server->close();
    try {
      (void)port.read_line(5000ms);
      FAIL("no disconnect");
    } catch (const LinkError& e) {
      CHECK(e.kind() == LinkError::Kind::Disconnected);
    }
  }
}

TEST_CASE("tcp: a refused connection is a disconnect that says so", "[devices]") {
  std::string spec;
  {
    auto listener = loopback_listener();
    spec = listener.port_spec();
  } // closed: nothing listens on the port any more
  try {
    client(spec);
    FAIL("connected");
  } catch (const LinkError& e) {
    CHECK(e.kind() == LinkError::Kind::Disconnected);
    CHECK(std::string(e.what()) == spec.substr(4) + ": connection refused");
  }
}

TEST_CASE("khepera-webots: a device of its own, with the relay's units", "[devices]") {
  CHECK(devices::parse_robot("khepera-webots") == RobotKind::KheperaWebots);
  CHECK(devices::robot_name(RobotKind::KheperaWebots) == "khepera-webots");
  CHECK(devices::robot_names().find("khepera-webots") != std::string_view::npos);
  const auto& d = devices::describe(RobotKind::KheperaWebots);
  CHECK(d.speed_max == 10);             // rad/s: Webots' default maxVelocity
  CHECK(d.speed_unit_um_s == 7500);     // 1 rad/s on a 7.5 mm wheel
  CHECK(d.odometry_pulse_nm == 471239); // 100 counts a turn of a 7.5 mm wheel
  CHECK(d.wheel_base_um == 52000);
  CHECK(d.diameter_um == 57000);
  CHECK(d.has_odometry);
  CHECK(d.odometry_read == 'H');
  CHECK(d.odometry_set == 0); // G does nothing on the relay
  const devices::Codec codec(RobotKind::KheperaWebots);
  CHECK_THROWS_AS(codec.set_odometry(0, 0), std::logic_error);
  CHECK(codec.unknown_command_reply("E") == "\n");
  CHECK(codec.safe_stop() == std::vector<std::string>{"D,0,0\r", "L,0,0\r", "L,1,0\r"});
  CHECK(bool(codec.decode_reply("B\r", "b,0,0\r\n")));
  // The three other robots are described as before.
  const auto& k = devices::describe(RobotKind::Khepera);
  CHECK((k.speed_max == 127 && k.speed_full == 10 && k.odometry_set == 'G' &&
         k.odometry_pulse_nm == 80000 && k.line.stop_bits == 2));
}

TEST_CASE("khepera-webots: the emulator answers as the relay does", "[devices]") {
  OnTcp emu(RobotKind::KheperaWebots, "circle:d=8");
  auto port = client(emu.port());
  CHECK(ask(port, "B\r") == "b,0,0\r\n");
  CHECK(ask(port, "E\r") == "\n");           // not in the relay's set
  CHECK(ask(port, "what\r") == "\n");        // an unknown line
  CHECK(ask(port, "D,99,-99\r") == "d\r\n"); // clamped to maxVelocity
  CHECK(ask(port, "D,10,10\r") == "d\r\n");
  for (int k = 0; k < 20; ++k) {
    const auto n = ask(port, "N\r");
    CHECK(n.rfind("n,", 0) == 0);
  }
  const auto h1 = ask(port, "H\r");
  CHECK(h1 != "h,0,0\r\n");
  CHECK(ask(port, "G,0,0\r") == "g\r\n");
  CHECK(ask(port, "H\r") == h1); // G did nothing: the counters are cumulative
  CHECK(ask(port, "L,0,1\r") == "l\r\n");
  // `exit` closes the connection.
  port.write_all("exit\r", 1000ms);
  CHECK_THROWS_AS(port.read_line(5000ms), LinkError);
  // And the relay takes no other client until the world is reset (the next test).
  emu.stop();
  CHECK(emu.emulator().sessions() == 1);
}

TEST_CASE("khepera-webots: the emulator acts on the first command of a read only, as the relay",
          "[devices]") {
  OnTcp emu(RobotKind::KheperaWebots, "circle:d=8");
  auto port = client(emu.port());
  CHECK(ask(port, "D,10,10\r") == "d\r\n");
  // Two commands in one write arrive in one read: the first is answered, the second is lost.
  port.write_all("B\rN\r", 1000ms);
  CHECK(port.read_line(5000ms).bytes == "b,0,0\r\n");
  const auto nothing = port.read_line(300ms);
  CHECK(nothing.bytes.empty()); // no reply to N: it was never acted on
  // N was lost, so the body has not moved: the wheels' counters still read zero.
  CHECK(ask(port, "H\r") == "h,0,0\r\n");
  // One command and its reply, then the next: each is acted on.
  CHECK(ask(port, "N\r").rfind("n,", 0) == 0);
  CHECK(ask(port, "H\r") != "h,0,0\r\n");
  // A read holding D and then N sets the speeds only.
  port.write_all("D,0,0\rN\r", 1000ms);
  CHECK(port.read_line(5000ms).bytes == "d\r\n");
  CHECK(port.read_line(300ms).bytes.empty());
  const auto h = ask(port, "H\r");
  CHECK(ask(port, "N\r").rfind("n,", 0) == 0);
  CHECK(ask(port, "H\r") == h); // stopped: N advanced a control period, the wheels did not turn
  port.close();
  emu.stop();
  CHECK(emu.emulator().trail().size() == 3); // the start, and the two N acted on
}

TEST_CASE("khepera-webots: the emulator accepts one client, once, as the relay", "[devices]") {
  OnTcp emu(RobotKind::KheperaWebots, "circle:d=8");
  auto first = client(emu.port());
  CHECK(ask(first, "B\r") == "b,0,0\r\n");
  // A second client while the first is connected: its connect completes in the backlog, but
  // nothing it sends is read or answered.
  auto second = client(emu.port());
  second.write_all("B\r", 1000ms);
  CHECK(second.read_line(300ms).bytes.empty());
  CHECK(ask(first, "B\r") == "b,0,0\r\n"); // the first is served as before
  second.close();
  // The first leaves; a client that comes after it is not served either (the relay accepts once,
  // when the simulation starts).
  first.close();
  std::this_thread::sleep_for(100ms);
  bool served = false;
  try {
    auto again = client(emu.port());
    again.write_all("B\r", 1000ms);
    served = again.read_line(300ms).complete;
  } catch (const LinkError&) {
    // refused outright: not served either
  }
  CHECK(!served);
  emu.stop();
  CHECK(emu.emulator().sessions() == 1);
  CHECK(emu.emulator().commands() == 2);
}

TEST_CASE("khepera-webots: the record loop (one command, then its reply) runs against the strict "
          "emulator, and a second run is not served",
          "[devices]") {
  TempDir dir;
  OnTcp emu(RobotKind::KheperaWebots, "circle:d=8");
  const auto log = dir.file("first.jsonl");
  const auto s = devices::record(options_for(RobotKind::KheperaWebots, emu.port(), 100, log));
  INFO(s.stop);
  CHECK(s.completed);
  CHECK(s.link.retries == 0);
  CHECK(s.safe_stop.stopped);
  // A second run: connected, never answered -- a link failure, the log says so.
  auto o = options_for(RobotKind::KheperaWebots, emu.port(), 100, dir.file("second.jsonl"));
  o.link.timeout = 50ms;
  o.link.tries = 2;
  o.link.stop_within = 300ms;
  const auto t = devices::record(o);
  CHECK(t.steps == 0);
  CHECK(t.kind == devices::StopKind::Link);
  CHECK(!t.safe_stop.stopped);
  emu.stop();
  CHECK(emu.emulator().sessions() == 1);
  const auto r = devices::replay(log);
  CHECK(r.identical);
  CHECK(r.hash == s.hash);
}

TEST_CASE("identification: a robot that is not the device asked for is refused at connect, with "
          "nothing but the version request sent and no log",
          "[devices]") {
  TempDir dir;
  SECTION("--device khepera against the Webots relay (its b,0,0)") {
    WebotsRelay relay;
    const auto log = dir.file("wrong.jsonl");
    try {
      (void)devices::record(options_for(RobotKind::Khepera, relay.port_spec(), 100, log));
      FAIL("the relay was taken for a Khepera");
    } catch (const antkit::kernel::InputError& e) {
      CHECK(e.where() == "device");
      const std::string what = e.what();
      INFO(what);
      CHECK(what.find("the robot answers 'b,0,0\\r\\n' to 'B\\r', not as --device khepera does") !=
            std::string::npos);
      CHECK(what.find("it answers as --device khepera-webots does") != std::string::npos);
    }
    CHECK(!std::filesystem::exists(log));
    CHECK(relay.reads() == std::vector<std::string>{"B\r"}); // nothing else: never driven
  }
  SECTION("--device khepera-webots against a Khepera") {
    OnTcp emu(RobotKind::Khepera, "circle:d=8");
    const auto log = dir.file("wrong.jsonl");
    try {
      (void)devices::record(options_for(RobotKind::KheperaWebots, emu.port(), 100, log));
      FAIL("a Khepera was taken for the relay");
    } catch (const antkit::kernel::InputError& e) {
      CHECK(std::string(e.what()).find("answers 'b,5.02,5.01\\r\\n' to 'B\\r', not as --device "
                                       "khepera-webots does") != std::string::npos);
      CHECK(std::string(e.what()).find("--device khepera does") != std::string::npos);
    }
    CHECK(!std::filesystem::exists(log));
    emu.stop();
    CHECK(emu.emulator().commands() == 1);
    CHECK(emu.emulator().trail().size() == 1); // never moved
  }
  SECTION("--device epuck against the relay, which does not know V") {
    WebotsRelay relay;
    const auto log = dir.file("wrong.jsonl");
    try {
      (void)devices::record(options_for(RobotKind::Epuck, relay.port_spec(), 100, log));
      FAIL("the relay was taken for an e-puck");
    } catch (const antkit::kernel::InputError& e) {
      CHECK(std::string(e.what()).find("answers '\\n' to 'V\\r', not as --device epuck does") !=
            std::string::npos);
    }
    CHECK(!std::filesystem::exists(log));
    for (const auto& read : relay.reads()) CHECK(read == "V\r"); // its tries, nothing else
  }
  SECTION("the right device: the identification is step 0's first exchange, and replay checks "
          "it") {
    WebotsRelay relay;
    const auto log = dir.file("right.jsonl");
    const auto s =
        devices::record(options_for(RobotKind::KheperaWebots, relay.port_spec(), 20, log));
    CHECK(s.completed);
    CHECK(relay.reads().front() == "B\r");
    auto lines = antkit::test::lines_of(log);
    REQUIRE(lines.size() == 22);
    CHECK(lines[0].rfind("{\"schema\":2,", 0) == 0);
    CHECK(lines[1].find("\"io\":[[\"B\\r\",\"b,0,0\\r\\n\",") != std::string::npos);
    CHECK(devices::replay(log).identical);
    // A reply that identifies another robot diverges there.
    const auto edited = dir.file("edited.jsonl");
    auto copy = lines;
    copy[1].replace(copy[1].find("b,0,0"), 5, "b,5.02,5.01");
    antkit::test::write_lines(edited, copy);
    const auto r = devices::replay(edited);
    CHECK(!r.identical);
    REQUIRE(r.first_divergence);
    CHECK(r.first_divergence->step == 0);
    CHECK(r.first_divergence->field == "io[0].received");
    // A schema-2 log without its identification diverges at its first exchange.
    copy = lines;
    const auto at = copy[1].find("[\"B\\r\"");
    copy[1].erase(at, copy[1].find(']', at) + 2 - at);
    antkit::test::write_lines(edited, copy);
    const auto missing = devices::replay(edited);
    CHECK(!missing.identical);
    REQUIRE(missing.first_divergence);
    CHECK(missing.first_divergence->field == "io[0].sent");
    // The same log declared schema 1 (before the identification) replays without it.
    copy[0].replace(0, 11, "{\"schema\":1");
    antkit::test::write_lines(edited, copy);
    CHECK(devices::replay(edited).identical);
  }
}

TEST_CASE("the relay test server: one command per read, one client once", "[devices]") {
  WebotsRelay relay;
  auto port = client(relay.port_spec());
  CHECK(ask(port, "B\r") == "b,0,0\r\n");
  CHECK(ask(port, "G,5,5\r") == "g\r\n");
  CHECK(ask(port, "H\r") == "h,0,0\r\n"); // G set nothing
  CHECK(ask(port, "X\r") == "\n");
  // Two commands in one write arrive in one read: only the first is acted on.
  port.write_all("B\rN\r", 1000ms);
  CHECK(port.read_line(5000ms).bytes == "b,0,0\r\n");
  CHECK(ask(port, "H\r") == "h,0,0\r\n"); // the next line answers H: N was lost
  CHECK(ask(port, "N\r") == "n,0,0,0,0,0,0,0,0\r\n");
  // A second client's connect completes in the backlog, but it is never accepted nor served.
  auto second = client(relay.port_spec());
  CHECK(ask(port, "B\r") == "b,0,0\r\n");
  CHECK(relay.accepted() == 1);
}

TEST_CASE("tcp: record drives the emulator served over TCP, and the log replays", "[devices]") {
  TempDir dir;
  OnTcp emu(RobotKind::Khepera, "circle:d=8");
  const auto log = dir.file("visit1.jsonl");
  const auto s = devices::record(options_for(RobotKind::Khepera, emu.port(), 300, log));
  CHECK(s.completed);
  CHECK(s.steps == 300);
  emu.stop();
  const auto r = devices::replay(log);
  CHECK(r.identical);
  CHECK(r.steps == 300);
  CHECK(r.hash == s.hash);
}

// Waits for the record loop's H baseline (odometry_set == 0: no G sent), in
// devices/src/record_loop.cpp.
TEST_CASE("khepera-webots: record against the relay and against the emulator, both replay",
          "[devices]") {
  TempDir dir;
  SECTION("the relay test server") {
    WebotsRelay relay;
    const auto log = dir.file("relay.jsonl");
    const auto s =
        devices::record(options_for(RobotKind::KheperaWebots, relay.port_spec(), 300, log));
    INFO(s.stop);
    CHECK(s.completed);
    CHECK(s.steps == 300);
    // Every read the relay acted on held one command: the adapter waits for each reply.
    for (const auto& read : relay.reads()) {
      INFO(read);
      CHECK(read.find('\r') == read.size() - 1);
      CHECK(read[0] != 'G'); // no counter reset is sent: it would do nothing
    }
    const auto r = devices::replay(log);
    INFO((r.first_divergence ? r.first_divergence->field : std::string()));
    CHECK(r.identical);
    CHECK(r.steps == 300);
    CHECK(r.hash == s.hash);
  }
  SECTION("the emulator over TCP") {
    OnTcp emu(RobotKind::KheperaWebots, "circle:d=8");
    const auto log = dir.file("emulator.jsonl");
    const auto s = devices::record(options_for(RobotKind::KheperaWebots, emu.port(), 300, log));
    INFO(s.stop);
    CHECK(s.completed);
    CHECK(s.steps == 300);
    emu.stop();
    const auto& trail = emu.emulator().trail();
    REQUIRE(trail.size() >= 300);
    CHECK(!(trail.back() == trail.front()));
    const auto r = devices::replay(log);
    INFO((r.first_divergence ? r.first_divergence->field : std::string()));
    CHECK(r.identical);
    CHECK(r.steps == 300);
    CHECK(r.hash == s.hash);
  }
}
