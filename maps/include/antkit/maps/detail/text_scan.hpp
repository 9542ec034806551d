#pragma once
// Small text-scanning helpers shared by the map readers: lines with their numbers and byte offsets
// turned into LINE:COL (the kernel's, text_lines.hpp), whole-number parsing with a cap, and
// printable quoting of bad input for error messages. Internal to antkit::maps; not part of its
// stable interface.
#include <antkit/kernel/grid.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/kernel/text_lines.hpp>
#include <antkit/maps/map_io.hpp>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace antkit::maps::detail {

// The lines and positions are the kernel's one line scanner (kernel/text_lines.hpp).
using Line = kernel::TextLine;
using LineReader = kernel::TextLines;
using Position = kernel::TextPosition;
using kernel::position_of;

[[noreturn]] inline void fail(const std::string& name, std::size_t line, std::size_t column,
                              const std::string& message) {
  throw kernel::InputError(name, line, column, message);
}

[[noreturn]] inline void fail_at(const std::string& name, std::string_view text, std::size_t offset,
                                 const std::string& message) {
  const auto p = position_of(text, offset);
  fail(name, p.line, p.column, message);
}

// Up to 40 bytes of `s` in single quotes, with bytes outside printable ASCII written as \xNN, so
// that a message about binary garbage stays one readable line.
inline std::string quoted(std::string_view s) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out = "'";
  const std::size_t shown = s.size() < 40 ? s.size() : 40;
  for (std::size_t i = 0; i < shown; ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 0xf];
    }
  }
  if (shown < s.size()) out += "...";
  return out + "'";
}

inline bool is_digit(char c) noexcept {
  return c >= '0' && c <= '9';
}
inline bool is_blank(char c) noexcept {
  return c == ' ' || c == '\t';
}

// A whole number written with decimal digits only (no sign, no spaces), at most `max`.
inline std::optional<std::uint64_t> parse_whole(std::string_view s, std::uint64_t max) {
  if (s.empty()) return std::nullopt;
  std::uint64_t value = 0;
  for (const char c : s) {
    if (!is_digit(c)) return std::nullopt;
    value = value * 10 + static_cast<std::uint64_t>(c - '0');
    if (value > max) return std::nullopt;
  }
  return value;
}

// The size checks every reader makes before it allocates a grid (see map_io.hpp, Size caps).
// Returns an empty string when width x height is acceptable, else what is wrong and what the
// caps are.
inline std::string size_problem(std::uint64_t width, std::uint64_t height) {
  const auto side = static_cast<std::uint64_t>(kernel::kMaxGridSide);
  if (width < 1 || width > side || height < 1 || height > side)
    return "map size " + std::to_string(width) + " x " + std::to_string(height) +
           " is outside the supported range; expected each side from 1 to " + std::to_string(side);
  if (width * height > static_cast<std::uint64_t>(kMaxMapCells))
    return "map size " + std::to_string(width) + " x " + std::to_string(height) + " = " +
           std::to_string(width * height) + " cells is over the cap of " +
           std::to_string(kMaxMapCells) + " cells; expected a smaller map";
  return {};
}

} // namespace antkit::maps::detail
