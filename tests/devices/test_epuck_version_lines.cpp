// The real e-puck answers V with two lines (PROTOCOLS.md, "e-puck (advanced sercom, ASCII mode)"
// and the e-puck2's ASCII differences: `v,Version ...` then `HW version: ...`); the emulator sends
// the first only. robot_epuck.cpp's identification rule says what becomes of the second line: the
// link drains it as a late line before the next command, or, when it comes after that command was
// sent, takes it for a bad reply and resends the command (the start's P,0,0: idempotent). Here a
// robot that sends it, both ways, over a real pty: identified once, the run goes on, the log
// replays.
#include "emulated_robot.hpp"

#include <antkit/devices/emulator.hpp>
#include <antkit/devices/log.hpp>
#include <antkit/devices/record_loop.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/devices/serial.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <atomic>
#include <catch2/catch.hpp>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

namespace devices = antkit::devices;
using antkit::test::TempDir;
using devices::RobotKind;

namespace {

constexpr std::string_view kHwLine = "HW version: FFF7\r\n";

// The e-puck's emulator, but its V answered with the second line too: in the same write as the
// first (WithFirst), or held back and sent in front of the reply to the next command (AfterNext:
// it arrived after that command was sent).
class TwoLineEpuck {
public:
  enum class Second { WithFirst, AfterNext };
  explicit TwoLineEpuck(Second when)
      : pty_(devices::Pty::open()),
        emulator_(RobotKind::Epuck,
                  antkit::geometry::build_arena_spec("circle:d=8").arena.walls_fx()),
        when_(when) {
    thread_ = std::thread([this] {
      devices::serve_pty(
          pty_, [this](std::string_view line) { return handle(line); },
          [this] {
            const std::lock_guard lock(mutex_);
            emulator_.reset();
            pending_.clear();
          },
          &stop_, false);
    });
  }
  TwoLineEpuck(const TwoLineEpuck&) = delete;
  TwoLineEpuck& operator=(const TwoLineEpuck&) = delete;
  ~TwoLineEpuck() {
    stop_ = true;
    thread_.join();
  }
  [[nodiscard]] const std::string& port() const noexcept { return pty_.slave_path(); }
  [[nodiscard]] int versions() const noexcept { return versions_; }

private:
  devices::EmulatorResponse handle(std::string_view line) {
    const std::lock_guard lock(mutex_);
    devices::EmulatorResponse r = emulator_.handle(line);
    if (line == "V") {
      ++versions_;
      if (when_ == Second::WithFirst)
        r.bytes += kHwLine;
      else
        pending_ = kHwLine;
    } else if (!pending_.empty()) {
      r.bytes = pending_ + r.bytes;
      pending_.clear();
    }
    return r;
  }
  devices::Pty pty_;
  std::mutex mutex_;
  devices::FirmwareEmulator emulator_;
  Second when_;
  std::string pending_;
  std::atomic<int> versions_{0};
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

} // namespace

TEST_CASE("epuck: a V answered with two lines (the real firmware's) identifies the robot and the "
          "second line is not taken for a later reply",
          "[devices]") {
  const auto when = GENERATE(TwoLineEpuck::Second::WithFirst, TwoLineEpuck::Second::AfterNext);
  const bool with_first = when == TwoLineEpuck::Second::WithFirst;
  INFO((with_first ? "the second line with the first" : "the second line after the next send"));
  TempDir dir;
  const auto log = dir.file("epuck.jsonl");
  devices::RecordSummary s;
  int versions = 0;
  {
    TwoLineEpuck robot(when);
    auto o = antkit::test::record_options(RobotKind::Epuck, robot.port(), "buffon", {{"visit", 1}},
                                          20, log);
    o.link.tries = 5;
    s = devices::record(o);
    versions = robot.versions();
  }
  INFO(s.stop);
  CHECK(s.succeeded());
  CHECK(s.completed);
  CHECK(s.steps == 20);
  CHECK(versions == 1); // identified once
  // The identification's reply is the first line alone; the second is where the link put it, in
  // step 0, and nowhere later.
  devices::LogReader reader(log);
  CHECK(reader.header().schema >= 2);
  devices::LogRecord r;
  REQUIRE(reader.next(r));
  REQUIRE(r.io.size() >= 3);
  CHECK(r.io[0].sent == "V\r");
  CHECK(r.io[0].received.rfind("v,Version ", 0) == 0);
  CHECK(r.io[0].received.find("HW version") == std::string::npos);
  std::size_t at = r.io.size();
  for (std::size_t i = 1; i < r.io.size(); ++i)
    if (r.io[i].received.find("HW version") != std::string::npos) {
      at = i;
      break;
    }
  REQUIRE(at < r.io.size());
  if (with_first) {
    // Waiting before the start's first send: drained, an exchange that sent nothing.
    CHECK(r.io[at].sent.empty());
    CHECK(r.io[at].received == kHwLine);
    CHECK(s.link.retries == 0);
  } else {
    // Read as the reply to the start's first command: a bad reply, so the command goes again
    // (its own reply, late by then, drained before the resend).
    CHECK_FALSE(r.io[at].sent.empty());
    CHECK(r.io[at].received.rfind(std::string(kHwLine), 0) == 0);
    bool resent = false;
    for (std::size_t i = at + 1; i < r.io.size(); ++i)
      resent = resent || r.io[i].sent == r.io[at].sent;
    CHECK(resent);
    CHECK(s.link.retries == 1);
  }
  while (reader.next(r))
    for (const auto& x : r.io) CHECK(x.received.find("HW version") == std::string::npos);
  // The replay runs the same link on these bytes: identical, and whole.
  const auto replayed = devices::replay(log);
  CHECK(replayed.identical);
  CHECK(replayed.complete);
  CHECK(replayed.steps == 20);
  CHECK(replayed.hash == s.hash);
}
