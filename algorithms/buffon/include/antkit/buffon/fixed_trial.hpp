#pragma once
// One Buffon trial in a buffer the caller gives (issue 27): what run_trial (measurement.hpp) does
// for trial `trial` without --precision, freestanding, so that the Cortex-M image runs it
// (mcu/src/buffon_run.cpp) and the host's tests hold it to run_trial. The world's buckets
// (WorldCore), the pheromone raster (RasterCore), visit 1's trail and the crossing index over it
// (CrossingCounterCore) are laid out in the buffer; the visits are visit.hpp's steps, so the hash,
// BC, the blocked steps and the exact crossing count are run_trial's. The exact count is taken
// online in visit 2 (CrossingCounterCore, whose total is count_proper_crossings of the two trails),
// so visit 2's trail is not kept.
//
// Memory (FixedTrialPlan): the crossing index's words are only known after visit 1, so the plan
// counts their bound: a step is at most 0.0625 units (speed <= 0.25, forward <= speed / 4),
// shorter than the index's buckets (0.5 units), so a segment covers at most 2 x 2 of them, over at
// most the walls' box. A buffer that holds the plan always holds the trial.
#include <antkit/buffon/crossing_counter_core.hpp>
#include <antkit/buffon/detector.hpp>
#include <antkit/buffon/pheromone_raster.hpp>
#include <antkit/buffon/visit.hpp>
#include <antkit/buffon/world.hpp>
#include <cstddef>
#include <cstdint>
#include <span>

namespace antkit::buffon {

// Byte offsets in the buffer (8-byte aligned) and the bytes of each part.
struct FixedTrialPlan {
  std::uint64_t world = 0, raster = 0, trail = 0, counter = 0; // bytes (counter: its bound)
  std::uint64_t start_at = 0, members_at = 0, raster_at = 0, trail_at = 0, counter_at = 0;
  std::uint64_t total = 0;
};

// The plan for a world of layout `world`, a raster initialised over its box, `steps` per visit.
[[nodiscard]] FixedTrialPlan plan_fixed_trial(const WorldLayout& world, const RasterCore& raster,
                                              std::int64_t steps) noexcept;

struct FixedTrialResult {
  std::uint64_t bc = 0, crossings_exact = 0, blocked = 0, hash = 0;
  std::int64_t length1_raw = 0, length2_raw = 0;
  std::uint64_t bytes = 0; // of the buffer used
};

// The parts of a trial: visit.hpp's (the behaviour, the hash) and the detector (bool
// update(bool pheromone)). These are the C++ cores; the Cortex-M image also runs the trial with the
// C API's (mcu/src/c_api_parts.hpp), through the same run_fixed_trial_with.
struct TrialParts : VisitParts {
  using Detector = CrossingDetector;
};

// Runs trial `trial` (seed, experiment kExperiment) of `steps` steps per visit over `walls` with
// `body` and trail width `width`, in `buffer` (8-byte aligned; the walls are read, not copied, and
// may lie outside it). Returns null, or why it cannot run (an invalid world, body, width, start, or
// a plan larger than the buffer: the message names it).
[[nodiscard]] const char* run_fixed_trial(std::span<const FxSegment> walls, BodyParams body,
                                          Fx width, std::uint64_t seed, std::uint64_t trial,
                                          std::int64_t steps, std::span<std::uint8_t> buffer,
                                          FixedTrialResult& result) noexcept;

namespace detail {
template <class T>
T* at(std::span<std::uint8_t> buffer, std::uint64_t offset) noexcept {
  return reinterpret_cast<T*>(buffer.data() + offset);
}

// One visit of `steps` steps from `start` with Parts' behaviour; on_step(position) after the start
// and every step: run_visit_steps (visit.hpp). Out of line so that the image's map file shows the
// step path's size: its first template argument is run_fixed_trial_with's lambda, so that its name
// reads visit<antkit::buffon::run_fixed_trial... (tests/mcu/check_footprint.sh,
// bench/mcu_footprint.sh).
template <class OnStep, class Parts, class Hash>
[[gnu::noinline]] VisitEnd visit(const WorldCore& world, std::uint64_t seed, std::uint64_t trial,
                                 int v, std::int64_t steps, const Pose& start, Hash& hash,
                                 OnStep on_step, Parts) {
  VisitStreams streams(seed, kExperiment, trial, v);
  typename Parts::Behaviour behaviour = Parts::behaviour(seed, trial, v);
  return run_visit_steps(world, behaviour, streams.noise, start, steps, hash, on_step);
}
} // namespace detail

// run_fixed_trial with the given parts (TrialParts: the C++ cores).
template <class Parts>
[[nodiscard]] const char* run_fixed_trial_with(std::span<const FxSegment> walls, BodyParams body,
                                               Fx width, std::uint64_t seed, std::uint64_t trial,
                                               std::int64_t steps, std::span<std::uint8_t> buffer,
                                               FixedTrialResult& result) noexcept {
  using detail::at;
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
  typename Parts::Hash hash = Parts::hash(seed);
  hash.add_u64(trial);
  // Visit 1 lays the trail and keeps its points for the crossing count.
  auto* trail = at<FxPoint>(buffer, plan.trail_at);
  std::size_t points = 0;
  const VisitEnd first = detail::visit(
      world, seed, trial, 1, steps, start1, hash,
      [&](FxPoint p) {
        raster.lay(p);
        trail[points++] = p;
      },
      Parts{});
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
  typename Parts::Detector detector;
  std::uint64_t bc = 0, crossings = 0;
  bool started = false;
  FxPoint previous{};
  const VisitEnd second = detail::visit(
      world, seed, trial, 2, steps, start2, hash,
      [&](FxPoint p) {
        if (detector.update(raster.at(p))) ++bc;
        if (started) crossings += counter.add(previous, p, [](std::uint32_t) {});
        started = true;
        previous = p;
      },
      Parts{});
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
