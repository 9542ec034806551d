// The analytic half of the sine bound (angle.hpp), checked exhaustively over the table. (The other
// half, a Z3 proof that sin_raw computes the documented integer formula without overflow, is not
// written yet: issue 7.)
//
// The bound |sin(a) - sin_exact(a)| <= 2^-(F+1) + 2.947e-7 splits as
//   (1) every table entry kSineQ30[i] is sin(i h) rounded to 2^-30, h = (pi/2)/1024: error <=
//   2^-31; (2) linear interpolation between exact samples errs by at most h^2/8 max|sin''| = h^2/8
//       (2.94137e-7) -- Taylor's theorem with the Lagrange remainder, on paper;
//   (3) interpolating rounded entries adds at most the entries' error (weights sum to 1): 2^-31;
//   (4) the final half-up rounding to F bits adds at most 2^-(F+1).
// (1) is checked here for all 1026 entries; (2)+(3) are checked on the exact (unrounded, 2^-50)
// interpolant at 64 points of every interval (1024 x 64 = 65536 points of the quarter wave, the
// middle of each interval, where (2) peaks, included), against h^2/8 + 2^-31 = 2.947e-7.
#include <antkit/kernel/angle.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>

namespace {
namespace ak = antkit::kernel;
constexpr long double kPi = 3.141592653589793238462643383279502884L;
constexpr long double kH = kPi / 2 / 1024;
} // namespace

TEST_CASE("every sine table entry is sin(i h) correctly rounded to 2^-30", "[angle][proof]") {
  const auto& table = ak::angle_tables::kSineQ30;
  long double worst = 0;
  int worst_i = -1;
  for (int i = 0; i < 1026; ++i) {
    const long double exact = std::ldexp(std::sin(kH * i), 30);
    const long double err =
        std::fabs(static_cast<long double>(table[static_cast<std::size_t>(i)]) - exact);
    if (err > worst) {
      worst = err;
      worst_i = i;
    }
  }
  INFO("worst entry " << worst_i << ", error " << worst << " units of 2^-30");
  // Correctly rounded: at most half a unit (long double sin is good to ~1e-19, far below).
  CHECK(worst <= 0.5L + 1e-6L);
}

TEST_CASE("the exact interpolant is within h^2/8 + 2^-31 of sin at 64 points of every interval",
          "[angle][proof]") {
  // h^2/8 (Lagrange remainder with max|sin''| = 1) plus the entries' rounding is the documented
  // 2.947e-7; the analytic bound must itself be below it.
  const long double analytic = kH * kH / 8 + std::ldexp(1.0L, -31);
  REQUIRE(analytic <= 2.947e-7L);
  long double worst = 0;
  std::uint32_t worst_u = 0;
  for (std::uint32_t interval = 0; interval < 1024; ++interval)
    for (std::uint32_t k = 0; k < 64; ++k) {
      const std::uint32_t u = (interval << 20) + (k << 14); // a 30-bit quarter-wave position
      const std::int64_t exact_units =
          ak::interpolate_exact<std::int64_t>(ak::angle_tables::kSineQ30, u);
      const long double value = std::ldexp(static_cast<long double>(exact_units), -50);
      const long double err =
          std::fabs(value - std::sin(std::ldexp(static_cast<long double>(u), -30) * kPi / 2));
      if (err > worst) {
        worst = err;
        worst_u = u;
      }
    }
  INFO("worst position u = " << worst_u << ", error " << worst);
  CHECK(worst <= analytic);
  // Not loose: the interpolation error does reach most of h^2/8 in the middle of an interval.
  CHECK(worst >= 0.9L * kH * kH / 8);
}
