// `antkit record` ended by a signal, as the real executable against `antkit emulate` on a pty
// (issue 43): every signal that ends a process from a terminal, a service manager or a closed SSH
// session stops the robot first, ends the log with its stop record, prints the summary, and exits
// 128 + the signal's number, so that `record --visit 1 ... && record --visit 2 ...` stops after
// the first; the log replays.
#include "antkit_child.hpp"
#include "run_antkit.hpp"

#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

using antkit::test::run_antkit;
using Child = antkit::test::AntkitChild;

namespace {

std::size_t lines_in(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::size_t n = 0;
  for (std::string line; std::getline(in, line);) ++n;
  return n;
}

} // namespace

TEST_CASE("antkit record exits 128 + N on signal N, after stopping the robot", "[cli][devices]") {
  const auto dir = antkit::test::scratch_dir("record-signals", "signals");
  for (const auto& [sig, name] : {std::pair{SIGINT, "SIGINT"}, std::pair{SIGTERM, "SIGTERM"},
                                  std::pair{SIGHUP, "SIGHUP"}, std::pair{SIGQUIT, "SIGQUIT"}}) {
    INFO(name);
    antkit::test::Emulator emu({"hemisson", "--arena", "circle:d=8"});
    const auto log = dir / (std::string(name) + ".jsonl");
    Child record({"record", "--device", "hemisson", "--port", emu.port(), "--controller", "buffon",
                  "--steps", "1000000000", "--out", log.string(), "--format", "json"});
    for (int i = 0; i < 3000 && lines_in(log) < 3; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    REQUIRE(lines_in(log) >= 3);
    const auto [status, out] = record.finish(sig);
    CHECK(status == 128 + sig);
    const auto j = nlohmann::json::parse(out);
    CHECK(j["stopped"] == std::string("interrupted by ") + name);
    CHECK(j["robot_stopped"] == true);
    CHECK(j["safe_stop"] == "acknowledged");
    CHECK(j["completed"] == false);
    const auto replay = run_antkit("replay " + log.string() + " --format json");
    INFO(replay.err);
    CHECK(replay.status == 0);
    CHECK(nlohmann::json::parse(replay.out)["identical"] == true);
  }
}

TEST_CASE("antkit record against a silent robot gives up within --stop-within and exits 1",
          "[cli][devices]") {
  const auto dir = antkit::test::scratch_dir("record-signals", "silent");
  antkit::test::Emulator emu({"epuck", "--arena", "circle:d=8", "--fault", "silent=30"});
  const auto log = dir / "silent.jsonl";
  const auto r = run_antkit("record --device epuck --port " + emu.port() +
                            " --controller buffon --steps 1000 --timeout 40 --tries 3"
                            " --stop-within 200 --out " +
                            log.string() + " --format json");
  INFO(r.err);
  CHECK(r.status == 1);
  CHECK(r.err.find("antkit: no acknowledgement of") != std::string::npos); // said while trying
  CHECK(r.err.find("the robot may still be moving") != std::string::npos);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["robot_stopped"] == false);
  const std::string failure = j["safe_stop"];
  CHECK(failure.find("gave up after 200 ms") != std::string::npos);
  CHECK(failure.find("not sent (the wheels' stop was not acknowledged)") != std::string::npos);
  const auto bad =
      run_antkit("record --device epuck --port " + emu.port() +
                 " --controller buffon --stop-within 0 --out " + (dir / "never.jsonl").string());
  CHECK(bad.status == 2);
  CHECK(bad.err.find("--stop-within") != std::string::npos);
  CHECK(!std::filesystem::exists(dir / "never.jsonl"));
}
