#include <algorithm>
#include <antkit/buffon/crossing_counter.hpp>
#include <antkit/kernel/input_error.hpp>
#include <limits>

namespace antkit::buffon {

namespace {
using kernel::Fx;
using kernel::FxPoint;

} // namespace

CrossingCounter::CrossingCounter(std::span<const FxPoint> finished) {
  CrossingLayout layout;
  if (!CrossingCounterCore::plan(finished, layout))
    throw kernel::InputError("trail", "a trail of more than 2^32 - 2 segments");
  if (finished.size() >= 2) {
    start_.resize(static_cast<std::size_t>(layout.buckets) + 1);
    ids_.resize(static_cast<std::size_t>(layout.ids));
    stamp_.resize(static_cast<std::size_t>(layout.segments));
  }
  core_.build(finished, layout, start_, ids_, stamp_);
}

std::uint64_t CrossingCounter::add(FxPoint a, FxPoint b, std::vector<std::uint32_t>* crossed) {
  return core_.add(a, b, [crossed](std::uint32_t id) {
    if (crossed) crossed->push_back(id);
  });
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
