// Section 8.1: the a + b x^c calibration fit and the RS / checkpoint runs behind Figure 14.
#include <antkit/buffon/checkpoints.hpp>
#include <antkit/experiments/calibration.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

namespace buffon = antkit::buffon;

TEST_CASE("the power fit recovers a + b x^c from exact points", "[property]") {
  rc::prop("four exact points of a decreasing power law are fitted to 1e-6", [] {
    const double a = *rc::gen::inRange(-90, 500) * 1.0; // y > 100 * 0.9^c - 90 > 10
    const double b = *rc::gen::inRange(100, 2000) * 1.0;
    const double c = -*rc::gen::inRange(50, 150) / 100.0;
    std::vector<double> x{0.13, 0.21, 0.35, 0.9}, y;
    for (double xi : x) y.push_back(a + b * std::pow(xi, c));
    const auto fit = antkit::experiments::fit_power_law(x, y);
    for (std::size_t i = 0; i < x.size(); ++i)
      RC_ASSERT(std::abs(fit(x[i]) - y[i]) <= 1e-6 * std::abs(y[i]));
  });
}

TEST_CASE("checkpoints: RS marks grow with the trail and stay within the arena") {
  const auto arena = antkit::geometry::build_arena_spec("circle:d=20").arena;
  const buffon::World world(arena.walls_fx());
  buffon::TrialParams p;
  const auto r = buffon::run_checkpoints(world, p, 0, std::int64_t{50} * 65536, 6);
  const double cell = static_cast<double>(r.rs_cell_raw) / 65536.0;
  for (std::size_t k = 0; k < 6; ++k) {
    if (k > 0) {
      CHECK(r.rs_cells[k] >= r.rs_cells[k - 1]);
      CHECK(r.length2_raw[k] >= r.length2_raw[k - 1]);
    }
    CHECK(static_cast<double>(r.rs_cells[k]) * cell * cell <= arena.area());
    // Visit 2's length at checkpoint k is within one step of (k + 1) * 50.
    CHECK(static_cast<double>(r.length2_raw[k]) / 65536.0 ==
          Approx(50.0 * static_cast<double>(k + 1)).margin(0.05));
  }
  // After 600 units of RS trail in a 314 unit^2 arena most of the reachable area is marked.
  CHECK(static_cast<double>(r.rs_cells[5]) * cell * cell > 0.5 * arena.area());
  // Buffon counts exist at every checkpoint in a small arena.
  CHECK(r.bc[0] > 0);
}
