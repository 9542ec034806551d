#pragma once
// rapidcheck generators of valid arenas for the geometry tests, and the exact oracle the
// rasterizer is held against.
#include <algorithm>
#include <antkit/geometry/arena.hpp>
#include <antkit/geometry/arena_cgal.hpp>
#include <cmath>
#include <rapidcheck.h>
#include <vector>

namespace antkit::test {

using geometry::ExactNumber;
using geometry::ExactPoint;
using geometry::ExactPolygon;
using geometry::ExactPolygonWithHoles;

// n / 10^k, exactly.
inline ExactNumber decimal(long n, int k) {
  long p = 1;
  for (int i = 0; i < k; ++i) p *= 10;
  return ExactNumber(n, static_cast<unsigned long>(p));
}

// A star-shaped polygon around the origin: n vertices at strictly increasing angles (one per
// angular sector, at a random place inside it), random radii, coordinates rounded to `digits`
// decimal places. Rounding can break simplicity in rare cases; those are discarded.
inline ExactPolygon random_star(int n, int digits) {
  std::vector<ExactPoint> points;
  const double two_pi = 6.283185307179586;
  long scale = 1;
  for (int i = 0; i < digits; ++i) scale *= 10;
  for (int k = 0; k < n; ++k) {
    const int where = *rc::gen::inRange(1, 99);     // place inside the sector, in percent
    const int radius = *rc::gen::inRange(20, 1000); // tenths of a unit
    const double angle = two_pi * (k + where / 100.0) / n;
    const double r = radius / 10.0;
    points.emplace_back(
        decimal(std::lround(r * std::cos(angle) * static_cast<double>(scale)), digits),
        decimal(std::lround(r * std::sin(angle) * static_cast<double>(scale)), digits));
  }
  ExactPolygon polygon(points.begin(), points.end());
  for (std::size_t i = 0; i < points.size(); ++i)
    RC_PRE(points[i] != points[(i + 1) % points.size()]);
  RC_PRE(polygon.is_simple());
  return polygon;
}

// A random arena with holes: outer boundary a star around the origin with radii of at least 60
// units, and up to three holes, each a small star (radius <= 5) around a centre at distance 20 or
// 40 on one of six spokes, so that holes are apart and inside.
inline geometry::Arena random_arena_with_holes(int digits) {
  const int n = *rc::gen::inRange(3, 40);
  std::vector<ExactPoint> points;
  const double two_pi = 6.283185307179586;
  long scale = 1;
  for (int i = 0; i < digits; ++i) scale *= 10;
  auto round = [&](double v) {
    return decimal(std::lround(v * static_cast<double>(scale)), digits);
  };
  for (int k = 0; k < n; ++k) {
    const double angle = two_pi * (k + *rc::gen::inRange(1, 99) / 100.0) / n;
    const double r = 60.0 + *rc::gen::inRange(0, 400) / 10.0;
    points.emplace_back(round(r * std::cos(angle)), round(r * std::sin(angle)));
  }
  ExactPolygon outer(points.begin(), points.end());
  // The outer star's vertices are at radius >= 60 and two consecutive ones at most 2 * 360 / n
  // degrees apart, so with n >= 12 its edges stay beyond 60 cos(30 deg) > 51: holes within
  // radius 45 of the origin fit.
  std::vector<ExactPolygon> holes;
  if (n >= 12) {
    const int hole_count = *rc::gen::inRange(0, 4);
    for (int h = 0; h < hole_count; ++h) {
      const double spoke = two_pi * h / 6.0 * 2.0; // spokes 0, 120, 240 degrees
      const double d = (h % 2 == 0) ? 20.0 : 40.0;
      const double cx = d * std::cos(spoke), cy = d * std::sin(spoke);
      const int m = *rc::gen::inRange(3, 9);
      std::vector<ExactPoint> hp;
      for (int k = 0; k < m; ++k) {
        const double angle = two_pi * (k + *rc::gen::inRange(1, 99) / 100.0) / m;
        const double r = 1.0 + *rc::gen::inRange(0, 40) / 10.0;
        hp.emplace_back(round(cx + r * std::cos(angle)), round(cy + r * std::sin(angle)));
      }
      holes.emplace_back(hp.begin(), hp.end());
    }
  }
  try {
    return geometry::make_arena(ExactPolygonWithHoles(outer, holes.begin(), holes.end()), "random");
  } catch (const std::exception&) {
    RC_DISCARD("rounding made the generated polygon invalid");
  }
}

// The rasterization rule, decided directly: the point is strictly inside the outer boundary and
// strictly outside every hole.
inline bool strictly_inside(const ExactPolygonWithHoles& p, const ExactPoint& q) {
  if (p.outer_boundary().bounded_side(q) != CGAL::ON_BOUNDED_SIDE) return false;
  return std::all_of(p.holes_begin(), p.holes_end(), [&](const ExactPolygon& h) {
    return h.bounded_side(q) == CGAL::ON_UNBOUNDED_SIDE;
  });
}

} // namespace antkit::test
