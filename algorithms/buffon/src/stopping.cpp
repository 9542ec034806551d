// Online stopping rule (issue 8, item 5): see stopping.hpp for the derivation.
#include <antkit/buffon/stopping.hpp>
#include <antkit/kernel/input_error.hpp>
#include <array>
#include <string>

namespace antkit::buffon {

// Dispersion of BC, variance / mean of BC (scaled to the mean L1 L2) over 200 trials x 50 000
// steps, width 0.1, seed 1 (`antkit buffon --arena SPEC --trials 200 --steps 50000 --format json`):
// circle:d=20 1.37, square:area=314 1.11, ellipse:area=314,e=0.968 2.46, circle:d=40 1.87. These
// arenas are small enough for 50 000 steps to mix; the rule takes the largest, rounded up to the
// next 0.1. In the 7854-area arenas (ring 44.5, plus 29.0, barrier-plus 25.0, obstacles 15.9) the
// two trails of 50 000 steps cover different parts of the arena and the counts are far from
// Poisson: there the interval is too narrow unless the visits are long enough to mix (issue 8
// report; not corrected here).
const std::uint32_t kMeasuredDispersionMilli = 2500;

namespace {

constexpr std::uint64_t kD = kPrecisionDenominator;
constexpr std::uint64_t kQ = 10000000; // c^2 = 0.9604 phi = 9604 m / 10^7
constexpr std::uint64_t kMaxCount = std::uint64_t{1} << 47;

__extension__ typedef unsigned __int128 u128; // GCC and Clang; -Wpedantic wants the marker
using U256 = std::array<std::uint64_t, 4>;    // little-endian 64-bit limbs

U256 mul(u128 a, u128 b) {
  const std::uint64_t a0 = static_cast<std::uint64_t>(a), a1 = static_cast<std::uint64_t>(a >> 64);
  const std::uint64_t b0 = static_cast<std::uint64_t>(b), b1 = static_cast<std::uint64_t>(b >> 64);
  U256 out{0, 0, 0, 0};
  auto add_at = [&out](int limb, u128 v) {
    for (int i = limb; i < 4 && v != 0; ++i) {
      const u128 s =
          static_cast<u128>(out[static_cast<std::size_t>(i)]) + static_cast<std::uint64_t>(v);
      out[static_cast<std::size_t>(i)] = static_cast<std::uint64_t>(s);
      v = (v >> 64) + (s >> 64);
    }
  };
  add_at(0, static_cast<u128>(a0) * b0);
  add_at(1, static_cast<u128>(a0) * b1);
  add_at(1, static_cast<u128>(a1) * b0);
  add_at(2, static_cast<u128>(a1) * b1);
  return out;
}

bool geq(const U256& x, const U256& y) {
  for (int i = 3; i >= 0; --i) {
    const auto k = static_cast<std::size_t>(i);
    if (x[k] != y[k]) return x[k] > y[k];
  }
  return true;
}

void check(std::uint32_t p, std::uint32_t m) {
  if (p < 1 || p >= kD)
    throw kernel::InputError("--precision", "the relative precision must be in (0, 1)");
  if (m < kDispersionDenominator || m > 10 * kDispersionDenominator)
    throw kernel::InputError("--dispersion", "the dispersion factor must be in [1, 10]");
}

// The exact test, domain already checked and n < 2^47.
bool reached(std::uint64_t n, std::uint64_t p, std::uint64_t m) {
  const std::uint64_t q = 9604 * m;                 // < 2^27
  if (static_cast<u128>(n) * kQ <= q) return false; // sqrt N <= c: no upper bound yet
  // Left: p N Q + (D + p) q < 2^20 2^47 2^24 + 2^21 2^27 < 2^92; its square < 2^184.
  const u128 left = static_cast<u128>(p) * n * kQ + static_cast<u128>(kD + p) * q;
  // Right: 4 (D + p)^2 q Q < 2^2 2^42 2^27 2^24 = 2^95, times N < 2^142.
  const u128 coeff = static_cast<u128>(4) * (kD + p) * (kD + p) * q * kQ;
  return geq(mul(left, left), mul(coeff, n));
}

} // namespace

bool precision_reached(std::uint64_t n, std::uint32_t precision_millionths,
                       std::uint32_t dispersion_milli) {
  check(precision_millionths, dispersion_milli);
  if (n >= kMaxCount) return true; // beyond every N* of the domain (see stop_count)
  return reached(n, precision_millionths, dispersion_milli);
}

std::uint64_t stop_count(std::uint32_t precision_millionths, std::uint32_t dispersion_milli) {
  check(precision_millionths, dispersion_milli);
  // Smallest N with the predicate: it is false at N <= c^2 and monotone above it. The largest
  // N* of the domain (p = 1, m = 10000) is about (2 c / P)^2 = 3.8e13 < 2^46 < kMaxCount.
  std::uint64_t lo = 0, hi = 1; // predicate false at lo (N = 0), search for a true hi
  while (!reached(hi, precision_millionths, dispersion_milli)) {
    lo = hi;
    hi *= 2;
  }
  while (hi - lo > 1) {
    const std::uint64_t mid = lo + (hi - lo) / 2;
    (reached(mid, precision_millionths, dispersion_milli) ? hi : lo) = mid;
  }
  return hi;
}

std::uint32_t parse_precision(std::string_view text) {
  const std::string shown(text);
  auto bad = [&shown]() {
    return kernel::InputError("--precision", "the precision must be a decimal in (0, 1) with at "
                                             "most six digits after the point, got '" +
                                                 shown + "'");
  };
  std::size_t i = 0;
  std::uint64_t whole = 0;
  bool any_digit = false;
  while (i < text.size() && text[i] >= '0' && text[i] <= '9') {
    whole = whole * 10 + static_cast<std::uint64_t>(text[i] - '0');
    if (whole >= 1) throw bad(); // P < 1
    any_digit = true;
    ++i;
  }
  std::uint64_t fraction = 0;
  int decimals = 0;
  if (i < text.size() && text[i] == '.') {
    ++i;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') {
      if (++decimals > 6) throw bad();
      fraction = fraction * 10 + static_cast<std::uint64_t>(text[i] - '0');
      any_digit = true;
      ++i;
    }
  }
  if (!any_digit || i != text.size()) throw bad();
  for (int d = decimals; d < 6; ++d) fraction *= 10;
  if (fraction == 0) throw bad(); // P > 0
  return static_cast<std::uint32_t>(fraction);
}

} // namespace antkit::buffon
