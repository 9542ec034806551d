// A hardware log as MCAP (devices/mcap_export.hpp): the channels, their schemas and counts for a
// committed recording (data/logs) and for one recorded here through an emulator; the same bytes
// twice; the replay's side-by-side file and its divergence. Read back with the test's MCAP reader
// (tests/support/mcap_reader.hpp). The official readers check the same files in ctest interop.mcap.
#include "emulated_robot.hpp"
#include "mcap_reader.hpp"
#include "test_paths.hpp"

#include <antkit/devices/log.hpp>
#include <antkit/devices/mcap_export.hpp>
#include <antkit/devices/odometry.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/devices/robot.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>
#include <sstream>

namespace devices = antkit::devices;
namespace reader = antkit::test::mcap;
using antkit::test::TempDir;

namespace {

std::string committed(const std::string& name) {
  return std::string(antkit::test::source_dir()) + "/data/logs/" + name;
}

devices::McapOptions with_arenas() {
  devices::McapOptions o;
  o.arena_walls = [](const std::string& spec) {
    return antkit::geometry::build_arena_spec(spec).arena.walls_fx();
  };
  return o;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// topic -> (schema name, messages)
std::map<std::string, std::pair<std::string, std::size_t>> channels_of(const reader::File& f) {
  std::map<std::string, std::pair<std::string, std::size_t>> out;
  for (const auto& [id, c] : f.channels)
    out[c.topic] = {c.schema_id == 0 ? "" : f.schemas.at(c.schema_id).name, 0};
  for (const auto& m : f.messages) ++out[f.channels.at(m.channel_id).topic].second;
  return out;
}

std::vector<nlohmann::json> messages_on(const reader::File& f, const std::string& topic) {
  std::vector<nlohmann::json> out;
  for (const auto& m : f.messages)
    if (f.channels.at(m.channel_id).topic == topic) out.push_back(nlohmann::json::parse(m.data));
  return out;
}

} // namespace

TEST_CASE("base64 as RFC 4648 spells it", "[devices][mcap]") {
  CHECK(devices::base64("") == "");
  CHECK(devices::base64("f") == "Zg==");
  CHECK(devices::base64("fo") == "Zm8=");
  CHECK(devices::base64("foo") == "Zm9v");
  CHECK(devices::base64("foobar") == "Zm9vYmFy");
  CHECK(devices::base64(std::string("\xff\x00\r\n", 4)) == "/wANCg==");
}

TEST_CASE("export mcap of a committed recording: channels, schemas, counts, same bytes",
          "[devices][mcap]") {
  TempDir dir;
  const auto log = committed("khepera_buffon_circle8.jsonl");
  const auto out = dir.file("k.mcap");
  const auto s = devices::export_mcap(log, out, with_arenas());
  const std::string bytes = slurp(out);
  CHECK(s.bytes == bytes.size());
  const auto f = reader::read(bytes);
  CHECK(f.library == "antkit");
  CHECK(f.profile == "");
  for (const auto& [id, schema] : f.schemas) CHECK(schema.encoding == "jsonschema");
  for (const auto& [id, c] : f.channels) CHECK(c.encoding == "json");
  using C = std::pair<std::string, std::size_t>;
  const std::map<std::string, C> expected{{"/pose", {"foxglove.PoseInFrame", 120}},
                                          {"/trail", {"foxglove.PosesInFrame", 60}},
                                          {"/antkit/step", {"antkit.Step", 120}},
                                          {"/antkit/io", {"antkit.Exchanges", 120}},
                                          {"/log", {"foxglove.Log", 2}},
                                          {"/arena", {"foxglove.SceneUpdate", 1}}};
  CHECK(channels_of(f) == expected);
  CHECK(s.messages == f.messages.size());
  CHECK(f.indexed_messages == f.messages.size());

  // Step 40 as the log holds it: times, sequence, command, bytes.
  devices::LogReader lr(log);
  devices::LogRecord r;
  for (int i = 0; i <= 40; ++i) REQUIRE(lr.next(r));
  const auto steps = messages_on(f, "/antkit/step");
  const auto& j = steps.at(40);
  CHECK(j["step"] == 40);
  CHECK(j["cmd"].get<std::vector<std::int64_t>>() == r.cmd);
  CHECK(j["odo"].get<std::vector<std::int64_t>>() == r.odo);
  CHECK(j["timestamp"]["sec"].get<std::int64_t>() * 1'000'000'000 +
            j["timestamp"]["nsec"].get<std::int64_t>() ==
        r.time_ns);
  const auto io = messages_on(f, "/antkit/io").at(40);
  REQUIRE(io["io"].size() == r.io.size());
  CHECK(io["io"][0]["sent"] == devices::base64(r.io[0].sent));
  for (const auto& m : f.messages) {
    const auto& topic = f.channels.at(m.channel_id).topic;
    if (topic == "/antkit/step")
      CHECK(m.log_time ==
            static_cast<std::uint64_t>(
                steps.at(m.sequence)["timestamp"]["sec"].get<std::int64_t>() * 1'000'000'000 +
                steps.at(m.sequence)["timestamp"]["nsec"].get<std::int64_t>()));
  }
  const auto logs = messages_on(f, "/log");
  CHECK(logs.back()["message"] == "stop: done");
  // The same log, the same bytes.
  const auto again = dir.file("k2.mcap");
  devices::export_mcap(log, again, with_arenas());
  CHECK(slurp(again) == bytes);
}

TEST_CASE("export mcap of a run recorded through an emulator", "[devices][mcap]") {
  TempDir dir;
  antkit::test::EmulatedRobot emu(devices::RobotKind::Epuck, "circle:d=8");
  const auto log = dir.file("epuck.jsonl");
  auto o =
      antkit::test::record_options(devices::RobotKind::Epuck, emu.port(), "buffon", {}, 45, log);
  o.link.timeout = std::chrono::milliseconds(2000);
  REQUIRE(devices::record(o).completed);
  emu.stop();
  const auto out = dir.file("epuck.mcap");
  devices::export_mcap(log, out); // no arena builder: no /arena channel
  const auto f = reader::read(slurp(out));
  const auto ch = channels_of(f);
  CHECK(ch.count("/arena") == 0);
  CHECK(ch.at("/pose").second == 45);
  CHECK(ch.at("/antkit/step").second == 45);
  CHECK(ch.at("/antkit/io").second == 45);
  CHECK(ch.at("/trail").second == 45); // every step: at most 100 over the run
  CHECK(ch.at("/log").second == 2);
  // The pose follows the dead reckoning: the robot moved away from the origin.
  const auto poses = messages_on(f, "/pose");
  CHECK(poses.back()["frame_id"] == "odom");
  // Unit quaternions about z, spelled with w >= 0.
  for (const auto& p : poses) {
    const double z = p["pose"]["orientation"]["z"], w = p["pose"]["orientation"]["w"];
    CHECK(w >= 0);
    CHECK(std::abs(z * z + w * w - 1) < 1e-3);
  }
  CHECK((poses.back()["pose"]["position"]["x"] != 0 || poses.back()["pose"]["position"]["y"] != 0));
  // The position is the dead reckoning's, in metres to the nanometre: written as a plain decimal
  // of at most nine places, within half a nanometre of the Q15.16 diameters it comes from.
  devices::LogReader lr(log);
  devices::LogRecord r;
  const auto& robot = devices::describe(devices::RobotKind::Epuck);
  std::optional<devices::DeadReckoning> dr;
  std::size_t k = 0;
  const auto texts = [&] {
    std::vector<std::string> found;
    for (const auto& m : f.messages)
      if (f.channels.at(m.channel_id).topic == "/pose") found.push_back(m.data);
    return found;
  }();
  while (lr.next(r)) {
    const devices::WheelTravel w{r.odo[0], r.odo[1]};
    if (!dr)
      dr.emplace(robot, w);
    else
      dr->update(w);
    const double unit = robot.diameter_um / 1e6 / 65536.0;
    INFO("step " << k << ": " << texts.at(k));
    const auto& at = poses.at(k)["pose"]["position"];
    CHECK(std::abs(at["x"].get<double>() - dr->position().x.raw() * unit) < 0.6e-9);
    CHECK(std::abs(at["y"].get<double>() - dr->position().y.raw() * unit) < 0.6e-9);
    for (const char* axis : {"\"x\":", "\"y\":"}) {
      const auto from = texts.at(k).find(axis) + 4;
      const auto number = texts.at(k).substr(from, texts.at(k).find_first_of(",}", from) - from);
      CHECK(number.find_first_not_of("-0123456789.") == std::string::npos);
      const auto point = number.find('.');
      if (point != std::string::npos) {
        CHECK(number.size() - point - 1 <= 9);
        CHECK(number.back() != '0');
      }
    }
    ++k;
  }
  CHECK(k == poses.size());
}

TEST_CASE("replay --mcap: recorded and replayed side by side, the divergence as an ERROR",
          "[devices][mcap]") {
  TempDir dir;
  const auto log = committed("khepera_buffon_circle8_cmd_edited.jsonl");
  const auto r = devices::replay(log);
  REQUIRE(!r.identical);
  REQUIRE(r.first_divergence->step == 40);
  const auto out = dir.file("r.mcap");
  devices::export_replay_mcap(log, r, out, with_arenas());
  const auto f = reader::read(slurp(out));
  const auto ch = channels_of(f);
  CHECK(ch.at("/recorded/step") == std::pair<std::string, std::size_t>{"antkit.Step", 120});
  CHECK(ch.at("/replayed/step") == std::pair<std::string, std::size_t>{"antkit.ReplayedStep", 41});
  const auto replayed = messages_on(f, "/replayed/step");
  CHECK(replayed.at(39)["identical"] == true);
  CHECK(replayed.back()["step"] == 40);
  CHECK(replayed.back()["identical"] == false);
  CHECK(replayed.back()["divergence"]["field"] == "cmd[1]");
  CHECK(replayed.back()["divergence"]["recorded"] == r.first_divergence->expected);
  CHECK(replayed.back()["divergence"]["replayed"] == r.first_divergence->actual);
  std::size_t errors = 0;
  const auto recorded = messages_on(f, "/recorded/step");
  for (const auto& m : f.messages)
    if (f.channels.at(m.channel_id).topic == "/log" &&
        nlohmann::json::parse(m.data)["level"] == 4) {
      ++errors;
      CHECK(m.sequence == 40);
      CHECK(nlohmann::json::parse(m.data)["timestamp"] == recorded.at(40)["timestamp"]);
    }
  CHECK(errors == 1);
}

TEST_CASE("export mcap refuses a malformed log at its line, and writes nothing",
          "[devices][mcap]") {
  TempDir dir;
  const auto log = dir.file("bad.jsonl");
  auto lines = antkit::test::lines_of(committed("khepera_buffon_circle8.jsonl"));
  lines[5] = "{\"step\":4,\"t_ns\":oops}";
  std::ofstream(log) << [&] {
    std::string s;
    for (const auto& l : lines) s += l + "\n";
    return s;
  }();
  const auto out = dir.file("bad.mcap");
  try {
    devices::export_mcap(log, out);
    FAIL("no error");
  } catch (const antkit::kernel::InputError& e) {
    CHECK(std::string(e.what()).find("bad.jsonl:6:") != std::string::npos);
  }
  CHECK(!std::filesystem::exists(out));
  // An arena the header names but geometry refuses: located at the header.
  lines = antkit::test::lines_of(committed("khepera_buffon_circle8.jsonl"));
  const auto at = lines[0].find("circle:d=8");
  lines[0].replace(at, 10, "circle:d=-1");
  {
    std::ofstream o(log);
    for (const auto& l : lines) o << l << "\n";
  }
  CHECK_THROWS_WITH(devices::export_mcap(log, out, with_arenas()),
                    Catch::Contains("bad.jsonl:1:1: the header's arena"));
  CHECK(!std::filesystem::exists(out));
}

TEST_CASE("export mcap: the same bytes on any number of threads, the trail growing with the run",
          "[devices][mcap]") {
  // 5000 steps (five chunks of 1024 steps and a part), the committed recording's steps over and
  // over, renumbered and retimed (the export does not replay: any well-formed log serves).
  TempDir dir;
  const auto lines = antkit::test::lines_of(committed("khepera_buffon_circle8.jsonl"));
  const std::size_t steps = 5000;
  const auto log = dir.file("long.jsonl");
  {
    std::ofstream out(log, std::ios::binary);
    out << lines[0] << '\n';
    for (std::size_t i = 0; i < steps; ++i) {
      const std::string& l = lines[1 + i % 120];
      const auto io = l.find(",\"io\":");
      out << "{\"step\":" << i << ",\"t_ns\":" << i * 1000 << l.substr(io) << '\n';
    }
    out << "{\"stop\":\"done\",\"step\":" << steps << ",\"io\":[]}\n";
  }
  std::map<unsigned, std::string> bytes;
  for (const unsigned threads : {1U, 2U, 3U, 8U}) {
    auto o = with_arenas();
    o.threads = threads;
    const auto out = dir.file("long" + std::to_string(threads) + ".mcap");
    const auto s = devices::export_mcap(log, out, o);
    CHECK(s.messages == 3 * steps + 100 + 2 + 1); // pose, step and io a step; trails; logs; arena
    bytes[threads] = slurp(out);
  }
  for (const auto& [threads, b] : bytes) {
    INFO("threads " << threads);
    CHECK(b == bytes.at(1));
  }
  const auto f = reader::read(bytes.at(1));
  CHECK(f.chunks >= 5);
  const auto poses = messages_on(f, "/pose");
  REQUIRE(poses.size() == steps);
  const auto trails = messages_on(f, "/trail");
  REQUIRE(trails.size() == 100); // every 50 steps, the last among them
  // Each trail: every 5th pose from the first (at most 1000 over the run), then the step's own.
  for (const auto& t : trails) {
    const std::size_t step = t["timestamp"]["nsec"].get<std::size_t>() / 1000;
    INFO("trail at step " << step);
    CHECK((step + 1) % 50 == 0);
    const auto& got = t["poses"];
    std::vector<std::size_t> want;
    for (std::size_t k = 0; k <= step; k += 5) want.push_back(k);
    if (step % 5 != 0) want.push_back(step);
    REQUIRE(got.size() == want.size());
    for (std::size_t j = 0; j < want.size(); ++j) CHECK(got[j] == poses[want[j]]["pose"]);
  }
  CHECK(trails.back()["poses"].back() == poses.back()["pose"]);
  // A line past the first chunks malformed: located, nothing written, on any thread count (the
  // threads formatting earlier chunks are stopped and joined).
  auto long_lines = antkit::test::lines_of(log);
  long_lines[3001] = "{\"step\":3000,\"t_ns\":oops}";
  {
    std::ofstream out(log, std::ios::binary);
    for (const auto& l : long_lines) out << l << '\n';
  }
  for (const unsigned threads : {1U, 2U, 8U}) {
    auto o = with_arenas();
    o.threads = threads;
    const auto out = dir.file("bad" + std::to_string(threads) + ".mcap");
    CHECK_THROWS_WITH(devices::export_mcap(log, out, o), Catch::Contains("long.jsonl:3002:"));
    CHECK(!std::filesystem::exists(out));
  }
}

TEST_CASE("export mcap: any records' numbers and bytes read back from the JSON", "[property]") {
  // Records of arbitrary integers (64-bit extremes among them), times and exchanged bytes: the
  // /antkit/step and /antkit/io messages hold exactly what the log holds.
  rc::prop("round trip", [] {
    const auto ints = rc::gen::container<std::vector<std::int64_t>>(
        rc::gen::oneOf(rc::gen::arbitrary<std::int64_t>(),
                       rc::gen::element(std::numeric_limits<std::int64_t>::min(),
                                        std::numeric_limits<std::int64_t>::max(), std::int64_t{0},
                                        std::int64_t{9}, std::int64_t{10}, std::int64_t{-10})));
    const auto count = *rc::gen::inRange<std::size_t>(1, 40);
    std::string log = R"({"schema":2,"antkit":"0","robot":"nobody","port":{"path":"p","baud":1,)"
                      R"("framing":"8N1"},"controller":{"name":"c","params":{}},"seed":1})"
                      "\n";
    std::vector<devices::LogRecord> records(count);
    std::int64_t t = 0;
    for (std::size_t i = 0; i < count; ++i) {
      auto& r = records[i];
      r.step = static_cast<std::int64_t>(i);
      t += *rc::gen::inRange<std::int64_t>(0, std::int64_t{1} << 40);
      r.time_ns = t;
      r.obs = *ints;
      r.cmd = *ints;
      r.odo = *ints;
      r.state = *rc::gen::arbitrary<std::uint64_t>();
      r.io = {{*rc::gen::arbitrary<std::string>(), *rc::gen::arbitrary<std::string>(),
               *rc::gen::element<std::int64_t>(-1, 0, t)}};
      log += devices::format_record(r) + "\n";
    }
    devices::LogReader reader("prop.jsonl", log);
    devices::McapOptions o;
    o.threads = 1;
    const auto f = reader::read(devices::mcap_of_log(reader, "prop.jsonl", o));
    const auto steps = messages_on(f, "/antkit/step");
    const auto io = messages_on(f, "/antkit/io");
    RC_ASSERT(steps.size() == count);
    for (std::size_t i = 0; i < count; ++i) {
      const auto& r = records[i];
      RC_ASSERT(steps[i]["obs"].get<std::vector<std::int64_t>>() == r.obs);
      RC_ASSERT(steps[i]["cmd"].get<std::vector<std::int64_t>>() == r.cmd);
      RC_ASSERT(steps[i]["odo"].get<std::vector<std::int64_t>>() == r.odo);
      RC_ASSERT(steps[i]["state"].get<std::string>() == antkit::kernel::hash_hex(r.state));
      RC_ASSERT(steps[i]["timestamp"]["sec"].get<std::int64_t>() * 1'000'000'000 +
                    steps[i]["timestamp"]["nsec"].get<std::int64_t>() ==
                r.time_ns);
      RC_ASSERT(io[i]["io"][0]["sent"].get<std::string>() == devices::base64(r.io[0].sent));
      RC_ASSERT(io[i]["io"][0]["received"].get<std::string>() == devices::base64(r.io[0].received));
      if (r.io[0].t_ns < 0)
        RC_ASSERT(io[i]["io"][0]["t_ns"].is_null());
      else
        RC_ASSERT(io[i]["io"][0]["t_ns"].get<std::int64_t>() == r.io[0].t_ns);
    }
  });
}
