// Buffon counts at trail-length checkpoints and the RS baseline (checkpoints.hpp).
#include <algorithm>
#include <antkit/buffon/checkpoints.hpp>
#include <antkit/buffon/randomized_search.hpp>
#include <antkit/buffon/step_root.hpp>
#include <antkit/buffon/stopping.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cmath>

namespace antkit::buffon {

namespace {

// A raster of bytes over the walls' bounding box (randomized_search.hpp's core over a vector);
// disk stamps as in PheromoneRaster.
struct ByteRaster : ByteRasterCore {
  std::vector<std::uint8_t> storage;
  ByteRaster(FxPoint lo, FxPoint hi, std::int64_t cell_raw, std::uint8_t init) {
    if (!ByteRasterCore::init(lo, hi, cell_raw))
      throw kernel::InputError("trail width", "raster too large for this arena and width");
    storage.resize(static_cast<std::size_t>(cells()));
    bind(storage.data(), init);
  }
};

// Runs a visit until its length reaches `limit_raw` (or the step cap), calling f(pose, length).
template <class F>
void walk(const World& world, const TrialParams& params, std::uint64_t trial, int visit,
          std::int64_t limit_raw, F&& f) {
  TrialParams p = params;
  // Enough steps for the limit at 1.3 times the default mean step (1680 / 50 000 units, so
  // 0.0336 = 2202 raw): the visit stops once the limit is passed.
  p.steps = limit_raw * 13 / (10 * 2202) + 1000;
  kernel::TraceHash unused;
  std::int64_t length = 0;
  std::uint64_t step = 0; // the previous step's length: the next one's guess (step_root.hpp)
  FxPoint prev{};
  bool first = true, done = false;
  // The callback ignores everything past the limit; a visit that falls short of it (a robot stuck
  // for long) leaves the last checkpoints at its final length.
  run_visit(world, p, trial, visit, unused, [&](const Pose& pose) {
    if (done) return false;
    if (!first) {
      const std::int64_t dx = std::int64_t{pose.position.x.raw()} - prev.x.raw();
      const std::int64_t dy = std::int64_t{pose.position.y.raw()} - prev.y.raw();
      step = step_root(static_cast<std::uint64_t>(dx * dx + dy * dy), step);
      length += static_cast<std::int64_t>(step);
    }
    first = false;
    prev = pose.position;
    if (length > limit_raw) {
      done = true;
      return false;
    }
    f(pose, length);
    return true;
  });
}

// RS's walk through run_visit: visit kRsVisit of `trial` for params.steps steps, marking the
// body's footprint from the start on, until `target` cells are marked; its steps go into `hash`.
struct RsWalk {
  std::uint64_t cells = 0, blocked = 0;
  std::int64_t length_raw = 0;
};
RsWalk rs_walk(const World& world, const TrialParams& params, std::uint64_t trial,
               std::uint64_t target, kernel::TraceHash& hash) {
  ByteRaster rs(world.lower(), world.upper(), kRsCellRaw, 0);
  RsWalk out;
  const VisitLog log = run_visit(world, params, trial, kRsVisit, hash, [&](const Pose& pose) {
    out.cells += rs_mark(rs, pose.position);
    return out.cells < target;
  });
  out.length_raw = log.length_raw;
  out.blocked = log.blocked;
  return out;
}

} // namespace

CheckpointResult run_checkpoints(const World& world, const TrialParams& params, std::uint64_t trial,
                                 std::int64_t step_raw, int count) {
  if (count < 1 || count > 250)
    throw kernel::InputError("checkpoints", "count must be in [1, 250]");
  if (step_raw < 1) throw kernel::InputError("checkpoints", "the spacing must be positive");
  const std::int64_t limit = step_raw * count;
  const auto k_of = [step_raw](std::int64_t len) { // first checkpoint whose prefix holds len
    return static_cast<std::uint8_t>(std::max<std::int64_t>(1, (len + step_raw - 1) / step_raw));
  };
  CheckpointResult out;
  const auto K = static_cast<std::size_t>(count);
  out.bc.assign(K, 0);
  out.length2_raw.assign(K, 0);
  out.rs_cells.assign(K, 0);

  // Visit 1: the first checkpoint at which each cell was marked (0xFF: never).
  ByteRaster first(world.lower(), world.upper(), std::max<std::int64_t>(1, params.width.raw() / 4),
                   0xFF);
  const std::int64_t half_width = params.width.raw() / 2;
  walk(world, params, trial, 1, limit, [&](const Pose& pose, std::int64_t len) {
    const std::uint8_t k = k_of(len);
    first.disk(pose.position, half_width, [k](std::uint8_t& cell) { cell = std::min(cell, k); });
  });
  // Visit 2: K detectors.
  std::vector<CrossingDetector> detectors(K);
  walk(world, params, trial, 2, limit, [&](const Pose& pose, std::int64_t len) {
    const std::uint8_t marked_at = first.at(pose.position);
    for (std::size_t k = 0; k < K; ++k) {
      if (len > step_raw * static_cast<std::int64_t>(k + 1)) continue;
      out.length2_raw[k] = len;
      if (detectors[k].update(marked_at <= k + 1)) ++out.bc[k];
    }
  });
  // RS: one walk of twice the length, marking the body's footprint.
  out.rs_cell_raw = kRsCellRaw;
  ByteRaster rs(world.lower(), world.upper(), out.rs_cell_raw, 0);
  std::uint64_t marked = 0;
  std::size_t next = 0;
  walk(world, params, trial, kRsVisit, 2 * limit, [&](const Pose& pose, std::int64_t len) {
    while (next < K && len > 2 * step_raw * static_cast<std::int64_t>(next + 1))
      out.rs_cells[next++] = marked;
    marked += rs_mark(rs, pose.position);
  });
  while (next < K) out.rs_cells[next++] = marked;
  return out;
}

Footprint rs_footprint(std::span<const FxPoint> trail) {
  Footprint out;
  out.cell_raw = kRsCellRaw;
  if (trail.empty()) return out;
  std::int32_t x0 = trail[0].x.raw(), y0 = trail[0].y.raw(), x1 = x0, y1 = y0;
  for (const auto& p : trail) {
    x0 = std::min(x0, p.x.raw()), y0 = std::min(y0, p.y.raw());
    x1 = std::max(x1, p.x.raw()), y1 = std::max(y1, p.y.raw());
  }
  const std::int32_t r = kBodyRadius.raw() + static_cast<std::int32_t>(out.cell_raw);
  ByteRaster rs({Fx::from_raw(x0 - r), Fx::from_raw(y0 - r)},
                {Fx::from_raw(x1 + r), Fx::from_raw(y1 + r)}, out.cell_raw, 0);
  for (const auto& p : trail) out.cells += rs_mark(rs, p);
  return out;
}

RsCost rs_cost_to_precision(const World& world, const TrialParams& params, std::uint64_t trial,
                            double area, std::uint32_t precision_millionths,
                            std::int64_t max_steps) {
  if (precision_millionths < 1 || precision_millionths >= kPrecisionDenominator)
    throw kernel::InputError("precision", "the relative precision must be in (0, 1)");
  const std::int64_t cell = kRsCellRaw;
  const double cell_area =
      static_cast<double>(cell) * static_cast<double>(cell) / 65536.0 / 65536.0;
  const double p = static_cast<double>(precision_millionths) / kPrecisionDenominator;
  // The first whole number of cells whose area reaches (1 - P) area: computed once, so the stop is
  // an integer comparison in the walk.
  const auto target = static_cast<std::uint64_t>(std::ceil((1.0 - p) * area / cell_area));
  TrialParams walk = params;
  walk.steps = max_steps;
  kernel::TraceHash unused;
  const RsWalk w = rs_walk(world, walk, trial, target, unused);
  RsCost out;
  out.length_raw = w.length_raw;
  out.reached = w.cells >= target;
  return out;
}

RsRun run_rs(const World& world, const TrialParams& params, std::uint64_t trial) {
  kernel::TraceHash hash(params.seed);
  hash.add_u64(trial);
  const RsWalk w = rs_walk(world, params, trial, UINT64_MAX, hash);
  hash.add_u64(w.cells).add_u64(w.blocked);
  RsRun out;
  out.cells = w.cells;
  out.cell_raw = kRsCellRaw;
  out.length_raw = w.length_raw;
  out.blocked = w.blocked;
  out.hash = hash.finish();
  return out;
}

} // namespace antkit::buffon
