// Exact rasterization of an arena (arena_raster.hpp): one scanline per row through the cell
// centres. On the scanline y = Y, the crossings of the walls with the half-open rule (an edge
// counts when min(y) <= Y < max(y)) split the line into intervals that alternate outside / inside
// for every point that is not on a wall (the crossing-number theorem; the half-open rule counts a
// vertex on the line once or twice consistently). Points on a wall are then removed: the crossings
// themselves (open intervals), and every vertex and horizontal edge lying on the line (closed
// intervals). Each interval end becomes a cell index by an exact floor or ceiling, so the grid is
// exactly the one that testing every centre with an exact point-in-polygon predicate would give,
// at the cost of a few rational operations per row instead of per cell.
#include <algorithm>
#include <antkit/geometry/arena_cgal.hpp>
#include <antkit/geometry/arena_raster.hpp>
#include <antkit/kernel/input_error.hpp>
#include <charconv>
#include <gmp.h>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace antkit::geometry {

CellSize::CellSize(std::int64_t num, std::int64_t den) : num_(num), den_(den) {
  if (num <= 0 || den <= 0) throw std::invalid_argument("CellSize: num and den must be positive");
  const auto g = std::gcd(num_, den_);
  num_ /= g;
  den_ /= g;
}

double CellSize::value() const noexcept {
  return static_cast<double>(num_) / static_cast<double>(den_);
}

CellSize CellSize::parse(std::string_view text, const std::string& where) {
  auto bad = [&](const std::string& why) {
    return kernel::InputError(where, "cell size '" + std::string(text.substr(0, 40)) + "' " + why);
  };
  std::size_t i = 0;
  std::string digits;
  long fraction = 0;
  while (i < text.size() && text[i] >= '0' && text[i] <= '9') digits += text[i++];
  if (i < text.size() && text[i] == '.') {
    ++i;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') digits += text[i++], ++fraction;
  }
  long exponent = 0;
  if (!digits.empty() && i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    bool negative = false;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) negative = text[i++] == '-';
    const auto* first = text.data() + i;
    const auto result = std::from_chars(first, text.data() + text.size(), exponent);
    if (result.ec != std::errc() || result.ptr == first || exponent < 0 || exponent > 30)
      throw bad("has a bad exponent; expected a positive decimal such as 1, 0.25 or 1e-2");
    i = static_cast<std::size_t>(result.ptr - text.data());
    if (negative) exponent = -exponent;
  }
  if (digits.empty() || i != text.size())
    throw bad("is not a positive decimal; expected e.g. 1, 0.25 or 1e-2");
  const auto significant = digits.find_first_not_of('0');
  if (significant == std::string::npos) throw bad("is zero; expected a positive size");
  if (digits.size() - significant > 18) throw bad("has more than 18 significant digits");
  const long scale = exponent - fraction;
  ExactNumber value(CGAL::Gmpz(digits.substr(significant)));
  mpz_t p;
  mpz_init(p);
  mpz_ui_pow_ui(p, 10, static_cast<unsigned long>(scale < 0 ? -scale : scale));
  ExactNumber power;
  mpq_set_z(power.mpq(), p);
  mpz_clear(p);
  value = scale < 0 ? value / power : value * power;
  if (value < ExactNumber(1, 1000000) || value > ExactNumber(1000000))
    throw bad("is outside [1e-6, 1e6]");
  const auto* q = value.mpq();
  if (mpz_fits_slong_p(mpq_numref(q)) == 0 || mpz_fits_slong_p(mpq_denref(q)) == 0)
    throw bad("has too many digits");
  return {mpz_get_si(mpq_numref(q)), mpz_get_si(mpq_denref(q))};
}

std::array<double, 2> RasterFrame::centre(kernel::Cell c) const {
  const double size = cell.value();
  return {(static_cast<double>(col0 + c.x) + 0.5) * size,
          (static_cast<double>(row0 - c.y) - 0.5) * size};
}

namespace {

std::int64_t to_int64(const CGAL::Gmpz& z) {
  return mpz_get_si(z.mpz());
}

struct Edge {
  ExactPoint p, q; // exact endpoints
  double ylo, yhi; // a conservative double range of y over the edge
  bool horizontal;
};

} // namespace

ArenaRaster rasterize(const Arena& arena, CellSize cell, std::size_t max_cells,
                      const std::string& where) {
  const auto& polygon = exact_polygon(arena);
  const auto& outer = polygon.outer_boundary();
  const ExactNumber c(static_cast<long>(cell.num()), static_cast<unsigned long>(cell.den()));

  // The frame: grid edges snapped outward to multiples of c. |coordinate| < 2^15 and c >= 1e-6
  // keep every index below 2^36, so int64 holds them.
  const auto col0 = floor_of(outer.left_vertex()->x() / c);
  const auto col1 = ceil_of(outer.right_vertex()->x() / c);
  const auto row0 = ceil_of(outer.top_vertex()->y() / c);
  const auto row1 = floor_of(outer.bottom_vertex()->y() / c);
  const std::int64_t width = to_int64(col1) - to_int64(col0);
  const std::int64_t height = to_int64(row0) - to_int64(row1);
  if (width > kernel::kMaxGridSide || height > kernel::kMaxGridSide ||
      static_cast<std::size_t>(width) * static_cast<std::size_t>(height) > max_cells)
    throw kernel::InputError(where, "a raster of " + std::to_string(width) + " x " +
                                        std::to_string(height) + " cells exceeds the limit of " +
                                        std::to_string(max_cells) + " cells (side at most " +
                                        std::to_string(kernel::kMaxGridSide) +
                                        "); choose a larger cell size");

  ArenaRaster out;
  out.frame.cell = cell;
  out.frame.col0 = to_int64(col0);
  out.frame.row0 = to_int64(row0);
  out.grid = kernel::OccupancyGrid(static_cast<std::int32_t>(width),
                                   static_cast<std::int32_t>(height), kernel::Occupancy::Blocked);

  std::vector<Edge> edges;
  auto add_ring = [&](const ExactPolygon& ring) {
    for (auto e = ring.edges_begin(); e != ring.edges_end(); ++e) {
      const auto a = CGAL::to_interval(e->source().y());
      const auto b = CGAL::to_interval(e->target().y());
      edges.push_back({e->source(), e->target(), std::min(a.first, b.first),
                       std::max(a.second, b.second), e->source().y() == e->target().y()});
    }
  };
  add_ring(outer);
  for (auto h = polygon.holes_begin(); h != polygon.holes_end(); ++h) add_ring(*h);

  // Rows go downward (decreasing Y): edges enter the active list in order of their top.
  std::vector<std::size_t> by_top(edges.size());
  std::iota(by_top.begin(), by_top.end(), std::size_t{0});
  std::sort(by_top.begin(), by_top.end(),
            [&](std::size_t a, std::size_t b) { return edges[a].yhi > edges[b].yhi; });
  std::size_t next = 0;
  std::vector<std::size_t> active;

  // centre x of column i is (col0 + i + 1/2) c, so "centre x > a" is "i > a / c - col0 - 1/2".
  const ExactNumber shift = ExactNumber(col0) + ExactNumber(1, 2);
  auto column_of = [&](const ExactNumber& x) { return x / c - shift; };
  auto clamp = [&](std::int64_t i) { return std::clamp<std::int64_t>(i, 0, width); };

  std::vector<ExactNumber> crossings;
  std::vector<std::pair<ExactNumber, ExactNumber>> on_wall; // closed x intervals
  for (std::int64_t j = 0; j < height; ++j) {
    // Y = (row0 - j - 1/2) c
    const ExactNumber y =
        (ExactNumber(row0) - ExactNumber(static_cast<long>(j)) - ExactNumber(1, 2)) * c;
    const auto yi = CGAL::to_interval(y);
    while (next < by_top.size() && edges[by_top[next]].yhi >= yi.first)
      active.push_back(by_top[next++]);
    // Drop edges wholly above the scanline: later rows are lower still.
    active.erase(std::remove_if(active.begin(), active.end(),
                                [&](std::size_t e) { return edges[e].ylo > yi.second; }),
                 active.end());
    crossings.clear();
    on_wall.clear();
    for (const std::size_t index : active) {
      const Edge& e = edges[index];
      if (e.horizontal) {
        if (e.p.y() == y)
          on_wall.emplace_back(CGAL::min(e.p.x(), e.q.x()), CGAL::max(e.p.x(), e.q.x()));
        continue;
      }
      // A vertex on the scanline is a wall point; each vertex is the source of exactly one edge.
      if (e.p.y() == y) on_wall.emplace_back(e.p.x(), e.p.x());
      const bool up = e.p.y() < e.q.y();
      const auto& lo = up ? e.p : e.q;
      const auto& hi = up ? e.q : e.p;
      if (lo.y() <= y && y < hi.y())
        crossings.push_back(lo.x() + (y - lo.y()) * (hi.x() - lo.x()) / (hi.y() - lo.y()));
    }
    std::sort(crossings.begin(), crossings.end());
    const auto row_begin = out.grid.cells().begin() + static_cast<std::ptrdiff_t>(j * width);
    auto set = [&](std::int64_t from, std::int64_t to, kernel::Occupancy value) {
      const auto a = clamp(from), b = clamp(to);
      if (a < b) std::fill(row_begin + a, row_begin + b, value);
    };
    for (std::size_t k = 0; k + 1 < crossings.size(); k += 2) {
      // Free: a < centre < b, i.e. floor(column_of(a)) + 1 <= i <= ceil(column_of(b)) - 1.
      const std::int64_t from = to_int64(floor_of(column_of(crossings[k]))) + 1;
      const std::int64_t to = to_int64(ceil_of(column_of(crossings[k + 1])));
      set(from, to, kernel::Occupancy::Free);
    }
    for (const auto& [a, b] : on_wall) {
      // Blocked: a <= centre <= b.
      const std::int64_t from = to_int64(ceil_of(column_of(a)));
      const std::int64_t to = to_int64(floor_of(column_of(b))) + 1;
      set(from, to, kernel::Occupancy::Blocked);
    }
  }
  return out;
}

} // namespace antkit::geometry
