#pragma once
// Points and segments in fixed-point coordinates, and exact integer predicates on them.
//
// All predicates work on the raw integers of the coordinates (Fx::raw(), the value times 2^16):
// scaling every coordinate by the same positive factor changes no orientation, so the answers are
// those of the exact real geometry of the fixed-point values, with no rounding anywhere.
//
// Exactness and range. orientation() is the sign of the cross product
//     (b - a) x (c - a) = (bx - ax)(cy - ay) - (by - ay)(cx - ax).
// In 64-bit arithmetic it is exact when every coordinate difference is at most 2^31 - 1 in
// magnitude: each product is then below 2^62 and their difference below 2^63. That holds when
// every raw coordinate lies in [-2^30, 2^30), i.e. every coordinate in [-16384, 16384) units
// (kExactInt64Raw below): the fast path. Outside that range (the full Fx range reaches 2^31 raw,
// differences need 33 bits and products 66) the same template is instantiated with a 128-bit
// integer, so every input gets an exact answer and none reaches undefined behaviour.
//
// What the relations mean (closed segments; a segment whose ends coincide is a point):
//   Disjoint          no common point.
//   ProperCrossing    exactly one common point, interior to both segments, and the segments are
//                     not collinear: the interiors cross.
//   Touching          they share at least one point but neither cross properly nor overlap in a
//                     stretch of positive length: an endpoint of one lies on the other (a shared
//                     endpoint, a T-junction), collinear segments that meet end to end at a single
//                     point, or a point-segment lying on the other.
//   CollinearOverlap  they share a stretch of positive length (so both are collinear).
#include <algorithm>
#include <antkit/kernel/fixed.hpp>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace antkit::kernel {

struct FxPoint {
  Fx x;
  Fx y;
  friend constexpr bool operator==(FxPoint, FxPoint) = default;
};

struct FxSegment {
  FxPoint a;
  FxPoint b;
  friend constexpr bool operator==(FxSegment, FxSegment) = default;
};

enum class SegmentRelation : std::uint8_t { Disjoint, Touching, ProperCrossing, CollinearOverlap };

// Raw coordinates in [-kExactInt64Raw, kExactInt64Raw) take the 64-bit path (see above).
inline constexpr std::int32_t kExactInt64Raw = std::int32_t{1} << 30;

namespace detail {

// kernel::int128 (int_ops.hpp: __int128, or soft::Int on 32-bit targets).
__extension__ using segment_wide = ANTKIT_INT128;

constexpr bool raw_in_int64_range(std::int32_t v) noexcept {
  // v in [-2^30, 2^30) <=> v + 2^30 in [0, 2^31), computed without signed overflow.
  return static_cast<std::uint32_t>(v) + static_cast<std::uint32_t>(kExactInt64Raw) <
         (std::uint32_t{1} << 31);
}
constexpr bool in_int64_range(FxPoint p) noexcept {
  return raw_in_int64_range(p.x.raw()) && raw_in_int64_range(p.y.raw());
}

} // namespace detail

// The sign (-1, 0, +1) of (b - a) x (c - a) computed in Int, from raw coordinates. Int must hold
// every difference of two coordinates and every product of two differences (see the range note at
// the top); that is the whole overflow argument. The sign is taken with two `if`s, not as the
// difference of two comparisons, so that the Z3 harness can run this source (each comparison forks
// the symbolic run; the proof is not in the suite yet: PROOFS.md, "Not yet proved"). gcc 12 -O2
// compiles both forms to branch-free code of the same length (setne/cmovg for this one).
template <class Int>
constexpr int orientation_in(Int ax, Int ay, Int bx, Int by, Int cx, Int cy) noexcept {
  const Int cross = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
  if (cross > Int{0}) return 1;
  if (cross < Int{0}) return -1;
  return 0;
}

template <class Int>
constexpr int orientation_in(FxPoint a, FxPoint b, FxPoint c) noexcept {
  return orientation_in<Int>(Int{a.x.raw()}, Int{a.y.raw()}, Int{b.x.raw()}, Int{b.y.raw()},
                             Int{c.x.raw()}, Int{c.y.raw()});
}

// Sign of the cross product (b - a) x (c - a), exact: +1 when c lies to the left of the directed
// line a -> b (counter-clockwise in a y-up frame; clockwise as drawn with y down), -1 to the right,
// 0 when a, b, c are collinear (or two of them coincide).
constexpr int orientation(FxPoint a, FxPoint b, FxPoint c) noexcept {
  if (detail::in_int64_range(a) && detail::in_int64_range(b) && detail::in_int64_range(c))
    return orientation_in<std::int64_t>(a, b, c);
  return orientation_in<detail::segment_wide>(a, b, c);
}

namespace detail {

// Lexicographic order on (x, y): along any line it is the order of the points on that line, which
// is all the collinear case needs.
constexpr bool lex_less(FxPoint p, FxPoint q) noexcept {
  return p.x.raw() < q.x.raw() || (p.x.raw() == q.x.raw() && p.y.raw() < q.y.raw());
}

template <class Int>
constexpr SegmentRelation classify_in(const FxSegment& s, const FxSegment& t) noexcept {
  const int o1 = orientation_in<Int>(s.a, s.b, t.a);
  const int o2 = orientation_in<Int>(s.a, s.b, t.b);
  const int o3 = orientation_in<Int>(t.a, t.b, s.a);
  const int o4 = orientation_in<Int>(t.a, t.b, s.b);
  if (o1 == 0 && o2 == 0 && o3 == 0 && o4 == 0) {
    // All four points on one line (or points coinciding): compare the two intervals along it.
    const FxPoint s_lo = lex_less(s.b, s.a) ? s.b : s.a, s_hi = lex_less(s.b, s.a) ? s.a : s.b;
    const FxPoint t_lo = lex_less(t.b, t.a) ? t.b : t.a, t_hi = lex_less(t.b, t.a) ? t.a : t.b;
    const FxPoint lo = lex_less(s_lo, t_lo) ? t_lo : s_lo; // the later start
    const FxPoint hi = lex_less(s_hi, t_hi) ? s_hi : t_hi; // the earlier end
    if (lex_less(hi, lo)) return SegmentRelation::Disjoint;
    if (hi == lo) return SegmentRelation::Touching;
    return SegmentRelation::CollinearOverlap;
  }
  // Not all on one line: the closed segments meet iff each one's ends are not strictly on the
  // same side of the other's line, and then in exactly one point. (A point-segment s gives
  // o1 = o2 = 0 and o3 = o4 != 0 here, hence Disjoint, as it should.)
  if (o1 * o2 > 0 || o3 * o4 > 0) return SegmentRelation::Disjoint;
  if (o1 != 0 && o2 != 0 && o3 != 0 && o4 != 0) return SegmentRelation::ProperCrossing;
  return SegmentRelation::Touching;
}

template <class Int>
constexpr bool properly_cross_in(const FxSegment& s, const FxSegment& t) noexcept {
  const int o1 = orientation_in<Int>(s.a, s.b, t.a);
  const int o2 = orientation_in<Int>(s.a, s.b, t.b);
  if (o1 * o2 >= 0) return false;
  const int o3 = orientation_in<Int>(t.a, t.b, s.a);
  const int o4 = orientation_in<Int>(t.a, t.b, s.b);
  return o3 * o4 < 0;
}

constexpr bool in_int64_range(const FxSegment& s, const FxSegment& t) noexcept {
  return in_int64_range(s.a) && in_int64_range(s.b) && in_int64_range(t.a) && in_int64_range(t.b);
}

} // namespace detail

// How two closed segments meet (see the definitions at the top of this file). Symmetric.
constexpr SegmentRelation classify(const FxSegment& s, const FxSegment& t) noexcept {
  if (detail::in_int64_range(s, t)) return detail::classify_in<std::int64_t>(s, t);
  return detail::classify_in<detail::segment_wide>(s, t);
}

// The interiors cross at exactly one point: classify(s, t) == ProperCrossing, computed with at
// most four orientations and no collinear case.
constexpr bool properly_cross(const FxSegment& s, const FxSegment& t) noexcept {
  if (detail::in_int64_range(s, t)) return detail::properly_cross_in<std::int64_t>(s, t);
  return detail::properly_cross_in<detail::segment_wide>(s, t);
}

// The number of pairs (segment i of polyline a, segment j of polyline b) that cross properly. A
// polyline of n points has n - 1 segments (none when n < 2); consecutive equal points are
// zero-length segments, which never cross properly. Touching and collinear overlaps are not
// counted: a crossing is counted only where one trail really passes from one side of the other to
// the other side at a single point. count_proper_crossings(a, a) counts every crossing of a with
// itself twice, once per order.
//
// Instead of the O(|a| |b|) pair loop, both polylines are cut into chunks of 16 consecutive
// segments, each with the bounding box of its segments. The chunks of b are bucketed into a
// uniform grid over the part of the plane where both polylines' bounding boxes overlap (about one
// bucket per chunk of b); each chunk of a is tested only against the chunks of b registered in the
// buckets its box covers, and a pair of chunks whose boxes overlap is taken in exactly one bucket:
// the one holding the lower corner (max of the minima) of the intersection of the two boxes. Its
// segments are then tested pair by pair, a pair whose boxes miss rejected before the predicate.
// Every pair of segments belongs to exactly one pair of chunks, so each crossing is counted once.
// Why chunks: a robot trail passes through a region in runs of short consecutive segments, so one
// box test rejects a whole run (per-segment bucketing tested every segment of every run met).
// Where the trails are dense at a chunk's scale (a chunk of b registered in more than two buckets
// on average: a small arena walked long, such as Figure 5's circles of diameter 20 and less), the
// chunk pairs cost more than they save and the per-segment buckets (the code before) are used.
// With short segments (robot trails) this is close to linear; many long segments that span the
// whole region fall back towards the pair loop. Deterministic: no hashing, no dependence on
// addresses.
inline std::uint64_t count_proper_crossings(std::span<const FxPoint> a,
                                            std::span<const FxPoint> b) {
  if (a.size() < 2 || b.size() < 2) return 0;
  const std::size_t na = a.size() - 1, nb = b.size() - 1;

  // Raw coordinates are 32-bit, so boxes are too (half the memory of 64-bit ones).
  struct Box {
    std::int32_t x0, y0, x1, y1;
  };
  auto box_of = [](FxPoint p, FxPoint q) {
    return Box{std::min(p.x.raw(), q.x.raw()), std::min(p.y.raw(), q.y.raw()),
               std::max(p.x.raw(), q.x.raw()), std::max(p.y.raw(), q.y.raw())};
  };
  auto meet = [](const Box& s, const Box& t) {
    return s.x0 <= t.x1 && s.x1 >= t.x0 && s.y0 <= t.y1 && s.y1 >= t.y0;
  };
  auto unite = [](Box& h, const Box& c) {
    h.x0 = std::min(h.x0, c.x0), h.y0 = std::min(h.y0, c.y0);
    h.x1 = std::max(h.x1, c.x1), h.y1 = std::max(h.y1, c.y1);
  };

  // Chunk c of a polyline is its segments c kChunk .. c kChunk + kChunk - 1 (fewer in the last),
  // i.e. its points c kChunk .. c kChunk + kChunk; its box is theirs. One pass per polyline gives
  // the chunks' boxes and, as their union, the polyline's bounding box.
  auto chunk_boxes = [&](std::span<const FxPoint> pts, std::size_t n, std::size_t kChunk,
                         Box& hull) {
    std::vector<Box> boxes((n + kChunk - 1) / kChunk);
    for (std::size_t c = 0; c < boxes.size(); ++c) {
      const std::size_t first = c * kChunk, last = std::min(n, first + kChunk);
      Box h = box_of(pts[first], pts[first]);
      for (std::size_t k = first + 1; k <= last; ++k) {
        const std::int32_t x = pts[k].x.raw(), y = pts[k].y.raw();
        h.x0 = std::min(h.x0, x), h.y0 = std::min(h.y0, y);
        h.x1 = std::max(h.x1, x), h.y1 = std::max(h.y1, y);
      }
      boxes[c] = h;
      if (c == 0)
        hull = h;
      else
        unite(hull, h);
    }
    return boxes;
  };
  constexpr std::size_t kLongChunk = 16;
  Box ha{}, hb{};
  std::vector<Box> chunks_a = chunk_boxes(a, na, kLongChunk, ha),
                   chunks_b = chunk_boxes(b, nb, kLongChunk, hb);

  // The 64-bit path is taken for all pairs at once when every point is in range, i.e. when both
  // bounding boxes' corners are (the range is an interval in each coordinate).
  auto box_in_range = [](const Box& h) {
    return detail::raw_in_int64_range(h.x0) && detail::raw_in_int64_range(h.x1) &&
           detail::raw_in_int64_range(h.y0) && detail::raw_in_int64_range(h.y1);
  };
  const bool narrow = box_in_range(ha) && box_in_range(hb);
  auto crosses = [narrow](const FxSegment& s, const FxSegment& t) {
    return narrow ? detail::properly_cross_in<std::int64_t>(s, t)
                  : detail::properly_cross_in<detail::segment_wide>(s, t);
  };

  auto pair_loop = [&] {
    std::uint64_t count = 0;
    for (std::size_t i = 0; i < na; ++i)
      for (std::size_t j = 0; j < nb; ++j)
        count += crosses(FxSegment{a[i], a[i + 1]}, FxSegment{b[j], b[j + 1]}) ? 1u : 0u;
    return count;
  };
  // Small inputs: the pair loop is cheaper than building buckets.
  if (na <= 16 || nb <= 16) return pair_loop();

  // The region where a crossing can be: the overlap of the two polylines' bounding boxes.
  const Box region32{std::max(ha.x0, hb.x0), std::max(ha.y0, hb.y0), std::min(ha.x1, hb.x1),
                     std::min(ha.y1, hb.y1)};
  const Box& region = region32;
  if (region.x0 > region.x1 || region.y0 > region.y1) return 0;
  // Counts with chunks of kChunk segments into `count`; false (nothing counted) when the chunks
  // of b would be registered in more than max_registrations buckets each on average.
  auto bucketed = [&](std::size_t kChunk, std::uint64_t max_registrations, std::uint64_t& count) {
    const std::size_t ncb = chunks_b.size();

    // About ncb buckets: at most G x G with G = ceil(sqrt(ncb)) capped at 1024 (a million buckets).
    // A bucket's sides are powers of two, the least for which G columns (rows) span the region's
    // extent, so that finding a bucket is a shift rather than a division (extent < 2^32).
    std::int64_t g = 1;
    while (g < 1024 && g * g < static_cast<std::int64_t>(ncb)) ++g;
    auto side_shift = [g](std::int64_t extent) {
      int shift = 0;
      while ((extent >> shift) >= g) ++shift;
      return shift;
    };
    const int shift_x = side_shift(std::int64_t{region.x1} - region.x0);
    const int shift_y = side_shift(std::int64_t{region.y1} - region.y0);
    const std::int64_t gx = ((std::int64_t{region.x1} - region.x0) >> shift_x) + 1; // columns
    const std::int64_t gy = ((std::int64_t{region.y1} - region.y0) >> shift_y) + 1; // rows
    auto bucket_x = [&](std::int64_t x) {
      return (std::clamp<std::int64_t>(x, region.x0, region.x1) - region.x0) >> shift_x;
    };
    auto bucket_y = [&](std::int64_t y) {
      return (std::clamp<std::int64_t>(y, region.y0, region.y1) - region.y0) >> shift_y;
    };

    // Compressed rows: start[k] .. start[k + 1] index the chunks of b in bucket k, in order. A
    // chunk is registered in every bucket its box covers; when that adds up to more than 64
    // registrations per chunk (many long segments), the buckets would cost more than they save, so
    // the pair loop is used instead (also what keeps memory bounded on any input).
    const auto buckets = static_cast<std::size_t>(gx * gy);
    std::uint64_t registrations = 0;
    for (const Box& cb : chunks_b) {
      if (!meet(cb, region)) continue;
      registrations += static_cast<std::uint64_t>(bucket_y(cb.y1) - bucket_y(cb.y0) + 1) *
                       static_cast<std::uint64_t>(bucket_x(cb.x1) - bucket_x(cb.x0) + 1);
    }
    if (registrations > max_registrations * static_cast<std::uint64_t>(ncb) ||
        nb >= (std::size_t{1} << 31))
      return false;
    std::vector<std::size_t> start(buckets + 1, 0);
    for (const Box& cb : chunks_b) {
      if (!meet(cb, region)) continue;
      for (std::int64_t by = bucket_y(cb.y0); by <= bucket_y(cb.y1); ++by)
        for (std::int64_t bx = bucket_x(cb.x0); bx <= bucket_x(cb.x1); ++bx)
          ++start[static_cast<std::size_t>(by * gx + bx) + 1];
    }
    for (std::size_t k = 0; k < buckets; ++k) start[k + 1] += start[k];
    std::vector<std::uint32_t> members(start[buckets]);
    {
      std::vector<std::size_t> fill(start.begin(), start.end() - 1);
      for (std::size_t c = 0; c < ncb; ++c) {
        const Box& cb = chunks_b[c];
        if (!meet(cb, region)) continue;
        for (std::int64_t by = bucket_y(cb.y0); by <= bucket_y(cb.y1); ++by)
          for (std::int64_t bx = bucket_x(cb.x0); bx <= bucket_x(cb.x1); ++bx)
            members[fill[static_cast<std::size_t>(by * gx + bx)]++] = static_cast<std::uint32_t>(c);
      }
    }

    // The segments of a chunk of a and of a chunk of b whose boxes meet: every pair of them.
    auto count_chunk_pair = [&](std::size_t i0, std::size_t i1, std::size_t j0, std::size_t j1,
                                const Box& box_b) {
      std::uint64_t pairs = 0;
      for (std::size_t i = i0; i < i1; ++i) {
        const Box bs = box_of(a[i], a[i + 1]);
        if (!meet(bs, box_b)) continue;
        const FxSegment s{a[i], a[i + 1]};
        for (std::size_t j = j0; j < j1; ++j) {
          if (!meet(bs, box_of(b[j], b[j + 1]))) continue;
          pairs += crosses(s, FxSegment{b[j], b[j + 1]}) ? 1u : 0u;
        }
      }
      return pairs;
    };

    count = 0;
    for (std::size_t ca = 0; ca < chunks_a.size(); ++ca) {
      const Box& bs = chunks_a[ca];
      if (!meet(bs, region)) continue;
      const std::size_t i0 = ca * kChunk, i1 = std::min(na, i0 + kChunk);
      for (std::int64_t by = bucket_y(bs.y0); by <= bucket_y(bs.y1); ++by)
        for (std::int64_t bx = bucket_x(bs.x0); bx <= bucket_x(bs.x1); ++bx) {
          const auto k = static_cast<std::size_t>(by * gx + bx);
          for (std::size_t m = start[k]; m < start[k + 1]; ++m) {
            const std::uint32_t cb = members[m];
            const Box& bt = chunks_b[cb];
            if (!meet(bs, bt)) continue;
            // Count the pair only in the bucket of the lower corner of the boxes' overlap.
            if (bucket_x(std::max(bs.x0, bt.x0)) != bx || bucket_y(std::max(bs.y0, bt.y0)) != by)
              continue;
            const std::size_t j0 = std::size_t{cb} * kChunk, j1 = std::min(nb, j0 + kChunk);
            count += count_chunk_pair(i0, i1, j0, j1, bt);
          }
        }
    }
    return true;
  };
  // Long chunks suit trails that are sparse at the scale of a chunk (a few chunks meet a bucket).
  // Where trails are dense (a small arena walked long: Figure 5's smallest), a long chunk's box
  // covers many small buckets and meets many others, and each chunk pair costs 256 box tests:
  // then one segment per chunk is cheaper, as is the pair loop for many long segments.
  // The per-segment buckets (the code before the chunks, unchanged): each segment of b in every
  // bucket its box covers, each segment of a tested against the segments of its buckets.
  auto per_segment = [&]() -> std::uint64_t {
    struct Box64 {
      std::int64_t x0, y0, x1, y1;
    };
    auto box64_of = [](FxPoint p, FxPoint q) {
      return Box64{std::min<std::int64_t>(p.x.raw(), q.x.raw()),
                   std::min<std::int64_t>(p.y.raw(), q.y.raw()),
                   std::max<std::int64_t>(p.x.raw(), q.x.raw()),
                   std::max<std::int64_t>(p.y.raw(), q.y.raw())};
    };
    const Box64 region64{region32.x0, region32.y0, region32.x1, region32.y1};
    // About nb buckets, G x G with G = ceil(sqrt(nb)) capped at 1024 (a million buckets), each of
    // side ceil(extent / G) raw units (extent <= 2^32, so everything fits in 64 bits).
    std::int64_t g = 1;
    while (g < 1024 && g * g < static_cast<std::int64_t>(nb)) ++g;
    const std::int64_t side_x = (region64.x1 - region64.x0 + g) / g; // ceil((extent + 1) / g)
    const std::int64_t side_y = (region64.y1 - region64.y0 + g) / g;
    auto bucket_x = [&](std::int64_t x) {
      return (std::clamp(x, region64.x0, region64.x1) - region64.x0) / side_x;
    };
    auto bucket_y = [&](std::int64_t y) {
      return (std::clamp(y, region64.y0, region64.y1) - region64.y0) / side_y;
    };
    auto overlaps_region = [&region64](const Box64& bx) {
      return bx.x0 <= region64.x1 && bx.x1 >= region64.x0 && bx.y0 <= region64.y1 &&
             bx.y1 >= region64.y0;
    };

    // Compressed rows: start[k] .. start[k + 1] index the segments of b in bucket k, in order of j.
    // A segment of b is registered in every bucket its bounding box covers; when that adds up to
    // more than 64 registrations per segment (many long segments), the buckets would cost more than
    // they save, so the pair loop is used instead (also what keeps memory bounded on any input).
    const auto buckets = static_cast<std::size_t>(g * g);
    std::vector<Box64> boxes_b(nb);
    std::uint64_t registrations = 0;
    for (std::size_t j = 0; j < nb; ++j) {
      boxes_b[j] = box64_of(b[j], b[j + 1]);
      if (!overlaps_region(boxes_b[j])) continue;
      registrations +=
          static_cast<std::uint64_t>(bucket_y(boxes_b[j].y1) - bucket_y(boxes_b[j].y0) + 1) *
          static_cast<std::uint64_t>(bucket_x(boxes_b[j].x1) - bucket_x(boxes_b[j].x0) + 1);
    }
    if (registrations > 64 * static_cast<std::uint64_t>(nb) || nb >= (std::size_t{1} << 31))
      return pair_loop();
    std::vector<std::size_t> start(buckets + 1, 0);
    for (std::size_t j = 0; j < nb; ++j) {
      if (!overlaps_region(boxes_b[j])) continue;
      for (std::int64_t by = bucket_y(boxes_b[j].y0); by <= bucket_y(boxes_b[j].y1); ++by)
        for (std::int64_t bx = bucket_x(boxes_b[j].x0); bx <= bucket_x(boxes_b[j].x1); ++bx)
          ++start[static_cast<std::size_t>(by * g + bx) + 1];
    }
    for (std::size_t k = 0; k < buckets; ++k) start[k + 1] += start[k];
    std::vector<std::uint32_t> members(start[buckets]);
    {
      std::vector<std::size_t> fill(start.begin(), start.end() - 1);
      for (std::size_t j = 0; j < nb; ++j) {
        if (!overlaps_region(boxes_b[j])) continue;
        for (std::int64_t by = bucket_y(boxes_b[j].y0); by <= bucket_y(boxes_b[j].y1); ++by)
          for (std::int64_t bx = bucket_x(boxes_b[j].x0); bx <= bucket_x(boxes_b[j].x1); ++bx)
            members[fill[static_cast<std::size_t>(by * g + bx)]++] = static_cast<std::uint32_t>(j);
      }
    }

    std::uint64_t count = 0;
    for (std::size_t i = 0; i < na; ++i) {
      const FxSegment s{a[i], a[i + 1]};
      const Box64 bs = box64_of(s.a, s.b);
      if (!overlaps_region(bs)) continue;
      for (std::int64_t by = bucket_y(bs.y0); by <= bucket_y(bs.y1); ++by)
        for (std::int64_t bx = bucket_x(bs.x0); bx <= bucket_x(bs.x1); ++bx) {
          const auto k = static_cast<std::size_t>(by * g + bx);
          for (std::size_t m = start[k]; m < start[k + 1]; ++m) {
            const std::uint32_t j = members[m];
            const Box64& bt = boxes_b[j];
            if (bt.x0 > bs.x1 || bt.x1 < bs.x0 || bt.y0 > bs.y1 || bt.y1 < bs.y0) continue;
            // Count the pair only in the bucket of the lower corner of the boxes' overlap.
            if (bucket_x(std::max(bs.x0, bt.x0)) != bx || bucket_y(std::max(bs.y0, bt.y0)) != by)
              continue;
            count += crosses(s, FxSegment{b[j], b[j + 1]}) ? 1u : 0u;
          }
        }
    }
    return count;
  };
  std::uint64_t count = 0;
  if (bucketed(kLongChunk, 2, count)) return count;
  return per_segment();
}

} // namespace antkit::kernel
