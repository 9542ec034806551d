// replay_records() reads a whole log a batch ahead on a second thread (replay.hpp): held to the
// reading on the calling thread, result for result and error for error, on a 2000-step Khepera
// log (eight batches) as it was recorded and damaged in the ways logs are damaged: cut at any
// byte, a malformed line, a record edited (a divergence, then the rest read unchecked), the stop
// record missing.
#include "emulated_robot.hpp"

#include <antkit/devices/controllers.hpp>
#include <antkit/devices/emulator.hpp>
#include <antkit/devices/log.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <fstream>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>
#include <sstream>
#include <variant>

namespace devices = antkit::devices;
using antkit::test::TempDir;

namespace {

// A Buffon visit of `steps` steps on the Khepera's firmware emulator, answered in process, logged
// as record() logs it (bench/bench_replay.cpp makes its log the same way).
std::string make_log(std::int64_t steps) {
  const auto robot = devices::RobotKind::Khepera;
  devices::FirmwareEmulator emu(robot,
                                antkit::geometry::build_arena_spec("circle:d=30").arena.walls_fx());
  const devices::Codec codec(robot);
  const auto spec = devices::make_spec("buffon", 3, {{"visit", 1}}, "test");
  auto controller = devices::make_controller(spec);
  devices::LogHeader header;
  header.antkit_version = "test";
  header.robot = "khepera";
  header.port = "(in process)";
  header.baud = codec.robot().line.baud;
  header.framing = codec.robot().line.framing();
  header.controller = spec.name;
  header.params = spec.params;
  header.seed = spec.seed;
  std::string text = devices::format_header(header) + "\n";
  const auto exchange = [&](const std::string& command, std::vector<devices::Exchange>& io) {
    std::string line = command;
    while (!line.empty() && (line.back() == '\r' || line.back() == '\n')) line.pop_back();
    io.push_back({command, emu.handle(line).bytes});
    return io.back().received;
  };
  devices::LogRecord rec;
  for (std::int64_t s = 0; s < steps; ++s) {
    rec.io.clear();
    if (s == 0) {
      exchange(codec.version(), rec.io);
      exchange(codec.set_odometry(0, 0), rec.io);
    }
    const auto readings = *codec.decode_proximity(exchange(codec.read_proximity(), rec.io)).value;
    controller->observe(codec.robot(), readings, rec.obs);
    controller->step(codec.robot(), rec.obs, rec.cmd);
    exchange(codec.set_speed(static_cast<std::int32_t>(rec.cmd[2]),
                             static_cast<std::int32_t>(rec.cmd[3])),
             rec.io);
    const auto odo = *codec.decode_odometry(exchange(codec.read_odometry(), rec.io)).value;
    rec.step = s;
    rec.time_ns = s * 100000;
    rec.odo.assign({odo.left, odo.right});
    rec.state = controller->state_hash();
    text += devices::format_record(rec) + "\n";
  }
  devices::LogStop stop{steps, "done", {}};
  for (const auto& command : codec.safe_stop()) exchange(command, stop.io);
  exchange(codec.read_speed(), stop.io);
  return text + devices::format_stop(stop) + "\n";
}

const std::string& long_log() {
  static const std::string log = make_log(2000);
  return log;
}

// The replay's result, or the error it threw.
using Outcome = std::variant<devices::ReplayResult, std::string>;
Outcome replay_with(const std::string& path, devices::detail::ReadAhead mode) {
  devices::detail::set_read_ahead(mode);
  Outcome out;
  try {
    out = devices::replay(path);
  } catch (const antkit::kernel::InputError& e) {
    out = std::string(e.what());
  }
  devices::detail::set_read_ahead(devices::detail::ReadAhead::Auto);
  return out;
}

std::string describe(const Outcome& o) {
  if (const auto* e = std::get_if<std::string>(&o)) return "error: " + *e;
  const auto& r = std::get<devices::ReplayResult>(o);
  std::ostringstream s;
  s << "steps " << r.steps << ", identical " << r.identical << ", truncated " << r.truncated
    << ", complete " << r.complete << ", hash " << r.hash;
  if (r.first_divergence)
    s << ", divergence at " << r.first_divergence->step << " " << r.first_divergence->field;
  return s.str();
}

void write(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

} // namespace

TEST_CASE("replay reads ahead to the same result: the recorded log", "[devices][replay]") {
  TempDir dir;
  const auto path = dir.file("long.jsonl");
  write(path, long_log());
  const auto ahead = replay_with(path, devices::detail::ReadAhead::Always);
  const auto here = replay_with(path, devices::detail::ReadAhead::Never);
  INFO(describe(ahead) << " / " << describe(here));
  REQUIRE(std::holds_alternative<devices::ReplayResult>(ahead));
  CHECK(std::get<devices::ReplayResult>(ahead).identical);
  CHECK(std::get<devices::ReplayResult>(ahead).steps == 2000);
  CHECK(ahead == here);
}

TEST_CASE("replay reads ahead to the same result: damaged logs", "[devices][replay][property]") {
  TempDir dir;
  const auto path = dir.file("damaged.jsonl");
  const std::string& log = long_log();
  std::vector<std::size_t> starts; // each line's first byte
  for (std::size_t at = 0; at < log.size(); at = log.find('\n', at) + 1) starts.push_back(at);
  rc::prop("the same outcome read ahead and not", [&] {
    std::string text = log;
    const auto line = *rc::gen::inRange<std::size_t>(1, starts.size() - 1);
    switch (*rc::gen::inRange(0, 4)) {
    case 0: // cut at any byte
      text.resize(*rc::gen::inRange<std::size_t>(starts[1], log.size()));
      break;
    case 1: // a malformed line
      text.replace(starts[line], starts[line + 1] - starts[line] - 1, "{\"step\":oops}");
      break;
    case 2: { // a record edited (its state hash), and maybe a malformed line after it
      const auto at = text.find("\"state\":\"", starts[line]) + 9;
      text[at] = text[at] == '0' ? '1' : '0';
      if (*rc::gen::arbitrary<bool>() && line + 1 < starts.size() - 1) {
        const auto later = *rc::gen::inRange<std::size_t>(line + 1, starts.size() - 1);
        text.replace(starts[later], starts[later + 1] - starts[later] - 1, "junk");
      }
      break;
    }
    default: // the stop record missing
      text.resize(starts.back());
    }
    write(path, text);
    const auto ahead = replay_with(path, devices::detail::ReadAhead::Always);
    const auto here = replay_with(path, devices::detail::ReadAhead::Never);
    RC_LOG() << describe(ahead) << " / " << describe(here) << "\n";
    RC_ASSERT(ahead == here);
  });
}
