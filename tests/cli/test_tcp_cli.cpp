// `antkit emulate --listen`, `record --port tcp:HOST:PORT` and `replay` end to end as the real
// executables over loopback TCP, and a port held by one `record` refused to a second (issue 26).
#include "antkit_child.hpp"
#include "run_antkit.hpp"

#include <catch2/catch.hpp>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

using antkit::test::lines_in;
using antkit::test::run_antkit;
using Child = antkit::test::AntkitChild;

namespace {

antkit::test::ScratchDir scratch_dir(const std::string& name) {
  return antkit::test::scratch_dir("tcp-cli", name);
}

} // namespace

TEST_CASE("antkit emulate --listen + record --port tcp: + replay, end to end", "[cli][devices]") {
  const auto dir = scratch_dir("e2e");
  Child emu({"emulate", "khepera", "--arena", "circle:d=8", "--listen", "127.0.0.1:0", "--format",
             "json"});
  const std::string port = emu.first_line();
  INFO(port);
  REQUIRE(port.rfind("tcp:127.0.0.1:", 0) == 0);
  CHECK(port != "tcp:127.0.0.1:0"); // the real port
  const auto log = (dir / "visit1.jsonl").string();
  const auto r =
      run_antkit("record --device khepera --port " + port +
                 " --controller buffon --visit 1 --steps 200 --out " + log + " --format json");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["steps"] == 200);
  CHECK(j["completed"] == true);

  const auto rp = run_antkit("replay " + log + " --format json");
  INFO(rp.err);
  REQUIRE(rp.status == 0);
  const auto k = nlohmann::json::parse(rp.out);
  CHECK(k["identical"] == true);
  CHECK(k["steps"] == 200);
  CHECK(k["hash"] == j["hash"]);

  // SIGTERM ends it cleanly, with its summary.
  const auto [status, summary] = emu.finish(SIGTERM);
  CHECK(status == 0);
  const auto s = nlohmann::json::parse(summary);
  CHECK(s["sessions"] == 1);
  CHECK(s["listen"] == port);
}

TEST_CASE("antkit record to a refused TCP port and with a bad spec", "[cli][devices]") {
  const auto dir = scratch_dir("bad");
  {
    // Nothing listens: a link failure (exit 1), and the summary claims no stop it never made.
    Child emu({"emulate", "khepera", "--listen", "127.0.0.1:0"});
    const std::string port = emu.first_line();
    emu.finish(SIGTERM);
    const auto refused = run_antkit("record --device khepera --port " + port +
                                    " --controller buffon --steps 5 --format json --out " +
                                    (dir / "refused.jsonl").string());
    INFO(refused.err);
    CHECK(refused.status == 1);
    const auto j = nlohmann::json::parse(refused.out);
    CHECK(j["safe_stop"] == "not needed: never connected");
    CHECK(j["hash"].is_null());
    CHECK(j["steps"] == 0);
    CHECK(j["stopped"].get<std::string>().rfind("link: disconnected", 0) == 0);
  }
  const auto bad = run_antkit("record --device khepera --port tcp:127.0.0.1:x --controller buffon "
                              "--steps 5 --out " +
                              (dir / "a.jsonl").string());
  CHECK(bad.status == 2);
  CHECK(bad.err.find("--port") != std::string::npos);
  CHECK(!std::filesystem::exists(dir / "a.jsonl"));
  const auto listen = run_antkit("emulate khepera --listen 127.0.0.1");
  CHECK(listen.status == 2);
  CHECK(listen.err.find("--listen") != std::string::npos);
  const auto floor = run_antkit("emulate stc-floor --listen 127.0.0.1:0");
  CHECK(floor.status == 2);
}

TEST_CASE("a second antkit record on a port a first one holds exits 2: port busy",
          "[cli][devices]") {
  const auto dir = scratch_dir("busy");
  Child emu({"emulate", "khepera", "--arena", "circle:d=8"});
  const std::string pty = emu.first_line();
  REQUIRE(pty.rfind("/dev/pts/", 0) == 0);
  const auto first_log = dir / "first.jsonl";
  Child first({"record", "--device", "khepera", "--port", pty, "--controller", "buffon", "--steps",
               "1000000000", "--out", first_log.string(), "--format", "json"});
  // The first holds the port once it has written a step.
  for (int i = 0; i < 3000 && lines_in(first_log) < 2; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  REQUIRE(lines_in(first_log) >= 2);

  const auto second_log = dir / "second.jsonl";
  const auto r = run_antkit("record --device khepera --port " + pty +
                            " --controller buffon --steps 5 --out " + second_log.string());
  INFO(r.err);
  CHECK(r.status == 2);
  CHECK(r.err.find("port busy") != std::string::npos);
  CHECK(r.err.find("held by process " + std::to_string(first.pid())) != std::string::npos);
  CHECK(!std::filesystem::exists(second_log));

  // The first run goes on and stops cleanly on SIGINT: the robot stopped, exit 128 + 2.
  const auto [status, out] = first.finish(SIGINT);
  CHECK(status == 130);
  CHECK(nlohmann::json::parse(out)["robot_stopped"] == true);
  emu.finish(SIGTERM);
}

TEST_CASE(
    "antkit record waits for the Webots relay's slow step by default: no command is sent twice",
    "[cli][devices]") {
  // Every reply 300 ms late, as a real-time relay answers within its 250 ms control step plus
  // jitter: the relay's default timeout (1000 ms, robot.hpp) waits for it, where the robots' 250 ms
  // would resend each command, and the relay would execute the resend as a second command.
  const auto dir = scratch_dir("webots-timeout");
  Child emu({"emulate", "khepera-webots", "--arena", "circle:d=8", "--fault", "delay=1:300",
             "--listen", "127.0.0.1:0"});
  const std::string port = emu.first_line();
  const auto r = run_antkit("record --device khepera-webots --port " + port +
                            " --controller buffon --visit 1 --steps 2 --out " +
                            (dir / "relay.jsonl").string() + " --format json");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["retries"] == 0);
  CHECK(j["faults"]["timeouts"] == 0);
  emu.finish(SIGTERM);
}

TEST_CASE("antkit record refuses a robot that is not --device's: exit 2, no log, the robot not "
          "driven",
          "[cli][devices]") {
  const auto dir = scratch_dir("wrong-robot");
  Child emu({"emulate", "khepera-webots", "--arena", "circle:d=8", "--listen", "127.0.0.1:0",
             "--format", "json"});
  const std::string port = emu.first_line();
  const auto log = dir / "wrong.jsonl";
  const auto r = run_antkit("record --device khepera --port " + port +
                            " --controller buffon --visit 1 --steps 100 --out " + log.string() +
                            " --format json");
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK(r.err ==
        "antkit: error: --device: khepera at " + port +
            ": the robot answers 'b,0,0\\r\\n' to 'B\\r', not as --device khepera does "
            "(b,BIOS,PROTOCOL with dotted version numbers (b,5.02,5.01 on a Khepera II)); "
            "it answers as --device khepera-webots does (only the identification was sent: "
            "the robot was not driven)\n");
  CHECK(!std::filesystem::exists(log));
  const auto [status, summary] = emu.finish(SIGTERM);
  CHECK(status == 0);
  const auto s = nlohmann::json::parse(summary);
  CHECK(s["commands"] == 1); // B, and nothing else
  CHECK(s["periods"] == 0);  // never moved
}
