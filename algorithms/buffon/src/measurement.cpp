// Buffon's-needle measurement: two visits, the pheromone raster, the detector (measurement.hpp).
#include <algorithm>
#include <antkit/algorithms/units.hpp>
#include <antkit/buffon/crossing_counter.hpp>
#include <antkit/buffon/measurement.hpp>
#include <antkit/buffon/stopping.hpp>
#include <antkit/kernel/input_error.hpp>
#include <optional>

namespace antkit::buffon {

PheromoneRaster::PheromoneRaster(FxPoint lower, FxPoint upper, Fx width,
                                 std::vector<std::uint64_t> storage)
    : storage_(std::move(storage)) {
  if (const RasterError e = init(lower, upper, width); e != RasterError::None)
    throw kernel::InputError("trail width", describe(e));
  storage_.assign(static_cast<std::size_t>(words()), 0);
  bind(storage_);
}

void detail::check_total_steps(std::int64_t steps) {
  if (steps < 2 || steps > 100000000)
    throw kernel::InputError("step budget", "the budget for both visits must be in [2, 100000000]");
}

void detail::check_visit_steps(std::int64_t steps) {
  if (steps < 0 || steps > 100000000)
    throw kernel::InputError("steps per visit", "the steps per visit must be in [0, 100000000]");
}

namespace {
// Memory one thread's trials reuse (the raster's bits, both trails): fresh pages for them were
// about a tenth of a trial's time. It holds no state between trials (every use discards the
// contents), so results do not depend on which thread ran what before. Buffers above kKeepBytes
// are not kept, so that one huge run does not pin its memory for the thread's lifetime.
struct Scratch {
  std::vector<std::uint64_t> raster;
  std::vector<FxPoint> trail1, trail2;
};
constexpr std::size_t kKeepBytes = std::size_t{64} << 20;
template <class T>
void keep(std::vector<T>& slot, std::vector<T>&& v) {
  if (v.capacity() * sizeof(T) <= kKeepBytes) slot = std::move(v);
}
} // namespace

TrialResult run_trial(const World& world, const TrialParams& params, std::uint64_t trial) {
  thread_local Scratch scratch;
  TrialResult result;
  result.trial = trial;
  kernel::TraceHash hash(params.seed);
  hash.add_u64(trial);
  PheromoneRaster raster(world.lower(), world.upper(), params.width, std::move(scratch.raster));
  const bool online1 = params.online_first_visit;
  if (online1 && params.precision_millionths == 0)
    throw kernel::InputError("stopping rule", "an online first visit needs a precision to stop on");
  if (params.total_steps != 0 && !online1)
    throw kernel::InputError("step budget", "a budget for both visits needs an online first visit");
  if (params.total_steps != 0) detail::check_total_steps(params.total_steps);
  WallEncounters encounters; // with precision_millionths only (bookkeeping for the estimate)
  const bool count_walls = params.precision_millionths != 0;
  TrialParams params1 = params;
  if (params.total_steps != 0) params1.steps = params.total_steps / 2;
  VisitLog first;
  if (!online1) {
    first = run_visit(
        world, params1, trial, 1, hash,
        [&](const Pose& p, const Observation& o) {
          raster.lay(p.position);
          if (count_walls) encounters.observe(o);
          return true;
        },
        std::move(scratch.trail1));
  } else {
    // Visit 1 decides its own length (stopping.hpp: FirstVisitMonitor).
    std::optional<SelfCrossingCounter> self;
    FirstVisitMonitor monitor(params.precision_millionths);
    std::vector<std::uint32_t> crossed;
    first = run_visit(
        world, params1, trial, 1, hash,
        [&](const Pose& p, const Observation& o) {
          raster.lay(p.position);
          encounters.observe(o);
          if (!self) {
            self.emplace(world.lower(), world.upper(), p.position); // the start pose
            return true;
          }
          crossed.clear();
          self->add(p.position, &crossed);
          for (std::uint32_t segment : crossed) monitor.crossing(segment);
          return !monitor.end_step();
        },
        std::move(scratch.trail1));
    result.first_visit_reached = monitor.reached();
    result.self_crossings = monitor.count();
    result.variance_self = monitor.variance();
    hash.add_u64(monitor.count());
  }
  CrossingDetector detector;
  std::uint64_t bc = 0;
  TrialParams params2 = params;
  if (params.visit2_steps != 0) params2.steps = params.visit2_steps;
  if (params.total_steps != 0)
    params2.steps = params.total_steps - static_cast<std::int64_t>(first.trail.size() - 1);
  VisitLog second;
  std::optional<std::uint64_t> counted; // visit 2's crossings, when the online rule counted them
  if (params.precision_millionths == 0) {
    second = run_visit(
        world, params2, trial, 2, hash,
        [&](const Pose& p) {
          if (detector.update(raster.at(p.position))) ++bc;
          return true;
        },
        std::move(scratch.trail2));
  } else {
    // The online rule (stopping.hpp): visit 2's exact crossings with visit 1, step by step.
    CrossingCounter counter(first.trail);
    PrecisionMonitor monitor(params.precision_millionths, first.trail.size() - 1);
    std::vector<std::uint32_t> crossed;
    FxPoint previous{};
    bool started = false;
    second = run_visit(
        world, params2, trial, 2, hash,
        [&](const Pose& p, const Observation& o) {
          if (detector.update(raster.at(p.position))) ++bc;
          encounters.observe(o);
          if (!std::exchange(started, true)) {
            previous = p.position; // the start pose: no segment yet
            return true;
          }
          crossed.clear();
          counter.add(previous, p.position, &crossed);
          previous = p.position;
          for (std::uint32_t segment : crossed) monitor.crossing(segment);
          return !monitor.end_step();
        },
        std::move(scratch.trail2));
    result.reached_precision = monitor.reached();
    result.variance_visit1 = monitor.spread().visit1;
    result.variance_visit2 = monitor.spread().visit2;
    counted = monitor.count(); // = count_proper_crossings(first, second): tests/convergence
    result.wall_encounters = encounters.count();
  }
  keep(scratch.raster, raster.release_storage());
  result.bc = bc;
  result.steps1 = static_cast<std::int64_t>(first.trail.size()) - 1;
  result.steps2 = static_cast<std::int64_t>(second.trail.size()) - 1;
  result.length1_raw = first.length_raw;
  result.length2_raw = second.length_raw;
  result.blocked = first.blocked + second.blocked;
  result.crossings_exact =
      counted ? *counted : kernel::count_proper_crossings(first.trail, second.trail);
  hash.add_u64(bc).add_u64(first.blocked).add_u64(second.blocked).add_u64(result.crossings_exact);
  result.hash = hash.finish();
  if (params.keep_trails) {
    result.trail1 = std::move(first.trail);
    result.trail2 = std::move(second.trail);
  } else {
    keep(scratch.trail1, std::move(first.trail));
    keep(scratch.trail2, std::move(second.trail));
  }
  return result;
}

std::vector<TrialResult> run_trials(const World& world, const TrialParams& params,
                                    std::uint64_t count, unsigned threads) {
  std::vector<TrialResult> results(static_cast<std::size_t>(count));
  algorithms::for_each_unit(count, threads, [&](std::uint64_t i, unsigned) {
    results[static_cast<std::size_t>(i)] = run_trial(world, params, i);
  });
  return results;
}

} // namespace antkit::buffon
