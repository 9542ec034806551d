// CRC-32 (crc32.hpp).
#include <antkit/io/crc32.hpp>
#include <array>
#include <cstddef>
#include <cstring>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define ANTKIT_CRC32_CLMUL 1
#include <immintrin.h>
#endif

namespace antkit::io {

namespace {

// Slicing by 8 (eight tables: table k advances a byte through k further zero bytes), so that the
// CRC of a large file costs about a byte-wise pass over an eighth of it.
using CrcTables = std::array<std::array<std::uint32_t, 256>, 8>;
constexpr CrcTables make_crc_tables() {
  CrcTables t{};
  for (std::uint32_t n = 0; n < 256; ++n) {
    std::uint32_t c = n;
    for (int k = 0; k < 8; ++k) c = (c & 1U) != 0 ? 0xEDB88320U ^ (c >> 1) : c >> 1;
    t[0][n] = c;
  }
  for (std::size_t k = 1; k < 8; ++k)
    for (std::size_t n = 0; n < 256; ++n) t[k][n] = (t[k - 1][n] >> 8) ^ t[0][t[k - 1][n] & 0xFFU];
  return t;
}
constexpr CrcTables kCrc = make_crc_tables();

// The register after `n` bytes from `p`, starting from `crc` (no inversions: crc32() inverts).
std::uint32_t crc_tables(std::uint32_t crc, const unsigned char* p, std::size_t n) noexcept {
  for (; n >= 8; n -= 8, p += 8) {
    // The bytes in file order, whatever the machine's byte order.
    const std::uint32_t lo =
        crc ^ (static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
               static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24);
    crc = kCrc[7][lo & 0xFFU] ^ kCrc[6][(lo >> 8) & 0xFFU] ^ kCrc[5][(lo >> 16) & 0xFFU] ^
          kCrc[4][lo >> 24] ^ kCrc[3][p[4]] ^ kCrc[2][p[5]] ^ kCrc[1][p[6]] ^ kCrc[0][p[7]];
  }
  for (; n > 0; --n, ++p) crc = kCrc[0][(crc ^ *p) & 0xFFU] ^ (crc >> 8);
  return crc;
}

#ifdef ANTKIT_CRC32_CLMUL

// Folding with carry-less multiplication (x86-64 PCLMULQDQ; the method of Gopal et al., "Fast CRC
// computation for generic polynomials using PCLMULQDQ instruction", Intel, 2009), derived here
// for the reflected bit order and finished by the tables instead of a Barrett reduction.
//
// In the reflected order bit i of a 16-byte block (its little-endian 128-bit value) is the
// coefficient of x^(127-i), and the register with a zero start over a message M is
// M(x) x^32 mod P(x), P = 0x104C11DB7. A block A that lies D bits before a later block T can
// be replaced by A x^D mod P xored into T: the message is unchanged modulo P, so its CRC is too.
// With A = A_lo x^64 + A_hi (A_lo the first eight bytes), A x^D = A_lo x^(64+D) + A_hi x^D.
// The carry-less product of two 64-bit reflected values has bit j for x^(126-j), one short of
// T's x^(127-j), so the constants are K1 = x^(63+D) mod P and K2 = x^(D-1) mod P, reflected to 64
// bits (degree d at bit 63-d). Each product has degree <= 94, so it fits T's 128 bits.
// What is left, one block and fewer than 16 bytes, goes through the tables.
constexpr std::uint64_t x_pow_mod_p(int n) {
  std::uint64_t r = 1;
  for (int k = 0; k < n; ++k) {
    r <<= 1;
    if ((r & (std::uint64_t{1} << 32)) != 0) r ^= 0x104C11DB7U;
  }
  return r;
}
constexpr std::uint64_t reflect64(std::uint64_t r) { // degree d (< 32) to bit 63 - d
  std::uint64_t out = 0;
  for (int d = 0; d < 32; ++d)
    if (((r >> d) & 1U) != 0) out |= std::uint64_t{1} << (63 - d);
  return out;
}
constexpr std::uint64_t kFold512Lo = reflect64(x_pow_mod_p(63 + 512));
constexpr std::uint64_t kFold512Hi = reflect64(x_pow_mod_p(512 - 1));
constexpr std::uint64_t kFold128Lo = reflect64(x_pow_mod_p(63 + 128));
constexpr std::uint64_t kFold128Hi = reflect64(x_pow_mod_p(128 - 1));

__attribute__((target("pclmul,sse2"))) inline __m128i fold(__m128i a, __m128i k, __m128i t) {
  return _mm_xor_si128(
      _mm_xor_si128(_mm_clmulepi64_si128(a, k, 0x00), _mm_clmulepi64_si128(a, k, 0x11)), t);
}

__attribute__((target("pclmul,sse2"))) std::uint32_t
crc_clmul(std::uint32_t crc, const unsigned char* p, std::size_t n) noexcept {
  // n >= 64. The start register is xored into the first four bytes (little-endian): the same
  // register as starting from it.
  const auto load = [](const unsigned char* q) {
    return _mm_loadu_si128(reinterpret_cast<const __m128i*>(q));
  };
  __m128i x0 = _mm_xor_si128(load(p), _mm_cvtsi32_si128(static_cast<int>(crc)));
  __m128i x1 = load(p + 16);
  __m128i x2 = load(p + 32);
  __m128i x3 = load(p + 48);
  p += 64;
  n -= 64;
  const __m128i k512 =
      _mm_set_epi64x(static_cast<long long>(kFold512Hi), static_cast<long long>(kFold512Lo));
  for (; n >= 64; n -= 64, p += 64) {
    x0 = fold(x0, k512, load(p));
    x1 = fold(x1, k512, load(p + 16));
    x2 = fold(x2, k512, load(p + 32));
    x3 = fold(x3, k512, load(p + 48));
  }
  const __m128i k128 =
      _mm_set_epi64x(static_cast<long long>(kFold128Hi), static_cast<long long>(kFold128Lo));
  __m128i x = fold(fold(fold(x0, k128, x1), k128, x2), k128, x3);
  for (; n >= 16; n -= 16, p += 16) x = fold(x, k128, load(p));
  alignas(16) unsigned char last[16];
  _mm_store_si128(reinterpret_cast<__m128i*>(last), x);
  return crc_tables(crc_tables(0, last, 16), p, n);
}

bool have_clmul() noexcept {
  static const bool have = __builtin_cpu_supports("pclmul") && __builtin_cpu_supports("sse2");
  return have;
}

#endif

} // namespace

std::uint32_t crc32_portable(std::string_view bytes, std::uint32_t crc) noexcept {
  return ~crc_tables(~crc, reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
}

std::uint32_t crc32(std::string_view bytes, std::uint32_t crc) noexcept {
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
#ifdef ANTKIT_CRC32_CLMUL
  if (bytes.size() >= 64 && have_clmul()) return ~crc_clmul(~crc, p, bytes.size());
#endif
  return ~crc_tables(~crc, p, bytes.size());
}

} // namespace antkit::io
