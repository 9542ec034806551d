// Buffon's-needle measurement: two visits, the pheromone raster, the detector (measurement.hpp).
#include <algorithm>
#include <antkit/buffon/measurement.hpp>
#include <antkit/kernel/input_error.hpp>
#include <atomic>
#include <exception>
#include <mutex>
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

PheromoneRaster::PheromoneRaster(FxPoint lower, FxPoint upper, Fx width) {
  if (width < Fx::from_ratio(1, 100) || width > Fx::from_int(10))
    throw kernel::InputError("--width", "the trail width must be in [0.01, 10] units");
  cell_ = std::max<std::int64_t>(1, width.raw() / 4);
  half_width_ = width.raw() / 2;
  x0_ = lower.x.raw();
  y0_ = lower.y.raw();
  cols_ = (std::int64_t{upper.x.raw()} - x0_) / cell_ + 1;
  rows_ = (std::int64_t{upper.y.raw()} - y0_) / cell_ + 1;
  if (cols_ * rows_ > (std::int64_t{1} << 33))
    throw kernel::InputError("--width", "the pheromone raster would exceed 2^33 cells (1 GiB); "
                                        "use a wider trail or a smaller arena");
  bits_.assign(static_cast<std::size_t>((cols_ * rows_ + 63) / 64), 0);
}

void PheromoneRaster::lay(FxPoint c) {
  const std::int64_t cx = c.x.raw() - x0_, cy = c.y.raw() - y0_;
  const std::int64_t i0 = std::max<std::int64_t>(0, floor_div(cx - half_width_, cell_));
  const std::int64_t i1 = std::min<std::int64_t>(cols_ - 1, floor_div(cx + half_width_, cell_));
  const std::int64_t j0 = std::max<std::int64_t>(0, floor_div(cy - half_width_, cell_));
  const std::int64_t j1 = std::min<std::int64_t>(rows_ - 1, floor_div(cy + half_width_, cell_));
  const std::int64_t r2 = half_width_ * half_width_;
  for (std::int64_t j = j0; j <= j1; ++j) {
    // Cell centres in doubled raw units avoid halves: centre = (2 j + 1) cell / 2.
    const std::int64_t dy2 = (2 * j + 1) * cell_ - 2 * cy;
    for (std::int64_t i = i0; i <= i1; ++i) {
      const std::int64_t dx2 = (2 * i + 1) * cell_ - 2 * cx;
      if (dx2 * dx2 + dy2 * dy2 > 4 * r2) continue;
      const auto k = static_cast<std::uint64_t>(j * cols_ + i);
      bits_[k >> 6] |= std::uint64_t{1} << (k & 63);
    }
  }
}

bool PheromoneRaster::at(FxPoint c) const {
  const std::int64_t i = floor_div(c.x.raw() - x0_, cell_);
  const std::int64_t j = floor_div(c.y.raw() - y0_, cell_);
  if (i < 0 || j < 0 || i >= cols_ || j >= rows_) return false;
  const auto k = static_cast<std::uint64_t>(j * cols_ + i);
  return ((bits_[k >> 6] >> (k & 63)) & 1u) != 0;
}

std::uint64_t PheromoneRaster::marked() const {
  std::uint64_t n = 0;
  for (std::uint64_t w : bits_) n += static_cast<std::uint64_t>(__builtin_popcountll(w));
  return n;
}

VisitLog run_visit(const World& world, const TrialParams& params, std::uint64_t trial, int visit,
                   kernel::TraceHash& hash, const std::function<bool(const Pose&)>& on_step) {
  if (params.steps < 0 || params.steps > 100000000)
    throw kernel::InputError("--steps", "the steps per visit must be in [0, 100000000]");
  const auto v = static_cast<std::uint64_t>(visit);
  kernel::Stream start_stream(params.seed, params.experiment, trial, v, 1);
  kernel::Stream noise(params.seed, params.experiment, trial, v, 2);
  ExplorationBehaviour behaviour(kernel::Stream(params.seed, params.experiment, trial, v, 0));
  Pose pose = world.start_pose(start_stream);
  VisitLog log;
  log.trail.reserve(static_cast<std::size_t>(params.steps) + 1);
  log.trail.push_back(pose.position);
  bool more = on_step(pose);
  auto word = [](std::int32_t lo, std::int32_t hi) {
    return static_cast<std::uint64_t>(static_cast<std::uint32_t>(lo)) |
           (static_cast<std::uint64_t>(static_cast<std::uint32_t>(hi)) << 32);
  };
  for (std::int64_t s = 0; more && s < params.steps; ++s) {
    const Observation obs = world.sense(pose, &noise);
    const Command cmd = behaviour.step(obs);
    const FxPoint before = pose.position;
    if (!world.move(pose, cmd)) ++log.blocked;
    const std::int64_t dx = std::int64_t{pose.position.x.raw()} - before.x.raw();
    const std::int64_t dy = std::int64_t{pose.position.y.raw()} - before.y.raw();
    // The step's length is within a few raw units of the commanded forward distance, so the exact
    // floor square root starts there and corrects by +/- 1 (isqrt64 was 15 % of a step's time).
    const auto n2 = static_cast<std::uint64_t>(dx * dx + dy * dy);
    std::uint64_t root = 0;
    if (n2 != 0) {
      const Fx forward = world.body().speed * (cmd.left + cmd.right) * Fx::from_ratio(1, 2);
      root = static_cast<std::uint64_t>(kernel::abs(forward).raw());
      while (root * root > n2) --root;
      while ((root + 1) * (root + 1) <= n2) ++root;
    }
    log.length_raw += static_cast<std::int64_t>(root);
    log.trail.push_back(pose.position);
    more = on_step(pose);
    hash.add_u64(word(pose.position.x.raw(), pose.position.y.raw()));
    hash.add_u64(word(static_cast<std::int32_t>(pose.heading.raw()), behaviour.r().raw()));
    hash.add_u64(word(behaviour.w_left().raw(), behaviour.w_right().raw()));
  }
  return log;
}

TrialResult run_trial(const World& world, const TrialParams& params, std::uint64_t trial) {
  TrialResult result;
  result.trial = trial;
  kernel::TraceHash hash(params.seed);
  hash.add_u64(trial);
  PheromoneRaster raster(world.lower(), world.upper(), params.width);
  VisitLog first = run_visit(world, params, trial, 1, hash, [&raster](const Pose& p) {
    raster.lay(p.position);
    return true;
  });
  CrossingDetector detector;
  std::uint64_t bc = 0;
  VisitLog second = run_visit(world, params, trial, 2, hash, [&](const Pose& p) {
    if (detector.update(raster.at(p.position))) ++bc;
    return params.stop_bc == 0 || bc < params.stop_bc;
  });
  result.bc = bc;
  result.length1_raw = first.length_raw;
  result.length2_raw = second.length_raw;
  result.blocked = first.blocked + second.blocked;
  result.crossings_exact = kernel::count_proper_crossings(first.trail, second.trail);
  hash.add_u64(bc).add_u64(first.blocked).add_u64(second.blocked).add_u64(result.crossings_exact);
  result.hash = hash.finish();
  if (params.keep_trails) {
    result.trail1 = std::move(first.trail);
    result.trail2 = std::move(second.trail);
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
