// `check stc` on a 1024 x 1024 sub-cell map's tour (1 048 576 positions), in memory: the C++ side
// of the Python package's call-overhead figure (bench/python_overhead.py runs this and the same
// check through `antkit.check_stc` and prints the ratio).
#include <antkit/kernel/grid.hpp>
#include <antkit/stc/world.hpp>
#include <antkit/testing/stc_audit.hpp>
#include <benchmark/benchmark.h>

namespace {

void BM_CheckStc1024(benchmark::State& state) {
  using antkit::kernel::Occupancy;
  antkit::maps::GridMap map;
  map.cells = antkit::kernel::OccupancyGrid(1024, 1024, Occupancy::Free);
  antkit::testing::TourFile tour;
  tour.path = antkit::stc::run_stc(map.cells, {0, 0}, antkit::stc::Variant::Offline).path;
  antkit::testing::StcCheckRequest request;
  request.start = antkit::kernel::Cell{0, 0};
  request.map_file = "map";
  request.tour_file = "path";
  for (auto _ : state) {
    const auto report = antkit::testing::check_stc(map, tour, request);
    if (!report.audit.ok()) state.SkipWithError("the tour did not pass");
    benchmark::DoNotOptimize(report.audit.covered);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(tour.path.size()));
}
BENCHMARK(BM_CheckStc1024)->Unit(benchmark::kMillisecond);

} // namespace
