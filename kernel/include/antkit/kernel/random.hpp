#pragma once
// Keyed, counter-based random streams (DESIGN.md, determinism rule 2).
//
// A stream is named by (seed, experiment, trial, robot, purpose). Its i-th 128-bit block is
// Philox4x32-10 (Salmon, Moraes, Dror, Shaw, SC'11) applied to the counter
//     (i mod 2^32, i div 2^32, name mod 2^32, name div 2^32)
// under the key (seed mod 2^32, seed div 2^32), where `name` is the 64-bit digest of
// (experiment, trial, robot, purpose) defined by stream_name() below. Philox is a bijection of the
// counter for a fixed key, so two streams with the same seed and different names never share a
// block (unless their 64-bit names collide), and a stream's output depends only on its name and on
// how many numbers were drawn from it, never on threads or on what ran before.
//
// Draws take 32-bit words from the block in order (x0, x1, x2, x3), then move to block i+1.
// next_u64() is (low word) | (next word << 32).
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace antkit::kernel {

// SplitMix64's finalizer (Steele, Lea, Flood 2014): a bijection of 64-bit words with full
// avalanche.
constexpr std::uint64_t mix64(std::uint64_t z) noexcept {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

// The 64-bit name of a stream: a chain of mix64 over its four key words, each offset by a distinct
// odd constant so that permuted keys give different names.
constexpr std::uint64_t stream_name(std::uint64_t experiment, std::uint64_t trial,
                                    std::uint64_t robot, std::uint64_t purpose) noexcept {
  std::uint64_t h = mix64(experiment + 0x9E3779B97F4A7C15ULL);
  h = mix64(h ^ (trial + 0xD1B54A32D192ED03ULL));
  h = mix64(h ^ (robot + 0xABC98388FB8FAC03ULL));
  h = mix64(h ^ (purpose + 0x8CB92BA72F3D8DD7ULL));
  return h;
}

// Philox4x32 with 10 rounds, the variant with published known-answer tests (Random123).
constexpr std::array<std::uint32_t, 4> philox4x32_10(std::array<std::uint32_t, 4> ctr,
                                                     std::array<std::uint32_t, 2> key) noexcept {
  constexpr std::uint32_t M0 = 0xD2511F53u, M1 = 0xCD9E8D57u;
  constexpr std::uint32_t W0 = 0x9E3779B9u, W1 = 0xBB67AE85u;
  for (int round = 0; round < 10; ++round) {
    const std::uint64_t p0 = std::uint64_t{M0} * ctr[0];
    const std::uint64_t p1 = std::uint64_t{M1} * ctr[2];
    const auto hi0 = static_cast<std::uint32_t>(p0 >> 32), lo0 = static_cast<std::uint32_t>(p0);
    const auto hi1 = static_cast<std::uint32_t>(p1 >> 32), lo1 = static_cast<std::uint32_t>(p1);
    ctr = {hi1 ^ ctr[1] ^ key[0], lo1, hi0 ^ ctr[3] ^ key[1], lo0};
    key[0] += W0;
    key[1] += W1;
  }
  return ctr;
}

#if defined(__SSE2__)
namespace detail {
// Philox4x32-10 on four counters at once in SSE2 lanes (SSE2 is part of every x86-64): x[w] holds
// word w of the four counters. The 32 x 32 -> 64-bit products come from pmuludq, which multiplies
// lanes 0 and 2; lanes 1 and 3 are shifted down and multiplied in a second one, and the halves are
// regrouped by shuffles. Integer operations only, so the results are the scalar rounds' bits.
inline std::array<std::array<std::uint32_t, 4>, 4>
philox4x32_10_x4_sse2(const std::array<std::array<std::uint32_t, 4>, 4>& ctr,
                      std::array<std::uint32_t, 2> key) noexcept {
  auto lane = [&](int w) {
    return _mm_setr_epi32(static_cast<int>(ctr[0][static_cast<std::size_t>(w)]),
                          static_cast<int>(ctr[1][static_cast<std::size_t>(w)]),
                          static_cast<int>(ctr[2][static_cast<std::size_t>(w)]),
                          static_cast<int>(ctr[3][static_cast<std::size_t>(w)]));
  };
  __m128i x0 = lane(0), x1 = lane(1), x2 = lane(2), x3 = lane(3);
  const __m128i m0 = _mm_set1_epi32(static_cast<int>(0xD2511F53u));
  const __m128i m1 = _mm_set1_epi32(static_cast<int>(0xCD9E8D57u));
  // The low and high halves of the four products x * m, each gathered into one vector.
  auto mul_hi_lo = [](__m128i x, __m128i m, __m128i& hi, __m128i& lo) {
    const __m128i even = _mm_mul_epu32(x, m);                           // lo0 hi0 lo2 hi2
    const __m128i odd = _mm_mul_epu32(_mm_srli_epi64(x, 32), m);        // lo1 hi1 lo3 hi3
    const __m128i e = _mm_shuffle_epi32(even, _MM_SHUFFLE(3, 1, 2, 0)); // lo0 lo2 hi0 hi2
    const __m128i o = _mm_shuffle_epi32(odd, _MM_SHUFFLE(3, 1, 2, 0));  // lo1 lo3 hi1 hi3
    lo = _mm_unpacklo_epi32(e, o);
    hi = _mm_unpackhi_epi32(e, o);
  };
  for (int round = 0; round < 10; ++round) {
    __m128i hi0, lo0, hi1, lo1;
    mul_hi_lo(x0, m0, hi0, lo0);
    mul_hi_lo(x2, m1, hi1, lo1);
    const __m128i k0 = _mm_set1_epi32(static_cast<int>(key[0]));
    const __m128i k1 = _mm_set1_epi32(static_cast<int>(key[1]));
    x0 = _mm_xor_si128(_mm_xor_si128(hi1, x1), k0);
    x1 = lo1;
    x2 = _mm_xor_si128(_mm_xor_si128(hi0, x3), k1);
    x3 = lo0;
    key[0] += 0x9E3779B9u;
    key[1] += 0xBB67AE85u;
  }
  alignas(16) std::array<std::array<std::uint32_t, 4>, 4> words{};
  _mm_store_si128(reinterpret_cast<__m128i*>(words[0].data()), x0);
  _mm_store_si128(reinterpret_cast<__m128i*>(words[1].data()), x1);
  _mm_store_si128(reinterpret_cast<__m128i*>(words[2].data()), x2);
  _mm_store_si128(reinterpret_cast<__m128i*>(words[3].data()), x3);
  std::array<std::array<std::uint32_t, 4>, 4> out{};
  for (std::size_t b = 0; b < 4; ++b)
    for (std::size_t w = 0; w < 4; ++w) out[b][w] = words[w][b];
  return out;
}
} // namespace detail
#endif

// Four Philox4x32-10 blocks under one key: the same four results as four calls of philox4x32_10.
// At run time on x86-64 the four are computed in SSE2 lanes (detail::philox4x32_10_x4_sse2, about
// half the instructions of four scalar blocks); otherwise round by round, four independent chains
// of multiplies that overlap in the processor.
constexpr std::array<std::array<std::uint32_t, 4>, 4>
philox4x32_10_x4(std::array<std::array<std::uint32_t, 4>, 4> ctr,
                 std::array<std::uint32_t, 2> key) noexcept {
#if defined(__SSE2__)
  if (!std::is_constant_evaluated()) return detail::philox4x32_10_x4_sse2(ctr, key);
#endif
  constexpr std::uint32_t M0 = 0xD2511F53u, M1 = 0xCD9E8D57u;
  constexpr std::uint32_t W0 = 0x9E3779B9u, W1 = 0xBB67AE85u;
  for (int round = 0; round < 10; ++round) {
    for (auto& c : ctr) {
      const std::uint64_t p0 = std::uint64_t{M0} * c[0];
      const std::uint64_t p1 = std::uint64_t{M1} * c[2];
      const auto hi0 = static_cast<std::uint32_t>(p0 >> 32), lo0 = static_cast<std::uint32_t>(p0);
      const auto hi1 = static_cast<std::uint32_t>(p1 >> 32), lo1 = static_cast<std::uint32_t>(p1);
      c = {hi1 ^ c[1] ^ key[0], lo1, hi0 ^ c[3] ^ key[1], lo0};
    }
    key[0] += W0;
    key[1] += W1;
  }
  return ctr;
}

// The width of an unsigned word type: a policy type (proofs/z3/z3_int.hpp's Int) states it as
// `bits`; a machine integer (unsigned __int128 included, which std::numeric_limits does not know in
// strict mode) by its size.
template <class U>
constexpr int lemire_word_bits() {
  if constexpr (requires { U::bits; }) {
    return U::bits;
  } else {
    return static_cast<int>(sizeof(U)) * 8;
  }
}

// Lemire's multiply-shift map of a uniform w-bit word x to [0, n), n >= 1, over an unsigned word
// type U and a type U2 of twice its width. It returns false when x falls in the rejected zone of
// the low product (low < 2^w mod n); accepting only the other words makes every value in [0, n)
// come from exactly floor(2^w / n) words, so the result is unbiased.
//
// The one copy of the map (DESIGN.md rule 6): Stream::below (through bounded_u32_t below), the
// fixed-point uniforms of fixed_random.hpp (32 and 64 bits) and the Buffon controller's draws all
// call it. proofs/z3/bounded_u32.cpp instantiates it through bounded_u32_t with Z3 bit-vectors at
// w = 32 and proves the rejection exact; the 64-bit instantiation is the same source at another
// width (not proved in Z3; the 8-bit one is checked exhaustively in
// tests/kernel/test_fixed_random.cpp). The two `if`s stay branches rather than selects: on machine
// words the remainder (a division) is then computed only when low < n, which is rare for small n;
// on Z3 words each `if` forks the proof run (z3_int.hpp, Session::decide), so the three paths are
// checked apart. Only unsigned arithmetic is used, so nothing can overflow; the one precondition is
// n != 0. (The outer casts matter only for types narrower than int, which C++ promotes.)
template <class U, class U2>
constexpr bool lemire_bounded(U x, U n, U& out) {
  constexpr int w = lemire_word_bits<U>();
  const U2 m = static_cast<U2>(static_cast<U2>(x) * static_cast<U2>(n));
  const auto low = static_cast<U>(m);
  if (low < n) {
    const U threshold = static_cast<U>(static_cast<U>(U{0} - n) % n); // 2^w mod n
    if (low < threshold) return false;
  }
  out = static_cast<U>(m >> w);
  return true;
}

// Lemire's map at 32 bits over an integer policy W (W::u32 and W::u64 are the 32- and 64-bit
// unsigned words): bounded_u32 below instantiates it with the machine words (MachineWords),
// proofs/z3/bounded_u32.cpp with Z3 bit-vectors.
template <class W>
constexpr bool bounded_u32_t(typename W::u32 x, typename W::u32 n, typename W::u32& out) {
  return lemire_bounded<typename W::u32, typename W::u64>(x, n, out);
}

// The machine instantiation's policy.
struct MachineWords {
  using u32 = std::uint32_t;
  using u64 = std::uint64_t;
};

constexpr bool bounded_u32(std::uint32_t x, std::uint32_t n, std::uint32_t& out) noexcept {
  return bounded_u32_t<MachineWords>(x, n, out);
}

class Stream {
public:
  constexpr explicit Stream(std::uint64_t seed, std::uint64_t experiment = 0,
                            std::uint64_t trial = 0, std::uint64_t robot = 0,
                            std::uint64_t purpose = 0) noexcept
      : key_{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)},
        name_(stream_name(experiment, trial, robot, purpose)) {}

  constexpr std::uint32_t next_u32() noexcept {
    if (word_ == 4) refill();
    return block_[word_++];
  }
  constexpr std::uint64_t next_u64() noexcept {
    const std::uint64_t lo = next_u32();
    return lo | (std::uint64_t{next_u32()} << 32);
  }
  // Unbiased integer in [0, n); n must be at least 1 (n == 0 returns 0 and draws nothing).
  constexpr std::uint32_t below(std::uint32_t n) noexcept {
    if (n == 0) return 0;
    std::uint32_t out = 0;
    while (!bounded_u32(next_u32(), n, out)) {
    }
    return out;
  }
  // Unbiased integer in [lo, hi], lo <= hi.
  constexpr std::int32_t between(std::int32_t lo, std::int32_t hi) noexcept {
    const auto span = static_cast<std::uint32_t>(static_cast<std::int64_t>(hi) - lo);
    if (span == 0xFFFFFFFFu) return static_cast<std::int32_t>(next_u32());
    return static_cast<std::int32_t>(static_cast<std::int64_t>(lo) + below(span + 1));
  }
  // True with probability num / den (0 <= num <= den, den >= 1), exactly.
  constexpr bool chance(std::uint32_t num, std::uint32_t den) noexcept { return below(den) < num; }

  // The batched draw: fills `out` with the next out.size() words, exactly the words that as many
  // next_u32() calls in a row would return, and leaves the stream where those calls would (so
  // next_u32() and next_u32s() can be mixed freely). Whole blocks are computed four at a time
  // (philox4x32_10_x4); a loop that needs many words draws them ahead in one call.
  constexpr void next_u32s(std::span<std::uint32_t> out) noexcept {
    std::size_t k = 0;
    const std::size_t n = out.size();
    while (k < n && word_ < 4) out[k++] = block_[word_++]; // the rest of the current block
    while (n - k >= 16) {
      std::array<std::array<std::uint32_t, 4>, 4> ctr{};
      for (std::uint64_t b = 0; b < 4; ++b) ctr[b] = counter(block_index_ + b);
      const auto blocks = philox4x32_10_x4(ctr, key_);
      for (const auto& block : blocks)
        for (std::uint32_t word : block) out[k++] = word;
      // As if the four blocks had been refilled and drawn one by one: the last one is the
      // current block, used up.
      block_ = blocks[3];
      block_index_ += 4;
      word_ = 4;
    }
    while (k < n) out[k++] = next_u32();
  }

  // How many 32-bit words have been drawn.
  [[nodiscard]] constexpr std::uint64_t drawn() const noexcept {
    return block_index_ == 0 ? 0 : (block_index_ - 1) * 4 + word_;
  }

private:
  // The counter of block i of this stream (see the top of the file).
  [[nodiscard]] constexpr std::array<std::uint32_t, 4> counter(std::uint64_t i) const noexcept {
    return {static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(i >> 32),
            static_cast<std::uint32_t>(name_), static_cast<std::uint32_t>(name_ >> 32)};
  }
  constexpr void refill() noexcept {
    block_ = philox4x32_10(counter(block_index_), key_);
    ++block_index_;
    word_ = 0;
  }

  std::array<std::uint32_t, 2> key_;
  std::uint64_t name_;
  std::uint64_t block_index_ = 0;
  std::array<std::uint32_t, 4> block_{};
  std::size_t word_ = 4;
};

} // namespace antkit::kernel
