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
#include <algorithm>
#include <antkit/buffon/crossing_counter_core.hpp>
#include <antkit/kernel/segment.hpp>
#include <cstdint>
#include <span>
#include <vector>

namespace antkit::buffon {

class CrossingCounter {
public:
  // Indexes the segments of `finished` (a polyline of n points has n - 1 segments; any Fx
  // coordinates), which must outlive the counter (it is read, not copied). Throws InputError for
  // more than 2^32 - 2 segments. The counting is CrossingCounterCore's, over vectors owned here.
  explicit CrossingCounter(std::span<const kernel::FxPoint> finished);
  // The core points into the vectors: moving keeps their buffers, a copy would not.
  CrossingCounter(const CrossingCounter&) = delete;
  CrossingCounter& operator=(const CrossingCounter&) = delete;
  CrossingCounter(CrossingCounter&&) noexcept = default;
  CrossingCounter& operator=(CrossingCounter&&) noexcept = default;
  ~CrossingCounter() = default;
  // The number of segments of the finished trail that segment (a, b) crosses properly. With
  // `crossed`, the index of each such segment (i joins points i and i + 1) is appended to it, in
  // the order of the bucket scan (deterministic, not sorted).
  std::uint64_t add(kernel::FxPoint a, kernel::FxPoint b,
                    std::vector<std::uint32_t>* crossed = nullptr);

private:
  std::vector<std::uint32_t> start_, ids_, stamp_;
  CrossingCounterCore core_;
};

// A growing set of segments that answers which of them a new segment crosses properly: the online
// counts of issue 17 (a visit's self-crossings, two markers' crossings) are built on it, so it is
// on every step's path and is built for that.
//  * Square buckets of 2^kShift raw over a box given up front (the arena's bounding box; coarser
//    buckets when the box would need more than 2^22). A point outside the box is clamped to the
//    border buckets, which keeps the answers exact (clamping is monotone).
//  * A trail passes through a bucket in runs of consecutive segments, so a bucket stores runs of
//    ids (first, count) with the run's bounding box: adding the next segment of a run is an
//    increment and four min/max, and a query skips a run whose box misses its own with four
//    comparisons, or reads the run's segments in order from one array.
//  * A pair of segments whose bounding boxes overlap is tested in exactly one bucket, the one
//    holding the lower-left corner of the boxes' intersection (which both boxes contain), so no
//    per-query stamps are needed; boxes that miss are rejected with four comparisons before the
//    exact predicate.
class GrowingTrailIndex {
public:
  static constexpr int kShift = 15; // buckets of 2^15 raw = 0.5 units

  GrowingTrailIndex(kernel::FxPoint lower, kernel::FxPoint upper);
  // Adds segment (a, b); its id is the number of segments added before it. Throws InputError for
  // more than 2^32 - 2 segments.
  std::uint32_t insert(kernel::FxPoint a, kernel::FxPoint b);
  // The number of the set's segments that (a, b) crosses properly; with `crossed`, their ids are
  // appended to it (in bucket-scan order).
  std::uint64_t cross(kernel::FxPoint a, kernel::FxPoint b,
                      std::vector<std::uint32_t>* crossed = nullptr) const;
  [[nodiscard]] std::uint64_t size() const noexcept { return segments_.size(); }

private:
  struct Run {
    std::uint32_t first, count;  // segments first .. first + count - 1
    std::int32_t x0, y0, x1, y1; // the run's bounding box, raw: a query skips a run that misses
  };
  [[nodiscard]] std::int64_t column(std::int64_t x) const noexcept {
    return std::clamp<std::int64_t>((x >> shift_) - bx0_, 0, cols_ - 1);
  }
  [[nodiscard]] std::int64_t row(std::int64_t y) const noexcept {
    return std::clamp<std::int64_t>((y >> shift_) - by0_, 0, rows_ - 1);
  }
  int shift_ = kShift;
  std::int64_t bx0_ = 0, by0_ = 0, cols_ = 1, rows_ = 1;
  std::vector<kernel::FxSegment> segments_;
  std::vector<std::vector<Run>> buckets_;
};

// Online exact self-crossing count (issue 17): the proper crossings of a growing polyline (the
// first visit, step by step) with its own earlier segments, so that visit 1 can estimate the area
// from its own trail while it lays it. For one isotropic curve of length L in a region of area A
// the expected number of self-crossings is L^2 / (pi A) (the two-curve law 2 L1 L2 / (pi A) over
// the L^2 / 2 pairs of the curve's elements), so A_pilot = L^2 / (pi S).
//
// The freshly laid stretch is excluded: a new segment is tested only against the segments at least
// kGap before it (segment i joins points i and i + 1; segment j is tested against i <= j - kGap).
// kGap = 25 steps is about one unit of trail (a step is 0.034 on average and at most 0.043), the
// robot's diameter: a
// crossing of a stretch still under the body is not one the detector at the centre could sense
// (it has not left the band), and pairs of elements that close along the curve are not the
// independent pairs the law counts. The choice is ours; the paper is silent.
//
// Deterministic: the count is a property of the polyline only (a GrowingTrailIndex over the box
// [lower, upper]), and tests hold it to the brute-force count of the pairs.
class SelfCrossingCounter {
public:
  static constexpr std::uint32_t kGap = 25;
  // `first`: the polyline's first point; [lower, upper]: the box its points lie in.
  SelfCrossingCounter(kernel::FxPoint lower, kernel::FxPoint upper, kernel::FxPoint first);
  // Extends the polyline to `next`; returns the number of proper crossings of the new segment with
  // the segments at least kGap before it, appending their indices to `crossed` when given. Throws
  // InputError for more than 2^32 - 2 segments.
  std::uint64_t add(kernel::FxPoint next, std::vector<std::uint32_t>* crossed = nullptr);
  // Segments so far.
  [[nodiscard]] std::uint64_t segments() const noexcept { return points_.size() - 1; }

private:
  std::vector<kernel::FxPoint> points_;
  GrowingTrailIndex index_;
};

} // namespace antkit::buffon
