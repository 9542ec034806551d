// Every way out of a run stops the robot, within a bound, and says honestly what it knows
// (issue 43, "every way out safe"): the signals that end a process (SIGHUP from a closed terminal
// too), a silent robot (the safe stop bounded, the LEDs not asked for after the wheels did not
// answer), and a second stop signal that cuts the safe stop short. Each log replays, its stop
// record's claims checked against its bytes.
#include "emulated_robot.hpp"

#include <antkit/devices/record_loop.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/devices/stop_signals.hpp>
#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <string>
#include <thread>
#include <vector>

namespace devices = antkit::devices;
using antkit::test::EmulatedRobot;
using antkit::test::TempDir;
using devices::RobotKind;

namespace {

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

// The safe stop's sends in the stop record (from the first send of `wheels`, the stop's first
// command; before it come the unfinished step's), resends included, and the span of their times.
struct StopSends {
  std::vector<std::string> sent;
  std::int64_t first_ns = -1, last_ns = -1;
};
StopSends stop_sends(const devices::ReplayResult& r, const std::string& wheels) {
  StopSends out;
  for (const auto& e : r.stop->io) {
    if (e.sent.empty() || (out.sent.empty() && e.sent != wheels)) continue;
    out.sent.push_back(e.sent);
    if (out.first_ns < 0) out.first_ns = e.t_ns;
    out.last_ns = e.t_ns;
  }
  return out;
}

} // namespace

TEST_CASE("every signal that ends a process stops the robot first and is named in the log",
          "[devices]") {
  for (const int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) {
    const std::string name = sig == SIGINT    ? "SIGINT"
                             : sig == SIGTERM ? "SIGTERM"
                             : sig == SIGHUP  ? "SIGHUP"
                                              : "SIGQUIT";
    DYNAMIC_SECTION(name) {
      TempDir dir;
      EmulatedRobot emu(RobotKind::Epuck, "circle:d=8");
      const auto log = dir.file("signal.jsonl");
      std::thread interrupter([sig] {
        std::this_thread::sleep_for(std::chrono::milliseconds(150));
        std::raise(sig);
      });
      const auto s = devices::record(
          antkit::test::record_options(RobotKind::Epuck, emu.port(), "buffon", {}, 1000000, log));
      interrupter.join();
      devices::StopSignals::reset();
      emu.stop();
      CHECK(s.kind == devices::StopKind::Interrupted);
      CHECK(s.signal == sig);
      CHECK(s.stop == "interrupted by " + name);
      CHECK(s.safe_stop.stopped); // acknowledged and read back at 0, 0
      CHECK(s.safe_stop.complete);
      CHECK(!s.succeeded()); // stopped on request is not "did what it set out to do"
      const auto r = devices::replay(log);
      CHECK(r.identical);
      REQUIRE(r.stop.has_value());
      CHECK(r.stop->reason == "interrupted by " + name);
    }
  }
}

TEST_CASE("a silent robot: the wheels' stop is bounded in time and the LEDs are not asked for",
          "[devices]") {
  TempDir dir;
  devices::EmulatorOptions eo;
  eo.faults = devices::parse_faults({"silent=40"}); // answers 40 commands, then nothing
  EmulatedRobot emu(RobotKind::Epuck, "circle:d=8", eo);
  const auto log = dir.file("silent.jsonl");
  auto o = antkit::test::record_options(RobotKind::Epuck, emu.port(), "buffon", {}, 1000, log);
  o.link.tries = 4;
  o.link.stop_within = std::chrono::milliseconds(300); // less than 3 rounds of 4 x 60 ms
  std::vector<std::string> notices;
  o.link.on_stop_notice = [&](const std::string& what) { notices.push_back(what); };
  const auto s = devices::record(o);
  emu.stop();
  CHECK(s.kind == devices::StopKind::Link);
  CHECK(!s.safe_stop.stopped);
  CHECK(!s.safe_stop.acknowledged);
  CHECK(contains(s.stop, "robot may be moving"));
  CHECK(contains(s.safe_stop.failure, "not sent (the wheels' stop was not acknowledged)"));
  CHECK(contains(s.safe_stop.failure, "gave up after 300 ms"));
  // What a person at the terminal heard: a round without an answer, then giving up.
  REQUIRE(notices.size() >= 2);
  CHECK(contains(notices.front(), "no acknowledgement of"));
  CHECK(contains(notices.back(), "gave up after 300 ms"));

  const auto r = devices::replay(log);
  CHECK(r.identical);
  REQUIRE(r.stop.has_value());
  const std::string wheels = devices::Codec(RobotKind::Epuck).safe_stop().front();
  const auto sends = stop_sends(r, wheels);
  REQUIRE(!sends.sent.empty());
  for (const auto& sent : sends.sent) CHECK(sent == wheels); // nothing but the wheels' stop
  // No send started after the bound (the log's own times).
  CHECK(sends.last_ns - sends.first_ns <= 300'000'000);
}

TEST_CASE("a second stop signal cuts the safe stop short, and the result claims nothing more",
          "[devices]") {
  TempDir dir;
  devices::EmulatorOptions eo;
  eo.faults = devices::parse_faults({"silent=40"});
  EmulatedRobot emu(RobotKind::Khepera, "circle:d=8", eo);
  const auto log = dir.file("cut.jsonl");
  auto o = antkit::test::record_options(RobotKind::Khepera, emu.port(), "buffon", {}, 1000, log);
  o.link.tries = 3;
  // The second Ctrl-C comes when the stop says it is still trying.
  int raised = 0;
  o.link.on_stop_notice = [&](const std::string& what) {
    if (raised == 0 && contains(what, "Ctrl-C again")) {
      ++raised;
      std::raise(SIGINT);
    }
  };
  const auto s = devices::record(o);
  devices::StopSignals::reset();
  emu.stop();
  CHECK(raised == 1);
  CHECK(s.kind == devices::StopKind::Link);
  CHECK(!s.safe_stop.stopped);
  CHECK(contains(s.safe_stop.failure, "cut short by a stop signal"));
  CHECK(contains(s.stop, "robot may be moving"));
  // Cut at the second round: one round of tries was sent, no more.
  const auto r = devices::replay(log);
  CHECK(r.identical);
  REQUIRE(r.stop.has_value());
  const std::string wheels = devices::Codec(RobotKind::Khepera).safe_stop().front();
  const auto sends = stop_sends(r, wheels);
  std::size_t wheel_sends = 0;
  for (const auto& sent : sends.sent)
    if (sent == wheels) ++wheel_sends;
  CHECK(wheel_sends == 3);
}
