// Fuzz target: `--precision P` (algorithms/buffon/src/stopping.cpp, parse_precision). Bad input
// must be an InputError about the precision (where() "precision", which antkit shows as
// --precision); an accepted text must be a plain decimal whose value,
// re-read here digit by digit, is exactly the millionths returned, in [1, 999999].
#include <antkit/buffon/stopping.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const std::uint32_t p = antkit::buffon::parse_precision(text);
    if (p < 1 || p > 999999) __builtin_trap();
    // Independent reading: digits before the point must be zeros, at most six after it.
    std::uint64_t value = 0;
    int after = -1; // digits after the point, -1 before it
    for (const char ch : text) {
      if (ch == '.') {
        if (after >= 0) __builtin_trap(); // two points accepted
        after = 0;
        continue;
      }
      if (ch < '0' || ch > '9') __builtin_trap(); // a non-digit accepted
      if (after < 0) {
        if (ch != '0') __builtin_trap(); // P >= 1 accepted
        continue;
      }
      if (++after > 6) __builtin_trap();
      value = value * 10 + static_cast<std::uint64_t>(ch - '0');
    }
    for (int d = after < 0 ? 0 : after; d < 6; ++d) value *= 10;
    if (value != p) __builtin_trap();
  } catch (const antkit::kernel::InputError& e) {
    if (e.where() != "precision") __builtin_trap();
  }
  return 0;
}
