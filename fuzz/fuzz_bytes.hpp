#pragma once
// The fuzzer's bytes read as a stream of small values, for the controller targets: every read
// succeeds (past the end it answers 0), so a short input is a short run, never a rejected one.
#include <cstddef>
#include <cstdint>

namespace antkit::fuzzing {

class Bytes {
public:
  Bytes(const std::uint8_t* data, std::size_t size) noexcept : data_(data), size_(size) {}

  [[nodiscard]] bool empty() const noexcept { return pos_ >= size_; }
  [[nodiscard]] std::size_t left() const noexcept { return pos_ < size_ ? size_ - pos_ : 0; }

  std::uint8_t u8() noexcept { return pos_ < size_ ? data_[pos_++] : 0; }
  std::uint16_t u16() noexcept {
    const auto lo = u8();
    return static_cast<std::uint16_t>(lo | (u8() << 8));
  }
  std::uint32_t u32() noexcept {
    const std::uint32_t lo = u16();
    return lo | (static_cast<std::uint32_t>(u16()) << 16);
  }
  // A value in [0, n) for 0 < n <= 256.
  unsigned below(unsigned n) noexcept { return static_cast<unsigned>(u8()) % n; }

private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

} // namespace antkit::fuzzing

#include <cstdio>

namespace antkit::fuzzing {

// A property of a fuzz target failed: say which, then trap (libFuzzer keeps the input; the
// replay binary under ctest dies, so the test fails).
[[noreturn]] inline void property_failed(const char* what, const char* file, int line) {
  std::fprintf(stderr, "%s:%d: property failed: %s\n", file, line, what);
  __builtin_trap();
}

} // namespace antkit::fuzzing

#define ANTKIT_FUZZ_REQUIRE(cond)                                                                  \
  do {                                                                                             \
    if (!(cond)) ::antkit::fuzzing::property_failed(#cond, __FILE__, __LINE__);                    \
  } while (false)
