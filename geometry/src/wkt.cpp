// WKT reading and writing of arenas (wkt.hpp): a hand-written recursive-descent reader that keeps
// byte positions for its messages and reads numbers exactly.
#include <antkit/geometry/arena_cgal.hpp>
#include <antkit/geometry/wkt.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cctype>
#include <fstream>
#include <gmp.h>
#include <iterator>
#include <stdexcept>
#include <vector>

namespace antkit::geometry {

namespace {

constexpr std::size_t kMaxDigits = 100;
constexpr long kMaxExponent = 100;

class Reader {
public:
  Reader(std::string_view text, const std::string& source) : text_(text), source_(source) {}

  Arena read() {
    skip_space();
    const Position start = here();
    const std::string keyword = word();
    if (keyword == "POLYGON") {
      skip_space();
      reject_empty_or_dimension();
      const Position at = here();
      auto polygon = polygon_text();
      finish();
      return make_arena(std::move(polygon), where(at));
    }
    if (keyword == "MULTIPOLYGON") {
      skip_space();
      reject_empty_or_dimension();
      expect('(');
      skip_space();
      const Position at = here();
      auto polygon = polygon_text();
      skip_space();
      if (peek() == ',')
        throw error(here(), "MULTIPOLYGON with more than one polygon; an arena is one connected "
                            "region, so expected exactly one polygon");
      expect(')');
      finish();
      return make_arena(std::move(polygon), where(at));
    }
    throw error(start, keyword.empty() ? "expected POLYGON or MULTIPOLYGON"
                                       : "unsupported geometry '" + clip(keyword) +
                                             "'; expected POLYGON or MULTIPOLYGON");
  }

private:
  struct Position {
    std::size_t line = 1, column = 1;
  };

  Position here() const { return pos_; }
  std::string where(Position p) const {
    return source_ + ":" + std::to_string(p.line) + ":" + std::to_string(p.column);
  }
  kernel::InputError error(Position p, const std::string& message) const {
    return kernel::InputError(source_, p.line, p.column, message);
  }
  static std::string clip(std::string s) { return s.size() > 40 ? s.substr(0, 40) + "..." : s; }

  bool at_end() const { return i_ >= text_.size(); }
  char peek() const { return at_end() ? '\0' : text_[i_]; }
  void advance() {
    if (text_[i_] == '\n') {
      ++pos_.line;
      pos_.column = 1;
    } else {
      ++pos_.column;
    }
    ++i_;
  }
  void skip_space() {
    while (!at_end() && (peek() == ' ' || peek() == '\t' || peek() == '\n' || peek() == '\r'))
      advance();
  }
  std::string describe_here() const {
    if (at_end()) return "end of input";
    const auto u = static_cast<unsigned char>(peek());
    if (u >= 0x21 && u < 0x7f) return std::string("'") + peek() + "'";
    static const char* hex = "0123456789abcdef";
    return std::string("byte 0x") + hex[u >> 4] + hex[u & 15];
  }
  void expect(char c) {
    if (peek() != c || at_end())
      throw error(here(), std::string("expected '") + c + "', found " + describe_here());
    advance();
  }
  // Letters only, upper-cased.
  std::string word() {
    std::string w;
    while (!at_end() && std::isalpha(static_cast<unsigned char>(peek())) != 0) {
      w += static_cast<char>(std::toupper(static_cast<unsigned char>(peek())));
      advance();
    }
    return w;
  }
  void reject_empty_or_dimension() {
    if (std::isalpha(static_cast<unsigned char>(peek())) == 0) return;
    const Position at = here();
    const std::string w = word();
    if (w == "EMPTY") throw error(at, "EMPTY geometry; an arena needs an outer boundary");
    throw error(at, "unsupported '" + clip(w) + "' (only 2D x y coordinates are read)");
  }
  void finish() {
    skip_space();
    if (!at_end()) throw error(here(), "unexpected " + describe_here() + " after the geometry");
  }

  // '(' ring (',' ring)* ')'
  ExactPolygonWithHoles polygon_text() {
    expect('(');
    std::vector<ExactPolygon> rings;
    while (true) {
      skip_space();
      rings.push_back(ring());
      skip_space();
      if (peek() == ',') {
        advance();
        continue;
      }
      expect(')');
      break;
    }
    ExactPolygon outer = std::move(rings.front());
    return ExactPolygonWithHoles(outer, rings.begin() + 1, rings.end());
  }

  // '(' point (',' point)* ')', closed: the last point repeats the first and is dropped.
  ExactPolygon ring() {
    const Position start = here();
    expect('(');
    std::vector<ExactPoint> points;
    while (true) {
      skip_space();
      points.push_back(point());
      skip_space();
      if (peek() == ',') {
        advance();
        continue;
      }
      expect(')');
      break;
    }
    if (points.size() < 4)
      throw error(start, "ring has " + std::to_string(points.size()) +
                             " points; expected at least 4 (three corners and the closing point)");
    if (points.front() != points.back())
      throw error(start, "ring is not closed; expected its last point to repeat its first");
    points.pop_back();
    return ExactPolygon(points.begin(), points.end());
  }

  ExactPoint point() {
    ExactNumber x = number();
    if (peek() != ' ' && peek() != '\t' && peek() != '\n' && peek() != '\r')
      throw error(here(), "expected whitespace between x and y, found " + describe_here());
    skip_space();
    ExactNumber y = number();
    const auto save = i_;
    const Position save_pos = pos_;
    skip_space();
    const char c = peek();
    if (c == '-' || c == '+' || c == '.' || (c >= '0' && c <= '9'))
      throw error(here(), "a third coordinate; only 2D x y points are read");
    i_ = save;
    pos_ = save_pos;
    return {std::move(x), std::move(y)};
  }

  // [+-] digits [. digits] [(e|E) [+-] digits], at least one digit in the mantissa; exact.
  ExactNumber number() {
    const Position start = here();
    bool negative = false;
    if (peek() == '+' || peek() == '-') {
      negative = peek() == '-';
      advance();
    }
    std::string digits;
    long fraction_digits = 0;
    while (!at_end() && std::isdigit(static_cast<unsigned char>(peek())) != 0) {
      digits += peek();
      advance();
    }
    if (peek() == '.' && !at_end()) {
      advance();
      while (!at_end() && std::isdigit(static_cast<unsigned char>(peek())) != 0) {
        digits += peek();
        ++fraction_digits;
        advance();
      }
    }
    if (digits.empty()) throw error(start, "expected a number, found " + describe_here());
    if (digits.size() > kMaxDigits)
      throw error(start, "number with more than " + std::to_string(kMaxDigits) + " digits");
    long exponent = 0;
    if (peek() == 'e' || peek() == 'E') {
      advance();
      bool exp_negative = false;
      if (peek() == '+' || peek() == '-') {
        exp_negative = peek() == '-';
        advance();
      }
      std::size_t exp_digits = 0;
      while (!at_end() && std::isdigit(static_cast<unsigned char>(peek())) != 0) {
        if (exponent <= kMaxExponent) exponent = exponent * 10 + (peek() - '0');
        ++exp_digits;
        advance();
      }
      if (exp_digits == 0)
        throw error(here(), "expected exponent digits, found " + describe_here());
      if (exponent > kMaxExponent)
        throw error(start, "exponent beyond +-" + std::to_string(kMaxExponent));
      if (exp_negative) exponent = -exponent;
    }
    // value = digits * 10^(exponent - fraction_digits)
    const long scale = exponent - fraction_digits;
    mpz_t m, p;
    mpz_init_set_str(m, digits.c_str(), 10);
    if (negative) mpz_neg(m, m);
    mpz_init(p);
    mpz_ui_pow_ui(p, 10, static_cast<unsigned long>(scale < 0 ? -scale : scale));
    ExactNumber value;
    if (scale >= 0) {
      mpz_mul(m, m, p);
      mpq_set_z(value.mpq(), m);
    } else {
      mpq_set_num(value.mpq(), m);
      mpq_set_den(value.mpq(), p);
      mpq_canonicalize(value.mpq());
    }
    mpz_clear(m);
    mpz_clear(p);
    if (value >= ExactNumber(32768) || value < ExactNumber(-32768))
      throw error(start, "coordinate outside [-32768, 32768), the range of the kernel's "
                         "fixed-point walls");
    return value;
  }

  std::string_view text_;
  const std::string& source_;
  std::size_t i_ = 0;
  Position pos_;
};

std::string coordinate_text(const ExactNumber& v) {
  std::string s = decimal_text(v);
  if (s.empty())
    throw std::invalid_argument("WKT: coordinate " + fraction_text(v) +
                                " has no finite decimal expansion");
  return s;
}

void write_ring(std::string& out, const ExactPolygon& ring) {
  out += '(';
  auto point = [&](const ExactPoint& p) {
    out += coordinate_text(p.x());
    out += ' ';
    out += coordinate_text(p.y());
  };
  for (const auto& p : ring.vertices()) {
    point(p);
    out += ", ";
  }
  point(*ring.vertices_begin());
  out += ')';
}

} // namespace

Arena read_wkt(std::string_view text, const std::string& source) {
  return Reader(text, source).read();
}

Arena read_wkt_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw kernel::InputError(path.string(), "cannot open the WKT file for reading");
  constexpr std::size_t kMaxBytes = std::size_t{64} << 20;
  std::string text;
  char buf[65536];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    text.append(buf, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxBytes)
      throw kernel::InputError(path.string(), "WKT file larger than 64 MiB");
  }
  if (in.bad()) throw kernel::InputError(path.string(), "read error");
  return read_wkt(text, path.string());
}

std::string write_wkt(const Arena& arena) {
  const auto& polygon = exact_polygon(arena);
  std::string out = "POLYGON (";
  write_ring(out, polygon.outer_boundary());
  for (auto it = polygon.holes_begin(); it != polygon.holes_end(); ++it) {
    out += ", ";
    write_ring(out, *it);
  }
  out += ")";
  return out;
}

} // namespace antkit::geometry
