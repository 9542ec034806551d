// The precision rule's interval and the erosion correction as `antkit buffon --precision` reports
// them (estimate.hpp, precision_estimate): the interval A_hat N / (N +/- z sqrt V) with V floored
// at N, its absent sides, the erosion factor's scaling, and the precision reached.
#include <antkit/buffon/estimate.hpp>
#include <antkit/buffon/stopping.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <rapidcheck/catch.h>

namespace buffon = antkit::buffon;

namespace {
const double kZ2 = static_cast<double>(buffon::PrecisionMonitor::kZSquaredMilli) / 1000.0;
}

TEST_CASE("precision_estimate: the rule's interval, the corrected estimate and the precision "
          "reached",
          "[buffon]") {
  // N = 400 crossings, V = 300 + 500 = 800 > N: z sqrt V = sqrt(5.118 * 800) = 63.99.
  const auto e = buffon::precision_estimate({1000.0, 400, 300.0, 500.0, 50, 2000.0});
  const double half = std::sqrt(kZ2 * 800);
  REQUIRE(e.ci.lower);
  REQUIRE(e.ci.upper);
  CHECK(*e.ci.lower == 1000.0 * 400 / (400 + half));
  CHECK(*e.ci.upper == 1000.0 * 400 / (400 - half));
  CHECK(*e.ci.lower == Approx(862.1).epsilon(1e-4));
  CHECK(*e.ci.upper == Approx(1190.4).epsilon(1e-4));
  // 1 + kappa E / L = 1 + 3.6 * 50 / 2000.
  CHECK(e.erosion_factor == Approx(1.09));
  CHECK(e.erosion_factor == buffon::erosion_factor(50, 2000.0));
  REQUIRE(e.area_corrected);
  CHECK(*e.area_corrected == 1000.0 * e.erosion_factor);
  REQUIRE(e.corrected_ci.lower);
  REQUIRE(e.corrected_ci.upper);
  CHECK(*e.corrected_ci.lower == *e.ci.lower * e.erosion_factor);
  CHECK(*e.corrected_ci.upper == *e.ci.upper * e.erosion_factor);
  REQUIRE(e.precision_reached);
  CHECK(*e.precision_reached == *e.ci.upper / 1000.0 - 1);
  CHECK(*e.precision_reached == Approx(half / (400 - half)));
}

TEST_CASE("precision_estimate: V is floored at N (Poisson)", "[buffon]") {
  const auto low = buffon::precision_estimate({500.0, 100, 1.0, 2.0, 0, 0});
  const auto poisson = buffon::precision_estimate({500.0, 100, 0.0, 0.0, 0, 0});
  const auto floor = buffon::precision_estimate({500.0, 100, 60.0, 40.0, 0, 0});
  CHECK(low.ci.lower == poisson.ci.lower);
  CHECK(low.ci.upper == poisson.ci.upper);
  CHECK(floor.ci.upper == poisson.ci.upper);
  CHECK(*poisson.ci.upper == 500.0 * 100 / (100 - std::sqrt(kZ2 * 100)));
  // No trail (no check yet): the factor is 1, the corrected values are the raw ones.
  CHECK(poisson.erosion_factor == 1);
  CHECK(poisson.area_corrected == 500.0);
}

TEST_CASE("precision_estimate: the sides it cannot bound are absent", "[buffon]") {
  // No estimate (N = 0): nothing, whatever the rest says.
  const auto none = buffon::precision_estimate({std::nullopt, 0, 5.0, 5.0, 10, 100.0});
  CHECK_FALSE(none.ci.lower);
  CHECK_FALSE(none.ci.upper);
  CHECK_FALSE(none.area_corrected);
  CHECK_FALSE(none.corrected_ci.lower);
  CHECK_FALSE(none.corrected_ci.upper);
  CHECK_FALSE(none.precision_reached);
  CHECK(none.erosion_factor == buffon::erosion_factor(10, 100.0));
  // N = 4, V = 4: z sqrt V = 4.52 > N, so no upper side and no precision reached.
  const auto few = buffon::precision_estimate({80.0, 4, 0.0, 0.0, 0, 10.0});
  REQUIRE(few.ci.lower);
  CHECK(*few.ci.lower == 80.0 * 4 / (4 + std::sqrt(kZ2 * 4)));
  CHECK_FALSE(few.ci.upper);
  CHECK_FALSE(few.corrected_ci.upper);
  CHECK_FALSE(few.precision_reached);
  REQUIRE(few.area_corrected);
  CHECK(*few.area_corrected == 80.0);
}

TEST_CASE("precision_estimate: the interval holds the estimate, and is narrower with more "
          "crossings",
          "[buffon][property]") {
  rc::prop("lower < A_hat < upper; precision reached = z sqrt V / (N - z sqrt V)",
           [](std::uint16_t n_small, std::uint16_t v1, std::uint16_t v2, std::uint16_t walls) {
             const std::uint64_t n = 20 + n_small;
             const double area = 1000.0;
             const auto e = buffon::precision_estimate(
                 {area, n, static_cast<double>(v1), static_cast<double>(v2), walls, 5000.0});
             const double half = std::sqrt(kZ2 * std::max(double(v1) + double(v2), double(n)));
             RC_ASSERT(e.ci.lower.has_value());
             RC_ASSERT(*e.ci.lower < area);
             RC_ASSERT(e.ci.upper.has_value() == (static_cast<double>(n) > half));
             if (e.ci.upper) {
               RC_ASSERT(*e.ci.upper > area);
               RC_ASSERT(std::abs(*e.precision_reached - half / (double(n) - half)) <=
                         1e-9 * (1 + *e.precision_reached));
             }
             RC_ASSERT(e.erosion_factor >= 1.0);
           });
}
