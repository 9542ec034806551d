#pragma once
// Online stopping rule for the second visit (issue 8, item 5; the paper's open question "can the
// first visit's duration be determined on-line?", asked of visit 2 here).
//
// What the robot knows while it walks visit 2 is its count BC and the two lengths L1, L2. The
// closed form A_hat = 2 L1 L2 / (pi N) and the count's 95 % interval from the square-root
// transform, sqrt(N) +/- c with c = 0.98 sqrt(phi) (estimate.hpp has phi = 1, a Poisson count;
// phi is the count's dispersion, variance / mean), give A an interval whose relative width
// depends on N alone: A in [A_hat N / (sqrt N + c)^2, A_hat N / (sqrt N - c)^2]. The upper side is
// the wider one, so the request "relative precision P" is met as soon as
//     N / (sqrt N - c)^2 <= 1 + P   with sqrt N > c,
// and the rule is "stop visit 2 when BC reaches N*(P, phi)", the least such N.
//
// The threshold is a decision (it ends a visit, so it moves the trace hash), hence exact integer
// arithmetic, no rounding anywhere: P = p / 10^6 (p in [1, 999999]) and phi = m / 1000
// (m in [1000, 10000]), so c^2 = 9604 m / 10^7. With r = sqrt N the condition is the quadratic
//     P r^2 - 2 (1 + P) c r + (1 + P) c^2 >= 0   with r > c,
// whose smaller root c sqrt(1+P) / (sqrt(1+P) + 1) is below c, so for r > c it is equivalent to
// the squared form (P N + (1 + P) c^2)^2 >= 4 (1 + P)^2 c^2 N, i.e. after multiplying by
// 10^12 10^14 (all integers, compared in 256 bits):
//     (p N Q + (D + p) q)^2 >= 4 (D + p)^2 q Q N,   D = 10^6, Q = 10^7, q = 9604 m,
// and N Q > q. The predicate is monotone in N above c^2 (a convex quadratic past its larger root),
// so N* is found by doubling then bisection. N* < 2^46 over the whole parameter range.
#include <cstdint>
#include <string_view>

namespace antkit::buffon {

inline constexpr std::uint32_t kPrecisionDenominator = 1000000; // P = p / 10^6
inline constexpr std::uint32_t kDispersionDenominator = 1000;   // phi = m / 1000

// The measured dispersion of BC (issue 8, item 5): variance / mean of BC over 200 trials of
// 50 000 steps per arena. See stopping.cpp for the figures: the largest over the arenas where the
// trails mix (2.46), rounded up to 2.5; unmixed large arenas are far more dispersed.
extern const std::uint32_t kMeasuredDispersionMilli;

// True when a count n meets the relative precision p / 10^6 with dispersion m / 1000 (the
// condition above, exactly). Throws InputError("--precision") when p is not in [1, 999999] and
// InputError("--dispersion") when m is not in [1000, 10000].
bool precision_reached(std::uint64_t n, std::uint32_t precision_millionths,
                       std::uint32_t dispersion_milli);

// N*(P, phi): the least count meeting the precision (same domain checks).
std::uint64_t stop_count(std::uint32_t precision_millionths, std::uint32_t dispersion_milli);

// Reads a precision P given as a plain decimal in (0, 1) with at most six digits after the point
// ("0.05", ".1", "0.000125") into millionths, exactly (no binary floating point on the way).
// Throws InputError("--precision") for anything else (empty, signs, exponents, 0, >= 1, more than
// six decimals).
std::uint32_t parse_precision(std::string_view text);

} // namespace antkit::buffon
