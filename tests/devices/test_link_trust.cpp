// Issue 26: a run is what it says, the robot is stopped on every way out or the result says it may
// not be, late replies are never taken for a later command's answer, logs are never replaced by
// accident, and replay checks every byte a log holds. End to end over real pseudo-terminals
// against the firmware emulators.
#include "emulated_robot.hpp"

#include <antkit/buffon/world.hpp>
#include <antkit/devices/log.hpp>
#include <antkit/devices/odometry.hpp>
#include <antkit/devices/protocol.hpp>
#include <antkit/devices/record_loop.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <cstdio>
#include <fstream>
#include <functional>

namespace devices = antkit::devices;
using antkit::test::EmulatedRobot;
using antkit::test::lines_of;
using antkit::test::record_options;
using antkit::test::TempDir;
using antkit::test::write_lines;
using devices::RobotKind;

namespace {

const RobotKind kRobots[] = {RobotKind::Khepera, RobotKind::Hemisson, RobotKind::Epuck};

devices::EmulatorOptions with_faults(std::uint64_t seed, const std::vector<std::string>& faults) {
  devices::EmulatorOptions eo;
  eo.seed = seed;
  eo.faults = devices::parse_faults(faults);
  return eo;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The log with record `step` (line step + 2) rewritten by `edit` through the writer's format.
std::string edited_record(const TempDir& dir, const std::string& log, std::int64_t step,
                          const std::function<void(devices::LogRecord&)>& edit) {
  devices::LogReader reader(log);
  devices::LogRecord rec;
  for (std::int64_t i = 0; i <= step; ++i) REQUIRE(reader.next(rec));
  edit(rec);
  auto lines = lines_of(log);
  lines[static_cast<std::size_t>(step) + 1] = devices::format_record(rec);
  const auto path = dir.file("edited.jsonl");
  write_lines(path, lines);
  return path;
}

// The log with its stop record rewritten by `edit`.
std::string edited_stop(const TempDir& dir, const std::string& log,
                        const std::function<void(devices::LogStop&)>& edit) {
  devices::LogReader reader(log);
  devices::LogRecord rec;
  while (reader.next(rec)) {
  }
  REQUIRE(reader.stop().has_value());
  auto stop = *reader.stop();
  edit(stop);
  auto lines = lines_of(log);
  lines.back() = devices::format_stop(stop);
  const auto path = dir.file("edited-stop.jsonl");
  write_lines(path, lines);
  return path;
}

} // namespace

TEST_CASE("the safe stop is resent until acknowledged and read back at zero", "[devices]") {
  // Issue 26: with 30 % of replies dropped, a one-step run ended with the wheels' stop sent once
  // and unacknowledged, and still reported success.
  for (const RobotKind robot : kRobots) {
    INFO(devices::robot_name(robot));
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      TempDir dir;
      EmulatedRobot emu(robot, "circle:d=8", with_faults(seed, {"drop=0.3"}));
      const auto log = dir.file("stop.jsonl");
      auto o = record_options(robot, emu.port(), "buffon", {}, 1, log);
      o.link.tries = 10;
      o.link.timeout = std::chrono::milliseconds(20);
      const auto s = devices::record(o);
      emu.stop();
      CHECK(s.kind == devices::StopKind::Done);
      CHECK(s.safe_stop.acknowledged);
      CHECK(s.safe_stop.stopped);
      CHECK(s.succeeded());
      // The last exchanges of the log: the speeds read back as zero.
      const auto r = devices::replay(log);
      CHECK(r.identical);
      CHECK(r.complete);
      REQUIRE(r.stop.has_value());
      CHECK(r.stop->reason.find("robot may be moving") == std::string::npos);
      bool read_back = false;
      for (const auto& ex : r.stop->io)
        read_back = read_back || (ex.sent == "E\r" && ex.received == "e,0,0\r\n");
      CHECK(read_back);
    }
  }
}

TEST_CASE("a robot that never confirms its stop makes the run a failure that says so",
          "[devices]") {
  // Every reply dropped: the first command fails, and the safe stop cannot be confirmed. The log
  // still ends with its stop record, which says the robot may be moving, and replays as such.
  TempDir dir;
  EmulatedRobot emu(RobotKind::Khepera, "circle:d=8", with_faults(1, {"drop=1"}));
  const auto log = dir.file("mute.jsonl");
  auto o = record_options(RobotKind::Khepera, emu.port(), "buffon", {}, 10, log);
  o.link.tries = 3;
  o.link.timeout = std::chrono::milliseconds(10);
  const auto s = devices::record(o);
  emu.stop();
  CHECK(s.kind == devices::StopKind::Link);
  CHECK(!s.safe_stop.acknowledged);
  CHECK(!s.safe_stop.stopped);
  CHECK(!s.succeeded());
  CHECK(s.stop.find("robot may be moving") != std::string::npos);
  const auto r = devices::replay(log);
  CHECK(r.identical);
  CHECK(r.complete);
  CHECK(r.steps == 0);
  // The wheels' stop was sent in every round, not once.
  REQUIRE(r.stop.has_value());
  int sends = 0;
  for (const auto& ex : r.stop->io) sends += ex.sent == "D,0,0\r" ? 1 : 0;
  CHECK(sends == 3 * 3);

  // The words of that stop record cannot be edited into a success.
  const auto lie = edited_stop(dir, log, [](devices::LogStop& st) {
    st.reason = st.reason.substr(0, st.reason.find("; robot may be moving"));
  });
  const auto e = devices::replay(lie);
  CHECK(!e.identical);
  REQUIRE(e.first_divergence.has_value());
  CHECK(e.first_divergence->field == "stop.reason");
}

TEST_CASE("an existing log is never replaced unless forced", "[devices]") {
  TempDir dir;
  EmulatedRobot emu(RobotKind::Epuck, "circle:d=8");
  const auto log = dir.file("visit.jsonl");
  { std::ofstream(log) << "a recorded visit\n"; }
  auto o = record_options(RobotKind::Epuck, emu.port(), "buffon", {}, 5, log);
  CHECK_THROWS_AS(devices::record(o), antkit::kernel::InputError);
  CHECK(slurp(log) == "a recorded visit\n");
  o.force = true;
  CHECK(devices::record(o).succeeded());
  CHECK(devices::replay(log).identical);
}

TEST_CASE("late replies are dropped as stale, never taken for a later command's answer",
          "[devices]") {
  // Issue 26: replies later than the timeout ended runs early (taken as the next command's
  // answer, then every resend of it failing). Here 5 % of replies come three timeouts late.
  for (const RobotKind robot : kRobots) {
    INFO(devices::robot_name(robot));
    TempDir dir;
    EmulatedRobot emu(robot, "circle:d=8", with_faults(5, {"delay=0.05:60"}));
    const auto log = dir.file("late.jsonl");
    auto o = record_options(robot, emu.port(), "buffon", {}, 300, log);
    o.link.timeout = std::chrono::milliseconds(20);
    const auto s = devices::record(o);
    emu.stop();
    CHECK(s.succeeded());
    CHECK(s.steps == 300);
    CHECK(s.link.stale > 0);
    const auto r = devices::replay(log);
    CHECK(r.identical);
    CHECK(r.steps == 300);
    CHECK(r.hash == s.hash);
  }
}

TEST_CASE("a long run through drops, garbage, cut and late replies at once, by default",
          "[devices][slow]") {
  // The defaults' arithmetic (link.hpp): 5 % of replies dropped, 5 % garbled and 5 % cut at once,
  // and replies three timeouts late, with the library's default tries and back-off. 4 000 steps
  // (12 000 commands; the measured failure rate's standard error is then 0.003) at a 20 ms timeout:
  // each drop and cut costs a whole timeout, so the test is mostly waiting (about 40 s). The
  // 100 000-step claim is the same arithmetic over the per-send failure rate this run measures,
  // which must be the faults' 1 - 0.95^3 = 0.143 (a loaded machine adds a few timeouts of its own,
  // hence the upper margin).
  TempDir dir;
  EmulatedRobot emu(RobotKind::Khepera, "circle:d=8",
                    with_faults(26, {"drop=0.05", "garbage=0.05", "cut=0.05", "delay=0.002:60"}));
  const auto log = dir.file("long.jsonl");
  devices::RecordOptions o;
  o.device = std::string(devices::robot_name(RobotKind::Khepera));
  o.port = emu.port();
  o.line = devices::describe(RobotKind::Khepera).line;
  o.controller = devices::make_spec("buffon", 3, {}, "test");
  o.steps = 4000;
  o.out = log;
  o.link.timeout = std::chrono::milliseconds(20);
  const auto s = devices::record(o);
  emu.stop();
  INFO(s.stop);
  CHECK(s.succeeded());
  CHECK(s.steps == 4000);
  const double failed = static_cast<double>(s.link.retries) / static_cast<double>(s.link.exchanges);
  CAPTURE(s.link.retries, s.link.exchanges, s.link.stale, failed);
  CHECK(failed > 0.12);
  CHECK(failed < 0.2);
  CHECK(s.link.stale > 0);
  const auto r = devices::replay(log);
  CHECK(r.identical);
  CHECK(r.steps == 4000);
  CHECK(r.hash == s.hash);
}

TEST_CASE("replay checks every byte of the log: a tooth per field", "[devices]") {
  // Khepera (wheel counters) and Hemisson (odometry re-derived from the sends), 40 steps; each
  // edit of step 20 is caught at step 20, in the field edited.
  for (const RobotKind robot : {RobotKind::Khepera, RobotKind::Hemisson}) {
    INFO(devices::robot_name(robot));
    TempDir dir;
    EmulatedRobot emu(robot, "circle:d=8");
    const auto log = dir.file("orig.jsonl");
    REQUIRE(devices::record(record_options(robot, emu.port(), "buffon", {}, 40, log)).succeeded());
    emu.stop();
    REQUIRE(devices::replay(log).identical);
    const auto find = [](devices::LogRecord& r, char letter) -> devices::Exchange& {
      for (auto& ex : r.io)
        if (!ex.sent.empty() && ex.sent[0] == letter) return ex;
      FAIL("no exchange sent " << letter);
      return r.io.front();
    };
    struct Edit {
      std::string name, field;
      std::function<void(devices::LogRecord&)> apply;
    };
    std::vector<Edit> edits{
        {"sent bytes", "io[",
         [&](devices::LogRecord& r) {
           auto& d = find(r, 'D');
           d.sent.insert(d.sent.size() - 1, "9"); // D,l,r -> D,l,r9
         }},
        {"acknowledgement", "io[", [&](devices::LogRecord& r) { find(r, 'D').received = "x\r\n"; }},
        {"bytes after a reply", "io[",
         [&](devices::LogRecord& r) { find(r, 'N').received += "n,1"; }},
        {"proximity reply", "obs",
         [&](devices::LogRecord& r) {
           auto& n = find(r, 'N');
           const std::string five = "n,5,5,5,5,5,5,5,5\r\n";
           n.received = n.received == five ? "n,6,6,6,6,6,6,6,6\r\n" : five;
         }},
        {"obs", "obs[0]", [](devices::LogRecord& r) { r.obs[0] += 1; }},
        {"cmd", "cmd[3]", [](devices::LogRecord& r) { r.cmd[3] += 1; }},
        {"state", "state", [](devices::LogRecord& r) { r.state ^= 4; }},
        {"odo", "odo[1]", [](devices::LogRecord& r) { r.odo[1] += 1; }},
        {"t_ns", "t_ns", [](devices::LogRecord& r) { r.time_ns = 0; }},
        {"an exchange's time out of order", "io[",
         [&](devices::LogRecord& r) { find(r, 'N').t_ns = 0; }},
    };
    if (robot == RobotKind::Hemisson) // the D's send ends the old speeds' time: it feeds odo
      edits.push_back({"the time of a speed change", "odo[",
                       [&](devices::LogRecord& r) { find(r, 'D').t_ns = find(r, 'N').t_ns; }});
    if (robot == RobotKind::Khepera)
      edits.push_back({"counter reply", "odo[0]", [&](devices::LogRecord& r) {
                         auto& h = find(r, 'H');
                         h.received = h.received == "h,7,7\r\n" ? "h,8,8\r\n" : "h,7,7\r\n";
                       }});
    for (const auto& edit : edits) {
      INFO(edit.name);
      const auto path = edited_record(dir, log, 20, edit.apply);
      const auto r = devices::replay(path);
      CHECK(!r.identical);
      CHECK(r.steps == 20);
      REQUIRE(r.first_divergence.has_value());
      CHECK(r.first_divergence->step == 20);
      CHECK(r.first_divergence->field.rfind(edit.field, 0) == 0);
    }
    // A stale line before a reply is what a live link may read: it replays.
    const auto stale = edited_record(
        dir, log, 20, [&](devices::LogRecord& r) { find(r, 'N').received.insert(0, "d\r\n"); });
    CHECK(devices::replay(stale).identical);

    // The stop record: its reason, and its safe stop's acknowledgement.
    const auto reason = edited_stop(dir, log, [](devices::LogStop& st) { st.reason = "stopped"; });
    auto r = devices::replay(reason);
    CHECK(!r.identical);
    REQUIRE(r.first_divergence.has_value());
    CHECK(r.first_divergence->field == "stop.reason");
    const auto ack = edited_stop(dir, log, [](devices::LogStop& st) {
      for (auto& ex : st.io)
        if (ex.sent == "D,0,0\r") ex.received = "x\r\n";
    });
    r = devices::replay(ack);
    CHECK(!r.identical);
    REQUIRE(r.first_divergence.has_value());
    CHECK(r.first_divergence->field.rfind("stop.", 0) == 0);
    const auto moving = edited_stop(
        dir, log, [](devices::LogStop& st) { st.reason += "; robot may be moving: claimed"; });
    r = devices::replay(moving);
    CHECK(!r.identical);
    REQUIRE(r.first_divergence.has_value());
    CHECK(r.first_divergence->field == "stop.reason");
  }
}

TEST_CASE("a log cut on a line boundary replays as far as it goes and says it never stopped",
          "[devices]") {
  TempDir dir;
  EmulatedRobot emu(RobotKind::Epuck, "circle:d=8");
  const auto log = dir.file("orig.jsonl");
  REQUIRE(devices::record(record_options(RobotKind::Epuck, emu.port(), "buffon", {}, 30, log))
              .succeeded());
  emu.stop();
  auto lines = lines_of(log);
  const auto full = devices::replay(log);
  CHECK(full.complete);
  // A power cut between two records: no stop record.
  lines.resize(21);
  const auto cut = dir.file("cut.jsonl");
  write_lines(cut, lines);
  const auto r = devices::replay(cut);
  CHECK(r.identical);
  CHECK(!r.truncated);
  CHECK(!r.complete);
  CHECK(r.steps == 20);
  // Only the header.
  lines.resize(1);
  write_lines(cut, lines);
  const auto h = devices::replay(cut);
  CHECK(h.identical);
  CHECK(!h.complete);
  CHECK(h.steps == 0);
}

TEST_CASE("two recordings back to back on one emulator are two sessions from the start pose",
          "[devices]") {
  // The emulator used to see a session end only as a moment with no client on the pty; a second
  // recording that opened the port at once could continue the first one's session (its body where
  // the first left it). The same controller and seed from the same pose give the same run.
  TempDir dir;
  EmulatedRobot emu(RobotKind::Khepera, "circle:d=8");
  std::uint64_t first = 0;
  for (int run = 0; run < 6; ++run) {
    INFO(run);
    const auto log = dir.file("run" + std::to_string(run) + ".jsonl");
    const auto s =
        devices::record(record_options(RobotKind::Khepera, emu.port(), "buffon", {}, 40, log));
    REQUIRE(s.succeeded());
    if (run == 0) first = s.hash;
    CHECK(s.hash == first);
  }
  emu.stop();
  CHECK(emu.emulator().sessions() == 6);
}

TEST_CASE("a robot without encoders is read once per model period and reckons its odometry from "
          "the logged times",
          "[devices]") {
  // The Hemisson's odometry is the travel the motion model gives the speeds in force, per model
  // period, times the time they were in force (record_loop.hpp, step 4). The model's step is
  // kDefaultSpeed body diameters at unit speed: 11031 / 65536 x 120 mm at 9 x 20 mm/s =
  // 112.213135 ms; its recordings default to reading once per such period.
  using namespace std::chrono_literals;
  const auto& hemisson = devices::describe(RobotKind::Hemisson);
  CHECK(devices::model_period(hemisson) == 112213135ns);
  CHECK(devices::default_period(hemisson) == 112213135ns);
  CHECK(devices::default_period(devices::describe(RobotKind::Khepera)) == 0ns);
  TempDir dir;
  EmulatedRobot emu(RobotKind::Hemisson, "circle:d=8");
  const auto log = dir.file("paced.jsonl");
  auto o = record_options(RobotKind::Hemisson, emu.port(), "buffon", {}, 6, log);
  o.device_options.erase("period"); // the robot's default
  REQUIRE(devices::record(o).succeeded());
  emu.stop();
  devices::LogReader reader(log);
  devices::LogRecord r;
  std::vector<devices::LogRecord> records;
  while (reader.next(r)) records.push_back(r);
  // The k-th read (from 0) comes no sooner than k periods after the first, and a step's time is
  // taken after its read. A lower bound only: nothing is timed against an upper bound.
  REQUIRE(records.size() == 6);
  CHECK(records.back().time_ns >= 5 * 112213135);
  // Every exchange has its send's time, in order, within its step.
  std::int64_t last = 0;
  for (const auto& rec : records)
    for (const auto& e : rec.io) {
      CHECK(e.t_ns >= last);
      CHECK(e.t_ns <= rec.time_ns);
      last = e.t_ns;
    }
  // The odometry recomputed here from the logged times and commands: the speeds of each D in force
  // from its send to the next D's, one model step's travel per 112213135 ns (step_travel2), in
  // micrometres (truncated), at every step's end (its D's send).
  __extension__ using i128 = __int128;
  i128 weighted[2] = {0, 0};
  std::int32_t left = 0, right = 0;
  std::int64_t since = -1;
  const i128 um_per_step = i128{11031} * 120000, um_per_s = i128{9} * 20000 * 65536;
  for (const auto& rec : records) {
    for (const auto& e : rec.io) {
      if (e.sent.empty()) continue;
      if (since >= 0) {
        const auto one = devices::step_travel2(hemisson, antkit::buffon::kDefaultSpeed,
                                               devices::from_wheel_command(hemisson, left),
                                               devices::from_wheel_command(hemisson, right), true);
        weighted[0] += one.left * (e.t_ns - since);
        weighted[1] += one.right * (e.t_ns - since);
      }
      since = e.t_ns;
      if (e.sent[0] == 'D') REQUIRE(std::sscanf(e.sent.c_str(), "D,%d,%d", &left, &right) == 2);
    }
    const i128 den = um_per_step * 1000000000 * 2 * 65536;
    CHECK(rec.odo[0] == static_cast<std::int64_t>(weighted[0] * um_per_s / den));
    CHECK(rec.odo[1] == static_cast<std::int64_t>(weighted[1] * um_per_s / den));
  }
  CHECK(records.back().odo[0] + records.back().odo[1] > 0); // it drove
  CHECK(devices::replay(log).identical);
}
