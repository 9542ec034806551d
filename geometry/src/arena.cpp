// Arena: validation, normalisation and the exact measures of a polygon with holes.
#include <CGAL/box_intersection_d.h>
#include <algorithm>
#include <antkit/geometry/arena.hpp>
#include <antkit/geometry/arena_cgal.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cmath>
#include <gmp.h>
#include <limits>
#include <utility>

namespace antkit::geometry {

struct Arena::Impl {
  ExactPolygonWithHoles polygon;
};

Arena::Arena(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}
Arena::~Arena() = default;

const ExactPolygonWithHoles& exact_polygon(const Arena& arena) {
  return arena.impl().polygon;
}

// ---- exact rational helpers -------------------------------------------------------------------

CGAL::Gmpz floor_of(const ExactNumber& q) {
  CGAL::Gmpz z;
  mpz_fdiv_q(z.mpz(), mpq_numref(q.mpq()), mpq_denref(q.mpq()));
  return z;
}

CGAL::Gmpz ceil_of(const ExactNumber& q) {
  CGAL::Gmpz z;
  mpz_cdiv_q(z.mpz(), mpq_numref(q.mpq()), mpq_denref(q.mpq()));
  return z;
}

namespace {
std::string mpz_text(mpz_srcptr z) {
  std::string s(mpz_sizeinbase(z, 10) + 2, '\0');
  mpz_get_str(s.data(), 10, z);
  s.resize(std::char_traits<char>::length(s.c_str()));
  return s;
}
} // namespace

std::string fraction_text(const ExactNumber& q) {
  // Gmpq keeps itself canonical (lowest terms, positive denominator).
  return mpz_text(mpq_numref(q.mpq())) + "/" + mpz_text(mpq_denref(q.mpq()));
}

std::string decimal_text(const ExactNumber& q) {
  // q = n / d with d = 2^a 5^b: q = n * 2^(k-a) 5^(k-b) / 10^k with k = max(a, b).
  mpz_t rest, scaled;
  mpz_init_set(rest, mpq_denref(q.mpq()));
  const auto a = mpz_scan1(rest, 0);
  mpz_tdiv_q_2exp(rest, rest, a);
  unsigned long b = 0;
  while (mpz_divisible_ui_p(rest, 5) != 0) {
    mpz_divexact_ui(rest, rest, 5);
    ++b;
  }
  const bool terminating = mpz_cmp_ui(rest, 1) == 0;
  std::string text;
  if (terminating) {
    const unsigned long k = std::max<unsigned long>(a, b);
    mpz_init_set(scaled, mpq_numref(q.mpq()));
    mpz_mul_2exp(scaled, scaled, k - a);
    mpz_t five;
    mpz_init(five);
    mpz_ui_pow_ui(five, 5, k - b);
    mpz_mul(scaled, scaled, five);
    mpz_clear(five);
    const bool negative = mpz_sgn(scaled) < 0;
    mpz_abs(scaled, scaled);
    std::string digits = mpz_text(scaled);
    if (digits.size() <= k) digits.insert(0, k + 1 - digits.size(), '0');
    if (k > 0) digits.insert(digits.end() - static_cast<std::ptrdiff_t>(k), '.');
    if (negative) digits.insert(digits.begin(), '-');
    text = std::move(digits);
    mpz_clear(scaled);
  }
  mpz_clear(rest);
  return text;
}

// ---- validation --------------------------------------------------------------------------------

namespace {

std::string ring_name(std::size_t ring) {
  return ring == 0 ? std::string("outer boundary") : "hole " + std::to_string(ring);
}

std::string point_text(const ExactPoint& p) {
  return "(" + std::to_string(CGAL::to_double(p.x())) + " " +
         std::to_string(CGAL::to_double(p.y())) + ")";
}

// A simple ring: >= 3 vertices, no repeated vertex, edges meet only at shared consecutive vertices.
// CGAL::Polygon_2::is_simple is exact on Gmpq and runs a sweep (O(n log n)).
void check_ring(ExactPolygon& ring, std::size_t index, const std::string& where) {
  if (ring.size() < 3)
    throw kernel::InputError(where, ring_name(index) + " has " + std::to_string(ring.size()) +
                                        " distinct vertices; a ring needs at least 3");
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const auto& p = ring[i];
    const auto& q = ring[(i + 1) % ring.size()];
    if (p == q)
      throw kernel::InputError(where, ring_name(index) + " repeats vertex " +
                                          std::to_string(i + 1) + " " + point_text(p) +
                                          "; expected distinct consecutive vertices");
  }
  if (!ring.is_simple())
    throw kernel::InputError(where, ring_name(index) +
                                        " is not simple (two of its edges cross or touch, or a "
                                        "vertex repeats); expected a simple polygon");
  // A simple polygon with three or more distinct vertices can still have zero area only if all
  // vertices are collinear, which is_simple rejects; the orientation is therefore defined.
  const auto orientation = ring.orientation();
  const bool want_ccw = index == 0;
  if ((orientation == CGAL::COUNTERCLOCKWISE) != want_ccw) {
    // Reverse keeping the first vertex first: v0, v(n-1), ..., v1.
    std::vector<ExactPoint> points(ring.vertices_begin(), ring.vertices_end());
    std::reverse(points.begin() + 1, points.end());
    ring = ExactPolygon(points.begin(), points.end());
  }
}

// No two different rings meet, not even at one point. The candidate edge pairs come from
// CGAL::box_intersection_d over conservative boxes of the edges (interval bounds of the exact
// coordinates), each pair then decided by the exact do_intersect.
void check_rings_apart(const std::vector<const ExactPolygon*>& rings, const std::string& where) {
  using Box =
      CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::pair<std::size_t, std::size_t>>;
  std::vector<Box> boxes;
  using EdgeId = std::pair<std::size_t, std::size_t>;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const auto& ring = *rings[r];
    for (std::size_t e = 0; e < ring.size(); ++e)
      boxes.emplace_back(ring.edge(e).bbox(), EdgeId{r, e});
  }
  bool found = false;
  std::pair<std::size_t, std::size_t> culprit{};
  auto callback = [&](const Box& a, const Box& b) {
    if (found || a.info().first == b.info().first) return;
    const auto sa = rings[a.info().first]->edge(a.info().second);
    const auto sb = rings[b.info().first]->edge(b.info().second);
    if (CGAL::do_intersect(sa, sb)) {
      found = true;
      culprit = std::minmax(a.info().first, b.info().first);
    }
  };
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), callback);
  if (found)
    throw kernel::InputError(where, ring_name(culprit.first) + " and " + ring_name(culprit.second) +
                                        " meet; expected holes strictly inside the outer "
                                        "boundary and apart from each other");
}

} // namespace

Arena make_arena(ExactPolygonWithHoles polygon, const std::string& where) {
  std::vector<ExactPolygon> holes(polygon.holes_begin(), polygon.holes_end());
  ExactPolygon outer = polygon.outer_boundary();
  check_ring(outer, 0, where);
  for (std::size_t h = 0; h < holes.size(); ++h) check_ring(holes[h], h + 1, where);

  std::vector<const ExactPolygon*> rings{&outer};
  for (const auto& hole : holes) rings.push_back(&hole);
  check_rings_apart(rings, where);
  // With no two rings meeting, a ring is inside another iff any one of its vertices is.
  for (std::size_t h = 0; h < holes.size(); ++h) {
    const auto& v = holes[h][0];
    if (outer.bounded_side(v) != CGAL::ON_BOUNDED_SIDE)
      throw kernel::InputError(where, ring_name(h + 1) +
                                          " is not inside the outer boundary; expected every hole "
                                          "strictly inside it");
    for (std::size_t g = 0; g < holes.size(); ++g)
      if (g != h && holes[g].bounded_side(v) == CGAL::ON_BOUNDED_SIDE)
        throw kernel::InputError(where, ring_name(h + 1) + " lies inside " + ring_name(g + 1) +
                                            "; expected holes apart from each other");
  }

  auto impl = std::make_shared<Arena::Impl>();
  impl->polygon = ExactPolygonWithHoles(outer, holes.begin(), holes.end());
  return Arena(std::move(impl));
}

// ---- measures -----------------------------------------------------------------------------------

namespace {
template <class F>
void for_each_ring(const ExactPolygonWithHoles& p, F&& f) {
  f(p.outer_boundary());
  for (auto it = p.holes_begin(); it != p.holes_end(); ++it) f(*it);
}

ExactNumber exact_area(const ExactPolygonWithHoles& p) {
  ExactNumber sum = 0;
  // Holes are clockwise, so their signed areas are negative: the sum is the free area.
  for_each_ring(p, [&](const ExactPolygon& ring) { sum += ring.area(); });
  return sum;
}
} // namespace

std::size_t Arena::vertex_count() const {
  std::size_t n = 0;
  for_each_ring(impl_->polygon, [&](const ExactPolygon& ring) { n += ring.size(); });
  return n;
}

std::size_t Arena::hole_count() const {
  return impl_->polygon.number_of_holes();
}

double Arena::area() const {
  return CGAL::to_double(exact_area(impl_->polygon));
}

std::string Arena::area_exact() const {
  return fraction_text(exact_area(impl_->polygon));
}

double Arena::perimeter() const {
  double sum = 0;
  for_each_ring(impl_->polygon, [&](const ExactPolygon& ring) {
    for (auto e = ring.edges_begin(); e != ring.edges_end(); ++e)
      sum += std::sqrt(CGAL::to_double(e->squared_length()));
  });
  return sum;
}

BoundingBox Arena::bbox() const {
  // The holes lie inside the outer boundary, so its extreme vertices are the arena's.
  const auto& outer = impl_->polygon.outer_boundary();
  return {CGAL::to_double(outer.left_vertex()->x()), CGAL::to_double(outer.bottom_vertex()->y()),
          CGAL::to_double(outer.right_vertex()->x()), CGAL::to_double(outer.top_vertex()->y())};
}

std::vector<std::vector<std::array<double, 2>>> Arena::rings() const {
  std::vector<std::vector<std::array<double, 2>>> out;
  for_each_ring(impl_->polygon, [&](const ExactPolygon& ring) {
    auto& r = out.emplace_back();
    for (const auto& p : ring.vertices())
      r.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y())});
  });
  return out;
}

namespace {
kernel::Fx to_fx(const ExactNumber& v) {
  // floor(v * 65536 + 1/2): round half up, exactly.
  const CGAL::Gmpz raw = floor_of(v * ExactNumber(65536) + ExactNumber(1, 2));
  if (mpz_cmp_si(raw.mpz(), std::numeric_limits<std::int32_t>::min()) < 0 ||
      mpz_cmp_si(raw.mpz(), std::numeric_limits<std::int32_t>::max()) > 0)
    throw kernel::InputError("arena", "coordinate " + std::to_string(CGAL::to_double(v)) +
                                          " is outside the Q15.16 range [-32768, 32768) of the "
                                          "kernel's fixed-point walls");
  return kernel::Fx::from_raw(static_cast<std::int32_t>(mpz_get_si(raw.mpz())));
}
} // namespace

std::vector<kernel::FxSegment> Arena::walls_fx() const {
  std::vector<kernel::FxSegment> walls;
  walls.reserve(vertex_count());
  for_each_ring(impl_->polygon, [&](const ExactPolygon& ring) {
    std::vector<kernel::FxPoint> points;
    for (const auto& p : ring.vertices()) points.push_back({to_fx(p.x()), to_fx(p.y())});
    for (std::size_t i = 0; i < points.size(); ++i)
      walls.push_back({points[i], points[(i + 1) % points.size()]});
  });
  return walls;
}

bool operator==(const Arena& a, const Arena& b) {
  const auto& p = a.impl().polygon;
  const auto& q = b.impl().polygon;
  if (p.number_of_holes() != q.number_of_holes()) return false;
  if (p.outer_boundary().container() != q.outer_boundary().container()) return false;
  return std::equal(
      p.holes_begin(), p.holes_end(), q.holes_begin(),
      [](const ExactPolygon& x, const ExactPolygon& y) { return x.container() == y.container(); });
}

} // namespace antkit::geometry
