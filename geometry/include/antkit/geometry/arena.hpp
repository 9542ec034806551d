#pragma once
// Arenas: the closed regions of paper 000 (Sahin, Girgin, Ugur 2006, section 4.1 and Figure 3) in
// which a robot measures area. An Arena is an exact polygon with holes (CGAL, rational
// coordinates), held behind a pointer so that this header compiles without CGAL: the simulators,
// the experiments and the command include it and get floating values for reports and fixed-point
// segments for decisions. Code that needs the CGAL polygon includes arena_cgal.hpp.
//
// Units and frame: the unit of length is the robot's diameter (the paper's unit). x grows to the
// right and y grows upward (the mathematical frame, unlike grids, whose y goes down; see
// arena_raster.hpp for the mapping). Every family is centred on the origin.
//
// Validity (checked by every way of making an Arena, so an Arena in hand is always valid):
//   * the outer boundary and each hole is a simple polygon: at least three vertices, no repeated
//     vertex, no two edges that meet except consecutive ones at their shared vertex, nonzero area;
//   * every hole lies strictly inside the outer boundary, and no two holes touch or nest: no
//     boundary of one ring meets another ring, not even at a single point. (Touching rings would
//     make the free region's topology depend on a single point, which no robot can pass through.)
//   * orientation is normalised: outer boundary counter-clockwise, holes clockwise. A ring given
//     the other way round is reversed keeping its first vertex first.
#include <antkit/kernel/segment.hpp>
#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace antkit::geometry {

// The paper's sizes (section 4.1): circles of diameter 10, 20, ..., 100 robot diameters; the
// standard arena is the circle of diameter 100; three ellipses of the standard area. (Section 6.1
// calls the two smallest arenas "348 and 1392 unit^2", the areas of diameters 21 and 42, which
// disagrees with "approximately ten times the body length"; the 10, 20, ..., 100 wins, and
// circle:d=21 builds the other reading.)
inline constexpr double kStandardDiameter = 100.0;
inline constexpr std::array<double, 10> kPaperCircleDiameters{10, 20, 30, 40, 50,
                                                              60, 70, 80, 90, 100};
inline constexpr std::array<double, 3> kPaperEccentricities{0.968, 0.994, 0.998};
// pi * 50^2, the area every arena of Figure 3(c)-(h) shares with the standard arena.
[[nodiscard]] double standard_area();

// Vertices of a curved boundary (circle, ellipse, ring walls). 256 keeps the polygon within
// R * (1 - cos(pi/256)) < 0.004 robot diameters of the ideal circle of diameter 100, far below the
// robot's size and the finest raster cell the experiments use (0.01), while the rasterizer still
// visits only a handful of edges per row.
inline constexpr int kCurveVertices = 256;

struct BoundingBox {
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
};

class Arena {
public:
  struct Impl; // defined in geometry/src/arena.cpp; arena_cgal.hpp gives access to its polygon

  explicit Arena(std::shared_ptr<const Impl> impl);
  Arena(const Arena&) = default;
  Arena(Arena&&) noexcept = default;
  Arena& operator=(const Arena&) = default;
  Arena& operator=(Arena&&) noexcept = default;
  ~Arena();

  // Vertices over all rings (outer boundary and holes), each counted once.
  [[nodiscard]] std::size_t vertex_count() const;
  [[nodiscard]] std::size_t hole_count() const;
  // The free area: outer area minus the holes' areas. area() is the exact value rounded to the
  // nearest double; area_exact() is the exact rational "p/q" in lowest terms.
  [[nodiscard]] double area() const;
  [[nodiscard]] std::string area_exact() const;
  // The length of every wall (outer boundary and holes), summed in double from exact squared edge
  // lengths (each edge's square root is correctly rounded; the sum is in ring order).
  [[nodiscard]] double perimeter() const;
  [[nodiscard]] BoundingBox bbox() const;
  // Each ring's vertices as doubles (outer first, then the holes), for plots and reports only.
  [[nodiscard]] std::vector<std::vector<std::array<double, 2>>> rings() const;

  // The walls as fixed-point segments for simulators: one segment per edge, the outer boundary's
  // edges first (counter-clockwise from its first vertex), then each hole's (clockwise), so that
  // the free region is always on the left of a segment. A coordinate v becomes Fx::from_raw(floor(v
  // * 65536 + 1/2)), computed exactly (round half up), so each endpoint is within half a raw unit
  // of the exact vertex. Throws kernel::InputError when a coordinate falls outside the Q15.16 range
  // [-32768, 32768).
  [[nodiscard]] std::vector<kernel::FxSegment> walls_fx() const;

  // Exact equality: same rings, same vertices, in the same order.
  friend bool operator==(const Arena& a, const Arena& b);

  [[nodiscard]] const Impl& impl() const noexcept { return *impl_; }

private:
  std::shared_ptr<const Impl> impl_; // immutable, so copies share it
};

// The eight families of Figure 3. Every builder puts its vertices on the 2^-16 lattice (the Q15.16
// grid of the kernel's fixed-point numbers, rounded half away from zero), so that walls_fx() is
// exact and arenas written as WKT are short. Curved walls are regular polygons (an affine image of
// one, for the ellipse) whose circumradius is scaled by sqrt(2 pi / (N sin(2 pi / N))) so that the
// N-gon's area equals the ideal curve's. The cosines and sines are computed by a Taylor series in
// IEEE double arithmetic (no libm transcendental calls), so the vertices are the same bits on every
// platform. What remains between area() and the ideal area is the lattice rounding: every vertex
// moves by at most 2^-17 per coordinate (2^-16.5 in distance), and moving the vertices of a polygon
// by at most delta changes its area by at most about perimeter * delta, so the stated bound is
//     |area() - ideal| <= perimeter() * 2^-16
// (tests/geometry and the arena_spec fuzzer check it for every family; at the paper's sizes the
// observed errors are 2.5 to 400 times smaller than the bound, relative errors at most 1.1e-6, for
// the smallest square; the standard circle is off by 2.9e-4 unit^2, relative 3.7e-8).
//
// Parameters outside their documented range throw kernel::InputError (where = `where`).

// (a) A circle of the given diameter, `vertices` vertices, the first on the positive x axis.
[[nodiscard]] Arena make_circle(double diameter, int vertices = kCurveVertices,
                                const std::string& where = "circle");
// (b) An axis-aligned square of the given area (the paper's squares have the area of the circle of
// the same index: side = d * sqrt(pi) / 2).
[[nodiscard]] Arena make_square(double area, const std::string& where = "square");
// (c) An ellipse of the given area and eccentricity e in [0, 0.9999], major axis along x:
// semi-axes a and b = a * sqrt(1 - e^2) with pi * a * b = area.
[[nodiscard]] Arena make_ellipse(double area, double eccentricity, int vertices = kCurveVertices,
                                 const std::string& where = "ellipse");

// (d), (e) The standard arena (a circle of diameter `diameter`, 100 in the paper) with a partial
// barrier at its centre: `|` is one vertical bar, `+` a vertical and a horizontal bar crossing at
// the centre. `length_fraction` is the bar's length as a fraction of the diameter (the paper's
// Figure 7 axis), in (0, 0.96]: at 0.96 the opening between a bar's end and the wall is two robot
// diameters, the paper's "couple of robot's diameter" at which the robot starts to get stuck.
// The paper does not give the barrier's thickness; the default is one robot diameter (the
// robot's own size: thin enough to take "not much space", thick enough that rasterizing at one
// cell per robot diameter always keeps the bar). The barrier is a hole of the polygon.
enum class Barrier { I, Plus };
[[nodiscard]] Arena make_barrier_arena(Barrier barrier, double length_fraction,
                                       double thickness = 1.0, double diameter = kStandardDiameter,
                                       int vertices = kCurveVertices,
                                       const std::string& where = "barrier");

// (f) A ring (annulus) of the given free area: the inner radius is `inner_ratio` times the outer
// radius. The figure is missing from the text; the default 0.5 gives a corridor as wide as the
// inner radius (28.9 robot diameters at the standard area) so that the robot's exploration sees a
// closed loop rather than a narrow tunnel.
[[nodiscard]] Arena make_ring(double area, double inner_ratio = 0.5, int vertices = kCurveVertices,
                              const std::string& where = "ring");

// (g) A plus (a cross with four equal arms) of the given area, axis-aligned. `arm_ratio` is the arm
// width over the overall span; the default 1/3 is the Greek cross made of five equal squares (the
// "plus" a reader draws when nothing else is said): area = span^2 (2 r - r^2).
[[nodiscard]] Arena make_plus(double area, double arm_ratio = 1.0 / 3.0,
                              const std::string& where = "plus");

// (h) A circle with small obstacles of the given free area. The figure is missing; the choice
// here: seven circular obstacles of diameter `obstacle_diameter` (default 5 robot diameters), one
// at the centre and six on the circle of radius D/4 at angles 0, 60, ..., 300 degrees, where D is
// the diameter of the circle of area `area` (100 at the standard area). None sits straight above
// the paper's start point (the central bottom of the arena), none touches another or the wall. The
// outer circle is enlarged so that the free area (outer minus obstacles) equals `area`. The
// obstacles have max(8, vertices / 8) vertices each.
[[nodiscard]] Arena make_obstacles_arena(double area, double obstacle_diameter = 5.0,
                                         int vertices = kCurveVertices,
                                         const std::string& where = "obstacles");

} // namespace antkit::geometry
