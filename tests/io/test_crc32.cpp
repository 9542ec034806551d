// The CRC-32 (io/crc32.hpp): the check values, and the folded (carry-less multiply) CRC equal to
// the tables' on every length up to 300 at every alignment and start value tried, and on random
// inputs up to 64 KiB (on a machine without PCLMULQDQ both sides are the tables, and these still
// check chaining).
#include <antkit/io/crc32.hpp>
#include <catch2/catch.hpp>
#include <cstdint>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>
#include <string>

namespace io = antkit::io;

TEST_CASE("crc32 check values, folded and portable", "[io][crc32]") {
  for (const auto f : {&io::crc32, &io::crc32_portable}) {
    CHECK(f("", 0) == 0U);
    CHECK(f("123456789", 0) == 0xCBF43926U);
    CHECK(f("The quick brown fox jumps over the lazy dog", 0) == 0x414FA339U);
    // 64 bytes and more take the folded path where the CPU has it.
    CHECK(f(std::string(64, '\0'), 0) == 0x758D6336U);
    CHECK(f(std::string(1000, 'a'), 0) == 0x9A38DA03U); // both values: Python's zlib.crc32
  }
}

TEST_CASE("crc32 folded equals the tables: every length to 300, every alignment to 16",
          "[io][crc32]") {
  // A buffer of bytes that are not periodic with any small period.
  std::string buf(300 + 16, '\0');
  std::uint32_t s = 12345;
  for (auto& c : buf) {
    s = s * 1103515245U + 12345U;
    c = static_cast<char>(s >> 23);
  }
  int mismatches = 0;
  for (std::size_t align = 0; align < 16; ++align)
    for (std::size_t n = 0; n <= 300; ++n)
      for (const std::uint32_t start : {0U, 0xFFFFFFFFU, 0x12345678U}) {
        const std::string_view v(buf.data() + align, n);
        if (io::crc32(v, start) != io::crc32_portable(v, start)) ++mismatches;
      }
  CHECK(mismatches == 0);
}

TEST_CASE("crc32 folded equals the tables on random inputs and chains", "[io][crc32][property]") {
  rc::prop("crc32(bytes, start) == crc32_portable(bytes, start); split anywhere, it chains", [] {
    const auto n = *rc::gen::inRange<std::size_t>(0, 65536);
    const auto bytes = *rc::gen::container<std::string>(n, rc::gen::arbitrary<char>());
    const auto start = *rc::gen::arbitrary<std::uint32_t>();
    const auto whole = io::crc32(bytes, start);
    RC_ASSERT(whole == io::crc32_portable(bytes, start));
    const auto cut = *rc::gen::inRange<std::size_t>(0, n + 1);
    const std::string_view v(bytes);
    RC_ASSERT(io::crc32(v.substr(cut), io::crc32(v.substr(0, cut), start)) == whole);
    // From the parts' own CRCs (each from 0): the MCAP writer's and reader's data-section CRC.
    const auto a = io::crc32(v.substr(0, cut));
    const auto b = io::crc32(v.substr(cut));
    RC_ASSERT(io::crc32_combine(a, b, n - cut) == io::crc32(v));
  });
}
