// kernel::TextLines and position_of (kernel/text_lines.hpp), the line scanner every text reader
// uses: LF and CRLF lines with their numbers and offsets, no empty last line after a final '\n',
// and byte offsets as LINE:COL.
#include <antkit/kernel/text_lines.hpp>
#include <catch2/catch.hpp>
#include <string>
#include <vector>

using antkit::kernel::position_of;
using antkit::kernel::TextLines;

TEST_CASE("TextLines: lines, numbers and offsets, LF or CRLF", "[kernel]") {
  const std::string text = "ab\r\n\ncd\nlast";
  TextLines lines(text);
  std::vector<std::string> seen;
  std::vector<std::size_t> numbers, offsets;
  while (const auto l = lines.next()) {
    seen.emplace_back(l->text);
    numbers.push_back(l->number);
    offsets.push_back(l->offset);
  }
  CHECK(seen == std::vector<std::string>{"ab", "", "cd", "last"});
  CHECK(numbers == std::vector<std::size_t>{1, 2, 3, 4});
  CHECK(offsets == std::vector<std::size_t>{0, 4, 5, 8});
  CHECK(lines.end_offset() == text.size());

  TextLines ends("x\n");
  CHECK(ends.next()->text == "x");
  CHECK_FALSE(ends.next()); // no empty line after the final '\n'
  CHECK_FALSE(TextLines("").next());
  CHECK(TextLines("\r").next()->text.empty()); // a lone CR is the line's CR
}

TEST_CASE("position_of: a byte offset as LINE:COL from 1", "[kernel]") {
  const std::string text = "ab\ncd\n";
  CHECK(position_of(text, 0).line == 1);
  CHECK(position_of(text, 0).column == 1);
  CHECK(position_of(text, 4).line == 2);
  CHECK(position_of(text, 4).column == 2);
  const auto [line, column] = position_of(text, text.size()); // after the final '\n'
  CHECK(line == 3);
  CHECK(column == 1);
  CHECK(position_of(text, 100).line == 3); // past the end is the end
  static_assert(position_of("a\nb", 2).line == 2);
}
