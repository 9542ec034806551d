// The map_server YAML subset (documented at parse_ros_yaml in antkit/maps/map_io.hpp). A parser of
// our own rather than a YAML library: the files are flat `key: value` lines, and a subset we state
// and check is easier to trust under a fuzzer than a general parser whose corners we do not need.
#include <antkit/maps/detail/text_scan.hpp>
#include <antkit/maps/map_io.hpp>
#include <array>
#include <charconv>
#include <cmath>
#include <map>
#include <system_error>

namespace antkit::maps {

namespace {

using detail::fail;

// A value with where it starts in the yaml (1-based line and column).
struct Scalar {
  std::string text;
  std::size_t line = 0;
  std::size_t column = 0;
};

constexpr std::array<std::string_view, 7> kKeys{
    "image", "resolution", "origin", "negate", "occupied_thresh", "free_thresh", "mode"};

std::string key_list() {
  std::string s;
  for (const auto k : kKeys) s += (s.empty() ? "" : ", ") + std::string(k);
  return s;
}

bool is_key_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || detail::is_digit(c) || c == '_';
}

// The rest of a line after a value must be blank or a comment.
void expect_line_end(const std::string& name, const detail::Line& line, std::size_t i) {
  while (i < line.text.size() && detail::is_blank(line.text[i])) ++i;
  if (i < line.text.size() && line.text[i] != '#')
    fail(name, line.number, i + 1,
         "unexpected " + detail::quoted(line.text.substr(i)) +
             " after the value; expected the end of the "
             "line or a # comment");
}

// A plain or quoted scalar starting at line.text[i]. Returns its text and consumes the line.
Scalar scalar_at(const std::string& name, const detail::Line& line, std::size_t i) {
  const auto s = line.text;
  Scalar out{{}, line.number, i + 1};
  const char q = s[i];
  if (q == '\'' || q == '"') {
    std::size_t j = i + 1;
    for (;; ++j) {
      if (j >= s.size())
        fail(name, line.number, i + 1,
             std::string("unterminated quoted value; expected a closing ") + q +
                 " on the same line (multi-line values are not supported)");
      if (q == '"' && s[j] == '\\')
        fail(name, line.number, j + 1,
             "backslash escapes are not supported in this YAML subset; expected a plain path");
      if (s[j] == q) {
        if (q == '\'' && j + 1 < s.size() && s[j + 1] == '\'') { // '' is a quote in '...'
          out.text += '\'';
          ++j;
          continue;
        }
        break;
      }
      out.text += s[j];
    }
    expect_line_end(name, line, j + 1);
    return out;
  }
  // YAML indicators that would start something other than a plain scalar.
  static constexpr std::string_view kIndicators = "{}[]&*!|>%@`,";
  if (kIndicators.find(q) != std::string_view::npos ||
      (q == '-' && (i + 1 == s.size() || detail::is_blank(s[i + 1]))))
    fail(name, line.number, i + 1,
         "unsupported YAML " + detail::quoted(s.substr(i, 1)) +
             " (this reader takes flat `key: value` lines); expected a plain value");
  // A plain scalar ends at " #" (a comment) or the end of the line; trailing blanks are dropped.
  std::size_t end = i;
  while (end < s.size() && !(s[end] == '#' && detail::is_blank(s[end - 1]))) ++end;
  while (end > i && detail::is_blank(s[end - 1])) --end;
  out.text = std::string(s.substr(i, end - i));
  return out;
}

double number(const std::string& name, const Scalar& v, const char* what) {
  std::string_view s = v.text;
  // YAML allows a leading '+'; from_chars does not.
  if (s.size() > 1 && s[0] == '+' && s[1] != '-') s.remove_prefix(1);
  double value = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (s.empty() || ec != std::errc{} || end != s.data() + s.size() || !std::isfinite(value))
    fail(name, v.line, v.column,
         std::string("bad ") + what + " " + detail::quoted(v.text) +
             "; expected a finite decimal number");
  return value;
}

} // namespace

RosMapYaml parse_ros_yaml(std::string_view text, const std::string& name) {
  std::map<std::string, Scalar, std::less<>> values;
  std::array<Scalar, 3> origin;
  bool saw_content = false;

  detail::LineReader lines(text);
  while (const auto line = lines.next()) {
    const auto s = line->text;
    std::size_t i = 0;
    while (i < s.size() && detail::is_blank(s[i])) ++i;
    if (i == s.size() || s[i] == '#') continue; // blank or comment line
    if (i > 0)
      fail(name, line->number, 1,
           "indented line (nested YAML is not supported); expected `key: value` at column 1");
    if (s == "---" || s.substr(0, 4) == "--- ") {
      if (saw_content)
        fail(name, line->number, 1,
             "a second YAML document; expected one map description per file");
      saw_content = true;
      continue;
    }
    saw_content = true;

    std::size_t k = 0;
    while (k < s.size() && is_key_char(s[k])) ++k;
    if (k == 0 || k == s.size() || s[k] != ':' || (k + 1 < s.size() && !detail::is_blank(s[k + 1])))
      fail(name, line->number, k + 1,
           "expected `key: value` (a key of letters, digits and _ followed by `: `), found " +
               detail::quoted(s));
    const std::string key(s.substr(0, k));
    bool known = false;
    for (const auto known_key : kKeys) known = known || key == known_key;
    if (!known)
      fail(name, line->number, 1,
           "unknown key " + detail::quoted(key) + "; expected one of " + key_list());
    if (values.count(key))
      fail(name, line->number, 1,
           "a second " + detail::quoted(key) + " (the first is on line " +
               std::to_string(values[key].line) + "); expected each key once");

    i = k + 1;
    while (i < s.size() && detail::is_blank(s[i])) ++i;
    if (i == s.size() || s[i] == '#')
      fail(name, line->number, i + 1,
           "no value for " + detail::quoted(key) +
               " (block values on the next lines are not supported); expected it on this line");

    if (key == "origin") {
      if (s[i] != '[')
        fail(name, line->number, i + 1, "origin must be a flow list; expected `[x, y, yaw]`");
      const auto close = s.find(']', i);
      if (close == std::string_view::npos)
        fail(name, line->number, s.size() + 1,
             "unterminated origin list; expected `]` on the same line");
      std::size_t item = 0;
      std::size_t p = i + 1;
      while (true) {
        const auto comma = std::min(s.find(',', p), close);
        std::size_t a = p;
        std::size_t b = comma;
        while (a < b && detail::is_blank(s[a])) ++a;
        while (b > a && detail::is_blank(s[b - 1])) --b;
        if (item == 3)
          fail(name, line->number, a + 1,
               "origin has more than three values; expected [x, y, yaw]");
        origin[item] = Scalar{std::string(s.substr(a, b - a)), line->number, a + 1};
        ++item;
        if (comma == close) break;
        p = comma + 1;
      }
      if (item != 3)
        fail(name, line->number, close + 1,
             "origin has " + std::to_string(item) + " values; expected three, [x, y, yaw]");
      expect_line_end(name, *line, close + 1);
      values[key] = Scalar{"", line->number, i + 1};
      continue;
    }
    values[key] = scalar_at(name, *line, i);
  }

  const auto eof = detail::position_of(text, text.size());
  auto required = [&](const char* key, const char* expected) -> const Scalar& {
    const auto it = values.find(key);
    if (it == values.end())
      fail(name, eof.line, eof.column,
           std::string("the yaml has no `") + key + ":`; expected one (" + expected + ")");
    return it->second;
  };

  RosMapYaml y;
  const auto& image = required("image", "the path of the PGM image");
  if (image.text.empty()) fail(name, image.line, image.column, "empty image path; expected a path");
  y.image = image.text;
  y.image_line = image.line;
  y.image_column = image.column;

  const auto& res = required("resolution", "metres per pixel");
  y.resolution = number(name, res, "resolution");
  if (!(y.resolution > 0))
    fail(name, res.line, res.column, "resolution " + res.text + " is not positive; expected > 0");

  required("origin", "[x, y, yaw]");
  y.origin_x = number(name, origin[0], "origin x");
  y.origin_y = number(name, origin[1], "origin y");
  y.origin_yaw = number(name, origin[2], "origin yaw");

  const auto& neg = required("negate", "0 or 1");
  if (neg.text == "0" || neg.text == "false") {
    y.negate = false;
  } else if (neg.text == "1" || neg.text == "true") {
    y.negate = true;
  } else {
    fail(name, neg.line, neg.column,
         "bad negate " + detail::quoted(neg.text) + "; expected 0 or 1");
  }

  auto threshold = [&](const char* key) {
    const auto& v = required(key, "a probability from 0 to 1");
    const double t = number(name, v, key);
    if (t < 0 || t > 1)
      fail(name, v.line, v.column,
           std::string(key) + " " + v.text + " is outside [0, 1]; expected a probability");
    return t;
  };
  y.occupied_thresh = threshold("occupied_thresh");
  y.free_thresh = threshold("free_thresh");
  if (y.free_thresh > y.occupied_thresh) {
    const auto& v = values.find("free_thresh")->second;
    fail(name, v.line, v.column,
         "free_thresh " + v.text + " is above occupied_thresh " +
             values.find("occupied_thresh")->second.text +
             "; expected free_thresh <= occupied_thresh");
  }

  if (const auto it = values.find("mode"); it != values.end()) {
    const auto& m = it->second;
    if (m.text == "trinary") {
      y.mode = RosMode::Trinary;
    } else if (m.text == "scale") {
      y.mode = RosMode::Scale;
    } else if (m.text == "raw") {
      y.mode = RosMode::Raw;
    } else {
      fail(name, m.line, m.column,
           "unknown mode " + detail::quoted(m.text) + "; expected trinary (or scale or raw)");
    }
    y.mode_line = m.line;
    y.mode_column = m.column;
  }
  return y;
}

} // namespace antkit::maps
