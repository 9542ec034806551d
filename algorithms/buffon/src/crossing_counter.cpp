#include <algorithm>
#include <antkit/buffon/crossing_counter.hpp>
#include <antkit/kernel/input_error.hpp>
#include <limits>

namespace antkit::buffon {

namespace {
using kernel::Fx;
using kernel::FxPoint;

// The bucket holding raw coordinate v: floor(v / 2^15) (arithmetic shift of a negative value
// rounds toward minus infinity, as C++20 defines it).
constexpr std::int64_t bucket_of(std::int32_t v, int shift) noexcept {
  return std::int64_t{v} >> shift;
}
} // namespace

CrossingCounter::CrossingCounter(std::span<const FxPoint> finished) : points_(finished) {
  if (points_.size() < 2) return;
  if (points_.size() - 1 > std::numeric_limits<std::uint32_t>::max() - 1)
    throw kernel::InputError("trail", "a trail of more than 2^32 - 2 segments");
  std::int64_t x0 = std::numeric_limits<std::int64_t>::max(), y0 = x0;
  std::int64_t x1 = std::numeric_limits<std::int64_t>::min(), y1 = x1;
  for (const FxPoint& p : points_) {
    x0 = std::min(x0, bucket_of(p.x.raw(), kBucketShift));
    y0 = std::min(y0, bucket_of(p.y.raw(), kBucketShift));
    x1 = std::max(x1, bucket_of(p.x.raw(), kBucketShift));
    y1 = std::max(y1, bucket_of(p.y.raw(), kBucketShift));
  }
  bx0_ = x0, by0_ = y0, cols_ = x1 - x0 + 1, rows_ = y1 - y0 + 1;
  const std::size_t segments = points_.size() - 1;
  // Two passes over the segments' bucket boxes: count, then fill (compressed rows).
  start_.assign(static_cast<std::size_t>(cols_ * rows_) + 1, 0);
  auto for_each_bucket = [this](std::size_t i, auto&& f) {
    const FxPoint a = points_[i], b = points_[i + 1];
    const std::int64_t i0 = bucket_of(std::min(a.x.raw(), b.x.raw()), kBucketShift) - bx0_;
    const std::int64_t i1 = bucket_of(std::max(a.x.raw(), b.x.raw()), kBucketShift) - bx0_;
    const std::int64_t j0 = bucket_of(std::min(a.y.raw(), b.y.raw()), kBucketShift) - by0_;
    const std::int64_t j1 = bucket_of(std::max(a.y.raw(), b.y.raw()), kBucketShift) - by0_;
    for (std::int64_t j = j0; j <= j1; ++j)
      for (std::int64_t k = i0; k <= i1; ++k) f(static_cast<std::size_t>(j * cols_ + k));
  };
  for (std::size_t i = 0; i < segments; ++i)
    for_each_bucket(i, [&](std::size_t b) { ++start_[b + 1]; });
  for (std::size_t b = 1; b < start_.size(); ++b) start_[b] += start_[b - 1];
  ids_.resize(start_.back());
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < segments; ++i)
    for_each_bucket(i, [&](std::size_t b) { ids_[fill[b]++] = static_cast<std::uint32_t>(i); });
  stamp_.assign(segments, 0);
}

std::uint64_t CrossingCounter::add(FxPoint a, FxPoint b, std::vector<std::uint32_t>* crossed) {
  if (ids_.empty()) return 0;
  const std::int64_t i0 =
      std::max<std::int64_t>(bucket_of(std::min(a.x.raw(), b.x.raw()), kBucketShift) - bx0_, 0);
  const std::int64_t i1 = std::min<std::int64_t>(
      bucket_of(std::max(a.x.raw(), b.x.raw()), kBucketShift) - bx0_, cols_ - 1);
  const std::int64_t j0 =
      std::max<std::int64_t>(bucket_of(std::min(a.y.raw(), b.y.raw()), kBucketShift) - by0_, 0);
  const std::int64_t j1 = std::min<std::int64_t>(
      bucket_of(std::max(a.y.raw(), b.y.raw()), kBucketShift) - by0_, rows_ - 1);
  if (i0 > i1 || j0 > j1) return 0; // wholly outside the finished trail's buckets
  const kernel::FxSegment s{a, b};
  if (++query_ == 0) { // the stamps wrapped: forget them all (once per 2^32 queries)
    std::fill(stamp_.begin(), stamp_.end(), 0);
    query_ = 1;
  }
  std::uint64_t n = 0;
  for (std::int64_t j = j0; j <= j1; ++j)
    for (std::int64_t k = i0; k <= i1; ++k) {
      const auto bucket = static_cast<std::size_t>(j * cols_ + k);
      for (std::uint32_t e = start_[bucket]; e < start_[bucket + 1]; ++e) {
        const std::uint32_t id = ids_[e];
        if (stamp_[id] == query_) continue;
        stamp_[id] = query_;
        const kernel::FxSegment t{points_[id], points_[id + 1]};
        if (!kernel::properly_cross(s, t)) continue;
        ++n;
        if (crossed) crossed->push_back(id);
      }
    }
  return n;
}

} // namespace antkit::buffon

namespace antkit::buffon {

GrowingTrailIndex::GrowingTrailIndex(FxPoint lower, FxPoint upper) {
  const std::int64_t x0 = std::min(lower.x.raw(), upper.x.raw());
  const std::int64_t x1 = std::max(lower.x.raw(), upper.x.raw());
  const std::int64_t y0 = std::min(lower.y.raw(), upper.y.raw());
  const std::int64_t y1 = std::max(lower.y.raw(), upper.y.raw());
  for (;; ++shift_) {
    bx0_ = x0 >> shift_, by0_ = y0 >> shift_;
    cols_ = (x1 >> shift_) - bx0_ + 1, rows_ = (y1 >> shift_) - by0_ + 1;
    if (cols_ * rows_ <= (std::int64_t{1} << 22)) break;
  }
  buckets_.resize(static_cast<std::size_t>(cols_ * rows_));
}

std::uint32_t GrowingTrailIndex::insert(FxPoint a, FxPoint b) {
  if (segments_.size() >= std::numeric_limits<std::uint32_t>::max() - 1)
    throw kernel::InputError("trail", "a trail of more than 2^32 - 2 segments");
  const auto id = static_cast<std::uint32_t>(segments_.size());
  segments_.push_back({a, b});
  const std::int32_t x0 = std::min(a.x.raw(), b.x.raw()), x1 = std::max(a.x.raw(), b.x.raw());
  const std::int32_t y0 = std::min(a.y.raw(), b.y.raw()), y1 = std::max(a.y.raw(), b.y.raw());
  const std::int64_t i0 = column(x0), i1 = column(x1), j0 = row(y0), j1 = row(y1);
  for (std::int64_t j = j0; j <= j1; ++j)
    for (std::int64_t i = i0; i <= i1; ++i) {
      auto& runs = buckets_[static_cast<std::size_t>(j * cols_ + i)];
      if (!runs.empty() && runs.back().first + runs.back().count == id) {
        Run& r = runs.back();
        ++r.count;
        r.x0 = std::min(r.x0, x0), r.y0 = std::min(r.y0, y0);
        r.x1 = std::max(r.x1, x1), r.y1 = std::max(r.y1, y1);
      } else {
        runs.push_back({id, 1, x0, y0, x1, y1});
      }
    }
  return id;
}

std::uint64_t GrowingTrailIndex::cross(FxPoint a, FxPoint b,
                                       std::vector<std::uint32_t>* crossed) const {
  const std::int32_t sx0 = std::min(a.x.raw(), b.x.raw()), sx1 = std::max(a.x.raw(), b.x.raw());
  const std::int32_t sy0 = std::min(a.y.raw(), b.y.raw()), sy1 = std::max(a.y.raw(), b.y.raw());
  const kernel::FxSegment s{a, b};
  std::uint64_t n = 0;
  const std::int64_t i0 = column(sx0), i1 = column(sx1), j0 = row(sy0), j1 = row(sy1);
  const bool one_bucket = i0 == i1 && j0 == j1;
  for (std::int64_t y = j0; y <= j1; ++y)
    for (std::int64_t x = i0; x <= i1; ++x)
      for (const Run& r : buckets_[static_cast<std::size_t>(y * cols_ + x)]) {
        if (r.x1 < sx0 || r.x0 > sx1 || r.y1 < sy0 || r.y0 > sy1) continue; // the run misses
        for (std::uint32_t id = r.first; id < r.first + r.count; ++id) {
          const kernel::FxSegment& t = segments_[id];
          const std::int32_t tx0 = std::min(t.a.x.raw(), t.b.x.raw());
          const std::int32_t tx1 = std::max(t.a.x.raw(), t.b.x.raw());
          const std::int32_t ty0 = std::min(t.a.y.raw(), t.b.y.raw());
          const std::int32_t ty1 = std::max(t.a.y.raw(), t.b.y.raw());
          if (tx1 < sx0 || tx0 > sx1 || ty1 < sy0 || ty0 > sy1) continue; // boxes apart
          // Tested in the bucket of the intersection's lower-left corner only (once per pair;
          // always this bucket when the new segment lies in one).
          if (!one_bucket && (column(std::max(tx0, sx0)) != x || row(std::max(ty0, sy0)) != y))
            continue;
          if (!kernel::properly_cross(s, t)) continue;
          ++n;
          if (crossed) crossed->push_back(id);
        }
      }
  return n;
}

SelfCrossingCounter::SelfCrossingCounter(FxPoint lower, FxPoint upper, FxPoint first)
    : points_{first}, index_(lower, upper) {}

std::uint64_t SelfCrossingCounter::add(FxPoint next, std::vector<std::uint32_t>* crossed) {
  const auto j = static_cast<std::uint64_t>(points_.size() - 1); // the new segment's index
  points_.push_back(next);
  // Segment j - kGap becomes testable now: the index holds exactly the segments 0 .. j - kGap, and
  // their ids in the index are their indices in the polyline.
  if (j >= kGap) index_.insert(points_[j - kGap], points_[j - kGap + 1]);
  return index_.cross(points_[j], next, crossed);
}

} // namespace antkit::buffon
