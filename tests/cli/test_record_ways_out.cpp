// `antkit record`'s ways out, as the real executable against `antkit emulate` on a pty (issue 43):
// every signal that ends a process from a terminal, a service manager or a closed SSH session
// stops the robot first, ends the log with its stop record, prints the summary, and exits 128 +
// the signal's number, so that `record --visit 1 ... && record --visit 2 ...` stops after the
// first (the log replays); a silent robot's safe stop is bounded; a full disk stops the robot and
// says so (exit 1 with the summary, not an internal error); an arena spec that names no arena and a
// log that is the robot's own port are refused before the robot moves.
#include "antkit_child.hpp"
#include "run_antkit.hpp"

#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <sys/wait.h>
#include <thread>

using antkit::test::lines_in;
using antkit::test::run_antkit;
using Child = antkit::test::AntkitChild;

TEST_CASE("antkit record exits 128 + N on signal N, after stopping the robot", "[cli][devices]") {
  const auto dir = antkit::test::scratch_dir("record-ways-out", "signals");
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
  const auto dir = antkit::test::scratch_dir("record-ways-out", "silent");
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

TEST_CASE("antkit record refuses an arena that names none and a log that is the robot's port",
          "[cli][devices]") {
  const auto dir = antkit::test::scratch_dir("record-ways-out", "refusals");
  antkit::test::Emulator emu({"khepera", "--arena", "circle:d=8"});
  for (const std::string arena : {"nonsense", "circle:d=-1", "circle:x=3", "missing.wkt"}) {
    INFO(arena);
    const auto log = dir / "arena.jsonl";
    const auto r =
        run_antkit("record --device khepera --port " + emu.port() +
                   " --controller buffon --steps 5 --arena " + arena + " --out " + log.string());
    CHECK(r.status == 2);
    CHECK(r.err.find(arena == "missing.wkt" ? "antkit: error: missing.wkt"
                                            : "antkit: error: --arena") != std::string::npos);
    CHECK(!std::filesystem::exists(log));
  }
  const auto port = run_antkit("record --device khepera --port " + emu.port() +
                               " --controller buffon --steps 5 --force --out " + emu.port());
  CHECK(port.status == 2);
  CHECK(port.err.find("is the robot's port") != std::string::npos);
  // The emulator was not written to: a run after it is answered as usual.
  const auto ok = run_antkit("record --device khepera --port " + emu.port() +
                             " --controller buffon --steps 5 --arena circle:d=8 --out " +
                             (dir / "ok.jsonl").string());
  INFO(ok.err);
  CHECK(ok.status == 0);
}

TEST_CASE("antkit record on a full disk stops the robot and says the log is not whole",
          "[cli][devices]") {
  // A file size limit (ulimit -f, with SIGXFSZ ignored so that a write past it fails with EFBIG)
  // stands in for a full disk: the log fills after a few dozen records.
  const auto dir = antkit::test::scratch_dir("record-ways-out", "full");
  antkit::test::Emulator emu({"epuck", "--arena", "circle:d=8"});
  const auto log = dir / "full.jsonl";
  const auto err = dir / "full.err";
  const std::string cmd =
      "sh -c \"ulimit -f 16; trap '' XFSZ; exec " + std::string(antkit::test::antkit_exe()) +
      " record --device epuck --port " + emu.port() + " --controller buffon --steps 100000 --out " +
      log.string() + " --format json\" 2>" + err.string();
  FILE* pipe = ::popen(cmd.c_str(), "r");
  REQUIRE(pipe != nullptr);
  std::string out;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) out.append(buf, n);
  const int raw = ::pclose(pipe);
  std::ifstream e(err);
  const std::string stderr_text((std::istreambuf_iterator<char>(e)), {});
  INFO(stderr_text);
  REQUIRE(WIFEXITED(raw));
  CHECK(WEXITSTATUS(raw) == 1); // a failed run, not an internal error (3)
  const auto j = nlohmann::json::parse(out);
  CHECK(j["robot_stopped"] == true); // the robot was stopped although the log could not say so
  CHECK(j["stopped"].get<std::string>().rfind("error: writing the log", 0) == 0);
  CHECK(j["log_error"].get<std::string>().find("File too large") != std::string::npos);
  CHECK(stderr_text.find("the log is not whole") != std::string::npos);
  // What the log holds replays as far as it goes.
  const auto replay = run_antkit("replay " + log.string() + " --format json");
  INFO(replay.err);
  CHECK(std::filesystem::file_size(log) <= 16 * 512);
  CHECK(nlohmann::json::parse(replay.out)["steps"].get<int>() > 0);
}
