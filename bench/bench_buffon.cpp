// Buffon's-needle measurement: simulated robot steps per second (sensing, behaviour, motion and
// pheromone, one core), one whole trial, and the exact crossing count of two default trails.
#include <antkit/buffon/checkpoints.hpp>
#include <antkit/buffon/crossing_counter.hpp>
#include <antkit/buffon/measurement.hpp>
#include <antkit/buffon/randomized_search.hpp>
#include <antkit/buffon/stopping.hpp>
#include <antkit/buffon/two_markers.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <benchmark/benchmark.h>
#include <optional>
#include <vector>

namespace {

namespace buffon = antkit::buffon;

const buffon::World& standard_world() {
  static const buffon::World w(antkit::geometry::build_arena_spec("circle:d=100").arena.walls_fx());
  return w;
}

// The trail of one default visit in the standard circle, recorded once.
const std::vector<antkit::kernel::FxPoint>& standard_trail() {
  static const std::vector<antkit::kernel::FxPoint> trail = [] {
    antkit::kernel::TraceHash h;
    return buffon::run_visit(standard_world(), buffon::TrialParams{}, 0, 1, h,
                             [](const buffon::Pose&) { return true; })
        .trail;
  }();
  return trail;
}

// Laying the pheromone along a recorded trail, alone: items = lay() calls. Argument 0: the fast
// path (lay), 1: the reference loop it replaced (lay_exact), for before/after ratios in one run.
void BM_BuffonLay(benchmark::State& state) {
  const auto& w = standard_world();
  const auto& trail = standard_trail();
  buffon::PheromoneRaster raster(w.lower(), w.upper(), buffon::kDefaultWidth);
  const bool exact = state.range(0) == 1;
  for (auto _ : state) {
    if (exact)
      for (const auto& p : trail) raster.lay_exact(p);
    else
      for (const auto& p : trail) raster.lay(p);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(trail.size()));
}
BENCHMARK(BM_BuffonLay)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// Reading the pheromone under a recorded trail (visit 2's sensing): items = at() calls.
// Argument 0: at(), 1: at_exact().
void BM_BuffonAt(benchmark::State& state) {
  const auto& w = standard_world();
  const auto& trail = standard_trail();
  buffon::PheromoneRaster raster(w.lower(), w.upper(), buffon::kDefaultWidth);
  for (std::size_t k = 0; k < trail.size(); k += 2) raster.lay(trail[k]);
  const bool exact = state.range(0) == 1;
  for (auto _ : state) {
    std::uint64_t n = 0;
    if (exact)
      for (const auto& p : trail) n += raster.at_exact(p) ? 1u : 0u;
    else
      for (const auto& p : trail) n += raster.at(p) ? 1u : 0u;
    benchmark::DoNotOptimize(n);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(trail.size()));
}
BENCHMARK(BM_BuffonAt)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// The behaviour's two draws per step (n, n_bar): items = steps. Argument 0: BufferedStream (the
// batched draw, four Philox blocks at a time), 1: kernel::uniform on the Stream (one block per
// two steps), for before/after ratios in one run.
void BM_BuffonDraws(benchmark::State& state) {
  namespace d = buffon::detail;
  const bool plain = state.range(0) == 1;
  constexpr std::int64_t kSteps = 50000;
  std::uint64_t trial = 0;
  for (auto _ : state) {
    antkit::kernel::Stream stream(1, buffon::kExperiment, trial++, 1, 0);
    buffon::BufferedStream buffered(stream);
    std::int64_t sum = 0;
    for (std::int64_t s = 0; s < kSteps; ++s) {
      if (plain) {
        sum += antkit::kernel::uniform(stream, -d::kNLimit, d::kNLimit).raw();
        sum += antkit::kernel::uniform(stream, d::kNBarLow, d::kOne).raw();
      } else {
        sum += buffered.uniform(-d::kNLimit, d::kNLimit).raw();
        sum += buffered.uniform(d::kNBarLow, d::kOne).raw();
      }
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * kSteps);
}
BENCHMARK(BM_BuffonDraws)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// One visit of 50 000 steps in the standard circle: items = robot steps. Argument 0 lays the
// pheromone at every step (the target: >= 10 M steps/s with sensing and pheromone),
// argument 1 does not (the robot alone: sensing, behaviour, motion, trace hash). The second
// argument is the circle's diameter: 100 is the standard arena (the target's), 20 a small one where
// walls are in sensor range far more often and the raster fits in the L2 cache.
void BM_BuffonVisitSteps(benchmark::State& state) {
  static const buffon::World small(
      antkit::geometry::build_arena_spec("circle:d=20").arena.walls_fx());
  const auto& w = state.range(1) == 20 ? small : standard_world();
  buffon::TrialParams p;
  buffon::PheromoneRaster raster(w.lower(), w.upper(), p.width);
  const bool lay = state.range(0) == 0;
  std::uint64_t trial = 0;
  for (auto _ : state) {
    antkit::kernel::TraceHash h;
    auto log = buffon::run_visit(w, p, trial++, 1, h, [&](const buffon::Pose& pose) {
      if (lay) raster.lay(pose.position);
      return true;
    });
    benchmark::DoNotOptimize(log.length_raw);
  }
  state.SetItemsProcessed(state.iterations() * p.steps);
}
BENCHMARK(BM_BuffonVisitSteps)
    ->Args({0, 100})
    ->Args({1, 100})
    ->Args({0, 20})
    ->Args({1, 20})
    ->Unit(benchmark::kMillisecond);

// Issue 17's online bookkeeping beside BM_BuffonVisitSteps/0 (laying only): a visit that also
// counts its exact self-crossings (SelfCrossingCounter), feeds FirstVisitMonitor and counts wall
// encounters (range(0) == 0), or a two-marker walk that tests each step against the other marker
// and inserts it into its own (range(0) == 1). The precision is 1 ppm, so no check stops the visit:
// every iteration is the full 50 000 steps, as in BM_BuffonVisitSteps. items = robot steps.
void BM_BuffonOnlineSteps(benchmark::State& state) {
  static const buffon::World small(
      antkit::geometry::build_arena_spec("circle:d=20").arena.walls_fx());
  const auto& w = state.range(1) == 20 ? small : standard_world();
  buffon::TrialParams p;
  p.precision_millionths = 1;
  buffon::PheromoneRaster raster(w.lower(), w.upper(), p.width);
  std::uint64_t trial = 0;
  std::vector<std::uint32_t> crossed;
  for (auto _ : state) {
    antkit::kernel::TraceHash h;
    if (state.range(0) == 0) {
      std::optional<buffon::SelfCrossingCounter> self;
      buffon::FirstVisitMonitor monitor(p.precision_millionths);
      buffon::WallEncounters encounters;
      auto log = buffon::run_visit(w, p, trial++, 1, h,
                                   [&](const buffon::Pose& pose, const buffon::Observation& o) {
                                     raster.lay(pose.position);
                                     encounters.observe(o);
                                     if (!self) {
                                       self.emplace(w.lower(), w.upper(), pose.position);
                                       return true;
                                     }
                                     crossed.clear();
                                     self->add(pose.position, &crossed);
                                     for (const std::uint32_t s : crossed) monitor.crossing(s);
                                     return !monitor.end_step();
                                   });
      benchmark::DoNotOptimize(log.length_raw);
      benchmark::DoNotOptimize(monitor.count());
    } else {
      p.total_steps = p.steps;
      benchmark::DoNotOptimize(buffon::run_two_marker_trial(w, p, trial++).hash);
    }
  }
  state.SetItemsProcessed(state.iterations() * p.steps);
}
BENCHMARK(BM_BuffonOnlineSteps)
    ->Args({0, 100})
    ->Args({1, 100})
    ->Args({0, 20})
    ->Args({1, 20})
    ->Unit(benchmark::kMillisecond);

// A whole default trial (two visits, BC, exact crossings, hash): items = robot steps.
void BM_BuffonTrial(benchmark::State& state) {
  const auto& w = standard_world();
  buffon::TrialParams p;
  std::uint64_t trial = 0;
  for (auto _ : state) benchmark::DoNotOptimize(buffon::run_trial(w, p, trial++).hash);
  state.SetItemsProcessed(state.iterations() * 2 * p.steps);
}
BENCHMARK(BM_BuffonTrial)->Unit(benchmark::kMillisecond);

// Issue 17's trials beside BM_BuffonTrial, the same 2 x 50 000 steps on the same arena, with a
// precision (1 ppm) that no check meets, so every trial runs its whole budget: the online first
// visit (range(0) == 0: self-crossings and FirstVisitMonitor in visit 1, online crossings and
// PrecisionMonitor in visit 2, wall encounters) and two markers (range(0) == 1). items = steps.
void BM_BuffonTrialOnline(benchmark::State& state) {
  const auto& w = standard_world();
  buffon::TrialParams p;
  p.precision_millionths = 1;
  p.total_steps = 2 * p.steps;
  p.online_first_visit = state.range(0) == 0;
  std::uint64_t trial = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(state.range(0) == 0
                                 ? buffon::run_trial(w, p, trial++).hash
                                 : buffon::run_two_marker_trial(w, p, trial++).hash);
  state.SetItemsProcessed(state.iterations() * 2 * p.steps);
}
BENCHMARK(BM_BuffonTrialOnline)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// Paper 000's Figure 14 trial (run_checkpoints: visit 1 to the longest of 10 checkpoints 168
// apart, visit 2 with a detector per checkpoint, and RS's walk of twice the length, stamping the
// body's footprint on cells of 0.1), as buffon-experiment --figure 14 runs it, in the circle of
// diameter 60. items = trials.
void BM_BuffonCheckpointTrial(benchmark::State& state) {
  static const buffon::World w(
      antkit::geometry::build_arena_spec("circle:d=60", "figure").arena.walls_fx());
  buffon::TrialParams p;
  std::uint64_t trial = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(
        buffon::run_checkpoints(w, p, trial++, std::int64_t{168} * 65536, 10).rs_cells);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_BuffonCheckpointTrial)->Unit(benchmark::kMillisecond);

// RS's footprint alone: the body's disk (radius 0.5) stamped on cells of 0.1 along the standard
// trail (rs_mark). items = stamps.
void BM_BuffonRsMark(benchmark::State& state) {
  const auto& trail = standard_trail();
  const auto& w = standard_world();
  buffon::ByteRasterCore g;
  g.init(w.lower(), w.upper(), buffon::kRsCellRaw);
  std::vector<std::uint8_t> storage(g.cells());
  std::uint64_t cells = 0;
  for (auto _ : state) {
    g.bind(storage.data(), 0);
    for (const auto& p : trail) cells += buffon::rs_mark(g, p);
  }
  benchmark::DoNotOptimize(cells);
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(trail.size()));
}
BENCHMARK(BM_BuffonRsMark)->Unit(benchmark::kMillisecond);

} // namespace
