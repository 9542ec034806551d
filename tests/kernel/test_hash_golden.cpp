// Golden values for the trace hash and the keyed random streams (DESIGN.md, rule 5: changing one
// is a deliberate, explained commit).
//
// Where the numbers come from: an independent implementation, in Python, of the definitions written
// in the header comments of hash.hpp and random.hpp (arbitrary-precision integers masked to 64 and
// 32 bits; its Philox reproduces the Random123 known answers before anything else is computed).
// They were not produced by running the C++ code. Besides the pinned numbers, the properties below
// check the C++ against a second, byte-at-a-time transcription of the same definitions, so that a
// change of the definition and a change of the code are told apart.
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/random.hpp>
#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>
#include <vector>

using antkit::kernel::hash_hex;
using antkit::kernel::mix64;
using antkit::kernel::philox4x32_10;
using antkit::kernel::Stream;
using antkit::kernel::stream_name;
using antkit::kernel::TraceHash;

namespace {

std::vector<std::uint8_t> iota_bytes(std::size_t n, std::uint8_t first) {
  std::vector<std::uint8_t> v(n);
  for (std::size_t k = 0; k < n; ++k) v[k] = static_cast<std::uint8_t>(first + k);
  return v;
}

// hash.hpp's definition read literally: bytes, then 8-byte little-endian words (zero-padded), the
// round, the length, the avalanche.
std::uint64_t spec_hash(const std::vector<std::uint8_t>& bytes, std::uint64_t seed) {
  auto rotl = [](std::uint64_t x, int r) { return (x << r) | (x >> (64 - r)); };
  std::uint64_t h = seed + TraceHash::P5;
  for (std::size_t k = 0; k < bytes.size(); k += 8) {
    std::uint64_t w = 0;
    for (std::size_t b = 0; b < 8 && k + b < bytes.size(); ++b)
      w |= std::uint64_t{bytes[k + b]} << (8 * b);
    const std::uint64_t round = rotl(w * TraceHash::P2, 31) * TraceHash::P1;
    h = rotl(h ^ round, 27) * TraceHash::P1 + TraceHash::P4;
  }
  h ^= bytes.size();
  h ^= h >> 33;
  h *= TraceHash::P2;
  h ^= h >> 29;
  h *= TraceHash::P3;
  h ^= h >> 32;
  return h;
}

} // namespace

TEST_CASE("trace hash golden values", "[hash]") {
  CHECK(TraceHash().finish() == 0xef46db3751d8e999ULL);
  CHECK(TraceHash(1).finish() == 0xd5afba1336a3be4bULL);

  // Every add_* once, 31 bytes in all: the little-endian two's-complement serialisation.
  TraceHash mixed;
  mixed.add_u8(0x01)
      .add_u16(0x0203)
      .add_u32(0x04050607)
      .add_u64(0x08090a0b0c0d0e0fULL)
      .add_i8(-1)
      .add_i16(-2)
      .add_i32(-3)
      .add_i64(-4)
      .add_bool(true);
  CHECK(mixed.bytes() == 31u);
  CHECK(mixed.finish() == 0x5c7cb74e71c0d4eaULL);

  const std::vector<std::uint8_t> all = iota_bytes(256, 0);
  CHECK(TraceHash().add_bytes(all).finish() == 0xd3b50ea9f0602474ULL);

  // Lengths around the 8-byte word: the padding and the length term, seed 42, bytes 1, 2, 3, ...
  const std::array<std::pair<std::size_t, std::uint64_t>, 5> lengths{{{1, 0xe6d2daacd3c956bdULL},
                                                                      {7, 0x883dabf3e75fe032ULL},
                                                                      {8, 0x19601f9a0efc5817ULL},
                                                                      {9, 0x5858342523f1ead3ULL},
                                                                      {16, 0xe564d8eb9903fcb7ULL}}};
  for (auto [n, want] : lengths) {
    INFO("length " << n);
    CHECK(TraceHash(42).add_bytes(iota_bytes(n, 1)).finish() == want);
  }
  CHECK(hash_hex(0xef46db3751d8e999ULL) == "ef46db3751d8e999");
  CHECK(hash_hex(0x00000000000000a1ULL) == "00000000000000a1");
}

TEST_CASE("random stream golden values", "[random]") {
  CHECK(mix64(0) == 0u);
  CHECK(mix64(1) == 0x5692161d100b05e5ULL);
  CHECK(stream_name(0, 0, 0, 0) == 0xb732999ebb1c7fedULL);

  Stream s0(0);
  const std::array<std::uint32_t, 10> s0_words{0x99046a80, 0x885e3925, 0x89d32aed, 0xa8b8d1d5,
                                               0xf1647f94, 0xd412d967, 0x45779f44, 0xdddb392b,
                                               0x02a8c5dd, 0x89a03f3d};
  for (std::uint32_t w : s0_words) CHECK(s0.next_u32() == w);

  Stream keyed(0x0123456789ABCDEFULL, 1, 2, 3, 4);
  for (std::uint32_t w :
       {0x3f2a7bf8u, 0x579e5fb6u, 0x5bbb4ae9u, 0x12093122u, 0x265af441u, 0x3c5d9019u})
    CHECK(keyed.next_u32() == w);
  for (std::uint64_t w : {0xbb9e430e2e1ec985ULL, 0x9ed07e55ffcb40c5ULL, 0x1817aeeddc65832aULL})
    CHECK(keyed.next_u64() == w);
  CHECK(keyed.drawn() == 12u);

  Stream dice(7, 0, 0, 0, 1);
  for (std::uint32_t v : {7u, 2u, 2u, 8u, 5u, 9u, 5u, 3u, 6u, 2u, 8u, 2u, 4u, 0u, 9u, 9u})
    CHECK(dice.below(10) == v);
  CHECK(dice.drawn() == 16u); // no rejection at n = 10 in these words

  Stream signed_dice(7, 0, 0, 0, 2);
  for (std::int32_t v : {3, 4, -3, 3, 3, -5, 4, -2, 1, -3, -4, -1})
    CHECK(signed_dice.between(-5, 5) == v);

  // n = 3e9 rejects 2^32 mod n = 1294967296 words of every 2^32; a stretch with rejections in it.
  Stream large(7, 0, 0, 0, 3);
  for (std::uint32_t v : {2725199732u, 1329827792u, 2334915969u, 2328290138u, 1787636401u,
                          1585767609u, 2355527949u, 1665435190u})
    CHECK(large.below(3000000000u) == v);
}

TEST_CASE("the trace hash is its documented definition", "[hash][property]") {
  rc::prop("TraceHash over bytes equals the word-by-word definition",
           [](std::vector<std::uint8_t> bytes, std::uint64_t seed) {
             RC_ASSERT(TraceHash(seed).add_bytes(bytes).finish() == spec_hash(bytes, seed));
           });
}

TEST_CASE("a stream is Philox over its documented counter and key", "[random][property]") {
  rc::prop("word k is word k mod 4 of block k div 4", [](std::uint64_t seed, std::uint64_t e,
                                                         std::uint64_t t, std::uint64_t r,
                                                         std::uint64_t p) {
    const auto skip = *rc::gen::inRange<std::uint64_t>(0, 64);
    Stream s(seed, e, t, r, p);
    for (std::uint64_t k = 0; k < skip; ++k) s.next_u32();
    const std::uint64_t name = stream_name(e, t, r, p);
    const std::uint64_t block = skip / 4;
    const auto words =
        philox4x32_10({static_cast<std::uint32_t>(block), static_cast<std::uint32_t>(block >> 32),
                       static_cast<std::uint32_t>(name), static_cast<std::uint32_t>(name >> 32)},
                      {static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)});
    RC_ASSERT(s.next_u32() == words[skip % 4]);
  });
}
