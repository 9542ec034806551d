#pragma once
// Random simple polygons with holes for the Crofton tests (issue 8 item 1), their exact area from
// CGAL, and the clipping of a dropped segment to one of them.
//
// CGAL is the oracle here, as CONTRIBUTING.md allows for tests: it is used in this header only,
// which only tests/crofton includes.
//
// Coordinates. Every vertex is a multiple of 1/16 of a unit with |coordinate| < 64, so it is exact
// in the kernel's fixed point (Q15.16), exact as a binary64 value and exact as a CGAL rational.
// Two CGAL views of the same rings are kept:
//   * `exact`: Simple_cartesian<Gmpq> (the geometry layer's ExactKernel): the exact area, as a
//     rational, is the sum of the signed ring areas (outer counter-clockwise, holes clockwise),
//     and make_arena's validator can be run on it;
//   * `fast`: Exact_predicates_inexact_constructions_kernel. Its predicates (orientation, and so
//     is_simple, do_intersect of segments, bounded_side) are exact for the binary64 inputs given,
//     with a floating-point filter; they decide validity in the generator and which side of the
//     boundary a point lies on when clipping. Nothing here needs its (inexact) constructions.
#include "crofton_common.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <algorithm>
#include <antkit/geometry/arena_cgal.hpp>
#include <array>
#include <cmath>
#include <cstdint>
#include <rapidcheck.h>
#include <utility>
#include <vector>

namespace antkit::test::crofton {

using FastKernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using FastPoint = FastKernel::Point_2;
using FastSegment = FastKernel::Segment_2;
using FastPolygon = CGAL::Polygon_2<FastKernel>;

// Vertices are integers in units of 1/kGrid.
inline constexpr std::int64_t kGrid = 16;
using GridPoint = std::array<std::int64_t, 2>;
using Ring = std::vector<GridPoint>;

inline FastPolygon fast_ring(const Ring& r) {
  FastPolygon p;
  for (const auto& v : r)
    p.push_back(FastPoint(static_cast<double>(v[0]) / kGrid, static_cast<double>(v[1]) / kGrid));
  return p;
}

inline geometry::ExactPolygon exact_ring(const Ring& r) {
  geometry::ExactPolygon p;
  for (const auto& v : r)
    p.push_back(geometry::ExactPoint(geometry::ExactNumber(v[0], kGrid),
                                     geometry::ExactNumber(v[1], kGrid)));
  return p;
}

struct RandomPolygon {
  // rings[0] the outer boundary (counter-clockwise), then the holes (clockwise)
  std::vector<Ring> rings;
  std::vector<FastPolygon> fast;         // the same rings, exact predicates
  geometry::ExactPolygonWithHoles exact; // the same rings, exact rationals
  geometry::ExactNumber exact_area;      // outer area minus the holes' areas, exactly
  double area_value = 0;                 // exact_area rounded to binary64
  double outer_area = 0;                 // the outer ring's area alone (holes ignored)
  Box bbox{};                            // of the outer ring

  double area() const { return area_value; }
  Box box() const { return bbox; }
  std::size_t holes() const { return rings.size() - 1; }
};

inline RandomPolygon make_polygon(std::vector<Ring> rings) {
  RandomPolygon g;
  g.rings = std::move(rings);
  for (const auto& r : g.rings) g.fast.push_back(fast_ring(r));
  g.exact = geometry::ExactPolygonWithHoles(exact_ring(g.rings[0]));
  for (std::size_t h = 1; h < g.rings.size(); ++h) g.exact.add_hole(exact_ring(g.rings[h]));
  // Polygon_with_holes_2 has no area of its own in CGAL 5.5: the outer ring's signed area plus the
  // holes' signed areas, which are negative because holes are clockwise.
  g.exact_area = g.exact.outer_boundary().area();
  for (auto h = g.exact.holes_begin(); h != g.exact.holes_end(); ++h) g.exact_area += h->area();
  g.area_value = CGAL::to_double(g.exact_area);
  g.outer_area = CGAL::to_double(g.exact.outer_boundary().area());
  const auto bb = g.fast[0].bbox();
  g.bbox = {bb.xmin(), bb.ymin(), bb.xmax(), bb.ymax()};
  return g;
}

// Strictly inside the region: inside the outer ring and outside every hole, not on any boundary.
inline bool inside(const RandomPolygon& g, double x, double y) {
  const FastPoint p(x, y);
  if (g.fast[0].bounded_side(p) != CGAL::ON_BOUNDED_SIDE) return false;
  for (std::size_t h = 1; h < g.fast.size(); ++h)
    if (g.fast[h].bounded_side(p) != CGAL::ON_UNBOUNDED_SIDE) return false;
  return true;
}

// Two simple rings share no point (closed edges, so touching at a single point counts as sharing)
// and neither lies inside the other.
inline bool rings_apart(const FastPolygon& a, const FastPolygon& b) {
  for (auto e = a.edges_begin(); e != a.edges_end(); ++e)
    for (auto f = b.edges_begin(); f != b.edges_end(); ++f)
      if (CGAL::do_intersect(*e, *f)) return false;
  // With no common point, a ring is inside the other iff any one of its vertices is.
  return a.bounded_side(b.vertex(0)) == CGAL::ON_UNBOUNDED_SIDE &&
         b.bounded_side(a.vertex(0)) == CGAL::ON_UNBOUNDED_SIDE;
}

// The validity the tests rely on (the same rules as geometry/arena.hpp's): every ring simple with
// nonzero area, the outer one counter-clockwise and every hole clockwise, every hole strictly
// inside the outer ring (its vertices on the bounded side, no common point with the outer ring),
// and no two holes sharing a point or nesting.
inline bool valid_rings(const std::vector<Ring>& rings) {
  if (rings.empty()) return false;
  std::vector<FastPolygon> f;
  for (const auto& r : rings) {
    if (r.size() < 3) return false;
    f.push_back(fast_ring(r));
    if (!f.back().is_simple()) return false;
  }
  if (f[0].orientation() != CGAL::COUNTERCLOCKWISE) return false;
  for (std::size_t h = 1; h < f.size(); ++h) {
    if (f[h].orientation() != CGAL::CLOCKWISE) return false;
    for (auto v = f[h].vertices_begin(); v != f[h].vertices_end(); ++v)
      if (f[0].bounded_side(*v) != CGAL::ON_BOUNDED_SIDE) return false;
    for (auto e = f[h].edges_begin(); e != f[h].edges_end(); ++e)
      for (auto o = f[0].edges_begin(); o != f[0].edges_end(); ++o)
        if (CGAL::do_intersect(*e, *o)) return false;
    for (std::size_t k = 1; k < h; ++k)
      if (!rings_apart(f[h], f[k])) return false;
  }
  return true;
}

// A star-shaped ring around (cx, cy) (grid units): n vertices at strictly increasing angles, one
// in each of n equal sectors at a random place inside it (5 % to 95 % of the sector, so that
// neighbours never share an angle), radius between min_percent % and 100 % of r_max (grid
// units), rounded to the grid. Counter-clockwise before rounding; rounding can break simplicity
// only for nearly degenerate draws, which the caller rejects.
inline Ring random_star(std::int64_t cx, std::int64_t cy, int n, std::int64_t r_max,
                        int min_percent) {
  Ring r;
  for (int k = 0; k < n; ++k) {
    const double where = *rc::gen::inRange(5, 96) / 100.0;
    const double radius = static_cast<double>(r_max) * *rc::gen::inRange(min_percent, 101) / 100.0;
    const double angle = 2 * kPi * (k + where) / n;
    r.push_back(
        {cx + std::llround(radius * std::cos(angle)), cy + std::llround(radius * std::sin(angle))});
  }
  return r;
}

// rapidcheck generator of a random polygon with between min_holes and max_holes holes (0..3).
// Outer ring: a star around the origin with 6..24 vertices and radius 16..32 units, each vertex
// at 45..100 % of it (so the ring is in general not convex). Holes: stars with 3..8 vertices and
// radius 10..30 % of the outer radius (large enough that ignoring them is a visible error in the
// area), centred uniformly (on the grid) in the outer ring's bounding box, reversed
// to clockwise, kept when the rings stay valid (valid_rings: strictly inside, apart from the
// other holes). A hole that does not fit in 100 tries, or an outer ring that rounding made
// non-simple, restarts the draw; both are rare for these sizes, so the distribution is close to
// the one described. The retries are bounded because rapidcheck's shrinking replays the draws
// with smaller values (all hole centres at the box corner, say), which may never fit: after 20
// restarts the polygon is returned with the holes that fitted (possibly fewer than min_holes;
// with a regular octagon of radius 16 as the outer ring if even that failed), so a shrink always
// ends. Callers that need the hole count check it. rapidcheck's inRange scales its range with
// the generation size (size 0 gives the minimum every time), so the generator is run at the
// nominal size 100 whatever size the property is at: the distribution above is the one drawn.
inline rc::Gen<RandomPolygon> random_polygon(int min_holes, int max_holes) {
  return rc::gen::resize(
      rc::kNominalSize, rc::gen::exec([=] {
        for (int restart = 0;; ++restart) {
          const bool last = restart >= 20;
          const int n = *rc::gen::inRange(6, 25);
          const std::int64_t radius = kGrid * *rc::gen::inRange(16, 33);
          std::vector<Ring> rings{random_star(0, 0, n, radius, 45)};
          if (!valid_rings(rings)) {
            if (!last) continue;
            rings[0].clear();
            for (int k = 0; k < 8; ++k) // a regular octagon, rounded to the grid: simple
              rings[0].push_back({std::llround(16.0 * kGrid * std::cos(2 * kPi * k / 8)),
                                  std::llround(16.0 * kGrid * std::sin(2 * kPi * k / 8))});
          }
          const int wanted = *rc::gen::inRange(min_holes, max_holes + 1);
          const auto bb = fast_ring(rings[0]).bbox();
          bool fitted = true;
          for (int h = 0; h < wanted && fitted; ++h) {
            fitted = false;
            for (int attempt = 0; attempt < 100 && !fitted; ++attempt) {
              const auto cx = *rc::gen::inRange(static_cast<std::int64_t>(bb.xmin() * kGrid),
                                                static_cast<std::int64_t>(bb.xmax() * kGrid) + 1);
              const auto cy = *rc::gen::inRange(static_cast<std::int64_t>(bb.ymin() * kGrid),
                                                static_cast<std::int64_t>(bb.ymax() * kGrid) + 1);
              const int m = *rc::gen::inRange(3, 9);
              const std::int64_t r = radius * *rc::gen::inRange(10, 31) / 100;
              Ring hole = random_star(cx, cy, m, r, 50);
              std::reverse(hole.begin(), hole.end());
              rings.push_back(hole);
              fitted = valid_rings(rings);
              if (!fitted) rings.pop_back();
            }
          }
          if (fitted || last) return make_polygon(std::move(rings));
        }
      }));
}

// A uniform integer in [lo, hi), whatever the property's current size (see random_polygon).
template <class T>
T uniform_in(T lo, T hi) {
  return *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(lo, hi));
}

// Parameter intervals [u, v] of p + t d, t in [0, 1], lying in the region, in increasing order.
// Every t where the segment meets a boundary edge splits [0, 1]; each resulting interval lies
// wholly inside or wholly outside (it crosses no edge), and its midpoint decides which, by an exact
// predicate on that binary64 point. Contiguous inside intervals (a split at a vertex or a spurious
// split) are merged. The split values themselves are binary64 solutions of the line equations:
// they are rounded anyway when the pieces become fixed-point segments, exactly as the rectangle
// clipping of test_crofton.cpp rounds its Liang-Barsky parameters. The edge test accepts s
// slightly outside [0, 1] so that a crossing at a vertex is never missed through rounding (an
// extra split only adds a boundary that the merge removes).
inline std::vector<std::pair<double, double>> clip_params(const RandomPolygon& g, double px,
                                                          double py, double dx, double dy) {
  std::vector<std::pair<double, double>> out;
  const Box& b = g.bbox;
  if (std::max(px, px + dx) < b.x0 || std::min(px, px + dx) > b.x1 ||
      std::max(py, py + dy) < b.y0 || std::min(py, py + dy) > b.y1)
    return out; // wholly outside the bounding box: rejected without looking at the edges
  std::vector<double> ts{0.0, 1.0};
  for (const auto& r : g.rings)
    for (std::size_t i = 0; i < r.size(); ++i) {
      const GridPoint& a = r[i];
      const GridPoint& c = r[(i + 1) % r.size()];
      const double ax = static_cast<double>(a[0]) / kGrid, ay = static_cast<double>(a[1]) / kGrid;
      const double ex = static_cast<double>(c[0] - a[0]) / kGrid,
                   ey = static_cast<double>(c[1] - a[1]) / kGrid;
      const double den = dx * ey - dy * ex;
      if (den == 0) continue; // parallel: no single crossing point (overlap has measure zero)
      const double wx = ax - px, wy = ay - py;
      const double t = (wx * ey - wy * ex) / den, s = (wx * dy - wy * dx) / den;
      if (t > 0 && t < 1 && s >= -1e-9 && s <= 1 + 1e-9) ts.push_back(t);
    }
  std::sort(ts.begin(), ts.end());
  for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
    const double u = ts[i], v = ts[i + 1];
    if (!(v > u)) continue;
    const double m = 0.5 * (u + v);
    if (!inside(g, px + m * dx, py + m * dy)) continue;
    if (!out.empty() && out.back().second == u)
      out.back().second = v;
    else
      out.emplace_back(u, v);
  }
  return out;
}

// The region interface of crofton_common.hpp: append the fixed-point pieces and add their lengths,
// measured from the rounded ends that are counted.
inline void add_clipped(const RandomPolygon& g, double px, double py, double dx, double dy,
                        std::vector<FxSegment>& out, double& length_inside) {
  for (auto [u, v] : clip_params(g, px, py, dx, dy)) {
    const FxSegment seg{to_fx(px + u * dx, py + u * dy), to_fx(px + v * dx, py + v * dy)};
    out.push_back(seg);
    length_inside += len(seg);
  }
}

} // namespace antkit::test::crofton
