#pragma once
// What the text readers of antkit::testing share (stc_audit.cpp, run_audit.cpp) beyond the
// kernel's line scanner (kernel/text_lines.hpp): headers, whole numbers and the wording of
// nlohmann-json's errors.
#include <antkit/kernel/text_lines.hpp>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

namespace antkit::testing::detail {

inline bool blank(char c) noexcept {
  return c == ' ' || c == '\t';
}

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

// A whole number written at l[i...]: an optional sign ('-', and '+' when `plus`), then digits.
// `i` moves past it. `digits` is false when there are none; `overflow` says the value left the
// int64 range (then `value` is not the number).
struct Whole {
  bool digits = false, overflow = false;
  std::int64_t value = 0;
};

inline Whole scan_whole(std::string_view l, std::size_t& i, bool plus = false) noexcept {
  Whole w;
  bool negative = false;
  if (i < l.size() && (l[i] == '-' || (plus && l[i] == '+'))) negative = l[i++] == '-';
  for (; i < l.size() && l[i] >= '0' && l[i] <= '9'; ++i) {
    w.digits = true;
    if (w.value > (std::numeric_limits<std::int64_t>::max() - 9) / 10) w.overflow = true;
    if (!w.overflow) w.value = w.value * 10 + (l[i] - '0');
  }
  if (negative) w.value = -w.value;
  return w;
}

// An nlohmann-json error's message without its tag: "[json.exception.parse_error.101] parse error
// at line 1, column 3: " (or "[json.exception.out_of_range.406] " for a number out of range) is
// left out, what follows kept. The caller says where, in its own terms.
inline std::string json_message(std::string what) {
  if (what.compare(0, 15, "[json.exception") != 0) return what;
  if (const auto end = what.find("] "); end != std::string::npos) what.erase(0, end + 2);
  if (what.compare(0, 11, "parse error") == 0)
    if (const auto colon = what.find(": "); colon != std::string::npos) what.erase(0, colon + 2);
  return what;
}

} // namespace antkit::testing::detail
