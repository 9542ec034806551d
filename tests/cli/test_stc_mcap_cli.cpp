// `antkit stc --mcap` (issue 42: --mcap where a run has a timeline): the tour read back with the
// tests' own MCAP reader (every CRC, index and offset checked): a pose a step at step * 100 ms, the
// spanning tree, and on /log an exact variant's first repeat as an ERROR at its step.
#include "mcap_reader.hpp"
#include "run_antkit.hpp"
#include "test_paths.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <unistd.h>

using antkit::test::run_antkit;
using Catch::Matchers::Contains;

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

} // namespace

TEST_CASE("antkit stc --mcap: a pose a step, the tree, and the first repeat at its step",
          "[cli][mcap]") {
  const auto dir =
      std::filesystem::temp_directory_path() / ("antkit-stc-mcap-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
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
  std::filesystem::remove_all(dir);
}
