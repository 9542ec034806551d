// CrossingCounterCore (crossing_counter_core.hpp). Freestanding: the Cortex-M image compiles this
// file too.
#include <algorithm>
#include <antkit/buffon/crossing_counter_core.hpp>
#include <limits>

namespace antkit::buffon {

namespace {
using kernel::FxPoint;
constexpr int kShift = CrossingCounterCore::kBucketShift;
constexpr std::int64_t bucket_of(std::int32_t v) noexcept {
  return std::int64_t{v} >> kShift;
}
// Calls f(b) for every bucket b the bounding box of segment i covers.
template <class F>
void for_each_bucket(std::span<const FxPoint> points, const CrossingLayout& l, std::size_t i,
                     F&& f) {
  const FxPoint a = points[i], b = points[i + 1];
  const std::int64_t i0 = bucket_of(std::min(a.x.raw(), b.x.raw())) - l.bx0;
  const std::int64_t i1 = bucket_of(std::max(a.x.raw(), b.x.raw())) - l.bx0;
  const std::int64_t j0 = bucket_of(std::min(a.y.raw(), b.y.raw())) - l.by0;
  const std::int64_t j1 = bucket_of(std::max(a.y.raw(), b.y.raw())) - l.by0;
  for (std::int64_t j = j0; j <= j1; ++j)
    for (std::int64_t k = i0; k <= i1; ++k) f(static_cast<std::size_t>(j * l.cols + k));
}
} // namespace

bool CrossingCounterCore::plan(std::span<const FxPoint> finished, CrossingLayout& layout) noexcept {
  layout = CrossingLayout{};
  if (finished.size() < 2) return true;
  if (finished.size() - 1 > std::numeric_limits<std::uint32_t>::max() - 1) return false;
  std::int64_t x0 = std::numeric_limits<std::int64_t>::max(), y0 = x0;
  std::int64_t x1 = std::numeric_limits<std::int64_t>::min(), y1 = x1;
  for (const FxPoint& p : finished) {
    x0 = std::min(x0, bucket_of(p.x.raw()));
    y0 = std::min(y0, bucket_of(p.y.raw()));
    x1 = std::max(x1, bucket_of(p.x.raw()));
    y1 = std::max(y1, bucket_of(p.y.raw()));
  }
  layout.bx0 = x0, layout.by0 = y0, layout.cols = x1 - x0 + 1, layout.rows = y1 - y0 + 1;
  layout.buckets = static_cast<std::uint64_t>(layout.cols * layout.rows);
  layout.segments = finished.size() - 1;
  for (std::size_t i = 0; i + 1 < finished.size(); ++i)
    for_each_bucket(finished, layout, i, [&](std::size_t) { ++layout.ids; });
  return true;
}

void CrossingCounterCore::build(std::span<const FxPoint> finished, const CrossingLayout& layout,
                                std::span<std::uint32_t> start, std::span<std::uint32_t> ids,
                                std::span<std::uint32_t> stamp) noexcept {
  points_ = finished;
  bx0_ = layout.bx0, by0_ = layout.by0, cols_ = layout.cols, rows_ = layout.rows;
  query_ = 0;
  if (finished.size() < 2) {
    start_ = {}, ids_ = {}, stamp_ = {};
    return;
  }
  // Compressed rows without a second array: count, prefix-sum to each bucket's end, then place
  // the segments last to first below it, so that each bucket lists its segments in order and
  // start[b] ends at its beginning (the layout the host's two-pass fill gave).
  const auto buckets = static_cast<std::size_t>(layout.buckets);
  const std::size_t segments = finished.size() - 1;
  for (std::size_t b = 0; b <= buckets; ++b) start[b] = 0;
  for (std::size_t i = 0; i < segments; ++i)
    for_each_bucket(finished, layout, i, [&](std::size_t b) { ++start[b]; });
  for (std::size_t b = 1; b < buckets; ++b) start[b] += start[b - 1];
  start[buckets] = start[buckets - 1];
  for (std::size_t i = segments; i-- > 0;)
    for_each_bucket(finished, layout, i,
                    [&](std::size_t b) { ids[--start[b]] = static_cast<std::uint32_t>(i); });
  for (std::uint32_t& s : stamp) s = 0;
  start_ = start, ids_ = ids, stamp_ = stamp;
}

} // namespace antkit::buffon
