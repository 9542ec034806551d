// Map files: how long reading, writing and component counting take on the largest shared maps
// (brc202d.map, 530 x 481; willow-2010-02-18-0.10, 566 x 608). The maps are the checkout's
// data/maps, relative to this source file.
#include <antkit/maps/components.hpp>
#include <antkit/maps/map_io.hpp>
#include <benchmark/benchmark.h>
#include <filesystem>

namespace {

std::filesystem::path shared_map(const char* relative) {
  return std::filesystem::path(__FILE__).parent_path() / "../data/maps" / relative;
}

void BM_ParseMovingAI(benchmark::State& state) {
  const auto path = shared_map("movingai/brc202d.map");
  if (!std::filesystem::exists(path)) return state.SkipWithError("data/maps is missing");
  const auto text = antkit::maps::read_map_file(path);
  for (auto _ : state) benchmark::DoNotOptimize(antkit::maps::parse_movingai(text, "brc202d"));
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(text.size()));
}
BENCHMARK(BM_ParseMovingAI)->Unit(benchmark::kMillisecond);

void BM_WriteMovingAI(benchmark::State& state) {
  const auto path = shared_map("movingai/brc202d.map");
  if (!std::filesystem::exists(path)) return state.SkipWithError("data/maps is missing");
  const auto map = antkit::maps::load_map(path);
  for (auto _ : state) benchmark::DoNotOptimize(antkit::maps::write_movingai(map));
}
BENCHMARK(BM_WriteMovingAI)->Unit(benchmark::kMillisecond);

void BM_LoadRosMap(benchmark::State& state) {
  const auto path = shared_map("ros/willow-2010-02-18-0.10.yaml");
  if (!std::filesystem::exists(path)) return state.SkipWithError("data/maps is missing");
  // File reading included: this is what `antkit map info` pays.
  for (auto _ : state) benchmark::DoNotOptimize(antkit::maps::load_map(path));
}
BENCHMARK(BM_LoadRosMap)->Unit(benchmark::kMillisecond);

void BM_FreeComponents(benchmark::State& state) {
  const auto path =
      shared_map(state.range(0) == 0 ? "movingai/brc202d.map" : "ros/willow-2010-02-18-0.10.yaml");
  if (!std::filesystem::exists(path)) return state.SkipWithError("data/maps is missing");
  const auto map = antkit::maps::load_map(path);
  for (auto _ : state) benchmark::DoNotOptimize(antkit::maps::free_components(map.cells));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(map.cells.size()));
}
// 0: brc202d (one component of 43151 cells), 1: willow (187 components, 109207 free cells).
BENCHMARK(BM_FreeComponents)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

} // namespace
