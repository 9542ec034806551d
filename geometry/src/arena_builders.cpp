// The eight arena families of paper 000, Figure 3 (see arena.hpp for the choices the paper leaves
// open). Every vertex is computed in IEEE double with +, -, *, / and sqrt only (each correctly
// rounded, and -ffp-contract=off keeps them unfused), then rounded to the 2^-16 lattice, so the
// exact arena is the same on every platform.
#include <antkit/geometry/arena.hpp>
#include <antkit/geometry/arena_cgal.hpp>
#include <antkit/kernel/input_error.hpp>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace antkit::geometry {

namespace {

// pi to the nearest double.
constexpr double kPi = 3.141592653589793238462643383279502884;

// cos and sin of 2 pi k / n by their Taylor series, after reducing the angle to [-pi/4, pi/4] by
// the exact integer octant of k / n (so the series converges in a dozen terms to within an ulp or
// two). Only basic IEEE operations: no libm, whose last bit differs between implementations.
std::array<double, 2> cos_sin_turn(std::int64_t k, std::int64_t n) {
  // k/n turns = octant/8 turns + remainder, with remainder in [-1/16, 1/16) turn.
  k %= n;
  if (k < 0) k += n;
  const std::int64_t octant = (16 * k + n) / (2 * n); // nearest eighth of a turn, 0..8
  const std::int64_t num = 8 * k - octant * n;        // remainder = num / (8 n) turns
  const double x = 2.0 * kPi * static_cast<double>(num) / (8.0 * static_cast<double>(n));
  double c = 0, s = 0, term_c = 1, term_s = x;
  const double x2 = x * x;
  for (int i = 1; i <= 14; ++i) {
    c += term_c;
    s += term_s;
    term_c *= -x2 / static_cast<double>((2 * i - 1) * (2 * i));
    term_s *= -x2 / static_cast<double>((2 * i) * (2 * i + 1));
  }
  // Rotate (c, s) by octant * 45 degrees using exact symmetries where they exist.
  constexpr double h = 0.70710678118654752440084436210484903928; // sqrt(1/2)
  switch (octant % 8) {
  case 0:
    return {c, s};
  case 1:
    return {h * (c - s), h * (c + s)};
  case 2:
    return {-s, c};
  case 3:
    return {-h * (c + s), h * (c - s)};
  case 4:
    return {-c, -s};
  case 5:
    return {h * (s - c), -h * (c + s)};
  case 6:
    return {s, -c};
  default:
    return {h * (c + s), h * (s - c)};
  }
}

// The lattice point nearest v (half away from zero): v * 65536 is exact in double.
ExactNumber lattice(double v, const std::string& where) {
  const double scaled = v * 65536.0;
  if (!(std::fabs(scaled) < 2147483648.0))
    throw kernel::InputError(where, "the arena does not fit the Q15.16 range [-32768, 32768) of "
                                    "the kernel's fixed-point walls; choose a smaller size");
  return ExactNumber(static_cast<long>(std::llround(scaled)), 65536L);
}

ExactPoint lattice_point(double x, double y, const std::string& where) {
  return {lattice(x, where), lattice(y, where)};
}

// sqrt(2 pi / (N sin(2 pi / N))): the circumradius of the regular N-gon whose area is pi r^2, per
// unit r.
double area_matching_factor(int n) {
  const double s = cos_sin_turn(1, n)[1];
  return std::sqrt(2.0 * kPi / (static_cast<double>(n) * s));
}

// An N-gon inscribed in the ellipse with semi-axes (a, b) scaled to the ellipse's area, centred at
// (cx, cy), first vertex on the +x axis, counter-clockwise.
ExactPolygon curved_ring(double cx, double cy, double a, double b, int n,
                         const std::string& where) {
  const double f = area_matching_factor(n);
  std::vector<ExactPoint> points;
  points.reserve(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    const auto [c, s] = cos_sin_turn(k, n);
    points.push_back(lattice_point(cx + f * a * c, cy + f * b * s, where));
  }
  return ExactPolygon(points.begin(), points.end());
}

ExactPolygon rectangle(double x0, double y0, double x1, double y1, const std::string& where) {
  std::vector<ExactPoint> points{lattice_point(x0, y0, where), lattice_point(x1, y0, where),
                                 lattice_point(x1, y1, where), lattice_point(x0, y1, where)};
  return ExactPolygon(points.begin(), points.end());
}

// A centred cross: arms of half-width w and half-span s, counter-clockwise from (s, -w).
ExactPolygon cross(double s, double w, const std::string& where) {
  const std::array<std::array<double, 2>, 12> corners{{{s, -w},
                                                       {s, w},
                                                       {w, w},
                                                       {w, s},
                                                       {-w, s},
                                                       {-w, w},
                                                       {-s, w},
                                                       {-s, -w},
                                                       {-w, -w},
                                                       {-w, -s},
                                                       {w, -s},
                                                       {w, -w}}};
  std::vector<ExactPoint> points;
  for (const auto& c : corners) points.push_back(lattice_point(c[0], c[1], where));
  return ExactPolygon(points.begin(), points.end());
}

void require(bool ok, const std::string& where, const std::string& what) {
  if (!ok) throw kernel::InputError(where, what);
}

// A parameter in a message: shortest form that shows what the user typed ("0.4", not "0.400000").
std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

void require_vertices(int n, const std::string& where) {
  require(n >= 8 && n <= 4096, where,
          "vertex count " + std::to_string(n) + " is outside [8, 4096]");
}

// Finite and inside [lo, hi]; the message names the parameter and the range.
void require_range(double v, double lo, double hi, const std::string& name,
                   const std::string& where) {
  require(std::isfinite(v) && v >= lo && v <= hi, where,
          name + " = " + number_text(v) + " is outside [" + number_text(lo) + ", " +
              number_text(hi) + "]");
}

ExactPolygonWithHoles with_holes(ExactPolygon outer, std::vector<ExactPolygon> holes = {}) {
  return ExactPolygonWithHoles(outer, holes.begin(), holes.end());
}

// The largest arena the builders accept: diameter 20000, comfortably inside the Q15.16 range.
constexpr double kMaxDiameter = 20000.0;
constexpr double kMaxArea = kPi / 4.0 * kMaxDiameter * kMaxDiameter;

} // namespace

double standard_area() {
  return kPi * 50.0 * 50.0;
}

Arena make_circle(double diameter, int vertices, const std::string& where) {
  require_range(diameter, 1.0, kMaxDiameter, "diameter", where);
  require_vertices(vertices, where);
  const double r = diameter / 2.0;
  return make_arena(with_holes(curved_ring(0, 0, r, r, vertices, where)), where);
}

Arena make_square(double area, const std::string& where) {
  require_range(area, 1.0, kMaxArea, "area", where);
  const double h = std::sqrt(area) / 2.0;
  return make_arena(with_holes(rectangle(-h, -h, h, h, where)), where);
}

Arena make_ellipse(double area, double eccentricity, int vertices, const std::string& where) {
  require_range(area, 1.0, kMaxArea, "area", where);
  require_range(eccentricity, 0.0, 0.9999, "eccentricity", where);
  require_vertices(vertices, where);
  const double ratio = std::sqrt(1.0 - eccentricity * eccentricity); // b / a
  const double a = std::sqrt(area / (kPi * ratio));
  return make_arena(with_holes(curved_ring(0, 0, a, a * ratio, vertices, where)), where);
}

Arena make_barrier_arena(Barrier barrier, double length_fraction, double thickness, double diameter,
                         int vertices, const std::string& where) {
  require_range(diameter, 10.0, kMaxDiameter, "diameter", where);
  require_range(length_fraction, 0.0, 0.96, "barrier length (fraction of the diameter)", where);
  require(length_fraction > 0.0, where,
          "barrier length must be positive (the arena without a barrier is `standard`)");
  const double length = length_fraction * diameter;
  require_range(thickness, 0.01, 10.0, "barrier thickness", where);
  require(thickness < length, where,
          "barrier thickness " + number_text(thickness) + " must be less than its length " +
              number_text(length));
  require_vertices(vertices, where);
  const double r = diameter / 2.0;
  ExactPolygon outer = curved_ring(0, 0, r, r, vertices, where);
  const double s = length / 2.0, w = thickness / 2.0;
  ExactPolygon hole = barrier == Barrier::I ? rectangle(-w, -s, w, s, where) : cross(s, w, where);
  return make_arena(with_holes(std::move(outer), {std::move(hole)}), where);
}

Arena make_ring(double area, double inner_ratio, int vertices, const std::string& where) {
  require_range(area, 1.0, kMaxArea, "area", where);
  require_range(inner_ratio, 0.05, 0.95, "inner radius ratio", where);
  require_vertices(vertices, where);
  // pi (R^2 - (rho R)^2) = area.
  const double outer = std::sqrt(area / (kPi * (1.0 - inner_ratio * inner_ratio)));
  const double inner = inner_ratio * outer;
  return make_arena(with_holes(curved_ring(0, 0, outer, outer, vertices, where),
                               {curved_ring(0, 0, inner, inner, vertices, where)}),
                    where);
}

Arena make_plus(double area, double arm_ratio, const std::string& where) {
  require_range(area, 1.0, kMaxArea, "area", where);
  require_range(arm_ratio, 0.05, 0.95, "arm width ratio", where);
  // area = span^2 (2 r - r^2).
  const double span = std::sqrt(area / (2.0 * arm_ratio - arm_ratio * arm_ratio));
  return make_arena(with_holes(cross(span / 2.0, arm_ratio * span / 2.0, where)), where);
}

Arena make_obstacles_arena(double area, double obstacle_diameter, int vertices,
                           const std::string& where) {
  require_range(area, 100.0, kMaxArea, "area", where);
  require_vertices(vertices, where);
  const double d = std::sqrt(4.0 * area / kPi); // the diameter of the circle of this area
  require_range(obstacle_diameter, 0.1, d / 8.0, "obstacle diameter", where);
  const double rho = obstacle_diameter / 2.0;
  // pi R^2 - 7 pi rho^2 = area.
  const double outer = std::sqrt(area / kPi + 7.0 * rho * rho);
  const int obstacle_vertices = vertices / 8 < 8 ? 8 : vertices / 8;
  std::vector<ExactPolygon> holes{curved_ring(0, 0, rho, rho, obstacle_vertices, where)};
  for (int k = 0; k < 6; ++k) {
    const auto [c, s] = cos_sin_turn(k, 6);
    // The centre goes on the lattice first, so that the six obstacles are (up to rounding ties)
    // translates of the central one.
    const double cx = CGAL::to_double(lattice(d / 4.0 * c, where));
    const double cy = CGAL::to_double(lattice(d / 4.0 * s, where));
    holes.push_back(curved_ring(cx, cy, rho, rho, obstacle_vertices, where));
  }
  return make_arena(with_holes(curved_ring(0, 0, outer, outer, vertices, where), std::move(holes)),
                    where);
}

} // namespace antkit::geometry
