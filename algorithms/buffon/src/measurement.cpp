// Buffon's-needle measurement: two visits, the pheromone raster, the detector (measurement.hpp).
#include <algorithm>
#include <antkit/buffon/crossing_counter.hpp>
#include <antkit/buffon/measurement.hpp>
#include <antkit/buffon/stopping.hpp>
#include <antkit/kernel/input_error.hpp>
#include <atomic>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

namespace antkit::buffon {

namespace {
std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  const std::int64_t q = a / b;
  return (a % b != 0 && ((a < 0) != (b < 0))) ? q - 1 : q;
}
} // namespace

std::uint64_t isqrt64(std::uint64_t n) noexcept {
  std::uint64_t r = 0;
  std::uint64_t bit = std::uint64_t{1} << 62;
  while (bit > n) bit >>= 2;
  while (bit != 0) {
    if (n >= r + bit) {
      n -= r + bit;
      r = (r >> 1) + bit;
    } else {
      r >>= 1;
    }
    bit >>= 2;
  }
  return r;
}

PheromoneRaster::PheromoneRaster(FxPoint lower, FxPoint upper, Fx width,
                                 std::vector<std::uint64_t> storage)
    : bits_(std::move(storage)) {
  if (width < Fx::from_ratio(1, 100) || width > Fx::from_int(10))
    throw kernel::InputError("trail width", "the trail width must be in [0.01, 10] units");
  cell_ = std::max<std::int64_t>(1, width.raw() / 4);
  half_width_ = width.raw() / 2;
  x0_ = lower.x.raw();
  y0_ = lower.y.raw();
  cols_ = (std::int64_t{upper.x.raw()} - x0_) / cell_ + 1;
  rows_ = (std::int64_t{upper.y.raw()} - y0_) / cell_ + 1;
  // The bands round the columns up to a multiple of 64: the limit is on the words allocated.
  if ((cols_ + 63) / 64 * rows_ > (std::int64_t{1} << 27))
    throw kernel::InputError("trail width", "the pheromone raster would exceed 2^27 words (1 GiB); "
                                            "use a wider trail or a smaller arena");
  r2_ = half_width_ * half_width_;
  reciprocal_ = (std::uint64_t{1} << 32) / static_cast<std::uint64_t>(cell_);
  fast_ = 2 * half_width_ < 5 * cell_; // holds for every width in range (cell >= 163 raw)
  // w up to about 0.56 units (every width of the paper's figures).
  narrow_ = 25 * cell_ * cell_ < (std::int64_t{1} << 31) && 4 * r2_ < (std::int64_t{1} << 31);
  bits_.assign(static_cast<std::size_t>((cols_ + 63) / 64 * rows_), 0);
}

void PheromoneRaster::lay_exact(FxPoint c) noexcept {
  const std::int64_t cx = c.x.raw() - x0_, cy = c.y.raw() - y0_;
  const std::int64_t i0 = std::max<std::int64_t>(0, floor_div(cx - half_width_, cell_));
  const std::int64_t i1 = std::min<std::int64_t>(cols_ - 1, floor_div(cx + half_width_, cell_));
  const std::int64_t j0 = std::max<std::int64_t>(0, floor_div(cy - half_width_, cell_));
  const std::int64_t j1 = std::min<std::int64_t>(rows_ - 1, floor_div(cy + half_width_, cell_));
  for (std::int64_t j = j0; j <= j1; ++j) {
    // Cell centres in doubled raw units avoid halves: centre = (2 j + 1) cell / 2.
    const std::int64_t dy2 = (2 * j + 1) * cell_ - 2 * cy;
    for (std::int64_t i = i0; i <= i1; ++i) {
      const std::int64_t dx2 = (2 * i + 1) * cell_ - 2 * cx;
      if (dx2 * dx2 + dy2 * dy2 > 4 * r2_) continue;
      bits_[word_index(i, j)] |= std::uint64_t{1} << (i & 63);
    }
  }
}

bool PheromoneRaster::at_exact(FxPoint c) const noexcept {
  const std::int64_t i = floor_div(c.x.raw() - x0_, cell_);
  const std::int64_t j = floor_div(c.y.raw() - y0_, cell_);
  if (i < 0 || j < 0 || i >= cols_ || j >= rows_) return false;
  return bit(i, j);
}

std::uint64_t PheromoneRaster::marked() const {
  std::uint64_t n = 0;
  for (std::uint64_t w : bits_) n += static_cast<std::uint64_t>(__builtin_popcountll(w));
  return n;
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

void parallel_for(std::uint64_t count, unsigned threads,
                  const std::function<void(std::uint64_t)>& f) {
  threads = std::max(1u, threads);
  if (threads == 1 || count <= 1) {
    for (std::uint64_t i = 0; i < count; ++i) f(i);
    return;
  }
  std::atomic<std::uint64_t> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto worker = [&] {
    for (;;) {
      const std::uint64_t i = next.fetch_add(1);
      if (i >= count) return;
      try {
        f(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
        next.store(count);
      }
    }
  };
  std::vector<std::thread> pool;
  const auto n = static_cast<unsigned>(std::min<std::uint64_t>(threads, count));
  pool.reserve(n);
  for (unsigned t = 0; t < n; ++t) pool.emplace_back(worker);
  for (auto& th : pool) th.join();
  if (error) std::rethrow_exception(error);
}

std::vector<TrialResult> run_trials(const World& world, const TrialParams& params,
                                    std::uint64_t count, unsigned threads) {
  std::vector<TrialResult> results(static_cast<std::size_t>(count));
  parallel_for(count, threads, [&](std::uint64_t i) {
    results[static_cast<std::size_t>(i)] = run_trial(world, params, i);
  });
  return results;
}

} // namespace antkit::buffon
