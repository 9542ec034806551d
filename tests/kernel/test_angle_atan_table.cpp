// The analytic half of atan2's bound (angle.hpp: at most 55 units), checked over the table. The
// other half is proved by Z3 on the shipped template (proofs/z3/angle_atan2.cpp: no undefined
// behaviour, the ratio rounded half up to 2^-30, the exact interpolation, the rounding to a unit
// and the exact folds), which reduces the bound to:
//   (1) every entry kAtanUnits[i] is atan(i / 1024) in units of 2^-32 turn, correctly rounded:
//       error <= 1/2 unit;
//   (2) linear interpolation between exact samples errs by at most h^2/8 max|atan''| with
//       h = 1/1024 and max|atan''| = 3 sqrt(3)/8 on [0, 1] (at t = 1/sqrt(3)): 7.74e-8 rad, 52.9
//       units (Taylor's theorem with the Lagrange remainder, on paper);
//   (3) interpolating rounded entries adds at most their error (the weights sum to 1): 1/2 unit;
//   (4) the rounding of the ratio (2^-31 in t, at most 2^-31 rad: 0.32 unit) and of the result
//       (1/2 unit).
// (1) is checked here for all 1026 entries (the last, atan(1025/1024), is read only with weight
// 0); (2) + (3) on the exact interpolant (units of 2^-20, before the final rounding) at 64 points
// of every interval, against 52.9 + 0.5 units; and the sum with (4) against the documented 55.
#include <antkit/kernel/angle.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>

namespace {
namespace ak = antkit::kernel;
constexpr long double kPi = 3.141592653589793238462643383279502884L;
constexpr long double kUnitsPerRadian = 4294967296.0L / (2 * kPi);
} // namespace

TEST_CASE("every atan table entry is atan(i/1024) correctly rounded to a unit", "[angle][proof]") {
  const auto& table = ak::angle_tables::kAtanUnits;
  long double worst = 0;
  int worst_i = -1;
  for (int i = 0; i < 1026; ++i) {
    const long double exact = std::atan(static_cast<long double>(i) / 1024) * kUnitsPerRadian;
    const long double err =
        std::fabs(static_cast<long double>(table[static_cast<std::size_t>(i)]) - exact);
    if (err > worst) {
      worst = err;
      worst_i = i;
    }
  }
  INFO("worst entry " << worst_i << ", error " << worst << " units");
  // Correctly rounded: at most half a unit (long double atan is good to ~1e-19 relative).
  CHECK(worst <= 0.5L + 1e-6L);
  CHECK(table[0] == 0);
  CHECK(table[1024] == 536870912); // atan(1) = an eighth of a turn, 2^29 units, exactly
}

TEST_CASE("the exact atan interpolant is within h^2/8 max|atan''| + 1/2 unit at 64 points of "
          "every interval",
          "[angle][proof]") {
  const long double h = 1.0L / 1024;
  const long double max_second = 3 * std::sqrt(3.0L) / 8; // |atan''(t)| = 2t/(1+t^2)^2, max
  const long double interpolation = h * h / 8 * max_second * kUnitsPerRadian;
  const long double bound = interpolation + 0.5L;
  // The documented 55 units hold with the ratio's and the result's rounding on top.
  REQUIRE(interpolation <= 52.9L + 0.05L);
  REQUIRE(bound + std::ldexp(1.0L, -31) * kUnitsPerRadian + 0.5L <= 55);
  long double worst = 0;
  std::uint32_t worst_u = 0;
  for (std::uint32_t interval = 0; interval < 1024; ++interval)
    for (std::uint32_t k = 0; k < 64; ++k) {
      const std::uint32_t u = (interval << 20) + (k << 14); // the ratio t in units of 2^-30
      const std::int64_t exact_scaled =
          ak::interpolate_exact<std::int64_t>(ak::angle_tables::kAtanUnits, u);
      const long double value = std::ldexp(static_cast<long double>(exact_scaled), -20);
      const long double err = std::fabs(
          value - std::atan(std::ldexp(static_cast<long double>(u), -30)) * kUnitsPerRadian);
      if (err > worst) {
        worst = err;
        worst_u = u;
      }
    }
  INFO("worst at t = " << std::ldexp(static_cast<long double>(worst_u), -30) << ": " << worst
                       << " units");
  CHECK(worst <= bound);
}
