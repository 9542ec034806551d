// One Buffon trial in the caller's buffer (fixed_trial.hpp). Freestanding: the Cortex-M image
// compiles this file too.
#include <antkit/buffon/fixed_trial.hpp>

namespace antkit::buffon {

namespace {

using kernel::FxPoint;

constexpr std::uint64_t align8(std::uint64_t n) noexcept {
  return (n + 7) & ~std::uint64_t{7};
}

} // namespace

FixedTrialPlan plan_fixed_trial(const WorldLayout& world, const RasterCore& raster,
                                std::int64_t steps) noexcept {
  FixedTrialPlan p;
  p.world = world.bytes();
  p.raster = raster.words() * 8;
  p.trail = static_cast<std::uint64_t>(steps + 1) * sizeof(FxPoint);
  constexpr int s = CrossingCounterCore::kBucketShift;
  const auto cols = static_cast<std::uint64_t>((std::int64_t{world.upper.x.raw()} >> s) -
                                               (std::int64_t{world.lower.x.raw()} >> s) + 1);
  const auto rows = static_cast<std::uint64_t>((std::int64_t{world.upper.y.raw()} >> s) -
                                               (std::int64_t{world.lower.y.raw()} >> s) + 1);
  const auto segments = static_cast<std::uint64_t>(steps);
  // Bucket starts, at most 4 ids per segment, one stamp per segment: 32-bit words.
  p.counter = (cols * rows + 1 + 4 * segments + segments) * 4;
  p.start_at = 0;
  p.members_at = align8((world.buckets + 1) * 4);
  p.raster_at = align8(p.members_at + world.members * sizeof(BucketWall));
  p.trail_at = align8(p.raster_at + p.raster);
  p.counter_at = align8(p.trail_at + p.trail);
  p.total = p.counter_at + p.counter;
  return p;
}

const char* run_fixed_trial(std::span<const FxSegment> walls, BodyParams body, Fx width,
                            std::uint64_t seed, std::uint64_t trial, std::int64_t steps,
                            std::span<std::uint8_t> buffer, FixedTrialResult& result) noexcept {
  return run_fixed_trial_with<TrialParts>(walls, body, width, seed, trial, steps, buffer, result);
}

} // namespace antkit::buffon
