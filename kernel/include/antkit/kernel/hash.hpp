#pragma once
// The trace hash: a 64-bit hash over a canonical, endian-independent byte stream.
//
// Definition (so that another implementation can reproduce it bit for bit):
//   * Every value is appended as its little-endian two's-complement bytes: add_u8/i8 one byte,
//     add_u16/i16 two, add_u32/i32 four, add_u64/i64 eight, add_bool one byte 0 or 1. Nothing else
//     (no type tags, no padding) enters the stream, so callers that want framing add it themselves.
//   * The stream is cut into 8-byte words w_0, w_1, ..., read little-endian; the last word is
//   padded
//     with zero bytes.
//   * h = seed + P5; for each word: h = rotl(h ^ round(w), 27) * P1 + P4, where
//     round(w) = rotl(w * P2, 31) * P1 (the round of xxHash64, whose primes P1..P5 these are).
//   * finish: h ^= number of bytes; then the xxHash64 avalanche
//     h ^= h >> 33; h *= P2; h ^= h >> 29; h *= P3; h ^= h >> 32.
// It is not xxHash64 itself (no four-lane stripe), and it is not cryptographic: it detects any
// divergence between two runs' traces, which is all a trace hash is for.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace antkit::kernel {

class TraceHash {
public:
  static constexpr std::uint64_t P1 = 0x9E3779B185EBCA87ULL;
  static constexpr std::uint64_t P2 = 0xC2B2AE3D27D4EB4FULL;
  static constexpr std::uint64_t P3 = 0x165667B19E3779F9ULL;
  static constexpr std::uint64_t P4 = 0x85EBCA77C2B2AE63ULL;
  static constexpr std::uint64_t P5 = 0x27D4EB2F165667C5ULL;

  constexpr explicit TraceHash(std::uint64_t seed = 0) noexcept : h_(seed + P5) {}

  constexpr TraceHash& add_u8(std::uint8_t v) noexcept {
    buffer_ |= std::uint64_t{v} << (8 * fill_);
    ++bytes_;
    if (++fill_ == 8) flush();
    return *this;
  }
  constexpr TraceHash& add_u16(std::uint16_t v) noexcept {
    return add_u8(static_cast<std::uint8_t>(v)).add_u8(static_cast<std::uint8_t>(v >> 8));
  }
  constexpr TraceHash& add_u32(std::uint32_t v) noexcept {
    return add_u16(static_cast<std::uint16_t>(v)).add_u16(static_cast<std::uint16_t>(v >> 16));
  }
  constexpr TraceHash& add_u64(std::uint64_t v) noexcept {
    if (fill_ == 0) { // aligned fast path: the same result as eight add_u8 calls
      absorb(v);
      bytes_ += 8;
      return *this;
    }
    return add_u32(static_cast<std::uint32_t>(v)).add_u32(static_cast<std::uint32_t>(v >> 32));
  }
  constexpr TraceHash& add_i8(std::int8_t v) noexcept {
    return add_u8(static_cast<std::uint8_t>(v));
  }
  constexpr TraceHash& add_i16(std::int16_t v) noexcept {
    return add_u16(static_cast<std::uint16_t>(v));
  }
  constexpr TraceHash& add_i32(std::int32_t v) noexcept {
    return add_u32(static_cast<std::uint32_t>(v));
  }
  constexpr TraceHash& add_i64(std::int64_t v) noexcept {
    return add_u64(static_cast<std::uint64_t>(v));
  }
  constexpr TraceHash& add_bool(bool v) noexcept { return add_u8(v ? 1 : 0); }
  constexpr TraceHash& add_bytes(std::span<const std::uint8_t> bytes) noexcept {
    for (std::uint8_t b : bytes) add_u8(b);
    return *this;
  }

  // The hash of everything added so far; the object stays usable.
  [[nodiscard]] constexpr std::uint64_t finish() const noexcept {
    std::uint64_t h = h_;
    if (fill_ != 0) h = step(h, buffer_);
    h ^= bytes_;
    h ^= h >> 33;
    h *= P2;
    h ^= h >> 29;
    h *= P3;
    h ^= h >> 32;
    return h;
  }

  [[nodiscard]] constexpr std::uint64_t bytes() const noexcept { return bytes_; }

private:
  static constexpr std::uint64_t rotl(std::uint64_t x, int r) noexcept {
    return (x << r) | (x >> (64 - r));
  }
  static constexpr std::uint64_t step(std::uint64_t h, std::uint64_t w) noexcept {
    return rotl(h ^ (rotl(w * P2, 31) * P1), 27) * P1 + P4;
  }
  constexpr void absorb(std::uint64_t w) noexcept { h_ = step(h_, w); }
  constexpr void flush() noexcept {
    absorb(buffer_);
    buffer_ = 0;
    fill_ = 0;
  }

  std::uint64_t h_;
  std::uint64_t buffer_ = 0;
  std::uint64_t bytes_ = 0;
  int fill_ = 0;
};

// Hex form used in JSON output and golden values: 16 lower-case digits, most significant first.
inline std::string hash_hex(std::uint64_t h) {
  constexpr char digits[] = "0123456789abcdef";
  std::string out(16, '0');
  for (int i = 15; i >= 0; --i) {
    out[static_cast<std::size_t>(i)] = digits[h & 0xF];
    h >>= 4;
  }
  return out;
}

} // namespace antkit::kernel
