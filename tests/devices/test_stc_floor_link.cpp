// The marker-floor robot on its link (issue 14): the codec, the emulator answering over a real
// pseudo-terminal, recording through it, and replaying the log.
#include "emulated_robot.hpp"

#include <antkit/devices/replay.hpp>
#include <antkit/devices/stc_floor/link.hpp>
#include <antkit/devices/stc_floor/record.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/stc/world.hpp>
#include <catch2/catch.hpp>
#include <fstream>
#include <functional>
#include <rapidcheck/catch.h>

namespace devices = antkit::devices;
namespace sf = antkit::devices::stc_floor;
namespace stc = antkit::stc;
using antkit::kernel::Occupancy;
using antkit::kernel::OccupancyGrid;
using antkit::test::TempDir;

namespace {

// The floor emulator serving a real pty from a thread of the test.
using FloorOnPty = antkit::test::OnPty<sf::FloorEmulator>;

OccupancyGrid board() {
  OccupancyGrid map(10, 8, Occupancy::Free);
  map[{4, 2}] = map[{5, 2}] = map[{4, 3}] = map[{5, 3}] = Occupancy::Blocked;
  return map;
}

} // namespace

TEST_CASE("stc floor link: CRC-32 is IEEE 802.3's", "[devices]") {
  const std::string check = "123456789";
  CHECK(sf::crc32({reinterpret_cast<const std::uint8_t*>(check.data()), check.size()}) ==
        0xCBF43926u);
  CHECK(sf::crc32({}) == 0u);
}

TEST_CASE("stc floor link: the emulator's replies decode and anything else is refused",
          "[devices][property]") {
  sf::FloorEmulator emu(board(), {0, 5}, 1, {}); // heading north, (0, 4) ahead is free
  CHECK(emu.handle("V").bytes == "v,antkit stc-floor emulator 1\r\n");
  CHECK(*sf::decode_forward(emu.handle("F,2000").bytes).value);
  CHECK(sf::decode_ack(emu.handle("R,1500").bytes, 'r'));
  CHECK(sf::decode_ack(emu.handle("L,0").bytes, 'l'));
  const std::string frame = emu.handle("C,0").bytes;
  const std::size_t eol = frame.find("\r\n") + 2;
  const auto h = sf::decode_frame_header(frame.substr(0, eol));
  REQUIRE(h);
  CHECK(h.value->width == 240);
  CHECK(h.value->bytes == 240 * 240 * 3);
  const auto img = sf::decode_frame(*h.value, std::string_view(frame).substr(eol));
  REQUIRE(img);
  CHECK(img.value->pixels.size() == h.value->bytes);
  // One flipped byte of the frame: the CRC catches it.
  std::string bad = frame.substr(eol);
  bad[1000] = static_cast<char>(bad[1000] ^ 1);
  CHECK_FALSE(sf::decode_frame(*h.value, bad));
  CHECK_FALSE(sf::decode_frame(*h.value, std::string_view(frame).substr(eol + 1)));
  for (const char* cmd : {"F", "F,-1", "F,60001", "R", "R,1,2", "L,2", "C,2", "X", "f,1", "F,1,"})
    CHECK(emu.handle(cmd).bytes == "z,Protocol error\r\n");
  // Replies: the letter, the arity, the range, CR LF and nothing after it.
  for (const char* line : {"f,2\r\n", "f\r\n", "f,1\n", "f,1\r\nx", "r,1\r\n", "g,1\r\n", ""})
    CHECK_FALSE(sf::decode_forward(line));
  for (const char* line :
       {"c,2,2,12,1\r\n", "c,2,2,11,1\r\n", "c,5000,1,15000,1\r\n", "c,2,2,12,4294967296\r\n",
        "c,2,2,12\r\n", "c,2,2,12,1", "c,2,2,12,-1\r\n"})
    CHECK(bool(sf::decode_frame_header(line)) == (std::string(line) == "c,2,2,12,1\r\n"));
  rc::prop("the header of any frame size and CRC decodes to itself", [] {
    const auto w = *rc::gen::inRange(1, 4097), hh = *rc::gen::inRange(1, 4097);
    const auto crc = *rc::gen::arbitrary<std::uint32_t>();
    const std::string line = "c," + std::to_string(w) + "," + std::to_string(hh) + "," +
                             std::to_string(3 * std::int64_t{w} * hh) + "," + std::to_string(crc) +
                             "\r\n";
    const auto d = sf::decode_frame_header(line);
    RC_ASSERT(d);
    RC_ASSERT(d.value->width == w && d.value->height == hh && d.value->crc == crc);
  });
}

namespace {

// A marker-floor run from sub-cell 0,0 over `port`. A fault-free robot: a generous timeout keeps a
// loaded machine (the sanitizer build renders frames slowly) from adding faults of its own; the
// tour must be the simulated one.
devices::RecordOptions floor_options(const std::string& controller, const std::string& port,
                                     const std::string& out) {
  devices::RecordOptions o;
  o.device = "stc-floor";
  o.controller.name = controller;
  o.port = port;
  o.device_options.set("start", stc::SubCell{0, 0});
  o.out = out;
  o.link.timeout = std::chrono::milliseconds(3000);
  return o;
}

} // namespace

TEST_CASE("stc floor link: a recorded run over a pty is the simulated tour and replays",
          "[devices]") {
  TempDir dir;
  const auto map = board();
  for (const auto variant : {stc::Variant::AntEdge, stc::Variant::Ant}) {
    INFO(stc::variant_name(variant));
    FloorOnPty robot(map, stc::SubCell{0, 0}, 1, sf::FloorOptions{});
    const auto name = std::string(stc::variant_name(variant));
    const auto o = floor_options(name, robot.port(), dir.file(name + ".jsonl"));
    const auto s = devices::record(o);
    robot.stop();
    CHECK(s.stop == "done");
    CHECK(s.kind == devices::StopKind::Done);
    CHECK(s.succeeded());
    REQUIRE(sf::tour_of(s));
    CHECK(sf::tour_of(s)->closed);
    CHECK(sf::tour_of(s)->returned_to_start);
    CHECK(s.safe_stop.complete);
    CHECK(s.safe_stop.failure.empty());
    const auto sim = stc::run_stc(map, {0, 0}, variant);
    CHECK(sf::tour_of(s)->path == sim.path);
    CHECK(stc::tour_hash(map.width(), map.height(), sf::tour_of(s)->path) == sim.hash);
    CHECK(robot.emulator().world().path() == sim.path);
    CHECK(robot.emulator().world().repeats() == 0);
    CHECK(sf::tour_of(s)->covered == sim.reachable_subcells);
    CHECK(sf::tour_of(s)->repeats == 0);
    const auto r = devices::replay(o.out);
    CHECK(r.identical);
    CHECK(r.steps == s.steps);
    CHECK(r.hash == s.hash);
    REQUIRE(r.stop);
    CHECK(r.stop->reason == "done");
  }
}

TEST_CASE("stc floor link: an edited log is caught at the edited step and field", "[devices]") {
  TempDir dir;
  const auto map = board();
  FloorOnPty robot(map, stc::SubCell{0, 0}, 1, sf::FloorOptions{});
  const auto o = floor_options("ant-edge", robot.port(), dir.file("floor.jsonl"));
  REQUIRE(sf::tour_of(devices::record(o))->closed);
  robot.stop();
  const auto lines = antkit::test::lines_of(o.out);
  struct Edit {
    std::string field;
    std::function<void(devices::LogRecord&)> apply;
  };
  const std::vector<Edit> edits{
      {"cmd[1]", [](devices::LogRecord& r) { r.cmd[1] ^= 1; }},
      {"state", [](devices::LogRecord& r) { r.state ^= 1; }},
      // What the robot saw: every sub-cell around it covered, no way on; the recorded decision
      // was a move (the tour does not close at step 20).
      {"cmd[0]", [](devices::LogRecord& r) { r.obs = {0, 0xFFF, 0, 0, 0, 0}; }},
      {"odo[0]", [](devices::LogRecord& r) { r.odo[0] += 1; }},
      {"io[",
       [](devices::LogRecord& r) {
         for (auto& ex : r.io)
           if (ex.sent[0] == 'C') ex.received = "c,2,2,13,1\r\n";
       }},
      // Every byte sent: a frame asked for in a mode the robot does not have, the LEDs lit for a
      // time the header does not give, a move sent twice, a move's reply that is not one.
      {"io[0].sent", [](devices::LogRecord& r) { r.io[0].sent = "C,2\r"; }},
      {"io[",
       [](devices::LogRecord& r) {
         for (auto& ex : r.io)
           if (ex.sent[0] == 'F') ex.sent = "F,1999\r";
       }},
      {"io[",
       [](devices::LogRecord& r) {
         for (std::size_t i = 0; i < r.io.size(); ++i)
           if (r.io[i].sent[0] == 'F') {
             r.io.insert(r.io.begin() + static_cast<std::ptrdiff_t>(i), r.io[i]);
             break;
           }
       }},
      {"io[", [](devices::LogRecord& r) {
         for (auto& ex : r.io)
           if (ex.sent[0] == 'F') ex.received = "f,7\r\n";
       }}};
  for (const auto& edit : edits) {
    INFO(edit.field);
    devices::LogReader reader(o.out);
    devices::LogRecord rec;
    for (int i = 0; i <= 20; ++i) REQUIRE(reader.next(rec));
    REQUIRE(rec.step == 20);
    bool moves = false;
    for (const auto& ex : rec.io) moves = moves || ex.sent[0] == 'F';
    REQUIRE(moves); // step 20 moves (see above): the edits of F have something to edit
    REQUIRE(rec.io[0].sent[0] == 'C');
    edit.apply(rec);
    auto edited = lines;
    edited[21] = devices::format_record(rec);
    const auto path = dir.file("edited.jsonl");
    antkit::test::write_lines(path, edited);
    const auto r = devices::replay(path);
    CHECK_FALSE(r.identical);
    CHECK(r.steps == 20);
    REQUIRE(r.first_divergence);
    CHECK(r.first_divergence->step == 20);
    CHECK(r.first_divergence->field.rfind(edit.field, 0) == 0);
  }
}

TEST_CASE("stc floor link: a robot that does not answer ends the run with its reason",
          "[devices]") {
  TempDir dir;
  devices::Pty pty = devices::Pty::open(); // nobody answers on the master
  devices::RecordOptions o;
  o.device = "stc-floor";
  o.controller.name = "ant-edge";
  o.port = pty.slave_path();
  o.device_options.set("start", stc::SubCell{0, 0});
  o.link.timeout = std::chrono::milliseconds(20);
  o.link.tries = 2;
  o.out = dir.file("silent.jsonl");
  const auto s = devices::record(o);
  REQUIRE(sf::tour_of(s));
  CHECK_FALSE(sf::tour_of(s)->closed);
  CHECK(s.kind == devices::StopKind::Link);
  CHECK(s.steps == 0);
  CHECK(s.stop.find("'C,1' failed after 2 sends: no reply") != std::string::npos);
  // The dark frame's C,1 and the safe stop's L,0, each sent twice.
  CHECK(s.link.retries == 2);
  CHECK(s.safe_stop.stopped);
  CHECK_FALSE(s.safe_stop.acknowledged);
  CHECK(s.stop.find("; safe stop: ") != std::string::npos);
  const auto r = devices::replay(o.out);
  CHECK(r.identical);
  REQUIRE(r.stop);
  CHECK(r.stop->reason.rfind("link: ", 0) == 0);
}

TEST_CASE("stc floor link: the stop record is checked: its words, its bytes, its safe stop",
          "[devices]") {
  // Issue 26: the marker-floor robot's log goes through the same checks as the other robots'
  // (replay.hpp): an edited stop record replays as a divergence in stop.*.
  TempDir dir;
  const auto map = board();
  FloorOnPty robot(map, stc::SubCell{0, 0}, 1, sf::FloorOptions{});
  const auto o = floor_options("ant-edge", robot.port(), dir.file("floor.jsonl"));
  REQUIRE(devices::record(o).succeeded());
  robot.stop();
  const auto original = devices::replay(o.out);
  REQUIRE(original.identical);
  REQUIRE(original.complete);
  REQUIRE(original.stop);
  CHECK(original.stop->reason == "done");
  REQUIRE_FALSE(original.stop->io.empty());
  CHECK(original.stop->io.back().sent == "L,0\r"); // the safe stop, acknowledged
  struct Edit {
    std::string what;
    std::function<void(devices::LogStop&)> apply;
  };
  const std::vector<Edit> edits{
      {"an unknown reason", [](devices::LogStop& s) { s.reason = "finished"; }},
      {"a bump that did not happen",
       [](devices::LogStop& s) { s.reason = "error: the robot bumped and did not move"; }},
      {"a failed safe stop that was acknowledged",
       [](devices::LogStop& s) { s.reason += "; safe stop: no reply"; }},
      {"a robot that may be moving",
       [](devices::LogStop& s) { s.reason += "; robot may be moving: no reply"; }},
      {"the safe stop's bytes", [](devices::LogStop& s) { s.io.back().sent = "L,1\r"; }},
      {"the safe stop's acknowledgement",
       [](devices::LogStop& s) { s.io.back().received = "x\r\n"; }},
      {"no safe stop", [](devices::LogStop& s) { s.io.clear(); }},
  };
  const auto lines = antkit::test::lines_of(o.out);
  for (const auto& edit : edits) {
    INFO(edit.what);
    auto stop = *original.stop;
    edit.apply(stop);
    auto edited = lines;
    edited.back() = devices::format_stop(stop);
    const auto path = dir.file("edited-stop.jsonl");
    antkit::test::write_lines(path, edited);
    const auto r = devices::replay(path);
    CHECK_FALSE(r.identical);
    CHECK(r.steps == original.steps);
    REQUIRE(r.first_divergence);
    CHECK(r.first_divergence->field.rfind("stop.", 0) == 0);
  }
}
