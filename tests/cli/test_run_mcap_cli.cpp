// `antkit stc --mcap`, `cover --mcap` and `check cover --mcap` (issue 42: --mcap where a run has a
// timeline), read back with the tests' own MCAP reader (every CRC, index and offset checked): a
// pose a step (a tick) at k * 100 ms, STC's spanning tree, and on /log the verdict: an exact
// variant's first repeat, or a trace's first broken rule, as an ERROR at its step.
#include "antkit_child.hpp"
#include "mcap_reader.hpp"
#include "run_antkit.hpp"
#include "scratch_dir.hpp"
#include "test_paths.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <unistd.h>

using antkit::test::run_antkit;
using antkit::test::slurp;
using Catch::Matchers::Contains;

TEST_CASE("antkit stc --mcap: a pose a step, the tree, and the first repeat at its step",
          "[cli][mcap]") {
  const antkit::test::ScratchDir dir("stc-mcap");
  const std::string map = antkit::test::source_path("data/maps/movingai/empty-32-32.map");
  // Marker noise makes the ant variant repeat sub-cells: the JSON path says where first.
  const std::string out = (dir / "noisy.mcap").string();
  const auto r = run_antkit("stc --map " + map +
                            " --variant ant --noise 0.02 --seed 3 --format "
                            "json --mcap " +
                            out);
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  REQUIRE(j["repeats"].get<int>() > 0);
  std::size_t first_repeat = 0;
  std::set<std::pair<int, int>> seen;
  for (std::size_t k = 0; k < j["path"].size(); ++k)
    if (!seen.insert({j["path"][k][0].get<int>(), j["path"][k][1].get<int>()}).second) {
      first_repeat = k;
      break;
    }
  REQUIRE(first_repeat > 0);
  const auto file = antkit::test::mcap::read(slurp(out));
  std::map<std::string, std::size_t> counts;
  std::vector<nlohmann::json> errors;
  for (const auto& m : file.messages) {
    const std::string topic = file.channels.at(m.channel_id).topic;
    ++counts[topic];
    const auto body = nlohmann::json::parse(m.data);
    if (topic == "/pose") {
      CHECK(m.log_time == m.sequence * 100000000ULL);
      // The sub-cell's centre: 1 m a sub-cell, y up from the map's bottom row.
      const auto& p = j["path"][m.sequence];
      CHECK(body["pose"]["position"]["x"] == p[0].get<double>() + 0.5);
      CHECK(body["pose"]["position"]["y"] == 32 - 1 - p[1].get<double>() + 0.5);
    }
    if (topic == "/log" && body["level"] == 4) {
      // The first repeat at its step; the broken invariants at the last step.
      CHECK(m.sequence == (errors.empty() ? first_repeat : j["path"].size() - 1));
      errors.push_back(body);
    }
    if (topic == "/tree") CHECK(body["entities"][0]["lines"][0]["points"].size() >= 2);
  }
  CHECK(counts["/pose"] == j["path"].size());
  CHECK(counts["/map"] == 1);
  CHECK(counts["/tree"] == 1);
  REQUIRE(errors.size() == 2); // the first repeat, then the broken invariants at the end
  CHECK_THAT(errors[0]["message"].get<std::string>(), Contains("entered a second time"));
  CHECK_THAT(errors[1]["message"].get<std::string>(), Contains("breaks an invariant"));
  // A map too large for a message a step is refused before the run, and nothing is written.
  std::ofstream(dir / "big.txt") << std::string(2100, '.') + "\n"
                                 << [] {
                                      std::string rows;
                                      for (int i = 1; i < 2100; ++i)
                                        rows += std::string(2100, '.') + "\n";
                                      return rows;
                                    }();
  const auto big = run_antkit("stc --map " + (dir / "big.txt").string() +
                              " --variant offline --mcap " + (dir / "big.mcap").string());
  CHECK(big.status == 2);
  CHECK_THAT(big.err, Contains("--mcap"));
  CHECK(big.out.empty());
  CHECK_FALSE(std::filesystem::exists(dir / "big.mcap"));
}

TEST_CASE("antkit cover --mcap and check cover --mcap: every robot each tick, the broken rule at "
          "its tick",
          "[cli][mcap]") {
  const antkit::test::ScratchDir dir("cover-mcap");
  const std::string map = antkit::test::source_path("data/maps/movingai/empty-32-32.map");
  const std::string trace = (dir / "run.trace").string(), mcap = (dir / "run.mcap").string();
  const auto r = run_antkit("cover --map " + map +
                            " --algo pm --robots 3 --limit 40 --format json "
                            "--trace " +
                            trace + " --mcap " + mcap);
  REQUIRE(r.status == 0);
  const auto file = antkit::test::mcap::read(slurp(mcap));
  std::map<std::string, std::size_t> counts;
  for (const auto& m : file.messages) {
    const std::string topic = file.channels.at(m.channel_id).topic;
    ++counts[topic];
    if (topic == "/log")
      CHECK(nlohmann::json::parse(m.data)["level"] == 2); // the run keeps every rule
    if (topic.rfind("/robot", 0) == 0) CHECK(m.log_time == m.sequence * 100000000ULL);
  }
  const auto ticks = counts["/robot0/pose"];
  CHECK(ticks >= 2);
  CHECK(counts["/robot1/pose"] == ticks);
  CHECK(counts["/robot2/pose"] == ticks);
  CHECK(counts["/log"] == 2);
  // Without --trace the scratch trace beside the MCAP file is gone.
  const auto alone = run_antkit("cover --map " + map + " --algo rw --limit 10 --mcap " +
                                (dir / "alone.mcap").string());
  CHECK(alone.status == 0);
  CHECK(std::filesystem::exists(dir / "alone.mcap"));
  CHECK_FALSE(std::filesystem::exists(dir / "alone.mcap.trace.tmp"));
  // A trace edited to teleport robot 1 at tick 2: check cover exits 1 and the MCAP file holds
  // the broken rule as an ERROR at tick 2's time.
  std::istringstream lines(slurp(trace));
  std::string edited, line;
  while (std::getline(lines, line)) {
    if (line.rfind("2,1,", 0) == 0) line = "2,1,30,30,0";
    edited += line + "\n";
  }
  std::ofstream(dir / "edited.trace") << edited;
  const auto bad =
      run_antkit("check cover --map " + map + " --log " + (dir / "edited.trace").string() +
                 " --mcap " + (dir / "edited.mcap").string());
  CHECK(bad.status == 1);
  const auto edited_file = antkit::test::mcap::read(slurp((dir / "edited.mcap").string()));
  std::size_t errors = 0;
  for (const auto& m : edited_file.messages)
    if (edited_file.channels.at(m.channel_id).topic == "/log") {
      const auto body = nlohmann::json::parse(m.data);
      if (body["level"] != 4) continue;
      ++errors;
      CHECK(m.sequence == 2);
      CHECK(m.log_time == 200000000ULL);
      CHECK_THAT(body["message"].get<std::string>(), Contains("tick 2, robot 1"));
    }
  CHECK(errors == 1);
  // --mcap with --bag is refused (bag export writes a bag's run).
  const auto refused = run_antkit("check cover --map " + map +
                                  " --bag x.mcap --topic /p "
                                  "--sensor 1 --mcap " +
                                  (dir / "no.mcap").string());
  CHECK(refused.status == 2);
  CHECK_THAT(refused.err, Contains("bag export"));
}
