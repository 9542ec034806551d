// The runs of the proved marks world (proofs/coq/AntStcWorld.v: `ant_run` and `ant_edge_run`,
// the robot running AntDecide.v's `decide` on the floor model) against the shipped run_stc of the
// ant and ant-edge variants, on the maps of its golden vectors. proof.coq.AntStcWorld requires
// coqc's `Compute` output to equal proofs/golden/AntStcWorld.out; this test requires the shipped
// code to walk the same positions and to stop where the model stops. Tested correspondence on four
// maps, beside the exhaustive ties of proof_tie_ant_stc (the decision on its whole domain, the
// world step on every map of up to 12 cells).
#include "coq_golden.hpp"
#include "test_paths.hpp"

#include <antkit/kernel/grid.hpp>
#include <antkit/stc/world.hpp>
#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using antkit::kernel::Cell;
using antkit::kernel::Occupancy;
using antkit::kernel::OccupancyGrid;

struct GoldenMap {
  const char* name;
  std::vector<Cell> cells; // as in the comment before the map's Compute in AntStcWorld.v
  Cell start;
  int quadrant; // E = 0, N = 1, W = 2, S = 3
};

const std::vector<GoldenMap>& golden_maps() {
  static const std::vector<GoldenMap> maps{
      {"ant_l", {{0, 0}, {0, 1}, {0, 2}, {1, 2}}, {0, 0}, 3},
      {"ant_block_2x3", {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {0, 2}, {1, 2}}, {0, 0}, 2},
      {"ant_ring", {{0, 0}, {1, 0}, {2, 0}, {0, 1}, {2, 1}, {0, 2}, {1, 2}, {2, 2}}, {1, 2}, 1},
      {"ant_two", {{0, 0}, {1, 0}, {0, 1}, {3, 0}, {3, 1}, {3, 2}}, {0, 1}, 0},
  };
  return maps;
}

OccupancyGrid sub_cell_map(const std::vector<Cell>& cells) {
  std::int32_t w = 0, h = 0;
  for (const Cell c : cells) {
    w = std::max(w, c.x + 1);
    h = std::max(h, c.y + 1);
  }
  OccupancyGrid map(2 * w, 2 * h, Occupancy::Blocked);
  for (const Cell c : cells)
    for (int q = 0; q < 4; ++q) map[antkit::stc::subcell_of(c, q)] = Occupancy::Free;
  return map;
}

// How many of the results in the golden file end in ", Stopped)".
int stopped_results(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  int n = 0;
  for (std::size_t pos = 0; (pos = text.find("Stopped)", pos)) != std::string::npos; ++pos) ++n;
  return n;
}

} // namespace

TEST_CASE("the shipped ant and ant-edge runs equal the proved marks world's golden runs - an L a "
          "2 x 3 block a ring and two components",
          "[proofs][stc]") {
  const std::string path = antkit::test::source_path("proofs/golden/AntStcWorld.out");
  const auto vectors = antkit::test::coq_golden_vectors(path);
  const auto& maps = golden_maps();
  // ant_run on each map, then ant_edge_run on each map.
  REQUIRE(vectors.size() == 2 * maps.size());
  CHECK(stopped_results(path) == static_cast<int>(vectors.size()));
  for (std::size_t v = 0; v < vectors.size(); ++v) {
    const GoldenMap& g = maps[v % maps.size()];
    const auto variant =
        v < maps.size() ? antkit::stc::Variant::Ant : antkit::stc::Variant::AntEdge;
    INFO("golden run " << v << ": " << g.name << (v < maps.size() ? " (ant)" : " (ant-edge)"));
    const std::vector<int>& xy = vectors[v];
    REQUIRE(xy.size() % 2 == 0);
    std::vector<Cell> model;
    for (std::size_t k = 0; k < xy.size(); k += 2) model.push_back({xy[k], xy[k + 1]});
    const OccupancyGrid map = sub_cell_map(g.cells);
    const Cell start = antkit::stc::subcell_of(g.start, g.quadrant);
    REQUIRE(model.front() == start);
    const antkit::stc::RunResult shipped = antkit::stc::run_stc(map, start, variant);
    CHECK(shipped.closed);
    CHECK_FALSE(shipped.refused);
    REQUIRE(shipped.path.size() == model.size());
    for (std::size_t k = 0; k < model.size(); ++k) {
      INFO("position " << k);
      CHECK(shipped.path[k] == model[k]);
    }
  }
}
