#pragma once
// rapidcheck generators for users' own property tests (and ours): grid maps of every shape the
// planners meet (random obstacles, perfect mazes, rooms with doors, combs, odd sizes, Unknown
// cells), STC cases (a sub-cell map and a start), arenas (random star polygons with holes, exact,
// through the WKT reader) and observation sequences for the controllers.
//
// Header-only: rapidcheck is a dependency of this header alone, not of antkit::testing's library
// (the checkers in stc.hpp, los.hpp, uniform.hpp need no rapidcheck). A consumer that includes it
// links rapidcheck itself (`find_package(rapidcheck CONFIG)`, target `rapidcheck`).
//
// Every generator draws only through rapidcheck, so a failing case is reproduced by rapidcheck's
// seed and shrinks with rapidcheck's shrinking: sizes and densities are drawn first and shrink
// towards the smallest, emptiest map.
#include <algorithm>
#include <antkit/buffon/exploration.hpp>
#include <antkit/geometry/arena.hpp>
#include <antkit/geometry/wkt.hpp>
#include <antkit/kernel/grid.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/stc/ant.hpp>
#include <cmath>
#include <cstdint>
#include <rapidcheck.h>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace antkit::testing::gen {

using kernel::Cell;
using kernel::Occupancy;
using kernel::OccupancyGrid;

// The shapes grid_map draws from.
enum class MapShape : std::uint8_t { Random, Maze, Rooms, Comb };

struct MapLimits {
  std::int32_t min_width = 1, max_width = 24;
  std::int32_t min_height = 1, max_height = 24;
  // At most this share (per mille) of the free cells becomes Unknown (0: no Unknown cells).
  int max_unknown_per_mille = 0;
};

namespace detail {

inline std::int32_t draw(std::int32_t lo, std::int32_t hi) { // [lo, hi], inclusive
  return *rc::gen::inRange<std::int32_t>(lo, hi + 1);
}

inline void fill(OccupancyGrid& g, Occupancy o) {
  for (std::int32_t y = 0; y < g.height(); ++y)
    for (std::int32_t x = 0; x < g.width(); ++x) g[{x, y}] = o;
}

inline void sprinkle_unknown(OccupancyGrid& g, int max_per_mille) {
  if (max_per_mille <= 0) return;
  const int share = *rc::gen::inRange(0, max_per_mille + 1);
  if (share == 0) return;
  for (std::int32_t y = 0; y < g.height(); ++y)
    for (std::int32_t x = 0; x < g.width(); ++x)
      if (g[{x, y}] == Occupancy::Free && *rc::gen::inRange(0, 1000) < share)
        g[{x, y}] = Occupancy::Unknown;
}

} // namespace detail

// Random obstacles: each cell blocked with a drawn density of 0..60 %.
inline rc::Gen<OccupancyGrid> random_grid(MapLimits l = {}) {
  return rc::gen::exec([l] {
    const auto w = detail::draw(l.min_width, l.max_width);
    const auto h = detail::draw(l.min_height, l.max_height);
    const int density = *rc::gen::inRange(0, 61);
    OccupancyGrid g(w, h, Occupancy::Free);
    for (std::int32_t y = 0; y < h; ++y)
      for (std::int32_t x = 0; x < w; ++x)
        if (*rc::gen::inRange(0, 100) < density) g[{x, y}] = Occupancy::Blocked;
    detail::sprinkle_unknown(g, l.max_unknown_per_mille);
    return g;
  });
}

// A perfect maze (one path between any two corridor cells): corridors on the even cells, carved
// by a randomised depth-first search from (0, 0). Odd sizes leave a blocked last row or column.
inline rc::Gen<OccupancyGrid> maze(MapLimits l = {}) {
  return rc::gen::exec([l] {
    const auto w = detail::draw(l.min_width, l.max_width);
    const auto h = detail::draw(l.min_height, l.max_height);
    OccupancyGrid g(w, h, Occupancy::Blocked);
    const std::int32_t nx = (w + 1) / 2, ny = (h + 1) / 2; // corridor nodes
    std::vector<std::uint8_t> seen(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny), 0);
    std::vector<Cell> stack{{0, 0}};
    seen[0] = 1;
    g[{0, 0}] = Occupancy::Free;
    static constexpr std::int32_t kDx[4] = {1, 0, -1, 0}, kDy[4] = {0, 1, 0, -1};
    while (!stack.empty()) {
      const Cell c = stack.back();
      std::vector<int> open;
      for (int d = 0; d < 4; ++d) {
        const std::int32_t x = c.x + kDx[d], y = c.y + kDy[d];
        if (x >= 0 && y >= 0 && x < nx && y < ny &&
            !seen[static_cast<std::size_t>(y) * static_cast<std::size_t>(nx) +
                  static_cast<std::size_t>(x)])
          open.push_back(d);
      }
      if (open.empty()) {
        stack.pop_back();
        continue;
      }
      const int d = open[*rc::gen::inRange<std::size_t>(0, open.size())];
      const Cell n{c.x + kDx[d], c.y + kDy[d]};
      seen[static_cast<std::size_t>(n.y) * static_cast<std::size_t>(nx) +
           static_cast<std::size_t>(n.x)] = 1;
      g[{2 * c.x + kDx[d], 2 * c.y + kDy[d]}] = Occupancy::Free; // the wall between
      g[{2 * n.x, 2 * n.y}] = Occupancy::Free;
      stack.push_back(n);
    }
    detail::sprinkle_unknown(g, l.max_unknown_per_mille);
    return g;
  });
}

// Rooms: the map split by blocked walls every `room` cells (3..8) in both directions, with one
// door (a free wall cell) per wall segment between neighbouring rooms, some doors left shut.
inline rc::Gen<OccupancyGrid> rooms(MapLimits l = {}) {
  return rc::gen::exec([l] {
    const auto w = detail::draw(l.min_width, l.max_width);
    const auto h = detail::draw(l.min_height, l.max_height);
    const std::int32_t room = detail::draw(3, 8);
    const int shut = *rc::gen::inRange(0, 30); // per cent of the doors left shut
    OccupancyGrid g(w, h, Occupancy::Free);
    for (std::int32_t y = 0; y < h; ++y)
      for (std::int32_t x = 0; x < w; ++x)
        if (x % (room + 1) == room || y % (room + 1) == room) g[{x, y}] = Occupancy::Blocked;
    // Doors: in each vertical wall segment one row, then in each horizontal one one column.
    auto doors = [&](bool vertical) {
      const std::int32_t walls_to = vertical ? w : h, along = vertical ? h : w;
      for (std::int32_t wall = room; wall < walls_to; wall += room + 1)
        for (std::int32_t from = 0; from < along; from += room + 1)
          if (*rc::gen::inRange(0, 100) >= shut) {
            const std::int32_t at =
                std::min<std::int32_t>(along - 1, from + detail::draw(0, room - 1));
            const Cell door = vertical ? Cell{wall, at} : Cell{at, wall};
            if (g[door] == Occupancy::Blocked && at % (room + 1) != room) g[door] = Occupancy::Free;
          }
    };
    doors(true);
    doors(false);
    detail::sprinkle_unknown(g, l.max_unknown_per_mille);
    return g;
  });
}

// A comb: a free spine along the top row and blocked teeth hanging from it, every `gap` columns
// (2..4), each reaching down to a drawn depth, so that the free space is long dead-end corridors
// (the worst case of coverage planners' backtracking).
inline rc::Gen<OccupancyGrid> comb(MapLimits l = {}) {
  return rc::gen::exec([l] {
    const auto w = detail::draw(l.min_width, l.max_width);
    const auto h = detail::draw(l.min_height, l.max_height);
    const std::int32_t gap = detail::draw(2, 4);
    OccupancyGrid g(w, h, Occupancy::Free);
    for (std::int32_t x = gap - 1; x < w; x += gap) {
      const std::int32_t depth = h <= 1 ? 0 : detail::draw(1, h - 1);
      for (std::int32_t y = h - depth; y < h; ++y) g[{x, y}] = Occupancy::Blocked;
    }
    detail::sprinkle_unknown(g, l.max_unknown_per_mille);
    return g;
  });
}

inline rc::Gen<OccupancyGrid> grid_map(MapShape shape, MapLimits l = {}) {
  switch (shape) {
  case MapShape::Maze:
    return maze(l);
  case MapShape::Rooms:
    return rooms(l);
  case MapShape::Comb:
    return comb(l);
  case MapShape::Random:
    break;
  }
  return random_grid(l);
}

// Any of the four shapes.
inline rc::Gen<OccupancyGrid> any_grid_map(MapLimits l = {}) {
  return rc::gen::oneOf(random_grid(l), maze(l), rooms(l), comb(l));
}

// A free cell of `g`, drawn uniformly; RC_DISCARD when there is none.
inline rc::Gen<Cell> free_cell(const OccupancyGrid& g) {
  std::vector<Cell> cells;
  for (std::int32_t y = 0; y < g.height(); ++y)
    for (std::int32_t x = 0; x < g.width(); ++x)
      if (g[{x, y}] == Occupancy::Free) cells.push_back({x, y});
  return rc::gen::exec([cells = std::move(cells)] {
    if (cells.empty()) RC_DISCARD("the map has no free cell");
    return cells[*rc::gen::inRange<std::size_t>(0, cells.size())];
  });
}

// An STC case: a sub-cell map (two sub-cells per cell side, as antkit stc reads a map) and a start
// sub-cell.
struct StcCase {
  OccupancyGrid map;
  Cell start;
};

struct StcLimits {
  std::int32_t max_cells_x = 10, max_cells_y = 10;
  bool partial_cells = false;     // sub-cells blocked on their own (partly free cells)
  bool start_in_free_cell = true; // the start's cell has four free sub-cells
  bool odd_sizes = true;          // an odd last row or column of sub-cells (never entered)
};

// Cells blocked with a drawn density (0..60 %), partly free cells when asked, an odd remainder
// holding anything, and a start among the free sub-cells (of free cells when asked); when none is
// free the first cell is freed. Mazes, rooms
// and combs: stc_case_from.
inline rc::Gen<StcCase> stc_case(StcLimits l = {}) {
  return rc::gen::exec([l] {
    const int cw = *rc::gen::inRange(1, l.max_cells_x + 1);
    const int ch = *rc::gen::inRange(1, l.max_cells_y + 1);
    const int odd_x = l.odd_sizes ? *rc::gen::inRange(0, 2) : 0;
    const int odd_y = l.odd_sizes ? *rc::gen::inRange(0, 2) : 0;
    const int cell_density = *rc::gen::inRange(0, 60);
    const int sub_density = l.partial_cells ? *rc::gen::inRange(0, 40) : 0;
    OccupancyGrid g(2 * cw + odd_x, 2 * ch + odd_y, Occupancy::Free);
    for (int cy = 0; cy < ch; ++cy)
      for (int cx = 0; cx < cw; ++cx) {
        const bool blocked = *rc::gen::inRange(0, 100) < cell_density;
        for (int q = 0; q < 4; ++q) {
          const Cell s{2 * cx + (q & 1), 2 * cy + (q >> 1)};
          const bool sub_blocked = sub_density > 0 && *rc::gen::inRange(0, 100) < sub_density;
          if (blocked || sub_blocked) g[s] = Occupancy::Blocked;
        }
      }
    if (odd_x || odd_y)
      for (std::int32_t y = 0; y < g.height(); ++y)
        for (std::int32_t x = 0; x < g.width(); ++x)
          if (x >= 2 * cw || y >= 2 * ch)
            g[{x, y}] = *rc::gen::inRange(0, 2) ? Occupancy::Free : Occupancy::Blocked;
    std::vector<Cell> starts;
    for (std::int32_t y = 0; y < 2 * ch; ++y)
      for (std::int32_t x = 0; x < 2 * cw; ++x) {
        if (g[{x, y}] != Occupancy::Free) continue;
        if (l.start_in_free_cell) {
          bool all = true;
          for (int q = 0; q < 4; ++q)
            all = all && g[{2 * (x / 2) + (q & 1), 2 * (y / 2) + (q >> 1)}] == Occupancy::Free;
          if (!all) continue;
        }
        starts.push_back({x, y});
      }
    if (starts.empty()) {
      for (int q = 0; q < 4; ++q) g[{q & 1, q >> 1}] = Occupancy::Free;
      starts.push_back({0, 0});
    }
    const auto pick = *rc::gen::inRange<std::size_t>(0, starts.size());
    return StcCase{std::move(g), starts[pick]};
  });
}

// A cell map turned into a sub-cell map (each cell two by two sub-cells), with a start sub-cell in
// a free cell: STC cases on mazes, rooms and combs. A map without a free cell gets its first cell
// freed (as stc_case does), so that this generator never discards.
inline rc::Gen<StcCase> stc_case_from(rc::Gen<OccupancyGrid> cells) {
  return rc::gen::exec([cells = std::move(cells)] {
    const OccupancyGrid c = *cells;
    OccupancyGrid g(2 * c.width(), 2 * c.height(), Occupancy::Free);
    std::vector<Cell> starts;
    for (std::int32_t y = 0; y < c.height(); ++y)
      for (std::int32_t x = 0; x < c.width(); ++x) {
        const Occupancy o = c[{x, y}] == Occupancy::Free ? Occupancy::Free : Occupancy::Blocked;
        for (int q = 0; q < 4; ++q) g[{2 * x + (q & 1), 2 * y + (q >> 1)}] = o;
        if (o == Occupancy::Free) starts.push_back({2 * x, 2 * y});
      }
    if (starts.empty()) {
      for (int q = 0; q < 4; ++q) g[{q & 1, q >> 1}] = Occupancy::Free;
      starts.push_back({0, 0});
    }
    const Cell s = starts[*rc::gen::inRange<std::size_t>(0, starts.size())];
    const int q = *rc::gen::inRange(0, 4);
    return StcCase{std::move(g), {s.x + (q & 1), s.y + (q >> 1)}};
  });
}

// A random arena with holes, exact (read through the WKT reader, so it is valid by arena.hpp's
// rules): the outer ring a star of 3..40 vertices around the origin at integer radii 60..100, up to
// three holes, each a small star (radius 1..5) centred on a spoke at distance 20 or 40. Rounding
// the vertices to 1/16 unit rarely breaks simplicity: such a draw is drawn again
// (rc::gen::suchThat), so the generator never discards. The vertices come from std::cos and
// std::sin: the same draw is the same arena wherever the C library's are the same.
struct ArenaCase {
  geometry::Arena arena;
  std::string wkt; // the text it was read from
};

// The WKT text of such an arena, valid or not.
inline rc::Gen<std::string> arena_wkt_text() {
  return rc::gen::exec([] {
    constexpr double kTwoPi = 6.283185307179586;
    auto coord = [](double v) { // to a multiple of 1/16, written exactly
      std::ostringstream s;
      s.precision(12);
      s << static_cast<double>(std::lround(v * 16.0)) / 16.0;
      return s.str();
    };
    std::ostringstream wkt;
    auto ring = [&](double cx, double cy, int n, double r_lo, double r_span_tenths) {
      wkt << '(';
      std::string first;
      for (int k = 0; k < n; ++k) {
        const double angle = kTwoPi * (k + *rc::gen::inRange(1, 99) / 100.0) / n;
        const double r = r_lo + *rc::gen::inRange(0, static_cast<int>(r_span_tenths) + 1) / 10.0;
        const std::string p =
            coord(cx + r * std::cos(angle)) + " " + coord(cy + r * std::sin(angle));
        if (k == 0) first = p;
        wkt << p << ", ";
      }
      wkt << first << ')';
    };
    const int n = *rc::gen::inRange(3, 41);
    wkt << "POLYGON (";
    ring(0, 0, n, 60.0, 400);
    // With n >= 12 the outer edges stay beyond 51 units from the origin: holes within 45 fit.
    const int holes = n >= 12 ? *rc::gen::inRange(0, 4) : 0;
    for (int h = 0; h < holes; ++h) {
      const double spoke = kTwoPi * h / 3.0, d = (h % 2 == 0) ? 20.0 : 40.0;
      wkt << ", ";
      ring(d * std::cos(spoke), d * std::sin(spoke), *rc::gen::inRange(3, 9), 1.0, 40);
    }
    wkt << ')';
    return wkt.str();
  });
}

inline rc::Gen<ArenaCase> arena_with_holes() {
  const auto valid = [](const std::string& text) {
    try {
      (void)geometry::read_wkt(text, "generated arena");
      return true;
    } catch (const kernel::InputError&) {
      return false;
    }
  };
  return rc::gen::map(rc::gen::suchThat(arena_wkt_text(), valid), [](const std::string& text) {
    return ArenaCase{geometry::read_wkt(text, "generated arena"), text};
  });
}

// Observation sequences, for controllers fed by something other than the simulator (a body that
// misbehaves, a recorded log): every value in the observation's documented range.
inline rc::Gen<buffon::Observation> buffon_observation() {
  return rc::gen::exec([] {
    buffon::Observation o;
    for (auto& r : o.ir) // I_i in [0, 1]: raw Q15.16 in [0, 65536], the ends drawn often
      r = kernel::Fx::from_raw(
          *rc::gen::weightedOneOf<std::int32_t>({{1, rc::gen::just<std::int32_t>(0)},
                                                 {1, rc::gen::just<std::int32_t>(65536)},
                                                 {4, rc::gen::inRange<std::int32_t>(0, 65537)}}));
    return o;
  });
}

// The ant's view (stc/ant.hpp): the free-neighbour mask and the marks of its five cells, any
// bits (a real camera can report anything).
inline rc::Gen<stc::MarkObservation> mark_observation() {
  return rc::gen::exec([] {
    stc::MarkObservation o;
    o.free_neighbours = *rc::gen::inRange<std::uint8_t>(0, 16);
    o.here = *rc::gen::inRange<std::uint8_t>(0, 16);
    for (auto& m : o.neighbour) m = *rc::gen::inRange<std::uint8_t>(0, 16);
    return o;
  });
}

template <typename Observation>
rc::Gen<std::vector<Observation>> observations(rc::Gen<Observation> one, std::size_t max_length) {
  return rc::gen::exec([one = std::move(one), max_length] {
    const auto n = *rc::gen::inRange<std::size_t>(0, max_length + 1);
    return *rc::gen::container<std::vector<Observation>>(n, one);
  });
}

} // namespace antkit::testing::gen
