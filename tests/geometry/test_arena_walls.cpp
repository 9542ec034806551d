// Walls as fixed-point segments: one per edge, chained ring by ring, each endpoint within half a
// raw unit (2^-17) of its exact vertex, and out-of-range coordinates refused.
#include "arena_generators.hpp"

#include <antkit/geometry/arena.hpp>
#include <antkit/geometry/arena_cgal.hpp>
#include <antkit/geometry/wkt.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>
#include <vector>

using namespace antkit::geometry;
using antkit::kernel::FxSegment;
using antkit::kernel::InputError;

namespace {

// |raw / 65536 - v| <= 1/2^17, decided exactly.
bool within_half_raw(std::int32_t raw, const ExactNumber& v) {
  const ExactNumber diff = ExactNumber(static_cast<long>(raw)) - v * ExactNumber(65536);
  return diff <= ExactNumber(1, 2) && diff >= ExactNumber(-1, 2);
}

// The walls follow the rings: segment k starts at vertex k and ends where segment k + 1 starts.
std::string walls_mismatch(const Arena& arena) {
  const auto walls = arena.walls_fx();
  if (walls.size() != arena.vertex_count()) return "one segment per edge";
  const auto& p = exact_polygon(arena);
  std::vector<const ExactPolygon*> rings{&p.outer_boundary()};
  for (auto h = p.holes_begin(); h != p.holes_end(); ++h) rings.push_back(&*h);
  std::size_t k = 0;
  for (const auto* ring : rings) {
    const std::size_t first = k;
    for (std::size_t i = 0; i < ring->size(); ++i, ++k) {
      const FxSegment& s = walls[k];
      const auto& v = (*ring)[i];
      if (!within_half_raw(s.a.x.raw(), v.x()) || !within_half_raw(s.a.y.raw(), v.y()))
        return "segment " + std::to_string(k) + " starts off its vertex";
      const FxSegment& following = walls[i + 1 == ring->size() ? first : k + 1];
      if (!(s.b == following.a)) return "segment " + std::to_string(k) + " is not chained";
    }
  }
  return "";
}

} // namespace

TEST_CASE("every family's walls are its edges, exactly on the 2^-16 lattice", "[walls]") {
  for (const Arena& a :
       {make_circle(10), make_circle(100), make_square(7854), make_ellipse(7854, 0.998),
        make_barrier_arena(Barrier::I, 0.4), make_barrier_arena(Barrier::Plus, 0.96),
        make_ring(7854), make_plus(7854), make_obstacles_arena(7854)}) {
    CHECK(walls_mismatch(a).empty());
    // Builders put vertices on the lattice, so the conversion is exact.
    const auto walls = a.walls_fx();
    const auto& outer = exact_polygon(a).outer_boundary();
    for (std::size_t i = 0; i < outer.size(); ++i)
      CHECK(ExactNumber(static_cast<long>(walls[i].a.x.raw()), 65536ul) == outer[i].x());
  }
}

TEST_CASE("a worked example: rounding half up", "[walls]") {
  // 1/2^17 is exactly half a raw unit: it rounds up to 1 raw; -1/2^17 rounds up to 0.
  const Arena a = read_wkt("POLYGON ((0.00000762939453125 -0.00000762939453125, 1 0, 1 1, "
                           "0.00000762939453125 -0.00000762939453125))");
  const auto walls = a.walls_fx();
  REQUIRE(walls.size() == 3);
  CHECK(walls[0].a.x.raw() == 1);
  CHECK(walls[0].a.y.raw() == 0);
  CHECK(walls[0].b.x.raw() == 65536);
}

TEST_CASE("walls of random decimal polygons stay within half a raw unit", "[walls][property]") {
  rc::prop("within 2^-17", [] {
    const Arena a = antkit::test::random_arena_with_holes(*rc::gen::inRange(0, 8));
    RC_ASSERT(walls_mismatch(a).empty());
  });
}

TEST_CASE("a coordinate that rounds out of Q15.16 is refused", "[walls]") {
  // 32767.99999 rounds to 2^31 - 1 raw; 32767.999999 rounds to 2^31, one past the range.
  const Arena fits = read_wkt("POLYGON ((0 0, 32767.99999 0, 0 1, 0 0))");
  CHECK(fits.walls_fx()[0].b.x.raw() == 2147483647);
  const Arena beyond = read_wkt("POLYGON ((0 0, 32767.999999 0, 0 1, 0 0))");
  CHECK_THROWS_AS(beyond.walls_fx(), InputError);
}
