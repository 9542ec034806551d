// `antkit record --mcap` and `antkit export mcap`, run as the real executables: the marker-floor
// robot's tour through its emulator, written as MCAP when the run ends and exported again from the
// log, byte for byte the same; its poses in the map's sub-cells (tests/support/mcap_reader.hpp).
#include "antkit_child.hpp"
#include "mcap_reader.hpp"
#include "run_antkit.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

using antkit::test::Emulator;
using antkit::test::run_antkit;
using antkit::test::slurp;

TEST_CASE("antkit record --mcap: the stc-floor tour as MCAP, the same as export mcap",
          "[cli][devices]") {
  const auto dir = antkit::test::scratch_dir("mcap-cli", "floor");
  const auto map = (dir / "board.map").string();
  {
    std::ofstream out(map);
    out << "type octile\nheight 4\nwidth 6\nmap\n......\n......\n......\n......\n";
  }
  const auto cal = (dir / "cal.json").string();
  REQUIRE(run_antkit("stc-floor-calibrate --ideal --out " + cal).status == 0);
  Emulator emu({"stc-floor", "--map", map, "--format", "json"});
  const auto log = (dir / "floor.jsonl").string();
  const auto recorded = (dir / "recorded.mcap").string();
  const auto r = run_antkit("record --device stc-floor --port " + emu.port() +
                            " --controller ant --map " + map + " --calibration " + cal + " --out " +
                            log + " --mcap " + recorded + " --format json");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  const auto steps = j["steps"].get<std::size_t>();
  REQUIRE(steps > 0);
  (void)emu.finish();

  const auto exported = (dir / "exported.mcap").string();
  const auto e = run_antkit("export mcap " + log + " --out " + exported + " --format json");
  REQUIRE(e.status == 0);
  const auto s = nlohmann::json::parse(e.out);
  CHECK(s["channels"]["/pose"] == steps);
  CHECK(s["channels"]["/antkit/step"] == steps);
  CHECK(s["channels"]["/log"] == 2);
  CHECK(s["channels"].count("/arena") == 0); // the floor's header names no arena
  const std::string bytes = slurp(exported);
  CHECK(slurp(recorded) == bytes);
  CHECK(s["bytes"] == bytes.size());

  const auto f = antkit::test::mcap::read(bytes);
  std::vector<nlohmann::json> poses;
  for (const auto& m : f.messages)
    if (f.channels.at(m.channel_id).topic == "/pose")
      poses.push_back(nlohmann::json::parse(m.data));
  REQUIRE(poses.size() == steps);
  CHECK(poses.front()["frame_id"] == "map");
  // The last pose is the tour's last sub-cell, as record reports it.
  const auto& path = j["tour"]["path"];
  const auto& last = poses.back()["pose"]["position"];
  CHECK(last["x"] == path.back()[0]);
  CHECK(last["y"] == path.back()[1]);
}
