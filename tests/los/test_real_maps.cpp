// Every real map in data/maps (MovingAI and ROS, up to 530x481 and ~600x600 cells): both
// algorithms finish, the final map is sound, and every observable cell is explored.
#include "run_antkit.hpp"

#include <antkit/los/explore.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/testing/los.hpp>
#include <catch2/catch.hpp>
#include <filesystem>

namespace los = antkit::los;

TEST_CASE("real maps: both algorithms complete soundly", "[slow]") {
  std::vector<std::filesystem::path> maps;
  for (const char* dir : {"movingai", "ros"})
    for (const auto& entry : std::filesystem::directory_iterator(antkit::test::shared_map(dir))) {
      const auto ext = entry.path().extension();
      if (ext == ".map" || ext == ".yaml") maps.push_back(entry.path());
    }
  std::sort(maps.begin(), maps.end());
  REQUIRE(maps.size() >= 17);
  for (const auto& path : maps) {
    const auto map = antkit::maps::load_map(path);
    const auto pair = los::start_pair(map.cells, los::default_start(map.cells));
    for (const auto algo : {los::Algorithm::FastWallFollow, los::Algorithm::Frontier}) {
      los::ExploreOptions options;
      options.algorithm = algo;
      const auto r = los::explore(map.cells, pair[0], pair[1], options);
      INFO(path.filename().string() << ", algorithm " << static_cast<int>(algo));
      CHECK(antkit::testing::check_sound(map.cells, r.cells).empty());
      CHECK(antkit::testing::check_complete(map.cells, r).empty());
      CHECK(r.explored + r.unobservable == map.cells.size());
    }
  }
}
