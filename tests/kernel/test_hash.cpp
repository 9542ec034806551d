#include <antkit/kernel/hash.hpp>
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

using antkit::kernel::TraceHash;

TEST_CASE("the trace hash is defined over bytes, not over calls", "[hash][property]") {
  rc::prop("add_u64 equals eight add_u8 at any alignment", [](std::uint64_t v, std::uint8_t lead) {
    TraceHash a, b;
    for (int i = 0; i < lead % 9; ++i) {
      a.add_u8(static_cast<std::uint8_t>(i));
      b.add_u8(static_cast<std::uint8_t>(i));
    }
    a.add_u64(v);
    for (int i = 0; i < 8; ++i) b.add_u8(static_cast<std::uint8_t>(v >> (8 * i)));
    RC_ASSERT(a.finish() == b.finish());
    RC_ASSERT(a.bytes() == b.bytes());
  });
  rc::prop("a trailing zero byte changes the hash", [](std::vector<std::uint8_t> bytes) {
    TraceHash a, b;
    a.add_bytes(bytes);
    b.add_bytes(bytes).add_u8(0);
    RC_ASSERT(a.finish() != b.finish());
  });
}
