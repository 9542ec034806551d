// Buffon's-needle measurement: simulated robot steps per second (sensing, behaviour, motion and
// pheromone, one core), one whole trial, and the exact crossing count of two default trails.
#include <antkit/buffon/measurement.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <benchmark/benchmark.h>

namespace {

namespace buffon = antkit::buffon;

const buffon::World& standard_world() {
  static const buffon::World w(antkit::geometry::build_arena_spec("circle:d=100").arena.walls_fx());
  return w;
}

// One visit of 50 000 steps laying pheromone: items = robot steps.
void BM_BuffonVisitSteps(benchmark::State& state) {
  const auto& w = standard_world();
  buffon::TrialParams p;
  buffon::PheromoneRaster raster(w.lower(), w.upper(), p.width);
  std::uint64_t trial = 0;
  for (auto _ : state) {
    antkit::kernel::TraceHash h;
    auto log = buffon::run_visit(w, p, trial++, 1, h, [&raster](const buffon::Pose& pose) {
      raster.lay(pose.position);
      return true;
    });
    benchmark::DoNotOptimize(log.length_raw);
  }
  state.SetItemsProcessed(state.iterations() * p.steps);
}
BENCHMARK(BM_BuffonVisitSteps)->Unit(benchmark::kMillisecond);

// A whole default trial (two visits, BC, exact crossings, hash): items = robot steps.
void BM_BuffonTrial(benchmark::State& state) {
  const auto& w = standard_world();
  buffon::TrialParams p;
  std::uint64_t trial = 0;
  for (auto _ : state) benchmark::DoNotOptimize(buffon::run_trial(w, p, trial++).hash);
  state.SetItemsProcessed(state.iterations() * 2 * p.steps);
}
BENCHMARK(BM_BuffonTrial)->Unit(benchmark::kMillisecond);

} // namespace
