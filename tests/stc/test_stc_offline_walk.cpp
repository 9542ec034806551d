// The fast paths of offline STC (the mask-and-table depth-first search, the run-at-a-time walk
// SpanningTree::tour, and the tour the search emits as it builds the tree) against references that
// share none of their code: the tour equals the cursor walk of the same tree
// (SpanningTree::advance, one sub-cell per step) and the tour of online STC (an independent
// depth-first search with the same neighbour order, run in the world), on random maps large enough
// to cross the 64 x 64-cell tiles of the tree's memory, with odd sizes and blocked border cells.
#include "stc_test_maps.hpp"

#include <antkit/stc/offline.hpp>
#include <antkit/stc/world.hpp>
#include <antkit/testing/stc.hpp>
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>
#include <string>
#include <vector>

using antkit::kernel::Cell;
using antkit::kernel::Occupancy;
using antkit::kernel::OccupancyGrid;
using namespace antkit::stc;

namespace {

// The tour by the cursor: begin(), then advance() until it reports the tour closed.
std::vector<SubCell> cursor_tour(const SpanningTree& tree) {
  std::vector<SubCell> path;
  SpanningTree::Cursor at = tree.begin();
  path.push_back(subcell_of(at.cell, at.q));
  while (tree.advance(at) >= 0) path.push_back(subcell_of(at.cell, at.q));
  return path;
}

struct LargeMap {
  OccupancyGrid map;
  Cell start;
  std::string describe;
};

// Up to 150 x 40, 40 x 150 or 100 x 100 cells (the tiles are 64 cells, the first one holding 63 of
// them beside the border); blocked cells at a random density; sometimes the whole ring of
// border cells blocked; an odd remainder column / row of random sub-cells; the start a random
// sub-cell of a random free cell.
rc::Gen<LargeMap> large_map() {
  return rc::gen::exec([] {
    // Wide, tall or square-ish, each a third of the time, so that the tile edges are crossed in
    // both axes.
    const int shape = *rc::gen::inRange(0, 3);
    const int a = *rc::gen::inRange(1, 151), b = *rc::gen::inRange(1, 41);
    const int side = *rc::gen::inRange(50, 101);
    const int cw = shape == 0 ? a : shape == 1 ? b : side;
    const int ch = shape == 0 ? b : shape == 1 ? a : *rc::gen::inRange(50, 101);
    const int odd_x = *rc::gen::inRange(0, 2), odd_y = *rc::gen::inRange(0, 2);
    const int density = *rc::gen::inRange(0, 50);
    const bool ring = *rc::gen::inRange(0, 4) == 0;
    OccupancyGrid g(2 * cw + odd_x, 2 * ch + odd_y, Occupancy::Free);
    for (int cy = 0; cy < ch; ++cy)
      for (int cx = 0; cx < cw; ++cx) {
        const bool border = cx == 0 || cy == 0 || cx == cw - 1 || cy == ch - 1;
        const bool blocked = (ring && border) || *rc::gen::inRange(0, 100) < density;
        if (blocked)
          for (int q = 0; q < 4; ++q) g[subcell_of({cx, cy}, q)] = Occupancy::Blocked;
      }
    for (std::int32_t y = 0; y < g.height(); ++y)
      for (std::int32_t x = 0; x < g.width(); ++x)
        if (x >= 2 * cw || y >= 2 * ch)
          g[{x, y}] = *rc::gen::inRange(0, 2) ? Occupancy::Free : Occupancy::Blocked;
    std::vector<Cell> free;
    for (int cy = 0; cy < ch; ++cy)
      for (int cx = 0; cx < cw; ++cx)
        if (cell_free(g, {cx, cy})) free.push_back({cx, cy});
    if (free.empty()) {
      const Cell c{cw / 2, ch / 2};
      for (int q = 0; q < 4; ++q) g[subcell_of(c, q)] = Occupancy::Free;
      free.push_back(c);
    }
    const Cell cell = free[*rc::gen::inRange<std::size_t>(0, free.size())];
    const Cell start = subcell_of(cell, *rc::gen::inRange(0, 4));
    const std::string text = std::to_string(g.width()) + " x " + std::to_string(g.height()) +
                             " sub-cells, density " + std::to_string(density) + "%, ring " +
                             (ring ? "blocked" : "random") + ", start (" + std::to_string(start.x) +
                             ", " + std::to_string(start.y) + ")";
    return LargeMap{std::move(g), start, text};
  });
}

} // namespace

TEST_CASE("offline fast paths: tour() and the search's own tour equal the cursor walk of the same "
          "tree and online STC's tour - on maps across tiles - odd sizes - blocked borders",
          "[stc][property]") {
  rc::prop("tour() == advance() walk == online", [] {
    const auto m = *large_map();
    RC_LOG() << m.describe << "\n";
    // Stored cell x is cx + 1: a map wider than 62 cells reaches the second tile column.
    RC_CLASSIFY(m.map.width() / 2 > 62 || m.map.height() / 2 > 62, "crosses a tile edge");
    const SpanningTree tree(m.map, m.start);
    const std::vector<SubCell> fast = tree.tour();
    RC_ASSERT(static_cast<std::int64_t>(fast.size()) == 4 * tree.cells());
    // The tour emitted by the search itself, and the tree it leaves, are the same.
    std::vector<SubCell> fused;
    const SpanningTree walked(m.map, m.start, [&](SubCell s) { fused.push_back(s); });
    const auto same_fused = antkit::testing::check_same_tour(fast, fused, "search's tour");
    RC_ASSERT(same_fused.describe() == "ok");
    RC_ASSERT(walked.cells() == tree.cells());
    RC_ASSERT(walked.tour() == fast);
    const auto same_cursor = antkit::testing::check_same_tour(cursor_tour(tree), fast, "tour()");
    RC_ASSERT(same_cursor.describe() == "ok");
    RunOptions options;
    const RunResult online = run_stc(m.map, m.start, Variant::Online, options);
    const auto same_online = antkit::testing::check_same_tour(online.path, fast, "offline tour()");
    RC_ASSERT(same_online.describe() == "ok");
    antkit::testing::StcTourChecker checker;
    const auto check = checker.check_exact(m.map, m.start, fast);
    RC_ASSERT(check.describe() == "ok");
    // Every in-tree cell's parent is in the tree and names it as a child (the search's bytes).
    for (int cy = 0; cy < tree.shape().cells_y; ++cy)
      for (int cx = 0; cx < tree.shape().cells_x; ++cx) {
        const Cell c{cx, cy};
        if (!tree.in_tree(c) || tree.is_root(c)) continue;
        const int p = tree.parent_direction(c);
        RC_ASSERT(tree.in_tree(step(c, p)));
        RC_ASSERT(((tree.children(step(c, p)) >> opposite(p)) & 1u) == 1u);
      }
  });
}

TEST_CASE("offline fast paths: an empty map of 130 x 70 cells crosses tile edges in every "
          "direction - the tour equals online STC's",
          "[stc]") {
  // 130 cells: stored columns 1..130 span three tiles; 70 rows span two. The spiral the search
  // takes on an empty map runs along every edge of every tile.
  const OccupancyGrid map(260, 140, Occupancy::Free);
  for (int q = 0; q < 4; ++q) {
    const Cell start = subcell_of({65, 33}, q);
    INFO("start (" << start.x << ", " << start.y << ")");
    const SpanningTree tree(map, start);
    CHECK(tree.cells() == 130 * 70);
    const std::vector<SubCell> fast = tree.tour();
    CHECK(fast == cursor_tour(tree));
    CHECK(fast == run_stc(map, start, Variant::Online).path);
    std::vector<SubCell> fused;
    const SpanningTree walked(map, start, [&](SubCell s) { fused.push_back(s); });
    CHECK(fused == fast);
  }
}
