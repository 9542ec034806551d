// WKT: exact reading and writing, round trips, and positioned errors.
#include "arena_generators.hpp"

#include <antkit/geometry/arena.hpp>
#include <antkit/geometry/arena_cgal.hpp>
#include <antkit/geometry/wkt.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>
#include <string>

using namespace antkit::geometry;
using antkit::kernel::InputError;

namespace {
std::string error_at(const std::string& wkt) {
  try {
    (void)read_wkt(wkt, "f.wkt");
  } catch (const InputError& e) {
    return e.where();
  }
  return "";
}
} // namespace

TEST_CASE("exact decimal and fraction texts", "[wkt]") {
  CHECK(decimal_text(ExactNumber(1, 2)) == "0.5");
  CHECK(decimal_text(ExactNumber(-3, 8)) == "-0.375");
  CHECK(decimal_text(ExactNumber(5)) == "5");
  CHECK(decimal_text(ExactNumber(-120)) == "-120");
  CHECK(decimal_text(ExactNumber(0)) == "0");
  CHECK(decimal_text(ExactNumber(1, 65536)) == "0.0000152587890625");
  CHECK(decimal_text(ExactNumber(-1, 1000)) == "-0.001");
  CHECK(decimal_text(ExactNumber(1, 3)).empty());
  CHECK(fraction_text(ExactNumber(6, 4)) == "3/2");
  CHECK(fraction_text(ExactNumber(-7)) == "-7/1");
}

TEST_CASE("a worked example: a square with a square hole", "[wkt]") {
  const Arena a = read_wkt("POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (2 2, 2 4, 4 4, 4 2, 2 2))");
  CHECK(a.area_exact() == "96/1");
  CHECK(a.area() == 96.0);
  CHECK(a.perimeter() == 48.0);
  CHECK(a.vertex_count() == 8);
  CHECK(a.hole_count() == 1);
  CHECK(write_wkt(a) == "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (2 2, 2 4, 4 4, 4 2, 2 2))");
}

TEST_CASE("numbers are read exactly, in every accepted spelling", "[wkt]") {
  const Arena a = read_wkt("polygon((0.1 0, 1e0 0, +1 .3e1, -0.5E-1 3, 0.1 0))");
  const auto& outer = exact_polygon(a).outer_boundary();
  CHECK(outer[0] == ExactPoint(ExactNumber(1, 10), 0));
  CHECK(outer[2] == ExactPoint(1, 3));
  CHECK(outer[3] == ExactPoint(ExactNumber(-1, 20), 3));
  CHECK(write_wkt(a) == "POLYGON ((0.1 0, 1 0, 1 3, -0.05 3, 0.1 0))");
}

TEST_CASE("layout: any case, any whitespace, and a MULTIPOLYGON of one polygon", "[wkt]") {
  const Arena a = read_wkt("POLYGON ((0 0, 4 0, 4 4, 0 0))");
  CHECK(read_wkt("  Polygon\n(\t( 0 0 ,4 0,\r\n4 4 , 0 0 ) )\n") == a);
  CHECK(read_wkt("MULTIPOLYGON (((0 0, 4 0, 4 4, 0 0)))") == a);
  // Clockwise outer ring: normalised to counter-clockwise keeping the first vertex.
  CHECK(read_wkt("POLYGON ((0 0, 4 4, 4 0, 0 0))") == a);
}

TEST_CASE("every family round-trips exactly", "[wkt]") {
  for (const Arena& a :
       {make_circle(100), make_square(7854), make_ellipse(7854, 0.998),
        make_barrier_arena(Barrier::I, 0.4), make_barrier_arena(Barrier::Plus, 0.8),
        make_ring(7854), make_plus(7854), make_obstacles_arena(7854)}) {
    const std::string text = write_wkt(a);
    const Arena b = read_wkt(text);
    CHECK(b == a);
    CHECK(b.area_exact() == a.area_exact());
    CHECK(write_wkt(b) == text);
  }
}

TEST_CASE("random polygons round-trip exactly through WKT", "[wkt][property]") {
  rc::prop("star polygons with decimals", [] {
    const int digits = *rc::gen::inRange(0, 7);
    const auto ring = antkit::test::random_star(*rc::gen::inRange(3, 60), digits);
    const Arena a = make_arena(ExactPolygonWithHoles(ring), "random");
    const std::string text = write_wkt(a);
    const Arena b = read_wkt(text);
    RC_ASSERT(b == a);
    RC_ASSERT(write_wkt(b) == text);
  });
  rc::prop("arenas with holes", [] {
    const Arena a = antkit::test::random_arena_with_holes(*rc::gen::inRange(0, 5));
    const Arena b = read_wkt(write_wkt(a));
    RC_ASSERT(b == a);
    RC_ASSERT(b.hole_count() == a.hole_count());
  });
}

TEST_CASE("malformed WKT is an InputError at its line and column", "[wkt]") {
  CHECK(error_at("") == "f.wkt:1:1");
  CHECK(error_at("LINESTRING (0 0, 1 1)") == "f.wkt:1:1");
  CHECK(error_at("POLYGON EMPTY") == "f.wkt:1:9");
  CHECK(error_at("POLYGON Z ((0 0 0, 1 0 0, 1 1 0, 0 0 0))") == "f.wkt:1:9");
  CHECK(error_at("POLYGON ((0 0, 1 0, 1 1, 0 0)") == "f.wkt:1:30");  // missing ')'
  CHECK(error_at("POLYGON ((0 0, 1 0, 1 1, 0 1))") == "f.wkt:1:10"); // not closed
  CHECK(error_at("POLYGON ((0 0, 1 0, 0 0))") == "f.wkt:1:10");      // too few points
  CHECK(error_at("POLYGON ((0 0, 1 x, 1 1, 0 0))") == "f.wkt:1:18");
  CHECK(error_at("POLYGON ((0 0 0, 1 0, 1 1, 0 0))") == "f.wkt:1:15"); // third coordinate
  CHECK(error_at("POLYGON ((0 0, 1 0, 1 1, 0 0)) x") == "f.wkt:1:32");
  CHECK(error_at("POLYGON ((0 0,\n1 0,\n1 1e,\n0 0))") == "f.wkt:3:5");
  CHECK(error_at("POLYGON ((0 0, 40000 0, 1 1, 0 0))") == "f.wkt:1:16"); // outside Q15.16
  CHECK(error_at("POLYGON ((0 0, 1e101 0, 1 1, 0 0))") == "f.wkt:1:16");
  CHECK(error_at("MULTIPOLYGON (((0 0, 1 0, 1 1, 0 0)), ((5 5, 6 5, 6 6, 5 5)))") == "f.wkt:1:37");
  CHECK(error_at("POLYGON ((0 0, 1 0, 1 1, 0 0))") == "");
}

TEST_CASE("invalid polygons name the polygon's position", "[wkt]") {
  // A bow tie, and a hole outside: rejected by validation, at the polygon's opening parenthesis.
  CHECK(error_at("POLYGON ((0 0, 1 1, 1 0, 0 1, 0 0))") == "f.wkt:1:9");
  CHECK(error_at("POLYGON ((0 0, 9 0, 9 9, 0 9, 0 0), (20 20, 21 20, 21 21, 20 20))") ==
        "f.wkt:1:9");
  CHECK(error_at("\n MULTIPOLYGON (((0 0, 1 1, 1 0, 0 1, 0 0)))") == "f.wkt:2:16");
}

TEST_CASE("a missing file is an InputError naming it", "[wkt]") {
  CHECK_THROWS_AS(read_wkt_file("/nonexistent/arena.wkt"), InputError);
}

TEST_CASE("arbitrary text never fails other than with an InputError", "[wkt][property]") {
  rc::prop("tokens", [] {
    const auto tokens = *rc::gen::container<std::vector<std::string>>(rc::gen::element<std::string>(
        "POLYGON", "MULTIPOLYGON", "(", ")", ",", " ", "0", "1", "-2.5", "1e3", "EMPTY", "\n"));
    std::string text;
    for (const auto& t : tokens) text += t;
    try {
      const Arena a = read_wkt(text);
      RC_ASSERT(read_wkt(write_wkt(a)) == a);
    } catch (const InputError& e) {
      RC_ASSERT(e.where().rfind("WKT:", 0) == 0);
    }
  });
}
