#include "text_lines.hpp"

#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/stc/path_format.hpp>
#include <antkit/testing/run_audit.hpp>
#include <antkit/testing/stc_audit.hpp>
#include <array>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <utility>

namespace antkit::testing {

using kernel::Cell;
using kernel::InputError;
using kernel::Occupancy;
using kernel::OccupancyGrid;

namespace {

constexpr std::size_t kMaxPositions = std::size_t{1} << 28;
constexpr std::size_t kMissedSample = 16;

std::int64_t manhattan(Cell a, Cell b) {
  return std::llabs(std::int64_t{a.x} - b.x) + std::llabs(std::int64_t{a.y} - b.y);
}

// The JSON forms, read by nlohmann's SAX interface: no document is built, so a tour of millions
// of positions costs its own vector only.
class TourSax : public nlohmann::json_sax<nlohmann::json> {
public:
  TourSax(std::string_view text, const std::string& source, TourFile& out)
      : text_(text), source_(source), out_(out) {}

  bool null() override { return value("null"); }
  bool boolean(bool) override { return value("a boolean"); }
  bool number_integer(number_integer_t v) override { return integer(v); }
  bool number_unsigned(number_unsigned_t v) override {
    return v > static_cast<number_unsigned_t>(std::numeric_limits<std::int64_t>::max())
               ? integer(std::numeric_limits<std::int64_t>::max())
               : integer(static_cast<std::int64_t>(v));
  }
  bool number_float(number_float_t, const string_t&) override {
    return value("a number that is not whole");
  }
  bool string(string_t&) override { return value("a string"); }
  bool binary(binary_t&) override { return value("binary data"); }
  bool start_object(std::size_t) override {
    if (frames_.empty()) {
      frames_.push_back({Role::Top, 0});
      return true;
    }
    value("an object");
    frames_.push_back({Role::Ignore, 0});
    return true;
  }
  bool key(string_t& k) override {
    if (frames_.size() == 1 && frames_.back().role == Role::Top) {
      key_ = k;
      if ((k == "path" && seen_path_) || (k == "start" && seen_start_))
        fail("", "\"" + k + "\" appears twice");
    }
    return true;
  }
  bool end_object() override {
    if (frames_.back().role == Role::Top && !seen_path_)
      fail("", "no \"path\": expected [[x, y], ...] or an object with \"path\", as antkit stc "
               "prints it");
    frames_.pop_back();
    return true;
  }
  bool start_array(std::size_t) override {
    if (frames_.empty()) {
      frames_.push_back({Role::Path, 0});
      seen_path_ = true;
      return true;
    }
    Frame& parent = frames_.back();
    if (parent.role == Role::Top && key_ == "path") {
      seen_path_ = true;
      frames_.push_back({Role::Path, 0});
    } else if (parent.role == Role::Top && key_ == "start") {
      seen_start_ = true;
      frames_.push_back({Role::Start, 0});
    } else if (parent.role == Role::Path) {
      if (out_.path.size() >= kMaxPositions) fail(where(), "more than 2^28 positions");
      frames_.push_back({Role::Pair, 0});
    } else if (parent.role == Role::Pair || parent.role == Role::Start) {
      value("an array");
    } else {
      frames_.push_back({Role::Ignore, 0});
    }
    return true;
  }
  bool end_array() override {
    const Frame f = frames_.back();
    if ((f.role == Role::Pair || f.role == Role::Start) && f.count != 2)
      fail(where(),
           "expected [x, y], two whole numbers; this array has " + std::to_string(f.count));
    if (f.role == Role::Pair) out_.path.push_back(pair_);
    if (f.role == Role::Start) out_.start = pair_;
    frames_.pop_back();
    return true;
  }
  bool parse_error(std::size_t position, const std::string&,
                   const nlohmann::detail::exception& e) override {
    const auto [line, column] = kernel::position_of(text_, position == 0 ? 0 : position - 1);
    throw InputError(source_, line, column, "JSON: " + detail::json_message(e.what()));
  }

private:
  enum class Role : std::uint8_t { Top, Path, Pair, Start, Ignore };
  struct Frame {
    Role role;
    int count;
  };

  std::string where() const {
    for (auto it = frames_.rbegin(); it != frames_.rend(); ++it)
      if (it->role == Role::Start) return "start";
    return "path[" + std::to_string(out_.path.size()) + "]";
  }
  [[noreturn]] void fail(const std::string& at, const std::string& message) const {
    throw InputError(source_, at.empty() ? message : at + ": " + message);
  }
  bool value(const std::string& what) {
    if (frames_.empty()) fail("", "expected [[x, y], ...] or an object with \"path\", not " + what);
    const Role r = frames_.back().role;
    if (r == Role::Pair || r == Role::Start) fail(where(), "expected a whole number, not " + what);
    if (r == Role::Path) fail(where(), "expected [x, y], not " + what);
    if (r == Role::Top && (key_ == "path" || key_ == "start"))
      fail(key_, "expected " + std::string(key_ == "path" ? "[[x, y], ...]" : "[x, y]") + ", not " +
                     what);
    return true;
  }
  bool integer(std::int64_t v) {
    if (frames_.empty() ||
        (frames_.back().role != Role::Pair && frames_.back().role != Role::Start))
      return value("a number");
    Frame& f = frames_.back();
    if (v < std::numeric_limits<std::int32_t>::min() ||
        v > std::numeric_limits<std::int32_t>::max())
      fail(where(), std::to_string(v) + " is outside [-2^31, 2^31)");
    if (f.count < 2) (f.count == 0 ? pair_.x : pair_.y) = static_cast<std::int32_t>(v);
    ++f.count;
    return true;
  }

  std::string_view text_;
  const std::string& source_;
  TourFile& out_;
  std::vector<Frame> frames_;
  std::string key_;
  bool seen_path_ = false, seen_start_ = false;
  Cell pair_{};
};

using detail::blank;

// CSV: "x,y" (or, by its header or `order`, "row,col") per line.
TourFile read_csv(std::string_view text, const std::string& source, TourOrder order) {
  TourFile out;
  out.order = order;
  kernel::TextLines lines(text);
  bool first = true;
  while (const auto next = lines.next()) {
    const std::string_view l = next->text;
    const std::size_t line = next->number;
    std::size_t i = 0;
    auto col = [&] { return i + 1; };
    auto skip = [&] {
      while (i < l.size() && blank(l[i])) ++i;
    };
    skip();
    if (i == l.size()) continue; // blank line
    if (first) {
      first = false;
      if (detail::is_header(l, "x,y") || detail::is_header(l, "row,col") ||
          detail::is_header(l, "y,x")) {
        out.order = detail::is_header(l, "x,y") ? TourOrder::XY : TourOrder::RowCol;
        out.order_from_header = true;
        continue;
      }
    }
    std::array<std::int32_t, 2> v{};
    for (int k = 0; k < 2; ++k) {
      skip();
      const std::size_t from = i;
      const detail::Whole n = detail::scan_whole(l, i, /*plus=*/true);
      if (!n.digits) {
        i = from;
        throw InputError(source, line, col(),
                         k == 0 ? (out.order == TourOrder::XY ? "expected x,y (two whole numbers)"
                                                              : "expected row,col (two whole "
                                                                "numbers)")
                                : (out.order == TourOrder::XY ? "expected y after the comma"
                                                              : "expected col after the comma"));
      }
      if (n.overflow || n.value < std::numeric_limits<std::int32_t>::min() ||
          n.value > std::numeric_limits<std::int32_t>::max()) {
        i = from;
        throw InputError(source, line, col(), "a coordinate outside [-2^31, 2^31)");
      }
      v[static_cast<std::size_t>(k)] = static_cast<std::int32_t>(n.value);
      skip();
      if (k == 0) {
        if (i == l.size() || l[i] != ',') throw InputError(source, line, col(), "expected ','");
        ++i;
      }
    }
    if (i != l.size())
      throw InputError(source, line, col(),
                       out.order == TourOrder::XY ? "unexpected text after x,y"
                                                  : "unexpected text after row,col");
    if (out.path.size() >= kMaxPositions)
      throw InputError(source, line, 1, "more than 2^28 positions");
    out.path.push_back(out.order == TourOrder::XY ? Cell{v[0], v[1]} : Cell{v[1], v[0]});
  }
  return out;
}

} // namespace

std::string_view tour_order_name(TourOrder order) noexcept {
  return order == TourOrder::XY ? "xy" : "rc";
}

std::string_view tour_rule_name(TourRule rule) noexcept {
  return rule == TourRule::ExactlyOnce ? "exactly-once" : "coverage";
}

StcAudit audit_stc_tour(const OccupancyGrid& map, Cell start, std::span<const Cell> path,
                        TourRule rule) {
  StcAudit a;
  a.rule = rule;
  if (path.size() > 1 && path.back() == path.front()) {
    a.closed_form = true;
    path = path.first(path.size() - 1);
  }
  a.positions = static_cast<std::int64_t>(path.size());
  StcTourChecker checker;
  std::vector<std::uint8_t> allowed;
  a.reachable = checker.reachable_subcells(map, start, rule == TourRule::ExactlyOnce, allowed);
  std::vector<std::uint8_t> seen(map.size(), 0);
  std::int64_t distinct = 0;
  for (std::size_t i = 0; i < path.size(); ++i) {
    const Cell s = path[i];
    if (i > 0 && manhattan(path[i - 1], s) != 1) ++a.illegal_moves;
    if (!map.in_bounds(s) || !allowed[map.index(s)]) {
      ++a.off_limits;
      if (map.in_bounds(s) && !seen[map.index(s)]++) ++distinct;
      continue;
    }
    if (seen[map.index(s)]++) {
      ++a.repeats;
    } else {
      ++a.covered;
      ++distinct;
    }
  }
  a.missed = a.reachable - a.covered;
  for (std::int32_t y = 0; y < map.height() && a.missed_sample.size() < kMissedSample; ++y)
    for (std::int32_t x = 0; x < map.width() && a.missed_sample.size() < kMissedSample; ++x)
      if (allowed[map.index({x, y})] && !seen[map.index({x, y})]) a.missed_sample.push_back({x, y});
  a.end_distance = path.empty() ? 0 : manhattan(path.back(), start);
  a.first = rule == TourRule::ExactlyOnce
                ? checker.check_exact(map, start, path)
                : checker.check_full(map, start, path, a.positions - distinct);
  return a;
}

TourFile read_tour(std::string_view text, const std::string& source, TourOrder order) {
  if (stc::path_format::is_binary(text)) {
    auto d = stc::path_format::decode(text, source, kMaxPositions);
    return {std::move(d.path), d.start};
  }
  std::size_t i = 0;
  while (i < text.size() && (blank(text[i]) || text[i] == '\n' || text[i] == '\r')) ++i;
  if (i == text.size()) throw InputError(source, "empty: no tour");
  if (text[i] != '[' && text[i] != '{') return read_csv(text, source, order);
  TourFile out;
  TourSax sax(text, source, out);
  nlohmann::json::sax_parse(text.begin(), text.end(), &sax);
  out.order = order;
  if (order == TourOrder::RowCol) { // JSON pairs as [row, col]
    for (auto& p : out.path) std::swap(p.x, p.y);
    if (out.start) std::swap(out.start->x, out.start->y);
  }
  return out;
}

TourFile read_tour_file(const std::filesystem::path& path, TourOrder order) {
  return read_tour(read_text_file(path, "tour", std::size_t{1} << 30), path.string(), order);
}

StcCheckReport check_stc_files(const StcCheckRequest& request) {
  return check_stc(maps::load_map(request.map_file),
                   read_tour_file(request.tour_file, request.order), request);
}

StcCheckReport check_stc(maps::GridMap map, const TourFile& tour, const StcCheckRequest& request) {
  StcCheckReport r;
  r.order = tour.order;
  r.order_from_header = tour.order_from_header;
  r.cells = request.cells;
  // With `cells`, the places the request names (the start, the map's and the tour file's start)
  // are cells; the map is checked in sub-cells, 2 x 2 per cell.
  const OccupancyGrid cells_map = map.cells;
  if (request.cells) {
    if (cells_map.width() > (1 << 29) || cells_map.height() > (1 << 29))
      throw InputError(request.map_file, "too large to split into sub-cells");
    OccupancyGrid sub(2 * cells_map.width(), 2 * cells_map.height(), Occupancy::Blocked);
    for (std::int32_t y = 0; y < sub.height(); ++y)
      for (std::int32_t x = 0; x < sub.width(); ++x)
        sub[{x, y}] =
            cells_map[{x / 2, y / 2}] == Occupancy::Free ? Occupancy::Free : Occupancy::Blocked;
    map.cells = std::move(sub);
  }
  r.width = map.cells.width();
  r.height = map.cells.height();
  const OccupancyGrid& named = request.cells ? cells_map : map.cells;
  const std::string unit = request.cells ? "cell" : "sub-cell";
  auto require_free = [&](Cell s, const std::string& where) {
    if (!named.in_bounds(s))
      throw InputError(where, "the start (" + std::to_string(s.x) + ", " + std::to_string(s.y) +
                                  ") is outside the " + std::to_string(named.width()) + "x" +
                                  std::to_string(named.height()) + " map");
    if (named[s] != Occupancy::Free)
      throw InputError(where, "the start (" + std::to_string(s.x) + ", " + std::to_string(s.y) +
                                  ") is not a free " + unit + " of the map");
  };
  std::optional<Cell> start;
  if (request.start) {
    start = *request.start;
    r.start_from = "--start";
    require_free(*start, "--start");
  } else if (tour.start) {
    start = *tour.start;
    r.start_from = "tour file";
    require_free(*start, request.tour_file);
  } else if (map.start) {
    start = *map.start;
    r.start_from = "map";
  } else if (!tour.path.empty()) {
    r.start = tour.path.front();
    r.start_from = "first position";
  } else {
    throw InputError(request.tour_file, "the tour is empty and no start is given");
  }
  if (start && request.cells) {
    // The tour may begin in any sub-cell of the start cell: that sub-cell is the start.
    r.start_cell = *start;
    r.start = {2 * start->x, 2 * start->y};
    if (!tour.path.empty()) {
      const Cell first = tour.path.front();
      if (first.x / 2 == start->x && first.y / 2 == start->y && first.x >= 0 && first.y >= 0)
        r.start = first;
    }
  } else if (start) {
    r.start = *start;
  } else if (request.cells) {
    r.start_cell = Cell{r.start.x / 2, r.start.y / 2};
  }
  r.audit = audit_stc_tour(map.cells, r.start, tour.path, request.rule);
  return r;
}

} // namespace antkit::testing
