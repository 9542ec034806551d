// Named arena specs: parsing with byte positions, then the family builders (arena_spec.hpp).
#include <algorithm>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/kernel/input_error.hpp>
#include <charconv>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

namespace antkit::geometry {

namespace {

constexpr double kPi = 3.141592653589793238462643383279502884;

struct Family {
  const char* name;
  std::vector<std::string> keys;
};

const std::vector<Family>& families() {
  static const std::vector<Family> all{
      {"standard", {"n"}},
      {"circle", {"d", "area", "n"}},
      {"square", {"area", "side", "d"}},
      {"ellipse", {"area", "e", "n"}},
      {"barrier-i", {"len", "t", "d", "n"}},
      {"barrier-plus", {"len", "t", "d", "n"}},
      {"ring", {"area", "ratio", "n"}},
      {"plus", {"area", "arm"}},
      {"obstacles", {"area", "size", "n"}},
  };
  return all;
}

std::string joined(const std::vector<std::string>& items) {
  std::string s;
  for (std::size_t i = 0; i < items.size(); ++i) s += (i ? ", " : "") + items[i];
  return s;
}

std::string printable(std::string_view s) {
  std::string out;
  for (const char c : s.substr(0, 40)) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7f) {
      out += c;
    } else {
      static const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[u >> 4];
      out += hex[u & 15];
    }
  }
  if (s.size() > 40) out += "...";
  return out;
}

// A decimal number, the whole of `text`: optional sign, digits, optional fraction, optional
// exponent. std::from_chars does the conversion (correctly rounded, locale-free).
bool parse_decimal(std::string_view text, double& value) {
  std::size_t i = 0;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  std::size_t digits = 0;
  while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i, ++digits;
  if (i < text.size() && text[i] == '.') {
    ++i;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i, ++digits;
  }
  if (digits == 0) return false;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    std::size_t exp_digits = 0;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i, ++exp_digits;
    if (exp_digits == 0) return false;
  }
  if (i != text.size()) return false;
  // from_chars takes no leading '+'.
  const std::size_t skip = text.front() == '+' ? 1 : 0;
  const auto result = std::from_chars(text.data() + skip, text.data() + text.size(), value);
  return result.ec == std::errc() && std::isfinite(value);
}

struct Parsed {
  ArenaSpec spec;
  std::map<std::string, std::size_t> columns; // key -> column of its value
};

Parsed parse(std::string_view text, const std::string& where) {
  auto fail = [&](std::size_t column, const std::string& message) -> kernel::InputError {
    return kernel::InputError(where, 1, column, message);
  };
  Parsed out;
  const auto colon = text.find(':');
  const std::string_view name = text.substr(0, colon);
  const auto& all = families();
  const auto family =
      std::find_if(all.begin(), all.end(), [&](const Family& f) { return name == f.name; });
  if (family == all.end()) {
    std::vector<std::string> names;
    for (const auto& f : all) names.emplace_back(f.name);
    throw fail(1, "unknown arena family '" + printable(name) + "'; expected one of " +
                      joined(names) + " (or a .wkt file)");
  }
  out.spec.family = family->name;
  if (colon == std::string_view::npos) return out;

  std::size_t pos = colon + 1;
  if (pos == text.size())
    throw fail(pos + 1, "expected KEY=VALUE after ':' (keys for " + out.spec.family + ": " +
                            joined(family->keys) + ")");
  while (true) {
    const auto comma = text.find(',', pos);
    const std::string_view item =
        text.substr(pos, comma == std::string_view::npos ? std::string_view::npos : comma - pos);
    const auto eq = item.find('=');
    if (eq == std::string_view::npos || eq == 0)
      throw fail(pos + 1, "expected KEY=VALUE, found '" + printable(item) + "'");
    const std::string key(item.substr(0, eq));
    if (std::find(family->keys.begin(), family->keys.end(), key) == family->keys.end())
      throw fail(pos + 1, "unknown parameter '" + printable(key) + "' for " + out.spec.family +
                              "; expected one of " + joined(family->keys));
    if (out.spec.params.count(key) != 0) throw fail(pos + 1, "parameter '" + key + "' given twice");
    const std::string_view value_text = item.substr(eq + 1);
    const std::size_t value_column = pos + eq + 2;
    double value = 0;
    if (!parse_decimal(value_text, value))
      throw fail(value_column, "bad number '" + printable(value_text) + "' for " + key +
                                   "; expected a decimal such as 100, 0.4 or 7.854e3");
    out.spec.params[key] = value;
    out.columns[key] = value_column;
    if (comma == std::string_view::npos) break;
    pos = comma + 1;
  }
  return out;
}

// Which spec key a builder's message is about: builders start their range messages with the
// parameter's name.
const std::vector<std::pair<std::string, std::string>>& builder_names() {
  static const std::vector<std::pair<std::string, std::string>> names{
      {"diameter", "d"},          {"area", "area"},
      {"eccentricity", "e"},      {"barrier length", "len"},
      {"barrier thickness", "t"}, {"inner radius ratio", "ratio"},
      {"arm width ratio", "arm"}, {"obstacle diameter", "size"},
      {"vertex count", "n"}};
  return names;
}

} // namespace

ArenaSpec parse_arena_spec(std::string_view text, const std::string& where) {
  return parse(text, where).spec;
}

NamedArena build_arena_spec(std::string_view text, const std::string& where) {
  const Parsed parsed = parse(text, where);
  const auto& p = parsed.spec.params;
  const std::string& family = parsed.spec.family;
  auto has = [&](const char* key) { return p.count(key) != 0; };
  auto get = [&](const char* key, double fallback) { return has(key) ? p.at(key) : fallback; };
  auto column_of = [&](const std::string& key) {
    const auto it = parsed.columns.find(key);
    return it == parsed.columns.end() ? std::size_t{1} : it->second;
  };
  auto fail = [&](const std::string& key, const std::string& message) {
    return kernel::InputError(where, 1, column_of(key), message);
  };
  // Exactly one of the given keys may size the arena.
  auto at_most_one = [&](std::vector<const char*> keys) {
    std::vector<const char*> given;
    for (const char* k : keys)
      if (has(k)) given.push_back(k);
    if (given.size() > 1)
      throw fail(given[1], std::string("give only one of ") + given[0] + " and " + given[1] +
                               " for " + family);
  };
  int n = kCurveVertices;
  if (has("n")) {
    const double v = p.at("n");
    if (!(v == std::floor(v)) || v < 8 || v > 4096)
      throw fail("n", "vertex count n must be a whole number in [8, 4096]");
    n = static_cast<int>(v);
  }
  const double standard = standard_area();
  // What the builders report maps back to the column of the value it is about; `area_key` is the
  // key that sized the arena when several can (square: side or d).
  std::string area_key = "area";
  auto build = [&](auto&& make) -> Arena {
    try {
      return make();
    } catch (const kernel::InputError& e) {
      for (const auto& [prefix, key] : builder_names()) {
        if (e.message().rfind(prefix, 0) == 0) {
          // A size derived from another key (circle:area= gives the diameter) points there.
          const std::string k = key == "area" || parsed.columns.count(key) == 0 ? area_key : key;
          throw fail(k, e.message());
        }
      }
      throw fail("", e.message());
    }
  };
  const std::string builder_where = where;

  if (family == "standard") {
    return {build([&] { return make_circle(kStandardDiameter, n, builder_where); }), standard};
  }
  if (family == "circle") {
    at_most_one({"d", "area"});
    double d = get("d", kStandardDiameter);
    if (has("area")) {
      const double area = p.at("area");
      if (!(area > 0)) throw fail("area", "area must be positive");
      d = 2.0 * std::sqrt(area / kPi);
      area_key = "area";
    }
    const double ideal = kPi * d * d / 4.0;
    return {build([&] { return make_circle(d, n, builder_where); }), ideal};
  }
  if (family == "square") {
    at_most_one({"area", "side", "d"});
    double area = get("area", standard);
    if (has("side")) {
      area = p.at("side") * p.at("side");
      area_key = "side";
    }
    if (has("d")) {
      area = kPi * p.at("d") * p.at("d") / 4.0;
      area_key = "d";
    }
    return {build([&] { return make_square(area, builder_where); }), area};
  }
  if (family == "ellipse") {
    if (!has("e"))
      throw fail("", "ellipse needs e=ECCENTRICITY (the paper's: 0.968, 0.994, 0.998)");
    const double area = get("area", standard);
    return {build([&] { return make_ellipse(area, p.at("e"), n, builder_where); }), area};
  }
  if (family == "barrier-i" || family == "barrier-plus") {
    if (!has("len"))
      throw fail("", family + " needs len=FRACTION (the barrier's length over the diameter)");
    const Barrier kind = family == "barrier-i" ? Barrier::I : Barrier::Plus;
    const double d = get("d", kStandardDiameter), t = get("t", 1.0), len = p.at("len");
    const double bar = len * d;
    const double barrier_area = kind == Barrier::I ? bar * t : 2.0 * bar * t - t * t;
    return {build([&] { return make_barrier_arena(kind, len, t, d, n, builder_where); }),
            kPi * d * d / 4.0 - barrier_area};
  }
  if (family == "ring") {
    const double area = get("area", standard);
    return {build([&] { return make_ring(area, get("ratio", 0.5), n, builder_where); }), area};
  }
  if (family == "plus") {
    const double area = get("area", standard);
    return {build([&] { return make_plus(area, get("arm", 1.0 / 3.0), builder_where); }), area};
  }
  // obstacles (parse() admits no other family)
  const double area = get("area", standard);
  return {build([&] { return make_obstacles_arena(area, get("size", 5.0), n, builder_where); }),
          area};
}

} // namespace antkit::geometry
