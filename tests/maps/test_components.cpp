// free_components and count_cells, held against an independent oracle (union-find over the
// 4-neighbour pairs): exhaustively on every small grid, and by property on larger random ones.
#include "map_test_support.hpp"

#include <antkit/maps/components.hpp>
#include <catch2/catch.hpp>
#include <numeric>

using antkit::kernel::Cell;
using antkit::kernel::Occupancy;
using antkit::kernel::OccupancyGrid;
using antkit::maps::free_components;
using antkit::maps::FreeComponents;

namespace {

// The oracle: union-find with path halving over right and down neighbour pairs; it shares no code
// and no traversal order with the stack search under test.
struct Oracle {
  std::vector<std::size_t> parent;
  std::size_t find(std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
};

// Checks a labelling against the oracle; returns an empty string when it agrees, else what broke.
std::string disagreement(const OccupancyGrid& g, const FreeComponents& c) {
  Oracle uf;
  uf.parent.resize(g.size());
  std::iota(uf.parent.begin(), uf.parent.end(), std::size_t{0});
  for (std::int32_t y = 0; y < g.height(); ++y)
    for (std::int32_t x = 0; x < g.width(); ++x) {
      if (g[Cell{x, y}] != Occupancy::Free) continue;
      for (const Cell next : {Cell{x + 1, y}, Cell{x, y + 1}})
        if (g.in_bounds(next) && g[next] == Occupancy::Free)
          uf.parent[uf.find(g.index(next))] = uf.find(g.index({x, y}));
    }
  if (c.label.width() != g.width() || c.label.height() != g.height()) return "label shape";
  std::vector<std::int64_t> label_of_root(g.size(), -1);
  std::vector<std::size_t> sizes;
  for (std::size_t i = 0; i < g.size(); ++i) {
    const auto l = c.label.cells()[i];
    if (g.cells()[i] != Occupancy::Free) {
      if (l != FreeComponents::kNotFree) return "a non-free cell has a label";
      continue;
    }
    const auto root = uf.find(i);
    if (label_of_root[root] < 0) {
      // A new component, met in row-major order: it must get the next number.
      if (l != static_cast<std::int32_t>(sizes.size())) return "numbering is not row-major";
      label_of_root[root] = l;
      sizes.push_back(0);
    }
    if (label_of_root[root] != l) return "two cells of one component have different labels";
    ++sizes[static_cast<std::size_t>(l)];
  }
  if (sizes != c.sizes) return "component sizes";
  return {};
}

OccupancyGrid grid_from_bits(std::int32_t w, std::int32_t h, std::uint32_t bits) {
  OccupancyGrid g(w, h);
  for (std::size_t i = 0; i < g.size(); ++i)
    g.cells()[i] = (bits >> i) & 1u ? Occupancy::Free : Occupancy::Blocked;
  return g;
}

} // namespace

TEST_CASE("free components agree with union-find on every grid up to 4 x 4", "[maps][proof]") {
  std::size_t grids = 0;
  for (std::int32_t w = 1; w <= 4; ++w)
    for (std::int32_t h = 1; h <= 4; ++h)
      for (std::uint32_t bits = 0; bits < (1u << (w * h)); ++bits) {
        const auto g = grid_from_bits(w, h, bits);
        const auto why = disagreement(g, free_components(g));
        if (!why.empty()) {
          INFO(w << "x" << h << " bits " << bits);
          FAIL(why);
        }
        ++grids;
      }
  CHECK(grids == 74954u); // the sum over w, h in 1..4 of 2^(w*h): every grid was visited
}

TEST_CASE("free components agree with union-find on random grids", "[maps][property]") {
  rc::prop("labels, numbering and sizes", [] {
    const auto g = *antkit::maps::test::gen_three_valued_grid(40);
    const auto c = free_components(g);
    RC_ASSERT(disagreement(g, c) == std::string());
    const auto counts = antkit::maps::count_cells(g);
    RC_ASSERT(std::accumulate(c.sizes.begin(), c.sizes.end(), std::size_t{0}) == counts.free);
    RC_ASSERT(counts.free + counts.blocked + counts.unknown == g.size());
    RC_ASSERT(c.largest() <= counts.free);
  });
}

TEST_CASE("free components: worked examples", "[maps]") {
  // Unknown separates as blocked does; a diagonal touch is not a 4-connection.
  const auto g = antkit::maps::parse_ascii(".#.\n?#.\n..#\n.#.\n", "ex.txt").cells;
  const auto c = free_components(g);
  CHECK(c.count() == 4);
  CHECK(c.sizes == std::vector<std::size_t>{1, 2, 3, 1});
  CHECK(c.largest() == 3);
  CHECK(c.label[Cell{0, 0}] == 0);
  CHECK(c.label[Cell{2, 0}] == 1);
  CHECK(c.label[Cell{2, 1}] == 1);
  CHECK(c.label[Cell{0, 2}] == 2);
  CHECK(c.label[Cell{2, 3}] == 3);
  CHECK(c.label[Cell{0, 1}] == FreeComponents::kNotFree);
  const auto counts = antkit::maps::count_cells(g);
  CHECK(counts == antkit::maps::CellCounts{7, 4, 1});

  const OccupancyGrid none(3, 2, Occupancy::Blocked);
  CHECK(free_components(none).count() == 0);
  CHECK(free_components(none).largest() == 0);
  CHECK(free_components(OccupancyGrid{}).count() == 0);
}

TEST_CASE("free components: a 1000 x 1000 serpentine corridor is one component", "[maps]") {
  // One corridor of about half a million cells: a recursive search would need that many frames.
  constexpr std::int32_t n = 1000;
  OccupancyGrid g(n, n, Occupancy::Blocked);
  for (std::int32_t y = 0; y < n; y += 2) {
    for (std::int32_t x = 0; x < n; ++x) g[Cell{x, y}] = Occupancy::Free;
    if (y + 1 < n) g[Cell{(y / 2) % 2 == 0 ? n - 1 : 0, y + 1}] = Occupancy::Free;
  }
  const auto c = free_components(g);
  CHECK(c.count() == 1);
  // 500 full rows and 500 one-cell connectors (the last one a dead end in row 999).
  CHECK(c.largest() == 500u * 1000u + 500u);
}
