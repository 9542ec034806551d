// antkit::testing's generators (generators.hpp) make what they say: sizes within the limits,
// Unknown cells only when asked, perfect mazes, rooms split by walls, combs with a free spine,
// valid arenas with their holes, observations in range.
#include <antkit/testing/generators.hpp>
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>
#include <vector>

namespace {

using namespace antkit;
using kernel::Cell;
using kernel::Occupancy;
using kernel::OccupancyGrid;
namespace gen = antkit::testing::gen;

std::int64_t count(const OccupancyGrid& g, Occupancy o) {
  std::int64_t n = 0;
  for (std::int32_t y = 0; y < g.height(); ++y)
    for (std::int32_t x = 0; x < g.width(); ++x) n += g[{x, y}] == o;
  return n;
}

// Free cells 4-connected to `from`, and the number of 4-adjacent free pairs among them.
std::pair<std::int64_t, std::int64_t> component(const OccupancyGrid& g, Cell from) {
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(g.width()) *
                                 static_cast<std::size_t>(g.height()));
  auto at = [&](Cell c) -> std::uint8_t& {
    return seen[static_cast<std::size_t>(c.y) * static_cast<std::size_t>(g.width()) +
                static_cast<std::size_t>(c.x)];
  };
  std::vector<Cell> queue{from};
  at(from) = 1;
  std::int64_t cells = 0, edges = 0;
  for (std::size_t i = 0; i < queue.size(); ++i) {
    const Cell c = queue[i];
    ++cells;
    for (const Cell d : {Cell{1, 0}, Cell{0, 1}, Cell{-1, 0}, Cell{0, -1}}) {
      const Cell n{c.x + d.x, c.y + d.y};
      if (!g.in_bounds(n) || g[n] != Occupancy::Free) continue;
      if (d.x + d.y > 0) ++edges;
      if (!at(n)) {
        at(n) = 1;
        queue.push_back(n);
      }
    }
  }
  return {cells, edges};
}

} // namespace

TEST_CASE("generators: every map is within its limits, Unknown only when asked",
          "[testing][property]") {
  rc::prop("any_grid_map", [] {
    const gen::MapLimits l{.min_width = 3, .max_width = 17, .min_height = 2, .max_height = 9};
    const auto g = *gen::any_grid_map(l);
    RC_ASSERT(g.width() >= 3 && g.width() <= 17 && g.height() >= 2 && g.height() <= 9);
    RC_ASSERT(count(g, Occupancy::Unknown) == 0);
    gen::MapLimits u = l;
    u.max_unknown_per_mille = 500;
    const auto h = *gen::any_grid_map(u);
    RC_ASSERT(count(h, Occupancy::Free) + count(h, Occupancy::Blocked) +
                  count(h, Occupancy::Unknown) ==
              std::int64_t{h.width()} * h.height());
  });
}

TEST_CASE("generators: a maze is perfect (its corridors a tree that reaches every even cell)",
          "[testing][property]") {
  rc::prop("maze", [] {
    const auto g = *gen::maze({.min_width = 1, .max_width = 21, .min_height = 1, .max_height = 21});
    const auto [cells, edges] = component(g, {0, 0});
    RC_ASSERT(cells == count(g, Occupancy::Free)); // connected
    RC_ASSERT(edges == cells - 1);                 // no cycle
    for (std::int32_t y = 0; y < g.height(); y += 2)
      for (std::int32_t x = 0; x < g.width(); x += 2) RC_ASSERT((g[{x, y}] == Occupancy::Free));
  });
}

TEST_CASE("generators: a comb's spine row is free and touches every free cell",
          "[testing][property]") {
  rc::prop("comb", [] {
    const auto g = *gen::comb({.min_width = 1, .max_width = 20, .min_height = 1, .max_height = 20});
    for (std::int32_t x = 0; x < g.width(); ++x) RC_ASSERT((g[{x, 0}] == Occupancy::Free));
    RC_ASSERT(component(g, {0, 0}).first == count(g, Occupancy::Free));
  });
}

TEST_CASE("generators: STC cases start on a free sub-cell of a free cell, inside the map",
          "[testing][property]") {
  rc::prop("stc_case and stc_case_from", [] {
    const auto a = *gen::stc_case({.max_cells_x = 6, .max_cells_y = 4});
    RC_ASSERT(a.map.width() <= 13 && a.map.height() <= 9);
    const auto b = *gen::stc_case_from(gen::rooms({.max_width = 9, .max_height = 9}));
    RC_ASSERT(b.map.width() % 2 == 0 && b.map.height() % 2 == 0);
    for (const auto* c : {&a, &b}) {
      RC_ASSERT(c->map.in_bounds(c->start));
      const Cell cell{c->start.x / 2 * 2, c->start.y / 2 * 2};
      for (int q = 0; q < 4; ++q)
        RC_ASSERT((c->map[{cell.x + (q & 1), cell.y + (q >> 1)}] == Occupancy::Free));
    }
  });
}

TEST_CASE("generators: arenas with holes are valid and hold their holes", "[testing][property]") {
  rc::prop("arena_with_holes", [] {
    const auto a = *gen::arena_with_holes();
    RC_ASSERT(a.arena.area() > 0.0);
    // Every vertex lies within 100.0625 of the origin: the arena within that circle.
    RC_ASSERT(a.arena.area() < 3.1416 * 100.07 * 100.07);
    RC_ASSERT(geometry::write_wkt(geometry::read_wkt(a.wkt)) == geometry::write_wkt(a.arena));
  });
}

TEST_CASE("generators: observations are in their documented ranges", "[testing][property]") {
  rc::prop("buffon and ant observations", [] {
    for (const auto& o : *gen::observations(gen::buffon_observation(), 20))
      for (const auto r : o.ir) RC_ASSERT(r.raw() >= 0 && r.raw() <= 65536);
    for (const auto& o : *gen::observations(gen::mark_observation(), 20)) {
      RC_ASSERT(o.free_neighbours < 16 && o.here < 16);
      for (const auto m : o.neighbour) RC_ASSERT(m < 16);
    }
  });
}

TEST_CASE("generators: the campaign's generators never discard, drawn outside a property",
          "[testing]") {
  // antkit campaign draws cases with gen(Random, size).value(), where a discard (RC_DISCARD) would
  // escape as an exception: all-blocked maps get a free cell and invalid arenas are drawn again.
  const auto stc = gen::stc_case_from(gen::any_grid_map({.max_width = 3, .max_height = 3}));
  const auto arena = gen::arena_with_holes();
  for (std::uint64_t seed = 1; seed <= 3000; ++seed) {
    INFO("seed " << seed);
    const auto c = stc(rc::Random(seed), 100).value();
    REQUIRE(c.map[c.start] == Occupancy::Free);
    if (seed <= 300) REQUIRE(arena(rc::Random(seed), 100).value().arena.area() > 0);
  }
}
