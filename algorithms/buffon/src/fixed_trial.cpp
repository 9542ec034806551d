// One Buffon trial in the caller's buffer (fixed_trial.hpp). Freestanding: the Cortex-M image
// compiles this file too.
#include <antkit/buffon/crossing_counter_core.hpp>
#include <antkit/buffon/detector.hpp>
#include <antkit/buffon/fixed_trial.hpp>
#include <antkit/buffon/visit.hpp>

namespace antkit::buffon {

namespace {

using kernel::FxPoint;

constexpr std::uint64_t align8(std::uint64_t n) noexcept {
  return (n + 7) & ~std::uint64_t{7};
}

template <class T>
T* at(std::span<std::uint8_t> buffer, std::uint64_t offset) noexcept {
  return reinterpret_cast<T*>(buffer.data() + offset);
}

struct VisitEnd {
  std::int64_t length_raw = 0;
  std::uint64_t blocked = 0;
};

// One visit of `steps` steps from `start`; on_step(position) after the start and every step:
// run_visit's loop (measurement.hpp), the same step and the same hash. Out of line so that the
// image's map file shows the step path's size.
template <class OnStep>
[[gnu::noinline]] VisitEnd visit(const WorldCore& world, std::uint64_t seed, std::uint64_t trial,
                                 int v, std::int64_t steps, const Pose& start,
                                 kernel::TraceHash& hash, OnStep on_step) {
  VisitStreams streams(seed, kExperiment, trial, v);
  ExplorationBehaviour behaviour(streams.behaviour);
  Pose pose = start;
  VisitEnd end;
  on_step(pose.position);
  for (std::int64_t s = 0; s < steps; ++s) {
    (void)visit_step(world, behaviour, pose, streams.noise, end.length_raw, end.blocked);
    on_step(pose.position);
    hash_visit_step(hash, pose, behaviour);
  }
  return end;
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
  if (steps < 0 || steps > 100000000) return "the steps per visit must be in [0, 100000000]";
  WorldLayout layout;
  if (const WorldError e = WorldCore::plan(walls, body, layout); e != WorldError::None)
    return describe(e);
  RasterCore raster;
  if (const RasterError e = raster.init(layout.lower, layout.upper, width); e != RasterError::None)
    return describe(e);
  const FixedTrialPlan plan = plan_fixed_trial(layout, raster, steps);
  if (plan.total > buffer.size()) return "the trial's plan is larger than the buffer";
  WorldCore world;
  world.build(
      walls, body, layout,
      {at<std::uint32_t>(buffer, plan.start_at), static_cast<std::size_t>(layout.buckets + 1)},
      {at<BucketWall>(buffer, plan.members_at), static_cast<std::size_t>(layout.members)});
  const std::span<std::uint64_t> bits(at<std::uint64_t>(buffer, plan.raster_at),
                                      static_cast<std::size_t>(raster.words()));
  for (std::uint64_t& w : bits) w = 0;
  raster.bind(bits);
  Pose start1{}, start2{};
  {
    VisitStreams s1(seed, kExperiment, trial, 1), s2(seed, kExperiment, trial, 2);
    if (const WorldError e = world.place_start(s1.start, start1); e != WorldError::None)
      return describe(e);
    if (const WorldError e = world.place_start(s2.start, start2); e != WorldError::None)
      return describe(e);
  }
  kernel::TraceHash hash(seed);
  hash.add_u64(trial);
  // Visit 1 lays the trail and keeps its points for the crossing count.
  auto* trail = at<FxPoint>(buffer, plan.trail_at);
  std::size_t points = 0;
  const VisitEnd first = visit(world, seed, trial, 1, steps, start1, hash, [&](FxPoint p) {
    raster.lay(p);
    trail[points++] = p;
  });
  // Visit 2 senses it (the detector), and its segments are counted against visit 1's.
  const std::span<const FxPoint> trail1(trail, points);
  CrossingLayout cl;
  if (!CrossingCounterCore::plan(trail1, cl)) return "visit 1's trail has more than 2^32 - 2 steps";
  if (plan.counter_at + cl.words() * 4 > plan.total) return "the crossing index exceeds its bound";
  auto* words = at<std::uint32_t>(buffer, plan.counter_at);
  CrossingCounterCore counter;
  counter.build(trail1, cl, {words, static_cast<std::size_t>(cl.buckets + 1)},
                {words + cl.buckets + 1, static_cast<std::size_t>(cl.ids)},
                {words + cl.buckets + 1 + cl.ids, static_cast<std::size_t>(cl.segments)});
  CrossingDetector detector;
  std::uint64_t bc = 0, crossings = 0;
  bool started = false;
  FxPoint previous{};
  const VisitEnd second = visit(world, seed, trial, 2, steps, start2, hash, [&](FxPoint p) {
    if (detector.update(raster.at(p))) ++bc;
    if (started) crossings += counter.add(previous, p, [](std::uint32_t) {});
    started = true;
    previous = p;
  });
  hash.add_u64(bc).add_u64(first.blocked).add_u64(second.blocked).add_u64(crossings);
  result.bc = bc;
  result.crossings_exact = crossings;
  result.blocked = first.blocked + second.blocked;
  result.hash = hash.finish();
  result.length1_raw = first.length_raw;
  result.length2_raw = second.length_raw;
  result.bytes = plan.counter_at + cl.words() * 4;
  return nullptr;
}

} // namespace antkit::buffon
