#pragma once
// The image's output: JSON and error messages built in a fixed buffer and written to the host's
// standard output in one semihosting call.
#include "semihost.hpp"

#include <cstddef>
#include <cstdint>

namespace antkit::mcu {

// A fixed buffer for the output, written out in one call.
class Text {
public:
  Text& operator<<(const char* s) noexcept {
    while (*s != 0 && n_ < sizeof buf_) buf_[n_++] = *s++;
    return *this;
  }
  Text& operator<<(std::int64_t v) noexcept {
    char digits[24];
    int k = 0;
    std::uint64_t u = v < 0 ? 0 - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
    do {
      digits[k++] = static_cast<char>('0' + u % 10);
      u /= 10;
    } while (u != 0);
    if (v < 0) digits[k++] = '-';
    while (k > 0 && n_ < sizeof buf_) buf_[n_++] = digits[--k];
    return *this;
  }
  Text& u64(std::uint64_t u) noexcept {
    char digits[24];
    int k = 0;
    do {
      digits[k++] = static_cast<char>('0' + u % 10);
      u /= 10;
    } while (u != 0);
    while (k > 0 && n_ < sizeof buf_) buf_[n_++] = digits[--k];
    return *this;
  }
  Text& hex(std::uint64_t h) noexcept {
    for (int i = 15; i >= 0 && n_ < sizeof buf_; --i)
      buf_[n_++] = "0123456789abcdef"[(h >> (4 * i)) & 0xF];
    return *this;
  }
  void flush() noexcept {
    const std::int32_t out = mcu::open_stdout();
    mcu::write(out, buf_, n_);
    mcu::close(out);
    n_ = 0;
  }

private:
  char buf_[512];
  std::size_t n_ = 0;
};

// "error: WHAT: WHY" on the host's standard output; returns the exit status 2 (bad input).
inline int refuse(const char* what, const char* why) {
  Text t;
  t << "error: " << what << ": " << why << "\n";
  t.flush();
  return 2;
}

} // namespace antkit::mcu
