#pragma once
// The line reading the text readers of antkit::testing share (stc_audit.cpp, run_audit.cpp).
#include <algorithm>
#include <cstddef>
#include <string_view>

namespace antkit::testing::detail {

inline bool blank(char c) noexcept {
  return c == ' ' || c == '\t';
}

// The lines of a text, LF or CRLF (the CR dropped), numbered from 1.
class Lines {
public:
  explicit Lines(std::string_view text) noexcept : text_(text) {}
  // The next line into `line`; false at the end of the text.
  bool next(std::string_view& line) noexcept {
    if (pos_ >= text_.size()) return false;
    ++number_;
    const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
    line = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    return true;
  }
  [[nodiscard]] std::size_t number() const noexcept { return number_; }

private:
  std::string_view text_;
  std::size_t pos_ = 0, number_ = 0;
};

// Whether `line` is `header` once spaces and tabs are left out ("x , y" is the header "x,y").
inline bool is_header(std::string_view line, std::string_view header) noexcept {
  std::size_t k = 0;
  for (const char c : line) {
    if (blank(c)) continue;
    if (k == header.size() || header[k] != c) return false;
    ++k;
  }
  return k == header.size();
}

} // namespace antkit::testing::detail
