// The kernel's integer segment predicates held against CGAL's exact predicates and constructions
// (CGAL is the oracle; it is used here only, never in the kernel).
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <antkit/kernel/segment.hpp>
#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <limits>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>
#include <variant>
#include <vector>

using antkit::kernel::classify;
using antkit::kernel::count_proper_crossings;
using antkit::kernel::Fx;
using antkit::kernel::FxPoint;
using antkit::kernel::FxSegment;
using antkit::kernel::kExactInt64Raw;
using antkit::kernel::orientation;
using antkit::kernel::orientation_in;
using antkit::kernel::properly_cross;
using antkit::kernel::SegmentRelation;

namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;

FxPoint raw_point(std::int32_t x, std::int32_t y) {
  return {Fx::from_raw(x), Fx::from_raw(y)};
}

// Raw coordinates are integers; CGAL gets them exactly (an int32 converts to its number type
// without loss), and a common scale factor changes no predicate.
K::Point_2 to_cgal(FxPoint p) {
  return {p.x.raw(), p.y.raw()};
}
K::Segment_2 to_cgal(const FxSegment& s) {
  return {to_cgal(s.a), to_cgal(s.b)};
}

// CGAL's answer in the kernel's terms, for non-degenerate segments: the intersection is empty, a
// segment of positive length (overlap), a point that is an endpoint of either (touching) or a point
// interior to both (a proper crossing).
SegmentRelation cgal_relation(const FxSegment& s, const FxSegment& t) {
  const K::Segment_2 cs = to_cgal(s), ct = to_cgal(t);
  if (!CGAL::do_intersect(cs, ct)) return SegmentRelation::Disjoint;
  const auto result = CGAL::intersection(cs, ct);
  if (const K::Segment_2* seg = boost::get<K::Segment_2>(&*result))
    return seg->is_degenerate() ? SegmentRelation::Touching : SegmentRelation::CollinearOverlap;
  const K::Point_2& p = *boost::get<K::Point_2>(&*result);
  if (p == cs.source() || p == cs.target() || p == ct.source() || p == ct.target())
    return SegmentRelation::Touching;
  return SegmentRelation::ProperCrossing;
}

// Coordinates drawn at three scales: a tiny lattice (collinear, touching and shared endpoints are
// common), around the edge of the 64-bit path's range, and the full int32 range (the 128-bit path).
std::int32_t coordinate(int scale) {
  switch (scale) {
  case 0:
    return *rc::gen::inRange(-3, 4);
  case 1: {
    const auto edge = *rc::gen::element(-kExactInt64Raw, kExactInt64Raw - 1);
    return edge + *rc::gen::inRange(-2, 3);
  }
  default:
    return *rc::gen::arbitrary<std::int32_t>();
  }
}

FxSegment random_segment(int scale) {
  const auto ax = coordinate(scale), ay = coordinate(scale);
  const auto bx = coordinate(scale), by = coordinate(scale);
  return {raw_point(ax, ay), raw_point(bx, by)};
}

bool degenerate(const FxSegment& s) {
  return s.a == s.b;
}

const char* name(SegmentRelation r) {
  switch (r) {
  case SegmentRelation::Disjoint:
    return "Disjoint";
  case SegmentRelation::Touching:
    return "Touching";
  case SegmentRelation::ProperCrossing:
    return "ProperCrossing";
  case SegmentRelation::CollinearOverlap:
    return "CollinearOverlap";
  }
  return "?";
}

std::uint64_t pair_loop(const std::vector<FxPoint>& a, const std::vector<FxPoint>& b) {
  std::uint64_t n = 0;
  for (std::size_t i = 0; i + 1 < a.size(); ++i)
    for (std::size_t j = 0; j + 1 < b.size(); ++j)
      n += properly_cross({a[i], a[i + 1]}, {b[j], b[j + 1]}) ? 1u : 0u;
  return n;
}

// A robot-like trail: a random walk of short steps (occasionally a long jump), on a lattice coarse
// enough that crossings, touchings and collinear runs all happen.
std::vector<FxPoint> trail(std::size_t n, std::int32_t step, std::int32_t unit) {
  std::vector<FxPoint> pts;
  std::int32_t x = *rc::gen::inRange(-20, 21), y = *rc::gen::inRange(-20, 21);
  for (std::size_t k = 0; k < n; ++k) {
    pts.push_back(raw_point(x * unit, y * unit));
    const bool jump = *rc::gen::inRange(0, 50) == 0;
    const std::int32_t reach = jump ? 40 : step;
    x = std::clamp(x + *rc::gen::inRange(-reach, reach + 1), -60, 60);
    y = std::clamp(y + *rc::gen::inRange(-reach, reach + 1), -60, 60);
  }
  return pts;
}

} // namespace

TEST_CASE("segment relations, worked examples", "[segment]") {
  auto seg = [](std::int32_t ax, std::int32_t ay, std::int32_t bx, std::int32_t by) {
    return FxSegment{{Fx::from_int(ax), Fx::from_int(ay)}, {Fx::from_int(bx), Fx::from_int(by)}};
  };
  CHECK(classify(seg(0, 0, 2, 2), seg(0, 2, 2, 0)) == SegmentRelation::ProperCrossing);
  CHECK(classify(seg(0, 0, 2, 0), seg(1, 0, 1, 5)) == SegmentRelation::Touching); // T-junction
  CHECK(classify(seg(0, 0, 2, 0), seg(2, 0, 3, 4)) == SegmentRelation::Touching); // shared end
  CHECK(classify(seg(0, 0, 2, 0), seg(2, 0, 5, 0)) == SegmentRelation::Touching); // end to end
  CHECK(classify(seg(0, 0, 2, 0), seg(1, 0, 5, 0)) == SegmentRelation::CollinearOverlap);
  CHECK(classify(seg(0, 0, 2, 0), seg(3, 0, 5, 0)) == SegmentRelation::Disjoint); // same line
  CHECK(classify(seg(0, 0, 2, 0), seg(0, 1, 2, 1)) == SegmentRelation::Disjoint); // parallel
  CHECK(classify(seg(0, 0, 2, 0), seg(1, 0, 1, 0)) == SegmentRelation::Touching); // a point on it
  CHECK(classify(seg(1, 1, 1, 1), seg(1, 1, 1, 1)) == SegmentRelation::Touching); // equal points
  CHECK(classify(seg(1, 1, 1, 1), seg(2, 2, 2, 2)) == SegmentRelation::Disjoint);
  CHECK(classify(seg(0, 0, 2, 0), seg(1, 1, 1, 1)) == SegmentRelation::Disjoint);
  CHECK(properly_cross(seg(0, 0, 2, 2), seg(0, 2, 2, 0)));
  CHECK(!properly_cross(seg(0, 0, 2, 0), seg(1, 0, 1, 5)));
  // Orientation convention: +1 for a left turn in a y-up frame.
  CHECK(orientation({Fx::from_int(0), Fx::from_int(0)}, {Fx::from_int(1), Fx::from_int(0)},
                    {Fx::from_int(0), Fx::from_int(1)}) == 1);
  // Extremes of the Fx range: differences need 33 bits and products 66 (the 128-bit path).
  const std::int32_t lo = std::numeric_limits<std::int32_t>::min();
  const std::int32_t hi = std::numeric_limits<std::int32_t>::max();
  CHECK(orientation(raw_point(lo, lo), raw_point(hi, hi), raw_point(hi, hi - 1)) == -1);
  CHECK(orientation(raw_point(lo, lo), raw_point(hi, hi), raw_point(lo + 1, lo + 1)) == 0);
  CHECK(classify({raw_point(lo, lo), raw_point(hi, hi)}, {raw_point(lo, hi), raw_point(hi, lo)}) ==
        SegmentRelation::ProperCrossing);
}

TEST_CASE("integer segment predicates agree with CGAL's exact ones", "[segment][property]") {
  rc::prop("orientation equals CGAL::orientation", [] {
    const int scale = *rc::gen::inRange(0, 3);
    const FxSegment s = random_segment(scale);
    const FxPoint c = raw_point(coordinate(scale), coordinate(scale));
    const int want = static_cast<int>(CGAL::orientation(to_cgal(s.a), to_cgal(s.b), to_cgal(c)));
    RC_ASSERT(orientation(s.a, s.b, c) == want);
  });
  rc::prop("classify equals CGAL's intersection, and is symmetric", [] {
    const int scale = *rc::gen::inRange(0, 3);
    const FxSegment s = random_segment(scale), t = random_segment(scale);
    RC_PRE(!degenerate(s) && !degenerate(t));
    const SegmentRelation r = classify(s, t);
    RC_ASSERT(std::string(name(r)) == name(cgal_relation(s, t)));
    RC_ASSERT(classify(t, s) == r);
    RC_ASSERT(classify({s.b, s.a}, t) == r);
    RC_ASSERT(properly_cross(s, t) == (r == SegmentRelation::ProperCrossing));
  });
  rc::prop("a point-segment touches exactly when CGAL says it lies on the other", [] {
    const int scale = *rc::gen::inRange(0, 3);
    const FxSegment t = random_segment(scale);
    const FxPoint p =
        *rc::gen::inRange(0, 2) == 0 ? t.a : raw_point(coordinate(scale), coordinate(scale));
    const bool on = degenerate(t) ? p == t.a : to_cgal(t).has_on(to_cgal(p));
    const SegmentRelation r = classify({p, p}, t);
    RC_ASSERT(r == (on ? SegmentRelation::Touching : SegmentRelation::Disjoint));
  });
  rc::prop("the 64-bit and 128-bit paths agree inside the 64-bit range", [] {
    auto near_edge = [] {
      const auto edge = *rc::gen::element(-kExactInt64Raw, kExactInt64Raw - 1, 0);
      return static_cast<std::int32_t>(std::clamp<std::int64_t>(
          std::int64_t{edge} + *rc::gen::inRange(-5, 6), -kExactInt64Raw, kExactInt64Raw - 1));
    };
    const FxPoint a = raw_point(near_edge(), near_edge()), b = raw_point(near_edge(), near_edge());
    const FxPoint c = raw_point(near_edge(), near_edge());
    __extension__ using wide = __int128;
    RC_ASSERT(orientation_in<std::int64_t>(a, b, c) == orientation_in<wide>(a, b, c));
  });
}

TEST_CASE("count_proper_crossings equals the pair loop", "[segment][property]") {
  rc::prop("random trails", [] {
    const auto na = *rc::gen::inRange<std::size_t>(0, 300);
    const auto nb = *rc::gen::inRange<std::size_t>(0, 300);
    const auto unit = *rc::gen::element(1, 1 << 16, 1 << 24); // raw units per lattice step
    const std::vector<FxPoint> a = trail(na, 3, unit), b = trail(nb, 3, unit);
    const std::uint64_t n = count_proper_crossings(a, b);
    RC_ASSERT(n == pair_loop(a, b));
    RC_ASSERT(n == count_proper_crossings(b, a));
  });
  rc::prop("long segments (the fallback) and far-apart trails", [] {
    const auto na = *rc::gen::inRange<std::size_t>(17, 120);
    const auto nb = *rc::gen::inRange<std::size_t>(17, 120);
    const std::vector<FxPoint> a = trail(na, 60, 1 << 10), b = trail(nb, 60, 1 << 10);
    RC_ASSERT(count_proper_crossings(a, b) == pair_loop(a, b));
    std::vector<FxPoint> far = b;
    for (FxPoint& p : far) p.x = Fx::from_raw(p.x.raw() + (1 << 20));
    RC_ASSERT(count_proper_crossings(a, far) == 0u);
  });
}

TEST_CASE("count_proper_crossings, worked example", "[segment]") {
  // A zigzag across a straight line crosses it once per zig, never at a vertex.
  std::vector<FxPoint> line{raw_point(-100, 0), raw_point(100, 0)};
  std::vector<FxPoint> zigzag;
  for (std::int32_t k = 0; k <= 40; ++k)
    zigzag.push_back(raw_point(-80 + 4 * k, k % 2 == 0 ? -3 : 5));
  CHECK(count_proper_crossings(zigzag, line) == 40u);
  // Touching at vertices is not crossing: the zigzag's vertices on the line itself.
  std::vector<FxPoint> on_line;
  for (std::int32_t k = 0; k <= 40; ++k)
    on_line.push_back(raw_point(-80 + 4 * k, k % 2 == 0 ? 0 : 5));
  CHECK(count_proper_crossings(on_line, line) == 0u);
  CHECK(count_proper_crossings(std::vector<FxPoint>{}, line) == 0u);
}

TEST_CASE("every pair of segments on a 4x4 lattice: classify equals CGAL", "[segment][proof]") {
  // Exhaustive small scope: all 16 x 16 ordered segments with ends on {0, 1, 2, 3}^2 (raw units),
  // every ordered pair of them, 65536 pairs. The lattice holds every kind of contact: crossings at
  // lattice and non-lattice points, T-junctions, shared ends, collinear overlaps and end-to-end
  // contacts, parallel and degenerate segments. Degenerate ones go through has_on.
  std::vector<FxSegment> all;
  for (std::int32_t p = 0; p < 16; ++p)
    for (std::int32_t q = 0; q < 16; ++q)
      all.push_back({raw_point(p % 4, p / 4), raw_point(q % 4, q / 4)});
  std::int64_t pairs = 0, mismatches = 0;
  std::array<std::int64_t, 4> seen{};
  for (const FxSegment& s : all)
    for (const FxSegment& t : all) {
      SegmentRelation want;
      if (degenerate(s) && degenerate(t))
        want = s.a == t.a ? SegmentRelation::Touching : SegmentRelation::Disjoint;
      else if (degenerate(s) || degenerate(t)) {
        const FxPoint p = degenerate(s) ? s.a : t.a;
        const FxSegment& seg = degenerate(s) ? t : s;
        want =
            to_cgal(seg).has_on(to_cgal(p)) ? SegmentRelation::Touching : SegmentRelation::Disjoint;
      } else {
        want = cgal_relation(s, t);
      }
      const SegmentRelation got = classify(s, t);
      mismatches +=
          got != want || properly_cross(s, t) != (want == SegmentRelation::ProperCrossing) ? 1 : 0;
      ++seen[static_cast<std::size_t>(want)];
      ++pairs;
    }
  CHECK(pairs == 65536);
  CHECK(mismatches == 0);
  // The scope really contains every relation.
  for (std::int64_t n : seen) CHECK(n > 0);
}
