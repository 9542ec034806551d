// Named arena specs: each names the builder call it documents, and bad specs are InputErrors at
// "SPEC:1:COL" pointing at what is wrong.
#include <antkit/geometry/arena.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>
#include <string>

using namespace antkit::geometry;
using antkit::kernel::InputError;

namespace {
constexpr double kPi = 3.141592653589793;

// The error's where() for a spec, or "" when it parses and builds.
std::string error_at(const std::string& spec) {
  try {
    (void)build_arena_spec(spec);
  } catch (const InputError& e) {
    return e.where();
  }
  return "";
}
} // namespace

TEST_CASE("specs build what the builders build", "[arena][spec]") {
  const double standard = standard_area();
  CHECK(build_arena_spec("standard").arena == make_circle(100));
  CHECK(build_arena_spec("circle").arena == make_circle(100));
  CHECK(build_arena_spec("circle:d=100").arena == make_circle(100));
  CHECK(build_arena_spec("circle:d=30,n=64").arena == make_circle(30, 64));
  CHECK(build_arena_spec("circle:area=7853.981633974483").arena == make_circle(100));
  CHECK(build_arena_spec("square:area=7854").arena == make_square(7854));
  CHECK(build_arena_spec("square:side=20").arena == make_square(400));
  CHECK(build_arena_spec("square:d=100").arena == make_square(kPi * 2500));
  CHECK(build_arena_spec("ellipse:area=7854,e=0.968").arena == make_ellipse(7854, 0.968));
  CHECK(build_arena_spec("ellipse:e=0.994").arena == make_ellipse(standard, 0.994));
  CHECK(build_arena_spec("barrier-i:len=0.4").arena == make_barrier_arena(Barrier::I, 0.4));
  CHECK(build_arena_spec("barrier-plus:len=0.4,t=2").arena ==
        make_barrier_arena(Barrier::Plus, 0.4, 2.0));
  CHECK(build_arena_spec("ring").arena == make_ring(standard));
  CHECK(build_arena_spec("ring:ratio=0.25").arena == make_ring(standard, 0.25));
  CHECK(build_arena_spec("plus:arm=0.5").arena == make_plus(standard, 0.5));
  CHECK(build_arena_spec("obstacles:size=3").arena == make_obstacles_arena(standard, 3));
  CHECK(build_arena_spec("circle:d=1e2").arena == make_circle(100));
}

TEST_CASE("a spec's ideal area is the unrounded shape's", "[arena][spec]") {
  CHECK(build_arena_spec("circle:d=10").ideal_area == Approx(kPi * 25));
  CHECK(build_arena_spec("barrier-i:len=0.5,t=2").ideal_area == Approx(kPi * 2500 - 50 * 2));
  CHECK(build_arena_spec("barrier-plus:len=0.5").ideal_area == Approx(kPi * 2500 - (100 - 1)));
  for (const char* spec : {"standard", "ring", "plus", "obstacles", "ellipse:e=0.998"}) {
    const auto named = build_arena_spec(spec);
    CHECK(named.ideal_area == Approx(kPi * 2500));
    CHECK(std::fabs(named.arena.area() - named.ideal_area) <= named.arena.perimeter() / 65536.0);
  }
}

TEST_CASE("bad specs point at the offending byte", "[arena][spec]") {
  CHECK(error_at("circel") == "SPEC:1:1");
  CHECK(error_at("") == "SPEC:1:1");
  CHECK(error_at("circle:") == "SPEC:1:8");
  CHECK(error_at("circle:x=1") == "SPEC:1:8");
  CHECK(error_at("circle:d") == "SPEC:1:8");
  CHECK(error_at("circle:=5") == "SPEC:1:8");
  CHECK(error_at("circle:d=abc") == "SPEC:1:10");
  CHECK(error_at("circle:d=") == "SPEC:1:10");
  CHECK(error_at("circle:d=1e999") == "SPEC:1:10");
  CHECK(error_at("circle:d=nan") == "SPEC:1:10");
  CHECK(error_at("circle:d=0.5") == "SPEC:1:10");      // below one robot diameter
  CHECK(error_at("circle:d=100,d=50") == "SPEC:1:14"); // twice
  CHECK(error_at("circle:d=100,") == "SPEC:1:14");
  CHECK(error_at("circle:d=100,area=5") == "SPEC:1:19"); // two sizes: at the second
  CHECK(error_at("circle:n=7.5") == "SPEC:1:10");
  CHECK(error_at("ellipse:area=7854") == "SPEC:1:1"); // e missing
  CHECK(error_at("ellipse:e=1") == "SPEC:1:11");
  CHECK(error_at("barrier-i:len=0.99") == "SPEC:1:15");
  CHECK(error_at("barrier-i:len=0.4,t=50") == "SPEC:1:21");
  CHECK(error_at("barrier-plus") == "SPEC:1:1"); // len missing
  CHECK(error_at("ring:ratio=1") == "SPEC:1:12");
  CHECK(error_at("square:side=0.1") == "SPEC:1:13");
  CHECK(error_at("plus:d=5") == "SPEC:1:6"); // plus has no d
  CHECK(error_at("obstacles:size=100") == "SPEC:1:16");
  CHECK(error_at("circle:d=100") == "");
}

TEST_CASE("the error names the input and says what was expected", "[arena][spec]") {
  try {
    (void)build_arena_spec("hexagon");
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).rfind("SPEC:1:1: unknown arena family 'hexagon'", 0) == 0);
    CHECK(std::string(e.what()).find("circle") != std::string::npos);
  }
}

TEST_CASE("any text either builds an arena or is an InputError", "[arena][spec][property]") {
  rc::prop("no other failure", [] {
    const auto family =
        *rc::gen::element<std::string>("circle", "square", "ellipse", "barrier-i", "barrier-plus",
                                       "ring", "plus", "obstacles", "standard", "bogus");
    const auto tail = *rc::gen::container<std::string>(
        rc::gen::element(':', ',', '=', 'd', 'e', 'n', 't', '.', '0', '1', '5', '9', '-', 'x'));
    const std::string spec = family + tail;
    try {
      const auto named = build_arena_spec(spec);
      RC_ASSERT(named.arena.area() > 0);
    } catch (const InputError& e) {
      RC_ASSERT(e.where().rfind("SPEC:1:", 0) == 0);
      RC_ASSERT(e.column() >= 1u);
      RC_ASSERT(e.column() <= spec.size() + 1);
    }
  });
}
