// Spanning Tree Coverage (issue 3): offline on 4096^2 sub-cells with 10 % blocked cells and on an
// empty 16384^2 map (target >= 100 M sub-cells/s on one core, <= 2 bytes per sub-cell beyond the
// map); online and ant on 4096^2 (target >= 20 M sub-cells/s). items/s below is sub-cells of the
// tour per second.
#include <antkit/kernel/random.hpp>
#include <antkit/stc/offline.hpp>
#include <antkit/stc/world.hpp>
#include <benchmark/benchmark.h>
#include <cstdint>
#include <sys/resource.h>

using antkit::kernel::Occupancy;
using antkit::kernel::OccupancyGrid;
using namespace antkit::stc;

namespace {

// side x side sub-cells; `blocked_percent` of the cells blocked (all four sub-cells), drawn from a
// keyed stream; the start cell (0, 0) is kept free.
OccupancyGrid bench_map(std::int32_t side, std::uint32_t blocked_percent) {
  OccupancyGrid map(side, side, Occupancy::Free);
  if (blocked_percent == 0) return map;
  antkit::kernel::Stream stream(2026, 3, 0, 0, 0x62656E6368); // "bench"
  for (std::int32_t cy = 0; cy < side / 2; ++cy)
    for (std::int32_t cx = 0; cx < side / 2; ++cx)
      if ((cx | cy) != 0 && stream.chance(blocked_percent, 100))
        for (int q = 0; q < 4; ++q) map[subcell_of({cx, cy}, q)] = Occupancy::Blocked;
  return map;
}

const OccupancyGrid& map_4096() {
  static const OccupancyGrid map = bench_map(4096, 10);
  return map;
}

long max_rss_kib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

// Offline STC, both phases (free cells from the map, the tree, the tour), from the map in memory.
void run_offline(benchmark::State& state, const OccupancyGrid& map) {
  std::int64_t subcells = 0;
  std::size_t extra_bytes = 0;
  for (auto _ : state) {
    const SpanningTree tree(map, {0, 0});
    std::uint64_t fold = 0;
    std::int64_t n = 0;
    tree.tour([&](SubCell s) {
      fold += static_cast<std::uint64_t>(s.x) * 31u + static_cast<std::uint64_t>(s.y);
      ++n;
    });
    benchmark::DoNotOptimize(fold);
    subcells += n;
    // The tree's one byte per cell is everything offline STC allocates beyond the map.
    extra_bytes = static_cast<std::size_t>(tree.shape().cells_x) *
                  static_cast<std::size_t>(tree.shape().cells_y);
  }
  state.SetItemsProcessed(subcells);
  state.counters["extra_bytes_per_subcell"] =
      static_cast<double>(extra_bytes) / static_cast<double>(map.size());
  state.counters["max_rss_MiB"] = static_cast<double>(max_rss_kib()) / 1024.0;
}

void BM_StcOffline4096Blocked10(benchmark::State& state) {
  run_offline(state, map_4096());
}
BENCHMARK(BM_StcOffline4096Blocked10)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_StcOffline16384Empty(benchmark::State& state) {
  const OccupancyGrid map(16384, 16384, Occupancy::Free); // 256 MiB, the map itself
  run_offline(state, map);
}
BENCHMARK(BM_StcOffline16384Empty)->Unit(benchmark::kMillisecond)->Iterations(2);

// A variant run as a controller in the simulated world (observations, marks, trace hash).
void run_world(benchmark::State& state, Variant variant) {
  const OccupancyGrid& map = map_4096();
  StcWorld world;
  RunOptions options;
  options.record_path = false;
  std::int64_t subcells = 0;
  for (auto _ : state) {
    const RunResult r = run_stc(world, map, {0, 0}, variant, options);
    benchmark::DoNotOptimize(r.hash);
    subcells += r.positions;
  }
  state.SetItemsProcessed(subcells);
}

void BM_StcOnline4096(benchmark::State& state) {
  run_world(state, Variant::Online);
}
BENCHMARK(BM_StcOnline4096)->Unit(benchmark::kMillisecond)->MinTime(2.0);
void BM_StcAnt4096(benchmark::State& state) {
  run_world(state, Variant::Ant);
}
BENCHMARK(BM_StcAnt4096)->Unit(benchmark::kMillisecond)->MinTime(2.0);
void BM_StcAntEdge4096(benchmark::State& state) {
  run_world(state, Variant::AntEdge);
}
BENCHMARK(BM_StcAntEdge4096)->Unit(benchmark::kMillisecond)->MinTime(2.0);
void BM_StcOfflineWorld4096(benchmark::State& state) {
  run_world(state, Variant::Offline);
}
BENCHMARK(BM_StcOfflineWorld4096)->Unit(benchmark::kMillisecond)->MinTime(2.0);

} // namespace
