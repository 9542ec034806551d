// run_coverage_traced and save_coverage_figure (experiments/coverage_run.hpp), what `antkit cover`
// writes: the traced run is the plain run (same hash), its trace reads back through
// testing::read_cover_trace with the run's poses, sensor and claims, and a trace that cannot be
// written is refused by its name with no file left.
#include "scratch_dir.hpp"

#include <antkit/experiments/coverage_run.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/testing/run_audit.hpp>
#include <antkit/uniform/scenario.hpp>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;
namespace uniform = antkit::uniform;

namespace {

uniform::CoverageWorld world(std::uint64_t seed) {
  auto map = uniform::random_obstacles(20, 16, 200000, seed, 0);
  auto poses = uniform::place_robots(map, 3, std::nullopt, seed, 0);
  return uniform::CoverageWorld(std::move(map), std::move(poses), 3);
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

} // namespace

TEST_CASE("run_coverage_traced: the plain run, with a trace check cover reads", "[uniform]") {
  const antkit::test::ScratchDir scratch("cover-run");
  const fs::path& dir = scratch.path();
  for (const auto algorithm : {uniform::Algorithm::PrimaryMovement, uniform::Algorithm::Frontier}) {
    auto plain_world = world(3);
    const auto plain = uniform::run_coverage(plain_world, algorithm, 3, 0, 2000);
    auto traced_world = world(3);
    const auto traced = antkit::experiments::run_coverage_traced(traced_world, algorithm, 3, 0,
                                                                 2000, 3, dir / "trace.csv");
    CHECK(traced.hash == plain.hash);
    CHECK(traced.viewed == plain.viewed);
    const auto t = antkit::testing::read_cover_trace(slurp(dir / "trace.csv"), "trace.csv");
    CHECK(t.robots == 3);
    CHECK(t.sensor == 3);
    CHECK(t.claim_viewed == traced.viewed);
    CHECK(t.claim_viewable == traced.viewable);
    REQUIRE_FALSE(t.cells.empty());
    for (std::size_t i = 0; i < 3; ++i) CHECK(t.cells.back()[i] == traced_world.robot(i).cell);

    antkit::experiments::save_coverage_figure("pm", traced_world, traced, 3, dir / "c.svg", "");
    CHECK(fs::exists(dir / "c.svg"));
  }
  SECTION("a trace in a missing directory: refused by its name, nothing written") {
    auto w = world(4);
    try {
      (void)antkit::experiments::run_coverage_traced(w, uniform::Algorithm::RandomWanderer, 4, 0,
                                                     100, 3, dir / "absent" / "trace.csv");
      FAIL("a trace was written into a missing directory");
    } catch (const antkit::kernel::InputError& e) {
      CHECK(e.where() == (dir / "absent" / "trace.csv").string());
    }
    CHECK_FALSE(fs::exists(dir / "absent"));
  }
}
