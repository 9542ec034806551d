// End to end over real pseudo-terminals: the firmware emulators answer the robots' protocols, the
// adapters run the controllers through the real serial link, the logs replay bit for bit, and
// every way a run can end leaves a complete, replayable log (issue 13).
#include "emulated_robot.hpp"

#include <antkit/devices/log.hpp>
#include <antkit/devices/odometry.hpp>
#include <antkit/devices/record_loop.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/devices/stop_signals.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <fstream>
#include <sstream>
#include <thread>

namespace devices = antkit::devices;
using antkit::test::EmulatedRobot;
using antkit::test::lines_of;
using antkit::test::TempDir;
using antkit::test::write_lines;
using devices::RobotKind;

namespace {

const RobotKind kRobots[] = {RobotKind::Khepera, RobotKind::Hemisson, RobotKind::Epuck};

devices::RecordOptions options_for(RobotKind robot, const std::string& port,
                                   const std::string& controller, const devices::Params& params,
                                   std::int64_t steps, const std::string& out) {
  auto o = antkit::test::record_options(robot, port, controller, params, steps, out);
  o.link.tries = 5;
  return o;
}

std::size_t count_records(const std::string& path) {
  devices::LogReader reader(path);
  devices::LogRecord r;
  std::size_t n = 0;
  while (reader.next(r)) ++n;
  return n;
}

} // namespace

TEST_CASE("each robot runs the Buffon behaviour through its emulator and the log replays",
          "[devices]") {
  for (const RobotKind robot : kRobots) {
    INFO(devices::robot_name(robot));
    TempDir dir;
    EmulatedRobot emu(robot, "circle:d=8");
    const auto log = dir.file("visit1.jsonl");
    const auto s =
        devices::record(options_for(robot, emu.port(), "buffon", {{"visit", 1}}, 300, log));
    CHECK(s.completed);
    CHECK(s.stop == "done");
    CHECK(s.steps == 300);
    CHECK(s.link.retries == 0);
    CHECK(s.safe_stop.stopped);
    CHECK(s.safe_stop.complete);
    emu.stop();
    // The body moved: the behaviour is not stuck at the start.
    const auto& trail = emu.emulator().trail();
    REQUIRE(trail.size() >= 300);
    CHECK(!(trail.back() == trail.front()));

    const auto r = devices::replay(log);
    CHECK(r.identical);
    CHECK(r.steps == 300);
    CHECK(!r.truncated);
    REQUIRE(r.stop.has_value());
    CHECK(r.stop->reason == "done");
    CHECK(r.hash == s.hash);
    CHECK(count_records(log) == 300);
  }
}

TEST_CASE("dead reckoning from the logged odometry recovers the emulated body's trail",
          "[devices]") {
  // The emulated encoders count the wheels' true travel (no slip), so the trail computed from the
  // log must follow the body: within a few thousandths of a diameter over 400 steps, once the two
  // frames are aligned (dead reckoning starts at the origin heading +x; the body starts where the
  // arena says, heading about +y).
  //
  // The Hemisson reckons its travel from the times its commands were sent (step 4 of
  // record_loop.hpp), while the emulator is lock-stepped (a model period per read): the two agree
  // when the reads come once per model period, the Hemisson's default pacing, so it runs paced
  // here, 60 steps (7 s).
  for (const RobotKind robot : kRobots) {
    INFO(devices::robot_name(robot));
    const bool reckoned = robot == RobotKind::Hemisson;
    const std::int64_t steps = reckoned ? 60 : 400;
    TempDir dir;
    EmulatedRobot emu(robot, "circle:d=8");
    const auto log = dir.file("run.jsonl");
    auto o = options_for(robot, emu.port(), "buffon", {{"visit", 1}}, steps, log);
    if (reckoned) o.device_options.erase("period"); // the model period
    REQUIRE(devices::record(o).completed);
    emu.stop();
    const auto trail = devices::trail_from_log(log);
    REQUIRE(trail.points.size() == static_cast<std::size_t>(steps));
    // Step k's odometry is read after the k-th sensor read, i.e. at trail point k + 1 of the
    // emulator (its trail starts with the start pose, before the first control period).
    const auto& truth = emu.emulator().trail();
    REQUIRE(truth.size() == static_cast<std::size_t>(steps + 1));
    // Align: rotate the dead-reckoned frame by the body's start heading (the first straight
    // stretch gives it) and translate to the body's first sensed position.
    const auto start = truth[1];
    double worst = 0;
    // The heading of the body at its first period, from the first non-trivial displacement.
    std::size_t k = 2;
    while (k < truth.size() && truth[k] == truth[1]) ++k;
    REQUIRE(k < truth.size());
    const double tx = (truth[k].x.raw() - start.x.raw()) / 65536.0,
                 ty = (truth[k].y.raw() - start.y.raw()) / 65536.0;
    const double dx = trail.points[k - 1].x.raw() / 65536.0,
                 dy = trail.points[k - 1].y.raw() / 65536.0;
    const double a = std::atan2(ty, tx) - std::atan2(dy, dx);
    for (std::size_t i = 0; i < trail.points.size(); ++i) {
      const double px = trail.points[i].x.raw() / 65536.0, py = trail.points[i].y.raw() / 65536.0;
      const double qx = start.x.raw() / 65536.0 + std::cos(a) * px - std::sin(a) * py;
      const double qy = start.y.raw() / 65536.0 + std::sin(a) * px + std::cos(a) * py;
      worst = std::max(worst, std::hypot(qx - truth[i + 1].x.raw() / 65536.0,
                                         qy - truth[i + 1].y.raw() / 65536.0));
    }
    CAPTURE(worst);
    // Encoder robots: pulse rounding only. The Hemisson: its reads come a little later than a
    // model period each (the sleep's overshoot, the exchange), time it reckons as travel and the
    // lock-stepped emulator does not: a few thousandths of a step per read on a quiet machine,
    // bounded here for a loaded one (the walk is about 10 diameters). Unpaced, it is off by
    // several diameters.
    CHECK(worst < (reckoned ? 0.25 : 0.05));
  }
}

TEST_CASE("every robot survives dropped, cut, garbled and late replies, reproducibly",
          "[devices]") {
  // The timeout is generous (200 ms against a pty round trip of well under a millisecond) so that a
  // loaded machine does not add timeouts of its own: the reproducibility check below relies on the
  // emulator's keyed fault stream being the only source of faults.
  const std::vector<std::vector<std::string>> kinds{
      {"drop=0.02"}, {"cut=0.02"}, {"garbage=0.03"}, {"delay=0.01:250"}};
  for (const RobotKind robot : kRobots) {
    for (const auto& spec : kinds) {
      INFO(devices::robot_name(robot) << " " << spec.front());
      TempDir dir;
      devices::EmulatorOptions eo;
      eo.seed = 3;
      eo.faults = devices::parse_faults(spec);
      EmulatedRobot emu(robot, "circle:d=8", eo);
      const auto log = dir.file("faulty.jsonl");
      auto o = options_for(robot, emu.port(), "buffon", {}, 100, log);
      o.link.timeout = std::chrono::milliseconds(200);
      const auto s = devices::record(o);
      emu.stop();
      CHECK(s.completed);
      CHECK(emu.emulator().faults() > 0);
      CHECK(s.link.retries > 0);                            // each fault kind costs a resend...
      CHECK(s.link.retries <= 3 * emu.emulator().faults()); // ...and only faults do
      const auto r = devices::replay(log);
      CHECK(r.identical);
      CHECK(r.steps == 100);
    }
    // Faults come from the emulator's keyed stream: the same seed, the same faulty run.
    std::uint64_t hashes[2] = {};
    for (int run = 0; run < 2; ++run) {
      TempDir dir;
      devices::EmulatorOptions eo;
      eo.seed = 11;
      eo.faults = devices::parse_faults({"drop=0.02", "cut=0.02", "garbage=0.02"});
      EmulatedRobot emu(robot, "circle:d=8", eo);
      auto o = options_for(robot, emu.port(), "buffon", {}, 100, dir.file("again.jsonl"));
      o.link.timeout = std::chrono::milliseconds(200);
      const auto s = devices::record(o);
      CHECK(s.completed);
      hashes[run] = s.hash;
    }
    CHECK(hashes[0] == hashes[1]);
  }
  // A reply within the timeout costs nothing.
  TempDir dir;
  devices::EmulatorOptions eo;
  eo.faults = devices::parse_faults({"delay=0.2:5"});
  EmulatedRobot emu(RobotKind::Epuck, "circle:d=8", eo);
  const auto log = dir.file("delay.jsonl");
  auto o = options_for(RobotKind::Epuck, emu.port(), "buffon", {}, 60, log);
  o.link.timeout = std::chrono::milliseconds(200);
  const auto s = devices::record(o);
  emu.stop();
  CHECK(s.completed);
  CHECK(s.link.retries == 0);
  CHECK(emu.emulator().faults() > 0);
  CHECK(devices::replay(log).identical);
}

TEST_CASE("a disconnect stops the run, and every step before it is in the log and replays",
          "[devices]") {
  TempDir dir;
  devices::EmulatorOptions eo;
  eo.faults = devices::parse_faults({"disconnect=100"});
  EmulatedRobot emu(RobotKind::Khepera, "circle:d=8", eo);
  const auto log = dir.file("cut.jsonl");
  const auto s =
      devices::record(options_for(RobotKind::Khepera, emu.port(), "buffon", {}, 500, log));
  CHECK(!s.completed);
  CHECK(s.stop.find("disconnected") != std::string::npos);
  // 100 commands answered: B (the identification), G, then three per step (N, D, H) -> 32 whole
  // steps.
  CHECK(s.steps == 32);
  CHECK(count_records(log) == 32);
  const auto r = devices::replay(log);
  CHECK(r.identical);
  CHECK(r.steps == 32);
  REQUIRE(r.stop.has_value());
  CHECK(r.stop->reason.find("disconnected") != std::string::npos);
  CHECK(!r.stop->io.empty()); // the unanswered command and the attempted safe stop
}

TEST_CASE("SIGINT stops the robot safely and ends the log", "[devices]") {
  TempDir dir;
  EmulatedRobot emu(RobotKind::Hemisson, "circle:d=8");
  const auto log = dir.file("sigint.jsonl");
  std::thread interrupter([] {
    std::this_thread::sleep_for(std::chrono::milliseconds(150));
    std::raise(SIGINT);
  });
  const auto s =
      devices::record(options_for(RobotKind::Hemisson, emu.port(), "buffon", {}, 1000000, log));
  interrupter.join();
  devices::StopSignals::reset();
  CHECK(!s.completed);
  CHECK(s.stop == "interrupted by SIGINT");
  CHECK(s.safe_stop.stopped); // the emulator acknowledged wheels-to-zero and reads back 0, 0
  CHECK(s.safe_stop.complete);
  emu.stop();
  // The last thing the robot was told is to stop its wheels.
  const auto r = devices::replay(log);
  CHECK(r.identical);
  CHECK(r.steps == s.steps);
  REQUIRE(r.stop.has_value());
  bool zeroed = false;
  for (const auto& ex : r.stop->io) zeroed = zeroed || ex.sent.rfind("D,0,0", 0) == 0;
  CHECK(zeroed);
}

TEST_CASE("an edited log is caught at the edited step and field", "[devices]") {
  TempDir dir;
  EmulatedRobot emu(RobotKind::Epuck, "circle:d=8");
  const auto log = dir.file("orig.jsonl");
  REQUIRE(
      devices::record(options_for(RobotKind::Epuck, emu.port(), "buffon", {}, 60, log)).completed);
  emu.stop();
  const auto lines = lines_of(log);
  REQUIRE(lines.size() == 62); // header, 60 steps, stop
  // Step 40 is line 42 (1-based): edit one field at a time through the writer's own format.
  struct Edit {
    std::string field;
    std::function<void(devices::LogRecord&)> apply;
  };
  const std::vector<Edit> edits{
      {"cmd[1]", [](devices::LogRecord& r) { r.cmd[1] += 1; }},
      {"state", [](devices::LogRecord& r) { r.state ^= 1; }},
      {"obs[2]", [](devices::LogRecord& r) { r.obs[2] += 1; }},
      {"odo[0]", [](devices::LogRecord& r) { r.odo[0] += 1; }},
      // The robot's reply itself: the first proximity value changed by the edit.
      {"obs", [](devices::LogRecord& r) {
         for (auto& ex : r.io)
           if (ex.sent[0] == 'N') ex.received = "n,4000,0,0,0,0,0,0,0\r\n";
       }}};
  for (const auto& edit : edits) {
    INFO(edit.field);
    // Read the record back, edit it, write it out in the canonical format.
    devices::LogReader reader(log);
    devices::LogRecord rec;
    for (int i = 0; i <= 40; ++i) REQUIRE(reader.next(rec));
    REQUIRE(rec.step == 40);
    edit.apply(rec);
    auto edited = lines;
    edited[41] = devices::format_record(rec);
    const auto path = dir.file("edited.jsonl");
    write_lines(path, edited);
    const auto r = devices::replay(path);
    CHECK(!r.identical);
    CHECK(r.steps == 40);
    REQUIRE(r.first_divergence.has_value());
    CHECK(r.first_divergence->step == 40);
    CHECK(r.first_divergence->field.rfind(edit.field, 0) == 0);
    // The rest was read unchecked: the log is still known to be whole, with its stop record.
    CHECK(r.complete);
    CHECK(r.stop.has_value());
  }
  // The last step's time, moved later than the safe stop's first send: held by the stop record's
  // exchange times (nothing after the last step held it before).
  {
    devices::LogReader reader(log);
    devices::LogRecord next, rec;
    while (reader.next(next)) rec = next; // (next() may leave its record half-filled at the end)
    REQUIRE(rec.step == 59);
    const auto stop = reader.stop();
    REQUIRE(stop.has_value());
    REQUIRE(!stop->io.empty());
    rec.time_ns = stop->io.front().t_ns + 1;
    auto edited = lines;
    edited[60] = devices::format_record(rec);
    const auto path = dir.file("late.jsonl");
    write_lines(path, edited);
    const auto r = devices::replay(path);
    CHECK(!r.identical);
    REQUIRE(r.first_divergence.has_value());
    CHECK(r.first_divergence->field == "stop.io[0].t");
  }
}

TEST_CASE("a truncated log replays up to its cut, and another schema version is refused",
          "[devices]") {
  TempDir dir;
  EmulatedRobot emu(RobotKind::Khepera, "circle:d=8");
  const auto log = dir.file("orig.jsonl");
  REQUIRE(devices::record(options_for(RobotKind::Khepera, emu.port(), "buffon", {}, 30, log))
              .completed);
  emu.stop();
  std::ifstream in(log, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // A power cut in the middle of step 20's record: steps 0-19 replay, the cut is reported.
  auto lines = lines_of(log);
  std::string cut;
  for (std::size_t i = 0; i < 21; ++i) cut += lines[i] + '\n';
  cut += lines[21].substr(0, lines[21].size() / 2);
  const auto path = dir.file("cut.jsonl");
  std::ofstream(path, std::ios::binary) << cut;
  const auto r = devices::replay(path);
  CHECK(r.identical);
  CHECK(r.truncated);
  CHECK(r.steps == 20);
  CHECK(!r.stop.has_value());

  // Schema 3: refused with the version in the message, at line 1.
  auto header = lines[0];
  const auto at = header.find("\"schema\":2");
  REQUIRE(at != std::string::npos);
  header.replace(at, 10, "\"schema\":3");
  lines[0] = header;
  const auto other = dir.file("schema3.jsonl");
  write_lines(other, lines);
  try {
    devices::replay(other);
    FAIL("a schema 3 log was accepted");
  } catch (const antkit::kernel::InputError& e) {
    CHECK(e.line() == 1);
    CHECK(std::string(e.what()).find("schema") != std::string::npos);
  }
}

TEST_CASE("the random wanderer steps and turns on each robot and replays", "[devices]") {
  for (const RobotKind robot : kRobots) {
    INFO(devices::robot_name(robot));
    TempDir dir;
    EmulatedRobot emu(robot, "square:d=6");
    const auto log = dir.file("wander.jsonl");
    const auto s = devices::record(options_for(robot, emu.port(), "wander", {}, 60, log));
    CHECK(s.completed);
    emu.stop();
    CHECK(!(emu.emulator().trail().back() == emu.emulator().trail().front()));
    const auto r = devices::replay(log);
    CHECK(r.identical);
    CHECK(r.steps == 60);
  }
}

TEST_CASE("Buffon from two recorded visits: the exact count of the dead-reckoned trails",
          "[devices]") {
  // Paper 000 section 7, as a computation: two visits recorded on the same emulated arena (the
  // same emulator seed, so the same start pose), then BC, the exact crossing count and A_hat.
  TempDir dir;
  std::string logs[2];
  for (int visit = 1; visit <= 2; ++visit) {
    EmulatedRobot emu(RobotKind::Khepera, "circle:d=8");
    logs[visit - 1] = dir.file("visit" + std::to_string(visit) + ".jsonl");
    REQUIRE(devices::record(options_for(RobotKind::Khepera, emu.port(), "buffon",
                                        {{"visit", visit}}, 1500, logs[visit - 1]))
                .completed);
  }
  const auto r = devices::buffon_from_logs(logs[0], logs[1], antkit::kernel::Fx::from_ratio(1, 10));
  CHECK(r.visit1.steps == 1500);
  CHECK(r.visit2.steps == 1500);
  CHECK(r.crossings_exact ==
        antkit::kernel::count_proper_crossings(r.visit1.points, r.visit2.points));
  CHECK(r.crossings_exact > 5);
  CHECK(r.bc > 0);
  REQUIRE(r.area.has_value());
  // The centre's reachable area in a circle of diameter 8 is below pi 4^2 = 50 and well above a
  // tenth of it; one pair of short visits gives an estimate, not a measurement.
  CHECK(*r.area > 5);
  CHECK(*r.area < 200);
  CHECK(r.diameter_m == Approx(0.055).margin(0.005));
}

TEST_CASE("emulate --pace: replies come no faster than the robot's baud rate allows", "[devices]") {
  // Khepera: 9600 baud, 8N2 = 11 bit times a byte, plus the command latency. A lower bound on the
  // logged time between steps, from the bytes each step received (a behaviour check: nothing is
  // timed against an upper bound).
  TempDir dir;
  devices::EmulatorOptions eo;
  eo.pace = true;
  EmulatedRobot emu(RobotKind::Khepera, "circle:d=8", eo);
  const auto log = dir.file("paced.jsonl");
  REQUIRE(devices::record(options_for(RobotKind::Khepera, emu.port(), "buffon", {}, 12, log))
              .completed);
  emu.stop();
  devices::LogReader reader(log);
  devices::LogRecord r;
  std::int64_t first = -1, last = 0, floor_ns = 0;
  while (reader.next(r)) {
    if (first < 0) {
      first = r.time_ns;
      continue;
    }
    last = r.time_ns;
    for (const auto& ex : r.io)
      floor_ns += static_cast<std::int64_t>(ex.received.size()) * 11 * 1000000000 / 9600 +
                  std::chrono::nanoseconds(devices::kCommandLatency).count();
  }
  CAPTURE(last - first, floor_ns);
  CHECK(floor_ns > 200000000); // 11 steps of N, D, H: over 0.2 s of line time
  CHECK(last - first >= floor_ns);
}
