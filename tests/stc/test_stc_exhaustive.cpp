// Exhaustive small-scope checks of issue 3: every map up to 4 x 4 cells with every start.
#include "stc_test_maps.hpp"

#include <antkit/stc/offline.hpp>
#include <antkit/stc/world.hpp>
#include <antkit/testing/stc.hpp>
#include <catch2/catch.hpp>

using antkit::kernel::Cell;
using antkit::kernel::Occupancy;
using antkit::kernel::OccupancyGrid;
using namespace antkit::stc;

namespace {

// Runs every cell map of cw x ch cells (a bit per cell: blocked or free) with every start sub-cell
// of every free cell: checks the offline tour's invariants 1-4 and that each of `others` produces
// it move for move. Returns the number of (map, start) pairs checked.
std::int64_t exhaust(int cw, int ch, const std::vector<Variant>& others) {
  OccupancyGrid map(2 * cw, 2 * ch, Occupancy::Free);
  antkit::testing::StcTourChecker checker;
  StcWorld world;
  std::int64_t pairs = 0;
  const std::uint32_t maps = 1u << (cw * ch);
  for (std::uint32_t mask = 0; mask < maps; ++mask) {
    antkit::stc::testing::cell_mask_map(map, cw, ch, mask);
    for (int c = 0; c < cw * ch; ++c) {
      if ((mask >> c) & 1u) continue;
      for (int q = 0; q < 4; ++q) {
        const Cell start = subcell_of({c % cw, c / cw}, q);
        const RunResult offline = run_stc(world, map, start, Variant::Offline);
        const auto check = checker.check_exact(map, start, offline.path);
        if (!check.ok) {
          INFO("map " << cw << "x" << ch << " cells, blocked mask " << mask << ", start ("
                      << start.x << ", " << start.y << "): " << check);
          REQUIRE(check.ok);
        }
        for (Variant v : others) {
          const RunResult r = run_stc(world, map, start, v);
          const auto same =
              antkit::testing::check_same_tour(offline.path, r.path, std::string(variant_name(v)));
          if (!same.ok) {
            INFO("map " << cw << "x" << ch << " cells, blocked mask " << mask << ", start ("
                        << start.x << ", " << start.y << "): " << same);
            REQUIRE(same.ok);
          }
        }
        ++pairs;
      }
    }
  }
  return pairs;
}

} // namespace

TEST_CASE("every cell map up to 4 x 3 cells - every start: invariants 1-5 for all exact variants",
          "[stc][proof]") {
  std::int64_t pairs = 0;
  for (int cw = 1; cw <= 4; ++cw)
    for (int ch = 1; ch <= 4; ++ch)
      if (cw * ch <= 12)
        pairs += exhaust(cw, ch, {Variant::Online, Variant::Ant, Variant::AntEdge});
  // Sum over the sizes of (free cells x 4 starts) over all maps: n * 2^(n-1) * 4 for n cells.
  std::int64_t expected = 0;
  for (int cw = 1; cw <= 4; ++cw)
    for (int ch = 1; ch <= 4; ++ch) {
      const int n = cw * ch;
      if (n <= 12) expected += std::int64_t{n} * (std::int64_t{1} << (n - 1)) * 4;
    }
  CHECK(pairs == expected);
}

// The largest part (2^16 maps, 2.1 million map-start pairs, 8.4 million tours): about 15 s of one
// core in the release build, so it is tagged [slow] as well (still run by `make test`).
TEST_CASE("every 4 x 4 cell map - every start: invariants 1-5 for all exact variants",
          "[stc][proof][slow]") {
  const std::int64_t pairs = exhaust(4, 4, {Variant::Online, Variant::Ant, Variant::AntEdge});
  CHECK(pairs == std::int64_t{16} * (std::int64_t{1} << 15) * 4);
}

TEST_CASE("full: every sub-cell map of 2 x 2 cells (4 x 4 sub-cells) - every free start",
          "[stc][proof]") {
  OccupancyGrid map(4, 4, Occupancy::Free);
  antkit::testing::StcTourChecker checker;
  StcWorld world;
  std::int64_t runs = 0;
  for (std::uint32_t mask = 0; mask < (1u << 16); ++mask) {
    for (int i = 0; i < 16; ++i)
      map[{i % 4, i / 4}] = ((mask >> i) & 1u) ? Occupancy::Blocked : Occupancy::Free;
    for (int i = 0; i < 16; ++i) {
      if ((mask >> i) & 1u) continue;
      const Cell start{i % 4, i / 4};
      const RunResult r = run_stc(world, map, start, Variant::Full);
      const auto check = checker.check_full(map, start, r.path, r.repeats);
      if (!check.ok) {
        INFO("sub-cell mask " << mask << ", start (" << start.x << ", " << start.y
                              << "): " << check);
        REQUIRE(check.ok);
      }
      ++runs;
    }
  }
  CHECK(runs == std::int64_t{16} * (1 << 15));
}
