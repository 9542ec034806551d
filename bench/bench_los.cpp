// Issue 5: the full exploration of a 512x512 map by the pair (target: under 1 s on one core), and
// of the largest real map in data/maps (brc202d, 530x481).
//   antkit_bench --benchmark_filter=Los
#include <antkit/los/explore.hpp>
#include <antkit/maps/map_io.hpp>
#include <benchmark/benchmark.h>
#include <filesystem>

namespace {

namespace los = antkit::los;
using antkit::kernel::OccupancyGrid;

// 512x512 with 1 % scattered single-cell obstacles (2600), or 200 blocks of six.
const OccupancyGrid& room512(bool blocks) {
  static const OccupancyGrid scattered = los::scattered_obstacles(512, 512, 2600, 1, 1, {0, 511});
  static const OccupancyGrid blocked = los::obstacle_blocks(512, 512, 200, 1, 1, {0, 511});
  return blocks ? blocked : scattered;
}

void run(benchmark::State& state, const OccupancyGrid& g, los::Algorithm algo, bool sight) {
  const auto pair = los::start_pair(g, los::default_start(g));
  los::ExploreOptions o;
  o.algorithm = algo;
  o.line_of_sight = sight;
  std::uint64_t steps = 0, eme = 0;
  for (auto _ : state) {
    const auto r = los::explore(g, pair[0], pair[1], o);
    steps = r.steps;
    eme = r.eme;
    benchmark::DoNotOptimize(r.hash);
  }
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["eme"] = static_cast<double>(eme);
}

void BM_LosFastWallFollow512(benchmark::State& state) {
  run(state, room512(state.range(0) != 0), los::Algorithm::FastWallFollow, true);
}
void BM_LosFrontier512(benchmark::State& state) {
  run(state, room512(state.range(0) != 0), los::Algorithm::Frontier, state.range(1) != 0);
}
void BM_LosBrc202d(benchmark::State& state) {
  // bench/ has no define for the shared folder: find it beside the source tree.
  const std::filesystem::path path =
      std::filesystem::path(__FILE__).parent_path() / "../data/maps/movingai/brc202d.map";
  if (!std::filesystem::exists(path)) {
    state.SkipWithError("brc202d.map not found");
    return;
  }
  static const OccupancyGrid g = antkit::maps::load_map(path).cells;
  run(state, g, state.range(0) == 0 ? los::Algorithm::FastWallFollow : los::Algorithm::Frontier,
      true);
}

} // namespace

BENCHMARK(BM_LosFastWallFollow512)
    ->ArgName("blocks")
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LosFrontier512)
    ->ArgNames({"blocks", "los"})
    ->Args({0, 1})
    ->Args({0, 0})
    ->Args({1, 1})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LosBrc202d)->ArgName("frontier")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
