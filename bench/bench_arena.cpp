// Arenas: building the standard arena, WKT round trips, and rasterizing the standard arena (the
// circle of diameter 100, 256 vertices) at the cell sizes the experiments use, down to 0.01.
#include <antkit/geometry/arena.hpp>
#include <antkit/geometry/arena_raster.hpp>
#include <antkit/geometry/wkt.hpp>
#include <benchmark/benchmark.h>
#include <string>

namespace {

using namespace antkit::geometry;

void BM_BuildStandardArena(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(make_circle(kStandardDiameter));
}
BENCHMARK(BM_BuildStandardArena)->Unit(benchmark::kMicrosecond);

void BM_BuildObstaclesArena(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(make_obstacles_arena(standard_area()));
}
BENCHMARK(BM_BuildObstaclesArena)->Unit(benchmark::kMicrosecond);

void BM_WktRoundTripStandard(benchmark::State& state) {
  const Arena arena = make_circle(kStandardDiameter);
  for (auto _ : state) benchmark::DoNotOptimize(read_wkt(write_wkt(arena)));
}
BENCHMARK(BM_WktRoundTripStandard)->Unit(benchmark::kMicrosecond);

// state.range(0) = cells per robot diameter: 1, 10, 100 (cell size 1, 0.1, 0.01).
void BM_RasterizeStandardArena(benchmark::State& state) {
  const Arena arena = make_circle(kStandardDiameter);
  const CellSize cell(1, state.range(0));
  std::size_t cells = 0;
  for (auto _ : state) {
    const auto raster = rasterize(arena, cell);
    cells = raster.grid.size();
    benchmark::DoNotOptimize(raster.grid.cells().data());
  }
  state.counters["cells"] = static_cast<double>(cells);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(cells));
}
BENCHMARK(BM_RasterizeStandardArena)->Arg(1)->Arg(10)->Arg(100)->Unit(benchmark::kMillisecond);

} // namespace
