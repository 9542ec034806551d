#pragma once
// Small text-scanning helpers shared by the map readers: lines with their numbers, byte offsets
// turned into LINE:COL, whole-number parsing with a cap, and printable quoting of bad input for
// error messages. Internal to antkit::maps; not part of its stable interface.
#include <antkit/kernel/grid.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/map_io.hpp>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace antkit::maps::detail {

// One line of a text: its content without the '\n' and without one '\r' before it (CRLF files),
// its number (from 1) and the byte offset of its first character.
struct Line {
  std::string_view text;
  std::size_t number = 0;
  std::size_t offset = 0;
};

class LineReader {
public:
  explicit LineReader(std::string_view text) : text_(text) {}
  // The next line, or nothing at the end. A text that ends with '\n' has no empty last line.
  std::optional<Line> next() {
    if (pos_ >= text_.size()) return std::nullopt;
    const auto end = text_.find('\n', pos_);
    const auto stop = end == std::string_view::npos ? text_.size() : end;
    Line line{text_.substr(pos_, stop - pos_), ++number_, pos_};
    if (!line.text.empty() && line.text.back() == '\r') line.text.remove_suffix(1);
    pos_ = end == std::string_view::npos ? text_.size() : end + 1;
    return line;
  }
  // Where the text ends, as a position (for "the file ends before ..." messages).
  [[nodiscard]] std::size_t end_offset() const noexcept { return text_.size(); }

private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t number_ = 0;
};

struct Position {
  std::size_t line = 1;
  std::size_t column = 1;
};

// The LINE:COL of a byte offset (lines counted by '\n', columns in bytes, both from 1). An offset
// at the very end of a text that ends with '\n' is on the line after the last one.
inline Position position_of(std::string_view text, std::size_t offset) {
  Position p;
  const auto stop = offset < text.size() ? offset : text.size();
  for (std::size_t i = 0; i < stop; ++i) {
    if (text[i] == '\n') {
      ++p.line;
      p.column = 1;
    } else {
      ++p.column;
    }
  }
  return p;
}

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
