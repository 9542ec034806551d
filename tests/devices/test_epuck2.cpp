// The e-puck2 in binary mode (issue 43): its codec's exact bytes, its firmware emulator's byte
// stream (PROTOCOLS.md, "e-puck (advanced sercom, binary mode)"), and the record loop over a real
// pseudo-terminal and TCP, with its framing faults, its safe stop without an acknowledgement, and
// the replay of every byte.
#include "emulated_robot.hpp"

#include <antkit/devices/controllers.hpp>
#include <antkit/devices/epuck2.hpp>
#include <antkit/devices/link.hpp>
#include <antkit/devices/log.hpp>
#include <antkit/devices/odometry.hpp>
#include <antkit/devices/record_loop.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <chrono>
#include <filesystem>
#include <functional>
#include <thread>

namespace devices = antkit::devices;
namespace epuck2 = antkit::devices::epuck2;
using antkit::test::lines_of;
using antkit::test::OnPty;
using antkit::test::TempDir;
using antkit::test::write_lines;

namespace {

std::string bytes(std::initializer_list<int> v) {
  std::string out;
  for (const int b : v) out += static_cast<char>(b);
  return out;
}

epuck2::Emulator make_emulator(devices::EmulatorOptions o = {}) {
  return epuck2::Emulator(antkit::geometry::build_arena_spec("circle:d=8").arena.walls_fx(), o);
}

class Epuck2OnPty : public OnPty<epuck2::Emulator> {
public:
  explicit Epuck2OnPty(devices::EmulatorOptions o = {})
      : OnPty(antkit::geometry::build_arena_spec("circle:d=8").arena.walls_fx(), o) {}
};

class Epuck2OnTcp {
public:
  explicit Epuck2OnTcp(devices::EmulatorOptions o = {})
      : listener_(
            devices::TcpListener::listen(devices::parse_tcp_endpoint("127.0.0.1:0", "test", true))),
        emulator_(make_emulator(o)) {
    thread_ = std::thread([this] { emulator_.serve(listener_, &stop_, false); });
  }
  ~Epuck2OnTcp() {
    stop_ = true;
    thread_.join();
  }
  [[nodiscard]] std::string port() const { return listener_.port_spec(); }

private:
  devices::TcpListener listener_;
  epuck2::Emulator emulator_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

devices::RecordOptions options(const std::string& port, std::int64_t steps, const std::string& out,
                               const std::string& device = "epuck2") {
  auto o = antkit::test::record_options(devices::RobotKind::Epuck, port, "buffon", {{"visit", 1}},
                                        steps, out);
  o.device = device;
  o.link.tries = 8;
  o.link.timeout = std::chrono::milliseconds(200);
  // The resync's read ends after 50 ms of quiet: the emulator's banner comes within it even on a
  // loaded machine.
  o.link.backoff_max = std::chrono::milliseconds(50);
  return o;
}

} // namespace

TEST_CASE("epuck2 codec: the exact request bytes, little-endian, the 0 at the end", "[devices]") {
  // [-'D' l r][-'N'][-'Q'][0]; -'D' = 0xBC, -'N' = 0xB2, -'Q' = 0xAF.
  CHECK(epuck2::step_sequence(300, -2) == bytes({0xBC, 0x2C, 0x01, 0xFE, 0xFF, 0xB2, 0xAF, 0x00}));
  // Clamped at +-1100 (MOTOR_SPEED_LIMIT): 1100 = 0x044C.
  CHECK(epuck2::step_sequence(5000, -5000) ==
        bytes({0xBC, 0x4C, 0x04, 0xB4, 0xFB, 0xB2, 0xAF, 0x00}));
  CHECK(epuck2::start_sequence() == bytes({0xB0, 0, 0, 0, 0, 0xAF, 0}));
  CHECK(epuck2::stop_sequence() == bytes({0xBC, 0, 0, 0, 0, 0xBB, 0}));
  CHECK(epuck2::resync_bytes() == std::string(36, '\0'));
  CHECK(epuck2::request('D') == static_cast<char>(0xBC));
  CHECK(epuck2::request('a') == static_cast<char>(0x9F));
}

TEST_CASE("epuck2 codec: replies are validated by size and range", "[devices]") {
  std::string reply;
  for (int i = 0; i < 8; ++i) reply += bytes({i * 100 & 0xFF, (i * 100) >> 8});
  reply += bytes({0xFF, 0xFF, 0x10, 0x00}); // counters -1, 16
  const auto d = epuck2::decode_step(reply);
  REQUIRE(d);
  CHECK(d.value->proximity.raw[7] == 700);
  CHECK(d.value->left == -1);
  CHECK(d.value->right == 16);
  CHECK_FALSE(epuck2::decode_step(reply.substr(0, 19)));
  CHECK_FALSE(epuck2::decode_step(reply + "x"));
  // A reading of 4096 or more is not a reading: text where binary was expected.
  CHECK_FALSE(epuck2::decode_step(std::string(epuck2::kBanner).substr(0, 20)));
  std::string high = reply;
  high[1] = 0x10;
  const auto bad = epuck2::decode_step(high);
  REQUIRE_FALSE(bad);
  CHECK(bad.error.column == 1);
  const auto pair = epuck2::decode_pair(bytes({0x00, 0x80, 0x01, 0x00}));
  REQUIRE(pair);
  CHECK(pair.value->left == -32768);
  CHECK(pair.value->right == 1);
  CHECK_FALSE(epuck2::decode_pair("abc"));
  // The 16-bit counters unwrap into a running count.
  CHECK(epuck2::unwrap(32767, -32768) == 32768);
  CHECK(epuck2::unwrap(65535, 0) == 65536);
  CHECK(epuck2::unwrap(-3, 5) == 5);
  CHECK(epuck2::unwrap(0, -10) == -10);
}

TEST_CASE("epuck2 emulator: one byte stream, binary sequences and ASCII lines, as the firmware",
          "[devices]") {
  auto emu = make_emulator();
  // The banner first, then the sequence's reply; a set-only sequence gets nothing.
  auto r = emu.feed(bytes({0xBC, 0x64, 0x00, 0x64, 0x00, 0x00}));
  CHECK(r.bytes == epuck2::kBanner);
  // Speeds read back as set; unknown request bytes (0x80, 'x') are skipped.
  r = emu.feed(bytes({0x80, 'x', 0xBB, 0x00}));
  CHECK(r.bytes == bytes({0x64, 0x00, 0x64, 0x00}));
  // No timeout: without its 0 the sequence waits; a 0 among arguments is data.
  r = emu.feed(bytes({0xBC, 0x00, 0x00, 0x05, 0x00, 0xBB}));
  CHECK(r.bytes.empty());
  r = emu.feed(bytes({0x00}));
  CHECK(r.bytes == bytes({0x00, 0x00, 0x05, 0x00}));
  // Batched: -'N' 16 bytes and -'Q' 4, concatenated.
  r = emu.feed(epuck2::step_sequence(0, 0));
  CHECK(r.bytes.size() == 20);
  // ASCII after the 0, CR-only: the e-puck2's V answers two lines.
  r = emu.feed("V\r");
  CHECK(r.bytes == "v,Version 2.0 antkit epuck2 emulator\r\nHW version: FFF7\r\n");
  // ASCII E shows a negative binary speed as 65536 + v.
  r = emu.feed(bytes({0xBC, 0xFE, 0xFF, 0x01, 0x00, 0x00}));
  r = emu.feed("E\r");
  CHECK(r.bytes == "e,65534,1\r\n");
  // CR LF then binary: the LF sends the firmware into its CR/LF skipping, and the next byte starts
  // an ASCII line whatever its value: no binary reply, and at the next CR "z,Command not found".
  r = emu.feed(std::string("E\r\n") + bytes({0xAF, 0x00}));
  CHECK(r.bytes == "e,65534,1\r\n");
  r = emu.feed("\r");
  CHECK(r.bytes == "z,Command not found\r\n");
  // R: nothing (the e-puck2 does not reset).
  CHECK(emu.feed("R\r").bytes.empty());
}

TEST_CASE("epuck2 emulator: paced, an answer waits the command latency and its bytes' time on the "
          "line, and a set-only sequence waits nothing",
          "[devices]") {
  devices::EmulatorOptions o;
  o.pace = true;
  auto emu = make_emulator(o);
  // 115 200 baud 8N1: 10 bit times a byte.
  const auto on_line = [](std::size_t n) {
    return devices::kCommandLatency + std::chrono::microseconds(n * 10 * 1000000 / 115200);
  };
  auto r = emu.feed(bytes({0xBC, 0x64, 0x00, 0x64, 0x00, 0x00})); // the banner only
  CHECK(r.delay == on_line(epuck2::kBanner.size()));
  r = emu.feed(epuck2::step_sequence(0, 0));
  REQUIRE(r.bytes.size() == 20);
  CHECK(r.delay == on_line(20)); // 2 ms + 1736 us
  CHECK(emu.feed(bytes({0xBC, 0x01, 0x00, 0x01, 0x00, 0x00})).delay.count() == 0);
  CHECK(make_emulator().feed(epuck2::step_sequence(0, 0)).delay.count() == 0); // unpaced
}

TEST_CASE("epuck2 emulator: faults per sequence, from its keyed stream", "[devices]") {
  devices::EmulatorOptions o;
  o.faults = devices::parse_faults({"unterminated=1"});
  auto emu = make_emulator(o);
  (void)emu.feed(""); // the banner
  // The 0 is lost: the firmware keeps reading (and loses every 0 here).
  CHECK(emu.feed(bytes({0xBB, 0x00})).bytes.empty());
  CHECK(emu.faults() > 0);
  o.faults = devices::parse_faults({"cut=1"});
  auto cut = make_emulator(o);
  (void)cut.feed("");
  CHECK(cut.feed(epuck2::step_sequence(0, 0)).bytes.size() == 10);
  o.faults = devices::parse_faults({"garbage=1"});
  auto junk = make_emulator(o);
  (void)junk.feed("");
  CHECK(junk.feed(epuck2::step_sequence(0, 0)).bytes.size() == epuck2::kBanner.size() + 20);
  CHECK_THROWS(devices::parse_faults({"unterminated=2"}));
}

TEST_CASE("epuck2 records over a pty in one round trip a step, and the log replays every byte",
          "[devices]") {
  TempDir dir;
  std::uint64_t ascii_hash = 0;
  {
    // The same run on the ASCII e-puck's emulator: the same body, so the same observations.
    antkit::test::EmulatedRobot ascii(devices::RobotKind::Epuck, "circle:d=8");
    const auto s = devices::record(options(ascii.port(), 300, dir.file("ascii.jsonl"), "epuck"));
    REQUIRE(s.completed);
    ascii_hash = s.hash;
  }
  Epuck2OnPty emu;
  const auto log = dir.file("visit1.jsonl");
  const auto s = devices::record(options(emu.port(), 300, log));
  emu.stop();
  CHECK(s.completed);
  CHECK(s.stop == "done");
  CHECK(s.steps == 300);
  CHECK(s.link.retries <= 1); // 0 but on a loaded host (the banner later than the resync's read)
  CHECK(s.safe_stop.stopped);
  CHECK(s.hash == ascii_hash); // the same observations, commands and states as the ASCII e-puck
  // One sequence a step: the identification (a resync, then the ASCII V), the start's resync and
  // counters, then one exchange per step.
  devices::LogReader reader(log);
  CHECK(reader.header().robot == "epuck2");
  CHECK(reader.header().schema == 2);
  devices::LogRecord rec;
  REQUIRE(reader.next(rec));
  for (const auto& e : rec.io)
    UNSCOPED_INFO(devices::printable(e.sent) << " -> " << devices::printable(e.received));
  REQUIRE(rec.io.size() >= 5);
  CHECK(rec.io[0].sent == epuck2::resync_bytes());
  CHECK(rec.io[1].sent == "V\r");
  CHECK(rec.io[1].received == "v,Version 2.0 antkit epuck2 emulator\r\n");
  CHECK(rec.io[2].sent == epuck2::resync_bytes());
  CHECK(rec.io[2].received == "HW version: FFF7\r\n"); // V's second line, read off by the resync
  CHECK(rec.io[3].sent == epuck2::start_sequence());
  CHECK(rec.io.back().sent == epuck2::step_sequence(0, 0));
  CHECK(rec.io.back().received.size() == 20);
  std::string step0;
  for (const auto& e : rec.io) step0 += e.received;
  CHECK(step0.find(epuck2::kBanner) != std::string::npos);
  if (s.link.retries == 0) CHECK(rec.io[0].received == epuck2::kBanner);
  REQUIRE(reader.next(rec));
  CHECK(rec.io.size() == 1);
  const auto r = devices::replay(log);
  CHECK(r.identical);
  CHECK(r.complete);
  CHECK(r.steps == 300);
  CHECK(r.hash == s.hash);

  // Every byte is checked: one reply byte changed (a counter's), one sent byte changed.
  const auto lines = lines_of(log);
  const auto elog = dir.file("edited.jsonl");
  const auto edit = [&](const std::function<void(devices::LogRecord&)>& change) {
    devices::LogReader in(log);
    std::vector<std::string> out{devices::format_header(in.header())};
    devices::LogRecord x;
    while (in.next(x)) {
      if (x.step == 4) change(x);
      out.push_back(devices::format_record(x));
    }
    out.push_back(devices::format_stop(*in.stop()));
    write_lines(elog, out);
  };
  edit([](devices::LogRecord& x) { x.io[0].received[16] ^= 1; });
  const auto received = devices::replay(elog);
  REQUIRE_FALSE(received.identical);
  CHECK(received.first_divergence->step == 4);
  edit([](devices::LogRecord& x) { x.io[0].sent[1] ^= 1; });
  const auto sent = devices::replay(elog);
  REQUIRE_FALSE(sent.identical);
  CHECK(sent.first_divergence->step == 4);
  CHECK(sent.first_divergence->field == "io[0].sent");
  auto edited = lines;
  // A stop record claiming the robot may be moving, when the bytes read it back at 0, 0.
  edited = lines;
  auto& stop = edited.back();
  stop.replace(stop.find("\"done\""), 6, "\"done; robot may be moving: x\"");
  write_lines(elog, edited);
  CHECK_FALSE(devices::replay(elog).identical);
}

TEST_CASE("epuck2: Buffon from two recorded visits, as from the ASCII e-puck's", "[devices]") {
  TempDir dir;
  const auto visits = [&](const std::string& device, auto& emu) {
    std::array<std::string, 2> logs;
    for (std::size_t i = 0; i < 2; ++i) {
      const std::int64_t visit = static_cast<std::int64_t>(i) + 1;
      logs[i] = dir.file(device + std::to_string(visit) + ".jsonl");
      auto o = options(emu.port(), 400, logs[i], device);
      o.controller = devices::make_spec("buffon", 7, {{"visit", visit}}, "test");
      REQUIRE(devices::record(o).completed);
    }
    return devices::buffon_from_logs(logs[0], logs[1], antkit::kernel::Fx::from_ratio(1, 10));
  };
  Epuck2OnPty binary;
  const auto b = visits("epuck2", binary);
  antkit::test::EmulatedRobot ascii(devices::RobotKind::Epuck, "circle:d=8");
  const auto a = visits("epuck", ascii);
  CHECK(b.bc == a.bc);
  CHECK(b.crossings_exact == a.crossings_exact);
  CHECK(b.visit1.points == a.visit1.points);
}

TEST_CASE("epuck2 records over TCP", "[devices]") {
  TempDir dir;
  Epuck2OnTcp emu;
  const auto log = dir.file("tcp.jsonl");
  const auto s = devices::record(options(emu.port(), 200, log));
  CHECK(s.completed);
  CHECK(s.safe_stop.stopped);
  CHECK(s.link.retries <= 1);
  CHECK(devices::replay(log).identical);
}

TEST_CASE("epuck2: identified at connect by its ASCII V, another robot refused with no log",
          "[devices]") {
  TempDir dir;
  SECTION("an ASCII e-puck (its V answers errors to the resync's zeros and V)") {
    antkit::test::EmulatedRobot ascii(devices::RobotKind::Epuck, "circle:d=8");
    const auto log = dir.file("wrong.jsonl");
    auto o = options(ascii.port(), 100, log);
    o.link.tries = 3;
    try {
      (void)devices::record(o);
      FAIL("an ASCII e-puck was taken for an e-puck2");
    } catch (const antkit::kernel::InputError& e) {
      INFO(e.what());
      CHECK(e.where() == "device");
      CHECK(std::string(e.what()).find("to 'V\\r', not as --device epuck2 does") !=
            std::string::npos);
    }
    CHECK(!std::filesystem::exists(log));
    ascii.stop();
    CHECK(ascii.emulator().trail().size() == 1); // never moved
  }
  SECTION("the e-puck2's rule") {
    CHECK(epuck2::identifies("v,Version 2.0 January 2018 GCtronic\r\n"));
    CHECK(epuck2::identifies("v,Version 12.1\r\n"));
    CHECK_FALSE(epuck2::identifies("v,Version 1.2.2 August 2008 GCtronic\r\n")); // e-puck1
    CHECK_FALSE(epuck2::identifies("v,Version x\r\n"));
    CHECK_FALSE(epuck2::identifies("v,Version 2.0\n"));
    CHECK_FALSE(epuck2::identifies("b,0,0\r\n"));
    CHECK_FALSE(epuck2::identifies("HW version: FFF7\r\n"));
  }
  SECTION("a schema-2 log whose V reply is edited diverges") {
    Epuck2OnPty emu;
    const auto log = dir.file("right.jsonl");
    const auto s = devices::record(options(emu.port(), 10, log));
    REQUIRE(s.completed);
    emu.stop();
    CHECK(devices::replay(log).identical);
    auto lines = lines_of(log);
    lines[1].replace(lines[1].find("Version 2.0"), 11, "Version 1.2");
    const auto elog = dir.file("edited.jsonl");
    write_lines(elog, lines);
    const auto r = devices::replay(elog);
    REQUIRE_FALSE(r.identical);
    CHECK(r.first_divergence->step == 0);
  }
}

TEST_CASE("epuck2 survives short replies, leftover bytes, a banner and lost terminators",
          "[devices]") {
  const std::vector<std::vector<std::string>> kinds{
      {"drop=0.03"},
      {"cut=0.03"},
      {"garbage=0.03"},
      {"unterminated=0.03"},
      {"delay=0.01:250"},
      {"drop=0.02", "cut=0.02", "unterminated=0.02", "garbage=0.02"},
      {"drop=0.02", "cut=0.02", "garbage=0.02"}};
  std::vector<std::uint64_t> hashes;
  for (const auto& spec : kinds) {
    INFO(spec.front() << " (" << spec.size() << ")");
    TempDir dir;
    devices::EmulatorOptions eo;
    eo.seed = 3;
    eo.faults = devices::parse_faults(spec);
    Epuck2OnPty emu(eo);
    const auto log = dir.file("faulty.jsonl");
    const auto s = devices::record(options(emu.port(), 150, log));
    emu.stop();
    CHECK(s.completed);
    CHECK(s.safe_stop.stopped);
    CHECK(emu.emulator().faults() > 0);
    CHECK(s.link.retries > 0);
    if (spec.size() == 3) hashes.push_back(s.hash);
    const auto r = devices::replay(log);
    CHECK(r.identical);
    CHECK(r.steps == 150);
  }
  // Faults come from the emulator's keyed stream: the same seed, the same faulty run. Not with
  // delays or lost terminators: the reply a resync ends arrives within the resync's read or after
  // the resend, as the host's load has it (the late-reply ambiguity, device_epuck2.cpp).
  TempDir dir;
  devices::EmulatorOptions eo;
  eo.seed = 3;
  eo.faults = devices::parse_faults(kinds.back());
  Epuck2OnPty emu(eo);
  const auto s = devices::record(options(emu.port(), 150, dir.file("again.jsonl")));
  CHECK(s.completed);
  CHECK(s.hash == hashes.back());
}

TEST_CASE("epuck2: a silent robot ends the run, not read back at 0, 0, and the log says so",
          "[devices]") {
  TempDir dir;
  devices::EmulatorOptions eo;
  eo.faults = devices::parse_faults({"silent=20"});
  Epuck2OnPty emu(eo);
  const auto log = dir.file("silent.jsonl");
  auto o = options(emu.port(), 100, log);
  o.link.tries = 3;
  o.link.timeout = std::chrono::milliseconds(20);
  o.link.stop_within = std::chrono::milliseconds(1000);
  const auto s = devices::record(o);
  CHECK_FALSE(s.completed);
  CHECK(s.kind == devices::StopKind::Link);
  CHECK_FALSE(s.safe_stop.stopped);
  CHECK(s.stop.find(devices::kRobotMayBeMoving) != std::string::npos);
  const auto r = devices::replay(log);
  CHECK(r.identical);
  CHECK(r.complete);
  // The same log claiming a stop read back: caught.
  auto lines = lines_of(log);
  auto& stop = lines.back();
  const auto from = stop.find("\"link: ");
  const auto to = stop.find("\",\"step\"");
  if (from != std::string::npos && to != std::string::npos) {
    stop.replace(from, to - from, "\"link: timeout: x");
    const auto elog = dir.file("edited.jsonl");
    write_lines(elog, lines);
    CHECK_FALSE(devices::replay(elog).identical);
  }
}

TEST_CASE("epuck2 runs the wanderer: its steps and turns in step sequences, and replays",
          "[devices]") {
  TempDir dir;
  Epuck2OnPty emu;
  const auto log = dir.file("wander.jsonl");
  auto o =
      antkit::test::record_options(devices::RobotKind::Epuck, emu.port(), "wander", {}, 60, log);
  o.device = "epuck2";
  const auto s = devices::record(o);
  REQUIRE(s.completed);
  emu.stop();
  const auto& trail = emu.emulator().body().trail();
  CHECK(!(trail.back() == trail.front())); // it moved
  // A move is several sequences in one step; a wait or a stop none.
  devices::LogReader reader(log);
  std::size_t longest = 0;
  for (devices::LogRecord r; reader.next(r);) longest = std::max(longest, r.io.size());
  CHECK(longest > 3);
  const auto r = devices::replay(log);
  CHECK(r.identical);
  CHECK(r.steps == 60);
  // An edited odometry is caught.
  auto lines = lines_of(log);
  const auto at = lines[30].find("\"odo\":[");
  REQUIRE(at != std::string::npos);
  lines[30].insert(at + 7, "1");
  const auto edited = dir.file("edited.jsonl");
  write_lines(edited, lines);
  CHECK_FALSE(devices::replay(edited).identical);
}

TEST_CASE("epuck2 runs every controller the e-puck runs, with the e-puck's observations and "
          "commands, and each log replays",
          "[devices]") {
  // Every controller the serial robots run (controllers.hpp), on the e-puck2 in binary mode and
  // on the ASCII e-puck: the same body, emulator world and seed, so the same observations,
  // commands and controller states step by step; only the bytes differ.
  TempDir dir;
  std::string names(devices::controller_names());
  std::size_t tried = 0;
  for (std::size_t at = 0; at < names.size();) {
    const std::size_t comma = std::min(names.find(", ", at), names.size());
    const std::string controller = names.substr(at, comma - at);
    at = comma + 2;
    INFO(controller);
    const devices::Params params =
        controller == "buffon" ? devices::Params{{"visit", 1}} : devices::Params{};
    std::vector<devices::LogRecord> steps[2];
    for (const bool binary : {true, false}) {
      const auto log = dir.file(controller + (binary ? "-epuck2.jsonl" : "-epuck.jsonl"));
      auto o =
          antkit::test::record_options(devices::RobotKind::Epuck, "", controller, params, 80, log);
      devices::RecordSummary s;
      if (binary) {
        Epuck2OnPty emu;
        o.port = emu.port();
        o.device = "epuck2";
        s = devices::record(o);
      } else {
        antkit::test::EmulatedRobot ascii(devices::RobotKind::Epuck, "circle:d=8");
        o.port = ascii.port();
        s = devices::record(o);
      }
      CHECK(s.completed);
      CHECK(s.safe_stop.stopped);
      const auto r = devices::replay(log);
      CHECK(r.identical);
      CHECK(r.steps == 80);
      devices::LogReader reader(log);
      for (devices::LogRecord rec; reader.next(rec);) steps[binary ? 0 : 1].push_back(rec);
    }
    REQUIRE(steps[0].size() == steps[1].size());
    for (std::size_t i = 0; i < steps[0].size(); ++i) {
      INFO("step " << i);
      CHECK(steps[0][i].obs == steps[1][i].obs);
      CHECK(steps[0][i].cmd == steps[1][i].cmd);
      CHECK(steps[0][i].state == steps[1][i].state);
    }
    ++tried;
  }
  CHECK(tried == 3); // buffon, rs, wander
}

TEST_CASE("epuck2: --watchdog ends a run whose robot went silent before the tries run out",
          "[devices]") {
  TempDir dir;
  devices::EmulatorOptions eo;
  eo.faults = devices::parse_faults({"silent=20"});
  Epuck2OnPty emu(eo);
  const auto log = dir.file("watchdog.jsonl");
  auto o = options(emu.port(), 100, log);
  o.link.tries = 1000; // 1000 x 20 ms: only the watchdog ends it soon
  o.link.timeout = std::chrono::milliseconds(20);
  o.link.watchdog = std::chrono::milliseconds(200);
  o.link.stop_within = std::chrono::milliseconds(300);
  const auto started = std::chrono::steady_clock::now();
  const auto s = devices::record(o);
  const auto took = std::chrono::steady_clock::now() - started;
  CHECK_FALSE(s.completed);
  CHECK(s.kind == devices::StopKind::Link);
  CHECK(s.stop.find("watchdog: no valid reply for") != std::string::npos);
  CHECK_FALSE(s.safe_stop.stopped);
  CHECK(took < std::chrono::seconds(10)); // far below the tries' 20 s
  CHECK(devices::replay(log).identical);
}

TEST_CASE("epuck2: 100 000 steps against the emulator over a pty", "[devices][slow]") {
  TempDir dir;
  Epuck2OnPty emu;
  const auto log = dir.file("long.jsonl");
  const auto t0 = std::chrono::steady_clock::now();
  const auto s = devices::record(options(emu.port(), 100000, log));
  const auto secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  emu.stop();
  WARN("epuck2: 100000 steps in " << secs << " s (" << 100000 / secs << " steps/s)");
  CHECK(s.completed);
  CHECK(s.steps == 100000);
  CHECK(s.safe_stop.stopped);
  const auto r = devices::replay(log);
  CHECK(r.identical);
  CHECK(r.steps == 100000);
}
