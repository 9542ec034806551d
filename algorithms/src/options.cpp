#include <algorithm>
#include <antkit/algorithms/options.hpp>
#include <antkit/kernel/input_error.hpp>
#include <charconv>
#include <limits>
#include <string>

namespace antkit::algorithms {

using kernel::InputError;

namespace {

std::string quoted(std::string_view text) {
  return "'" + std::string(text) + "'";
}

} // namespace

std::int64_t parse_integer(std::string_view option, std::string_view text, std::string_view what) {
  std::int64_t v = 0;
  const auto* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (text.empty() || ec != std::errc{} || ptr != end)
    throw InputError(std::string(option), quoted(text) + " is not " + std::string(what));
  return v;
}

std::pair<std::int64_t, std::int64_t> parse_pair(std::string_view option, std::string_view text,
                                                 char separator, std::string_view expected) {
  const auto cut = text.find(separator);
  const std::string message = quoted(text) + " is not of the form " + std::string(expected);
  if (cut == std::string_view::npos) throw InputError(std::string(option), message);
  try {
    return {parse_integer(option, text.substr(0, cut)),
            parse_integer(option, text.substr(cut + 1))};
  } catch (const InputError&) {
    throw InputError(std::string(option), message);
  }
}

kernel::Cell parse_cell(std::string_view option, std::string_view text) {
  const auto [x, y] = parse_pair(option, text, ',', "X,Y (two integers)");
  constexpr auto lo = std::numeric_limits<std::int32_t>::min();
  constexpr auto hi = std::numeric_limits<std::int32_t>::max();
  if (x < lo || x > hi || y < lo || y > hi)
    throw InputError(std::string(option), quoted(text) + " is out of range");
  return {static_cast<std::int32_t>(x), static_cast<std::int32_t>(y)};
}

std::uint32_t parse_probability_ppm(std::string_view option, std::string_view text) {
  const std::string expected = quoted(text) + " is not a probability: expected a decimal in [0, 1] "
                                              "with at most six decimals, e.g. 0.01";
  std::size_t i = 0;
  std::uint64_t whole = 0;
  bool digits = false;
  for (; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i) {
    whole = std::min<std::uint64_t>(whole * 10 + static_cast<std::uint64_t>(text[i] - '0'), 10);
    digits = true;
  }
  std::uint64_t fraction = 0;
  int places = 0;
  if (i < text.size() && text[i] == '.') {
    for (++i; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i) {
      if (++places > 6) throw InputError(std::string(option), expected);
      fraction = fraction * 10 + static_cast<std::uint64_t>(text[i] - '0');
      digits = true;
    }
  }
  if (!digits || i != text.size()) throw InputError(std::string(option), expected);
  for (; places < 6; ++places) fraction *= 10;
  const std::uint64_t ppm = whole * 1'000'000 + fraction;
  if (ppm > 1'000'000) throw InputError(std::string(option), expected);
  return static_cast<std::uint32_t>(ppm);
}

} // namespace antkit::algorithms
