// crc32_combine (crc32.hpp).
#include <antkit/io/crc32.hpp>
#include <array>

namespace antkit::io {

namespace {

constexpr std::uint32_t kPolynomial = 0xEDB88320U; // reflected
constexpr std::uint32_t kOne = 0x80000000U;        // x^0, reflected

// a(x) b(x) mod P(x), both reflected.
constexpr std::uint32_t multiply(std::uint32_t a, std::uint32_t b) noexcept {
  std::uint32_t product = 0;
  for (std::uint32_t bit = kOne; bit != 0; bit >>= 1) {
    if ((a & bit) != 0) product ^= b;
    b = (b & 1U) != 0 ? (b >> 1) ^ kPolynomial : b >> 1; // b *= x
  }
  return product;
}

// x^(2^k) mod P for k = 0..66 (length_b's 64 binary digits, from 2^3 on).
constexpr std::array<std::uint32_t, 67> make_powers() {
  std::array<std::uint32_t, 67> p{};
  p[0] = kOne >> 1; // x^1
  for (std::size_t k = 1; k < p.size(); ++k) p[k] = multiply(p[k - 1], p[k - 1]);
  return p;
}
constexpr std::array<std::uint32_t, 67> kPowers = make_powers();

} // namespace

std::uint32_t crc32_combine(std::uint32_t crc_a, std::uint32_t crc_b,
                            std::uint64_t length_b) noexcept {
  // x^(8 length_b) mod P, by the binary digits of length_b (8 = 2^3).
  std::uint32_t shift = kOne;
  for (std::size_t k = 3; length_b != 0; length_b >>= 1, ++k)
    if ((length_b & 1U) != 0) shift = multiply(kPowers[k], shift);
  return multiply(shift, crc_a) ^ crc_b;
}

} // namespace antkit::io
