// The eight arena families of paper 000, Figure 3: each builds, is valid, and has the area it
// promises within the stated bound |area - ideal| <= perimeter * 2^-16 (arena.hpp).
#include "arena_generators.hpp"

#include <antkit/geometry/arena.hpp>
#include <antkit/geometry/arena_cgal.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <rapidcheck/catch.h>
#include <string>
#include <vector>

using namespace antkit::geometry;
using antkit::kernel::InputError;

namespace {

constexpr double kPi = 3.141592653589793;
constexpr double kRawUnit = 1.0 / 65536.0;

struct Case {
  std::string name;
  Arena arena;
  double ideal;
  std::size_t holes;
};

std::vector<Case> paper_arenas() {
  std::vector<Case> cases;
  const double standard = kPi * 2500.0;
  for (const double d : kPaperCircleDiameters) {
    cases.push_back({"circle d=" + std::to_string(d), make_circle(d), kPi * d * d / 4, 0});
    const double area = kPi * d * d / 4;
    cases.push_back({"square d=" + std::to_string(d), make_square(area), area, 0});
  }
  for (const double e : kPaperEccentricities)
    cases.push_back({"ellipse e=" + std::to_string(e), make_ellipse(standard, e), standard, 0});
  for (const double len : {0.1, 0.2, 0.4, 0.6, 0.8, 0.9, 0.96}) {
    const double l = len * 100;
    cases.push_back({"barrier | len=" + std::to_string(len), make_barrier_arena(Barrier::I, len),
                     standard - l * 1.0, 1});
    cases.push_back({"barrier + len=" + std::to_string(len), make_barrier_arena(Barrier::Plus, len),
                     standard - (2 * l - 1.0), 1});
  }
  cases.push_back({"ring", make_ring(standard), standard, 1});
  cases.push_back({"plus", make_plus(standard), standard, 0});
  cases.push_back({"obstacles", make_obstacles_arena(standard), standard, 7});
  return cases;
}

// Re-validating an arena's own polygon must accept it unchanged: the invariants hold.
void require_valid(const Arena& a) {
  const Arena again = make_arena(exact_polygon(a), "again");
  REQUIRE(again == a);
  const auto& p = exact_polygon(a);
  REQUIRE(p.outer_boundary().orientation() == CGAL::COUNTERCLOCKWISE);
  for (auto h = p.holes_begin(); h != p.holes_end(); ++h)
    REQUIRE(h->orientation() == CGAL::CLOCKWISE);
}

} // namespace

TEST_CASE("every family of Figure 3 builds valid arenas with the paper's areas", "[arena]") {
  for (const auto& c : paper_arenas()) {
    INFO(c.name);
    require_valid(c.arena);
    CHECK(c.arena.hole_count() == c.holes);
    const double error = std::fabs(c.arena.area() - c.ideal);
    CHECK(error <= c.arena.perimeter() * kRawUnit);
    // The exact and the floating area agree.
    const auto text = c.arena.area_exact();
    const auto slash = text.find('/');
    REQUIRE(slash != std::string::npos);
    CHECK(std::stod(text.substr(0, slash)) / std::stod(text.substr(slash + 1)) ==
          Approx(c.arena.area()).epsilon(1e-12));
  }
}

TEST_CASE("the paper's sizes: diameters 10..100, squares of equal area, ellipses' shapes",
          "[arena]") {
  for (const double d : kPaperCircleDiameters) {
    const auto box = make_circle(d).bbox();
    // The area-matched 256-gon's circumradius exceeds d/2 by a factor of 1 + O(1/N^2).
    CHECK(box.xmax == Approx(d / 2).epsilon(1e-4));
    CHECK(box.xmin == Approx(-d / 2).epsilon(1e-4));
    const auto square = make_square(kPi * d * d / 4).bbox();
    CHECK(square.xmax - square.xmin == Approx(d * std::sqrt(kPi) / 2).epsilon(1e-6));
  }
  for (const double e : kPaperEccentricities) {
    const auto box = make_ellipse(kPi * 2500, e).bbox();
    // Semi-axes from the box: a along x (a vertex sits on the axis), b along y (within the
    // polygon's sagitta of the ideal ellipse).
    const double a = box.xmax, b = box.ymax;
    CHECK(std::sqrt(1 - (b / a) * (b / a)) == Approx(e).epsilon(1e-4));
  }
  CHECK(standard_area() == Approx(7853.981633974483));
}

TEST_CASE("vertex counts and the layout of holes are as documented", "[arena]") {
  CHECK(make_circle(100).vertex_count() == 256);
  CHECK(make_circle(100, 64).vertex_count() == 64);
  CHECK(make_square(100).vertex_count() == 4);
  CHECK(make_barrier_arena(Barrier::I, 0.4).vertex_count() == 256 + 4);
  CHECK(make_barrier_arena(Barrier::Plus, 0.4).vertex_count() == 256 + 12);
  CHECK(make_ring(kPi * 2500).vertex_count() == 512);
  CHECK(make_plus(kPi * 2500).vertex_count() == 12);
  CHECK(make_obstacles_arena(kPi * 2500).vertex_count() == 256 + 7 * 32);
  // The ring's inner radius is half its outer radius.
  const auto rings = make_ring(kPi * 2500).rings();
  CHECK(rings[1][0][0] / rings[0][0][0] == Approx(0.5).epsilon(1e-6));
  // The plus's arm width is a third of its span.
  const auto plus = make_plus(kPi * 2500).bbox();
  const auto cross = make_plus(kPi * 2500).rings()[0];
  CHECK(2 * cross[0][1] / (plus.xmin - plus.xmax) == Approx(1.0 / 3).epsilon(1e-6));
}

TEST_CASE("curved walls: every vertex is within a raw unit of the area-matched circle",
          "[arena][property]") {
  rc::prop("circle", [] {
    const int n = *rc::gen::inRange(8, 1025);
    const double d = *rc::gen::inRange(10, 2001) / 10.0;
    const Arena a = make_circle(d, n);
    const double factor = std::sqrt(2 * kPi / (n * std::sin(2 * kPi / n)));
    const double r = d / 2 * factor;
    const auto rings = a.rings();
    for (const auto& v : rings[0]) RC_ASSERT(std::fabs(std::hypot(v[0], v[1]) - r) <= kRawUnit);
    RC_ASSERT(std::fabs(a.area() - kPi * d * d / 4) <= a.perimeter() * kRawUnit);
  });
}

TEST_CASE("the builders are deterministic: the same parameters give the same exact arena",
          "[arena]") {
  CHECK(make_circle(100) == make_circle(100));
  CHECK(make_obstacles_arena(7853.98) == make_obstacles_arena(7853.98));
  CHECK_FALSE(make_circle(100) == make_circle(100, 128));
}

TEST_CASE("parameters out of range are bad input", "[arena]") {
  CHECK_THROWS_AS(make_circle(0.5), InputError);
  CHECK_THROWS_AS(make_circle(100, 4), InputError);
  CHECK_THROWS_AS(make_circle(std::nan("")), InputError);
  CHECK_THROWS_AS(make_ellipse(7854, 1.0), InputError);
  CHECK_THROWS_AS(make_barrier_arena(Barrier::I, 0.97), InputError);
  CHECK_THROWS_AS(make_barrier_arena(Barrier::I, 0.0), InputError);
  CHECK_THROWS_AS(make_barrier_arena(Barrier::Plus, 0.005, 1.0), InputError); // thicker than long
  CHECK_THROWS_AS(make_ring(7854, 0.99), InputError);
  CHECK_THROWS_AS(make_plus(7854, 1.0), InputError);
  CHECK_THROWS_AS(make_obstacles_arena(7854, 20.0), InputError);
  CHECK_THROWS_AS(make_ellipse(3e8, 0.9999), InputError);
}

TEST_CASE("make_arena normalises orientation and rejects invalid polygons", "[arena]") {
  using antkit::test::decimal;
  auto ring = [](std::vector<std::pair<int, int>> pts) {
    std::vector<ExactPoint> p;
    for (auto [x, y] : pts) p.emplace_back(x, y);
    return ExactPolygon(p.begin(), p.end());
  };
  auto with = [](ExactPolygon outer, std::vector<ExactPolygon> holes = {}) {
    return ExactPolygonWithHoles(outer, holes.begin(), holes.end());
  };
  const auto square = ring({{0, 0}, {10, 0}, {10, 10}, {0, 10}});
  const auto clockwise = ring({{0, 0}, {0, 10}, {10, 10}, {10, 0}});

  SECTION("a clockwise outer ring is reversed keeping its first vertex") {
    const Arena a = make_arena(with(clockwise), "t");
    CHECK(a == make_arena(with(square), "t"));
    CHECK(a.area_exact() == "100/1");
  }
  SECTION("a counter-clockwise hole is reversed") {
    const Arena a = make_arena(with(square, {ring({{2, 2}, {4, 2}, {4, 4}})}), "t");
    CHECK(exact_polygon(a).holes_begin()->orientation() == CGAL::CLOCKWISE);
    CHECK(a.area_exact() == "98/1");
  }
  SECTION("invalid") {
    const std::vector<ExactPolygonWithHoles> bad{
        with(ring({{0, 0}, {10, 10}, {10, 0}, {0, 10}})),     // bow tie
        with(ring({{0, 0}, {10, 0}, {20, 0}})),               // collinear
        with(ring({{0, 0}, {10, 0}, {10, 0}, {0, 10}})),      // repeated vertex
        with(ring({{0, 0}, {10, 0}})),                        // two vertices
        with(square, {ring({{20, 20}, {22, 20}, {22, 22}})}), // hole outside
        with(square, {ring({{0, 0}, {2, 1}, {1, 2}})}),       // hole touches a corner
        with(square, {ring({{5, 0}, {6, 2}, {4, 2}})}),       // hole touches an edge
        with(square, {ring({{-1, 5}, {5, 4}, {5, 6}})}),      // hole crosses the wall
        with(square, {ring({{1, 1}, {9, 1}, {9, 9}, {1, 9}}), ring({{4, 4}, {5, 4}, {5, 5}})}),
        with(square, {ring({{1, 1}, {5, 1}, {5, 5}}), ring({{5, 1}, {8, 1}, {8, 4}})}), // touch
        with(square, {ring({{1, 1}, {6, 1}, {6, 6}}), ring({{4, 2}, {8, 2}, {8, 6}})}), // overlap
    };
    for (std::size_t i = 0; i < bad.size(); ++i) {
      INFO("case " << i);
      CHECK_THROWS_AS(make_arena(bad[i], "t"), InputError);
    }
  }
  SECTION("holes that come close without touching are fine") {
    const auto hole = ring({{1, 1}, {5, 1}, {5, 5}});
    std::vector<ExactPoint> near{
        {ExactPoint(decimal(50001, 4), 1)}, ExactPoint(8, 1), ExactPoint(8, 4)};
    CHECK_NOTHROW(make_arena(with(square, {hole, ExactPolygon(near.begin(), near.end())}), "t"));
  }
}

TEST_CASE("random arenas with holes are valid and re-validate unchanged", "[arena][property]") {
  rc::prop("valid", [] {
    const Arena a = antkit::test::random_arena_with_holes(*rc::gen::inRange(0, 4));
    RC_ASSERT(make_arena(exact_polygon(a), "again") == a);
    RC_ASSERT(a.area() > 0);
  });
}
