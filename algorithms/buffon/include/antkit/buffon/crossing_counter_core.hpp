#pragma once
// The online exact crossing count of CrossingCounter (crossing_counter.hpp: what it counts and how
// it buckets the finished trail) over storage the caller provides (issue 27). Freestanding: the
// Cortex-M image counts visit 2's crossings with visit 1 with it, from the same source
// (crossing_counter_core.cpp), in its own buffer; the host's CrossingCounter owns the storage in
// vectors and throws where plan() returns an error. The same buckets, ids and stamps, so the same
// counts and the same crossed segments in the same order.
#include <antkit/kernel/segment.hpp>
#include <cstdint>
#include <span>

namespace antkit::buffon {

// The storage a CrossingCounterCore needs for one finished trail (CrossingCounterCore::plan):
// `buckets` + 1 bucket starts, `ids` bucket entries and `segments` stamps, all 32-bit words; and
// the bucket grid they were counted for.
struct CrossingLayout {
  std::uint64_t buckets = 0, ids = 0, segments = 0;
  std::int64_t bx0 = 0, by0 = 0, cols = 0, rows = 0; // grid origin (in buckets) and size
  [[nodiscard]] std::uint64_t words() const noexcept { return buckets + 1 + ids + segments; }
};

class CrossingCounterCore {
public:
  static constexpr int kBucketShift = 15; // buckets of 2^15 raw = 0.5 units

  // The layout for `finished` (a polyline of n points has n - 1 segments). False for more than
  // 2^32 - 2 segments.
  [[nodiscard]] static bool plan(std::span<const kernel::FxPoint> finished,
                                 CrossingLayout& layout) noexcept;
  // Indexes `finished` into the caller's words (sizes from `layout`, which plan() gave for the same
  // points). The points and the words must outlive the counter (they are read, not copied).
  void build(std::span<const kernel::FxPoint> finished, const CrossingLayout& layout,
             std::span<std::uint32_t> start, std::span<std::uint32_t> ids,
             std::span<std::uint32_t> stamp) noexcept;

  // The number of segments of the finished trail that segment (a, b) crosses properly; on_cross(i)
  // is called with the index of each (i joins points i and i + 1), in the order of the bucket
  // scan (deterministic, not sorted).
  template <class OnCross>
  std::uint64_t add(kernel::FxPoint a, kernel::FxPoint b, OnCross&& on_cross) noexcept {
    if (ids_.empty()) return 0;
    const std::int64_t i0 =
        std::max<std::int64_t>(bucket_of(std::min(a.x.raw(), b.x.raw())) - bx0_, 0);
    const std::int64_t i1 =
        std::min<std::int64_t>(bucket_of(std::max(a.x.raw(), b.x.raw())) - bx0_, cols_ - 1);
    const std::int64_t j0 =
        std::max<std::int64_t>(bucket_of(std::min(a.y.raw(), b.y.raw())) - by0_, 0);
    const std::int64_t j1 =
        std::min<std::int64_t>(bucket_of(std::max(a.y.raw(), b.y.raw())) - by0_, rows_ - 1);
    if (i0 > i1 || j0 > j1) return 0; // wholly outside the finished trail's buckets
    const kernel::FxSegment s{a, b};
    if (++query_ == 0) { // the stamps wrapped: forget them all (once per 2^32 queries)
      for (std::uint32_t& t : stamp_) t = 0;
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
          on_cross(id);
        }
      }
    return n;
  }

private:
  // The bucket holding raw coordinate v: floor(v / 2^15) (arithmetic shift of a negative value
  // rounds toward minus infinity, as C++20 defines it).
  static constexpr std::int64_t bucket_of(std::int32_t v) noexcept {
    return std::int64_t{v} >> kBucketShift;
  }
  std::span<const kernel::FxPoint> points_;
  std::int64_t bx0_ = 0, by0_ = 0, cols_ = 0, rows_ = 0;
  std::span<const std::uint32_t> start_; // CSR: bucket b's ids in [start_[b], start_[b+1])
  std::span<const std::uint32_t> ids_;   // segment i joins points_[i], points_[i + 1]
  std::span<std::uint32_t> stamp_;       // last query that tested segment i
  std::uint32_t query_ = 0;
};

} // namespace antkit::buffon
