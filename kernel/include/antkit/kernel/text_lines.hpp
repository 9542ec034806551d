#pragma once
// The one line scanner of antkit's text readers (the map files of antkit::maps, the tours, traces
// and cell files of antkit::testing): a text's lines with their numbers and offsets, and a byte
// offset as the LINE:COL a located InputError (input_error.hpp) names. Here, in the lowest layer,
// so that every reader above uses the same one.
#include <cstddef>
#include <optional>
#include <string_view>

namespace antkit::kernel {

// One line of a text: its content without the '\n' and without one '\r' before it (CRLF files),
// its number (from 1) and the byte offset of its first character.
struct TextLine {
  std::string_view text;
  std::size_t number = 0;
  std::size_t offset = 0;
};

// The lines of a text, LF or CRLF, in order.
class TextLines {
public:
  explicit TextLines(std::string_view text) noexcept : text_(text) {}
  // The next line, or nothing at the end. A text that ends with '\n' has no empty last line.
  std::optional<TextLine> next() noexcept {
    if (pos_ >= text_.size()) return std::nullopt;
    const auto end = text_.find('\n', pos_);
    const auto stop = end == std::string_view::npos ? text_.size() : end;
    TextLine line{text_.substr(pos_, stop - pos_), ++number_, pos_};
    if (!line.text.empty() && line.text.back() == '\r') line.text.remove_suffix(1);
    pos_ = end == std::string_view::npos ? text_.size() : end + 1;
    return line;
  }
  // Where the text ends, as an offset (for "the file ends before ..." messages).
  [[nodiscard]] std::size_t end_offset() const noexcept { return text_.size(); }

private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t number_ = 0;
};

struct TextPosition {
  std::size_t line = 1;
  std::size_t column = 1;
};

// The LINE:COL of a byte offset (lines counted by '\n', columns in bytes, both from 1). An offset
// past the end is the end; an offset at the very end of a text that ends with '\n' is on the line
// after the last one.
[[nodiscard]] constexpr TextPosition position_of(std::string_view text,
                                                 std::size_t offset) noexcept {
  TextPosition p;
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

} // namespace antkit::kernel
