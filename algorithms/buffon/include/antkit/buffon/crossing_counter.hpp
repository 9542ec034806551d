#pragma once
// Online exact crossing count (issue 8, item 5): the proper crossings of a growing polyline (the
// second visit, step by step) with a finished one (the first visit's trail), so that a stopping
// rule can watch the count N while the robot walks. The total over a whole visit equals
// kernel::count_proper_crossings(trail1, trail2) (tests/convergence holds them to each other).
//
// The finished trail's segments are bucketed once into a uniform grid of square buckets (side
// 2^15 raw = 0.5 unit: a robot step is at most 0.05, so a segment spans one to four buckets). A new
// segment is tested, with the kernel's exact predicate, against the segments registered in the
// buckets its bounding box covers, each at most once (a per-segment stamp). Segments outside the
// grid cannot cross any of the finished trail's. Deterministic: the count is a property of the two
// polylines only.
#include <antkit/kernel/segment.hpp>
#include <cstdint>
#include <span>
#include <vector>

namespace antkit::buffon {

class CrossingCounter {
public:
  // Indexes the segments of `finished` (a polyline of n points has n - 1 segments; any Fx
  // coordinates), which must outlive the counter (it is read, not copied). Throws InputError for
  // more than 2^32 - 2 segments.
  explicit CrossingCounter(std::span<const kernel::FxPoint> finished);
  // The number of segments of the finished trail that segment (a, b) crosses properly. With
  // `crossed`, the index of each such segment (i joins points i and i + 1) is appended to it, in
  // the order of the bucket scan (deterministic, not sorted).
  std::uint64_t add(kernel::FxPoint a, kernel::FxPoint b,
                    std::vector<std::uint32_t>* crossed = nullptr);

private:
  static constexpr int kBucketShift = 15;
  std::span<const kernel::FxPoint> points_;
  std::int64_t bx0_ = 0, by0_ = 0, cols_ = 0, rows_ = 0; // bucket grid origin (in buckets), size
  std::vector<std::uint32_t> start_; // CSR: bucket b's ids in [start_[b], start_[b+1])
  std::vector<std::uint32_t> ids_;   // segment i joins points_[i], points_[i + 1]
  std::vector<std::uint32_t> stamp_; // last query that tested segment i
  std::uint32_t query_ = 0;
};

} // namespace antkit::buffon
