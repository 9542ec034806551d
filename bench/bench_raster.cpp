// Rasterization and line-of-sight speed: cells per second (items_per_second) over fixed sets of
// segments between random cells of a 1024 x 1024 grid, and proper-crossing counts between trails.
#include <algorithm>
#include <antkit/kernel/random.hpp>
#include <antkit/kernel/raster.hpp>
#include <antkit/kernel/segment.hpp>
#include <benchmark/benchmark.h>
#include <cstdint>
#include <utility>
#include <vector>

namespace {

using antkit::kernel::Cell;
using antkit::kernel::Fx;
using antkit::kernel::FxPoint;
using antkit::kernel::Occupancy;
using antkit::kernel::OccupancyGrid;
using antkit::kernel::Stream;

constexpr std::int32_t kSide = 1024;

std::vector<std::pair<Cell, Cell>> segments(std::size_t n, std::int32_t max_length) {
  Stream s(2026, 0, 0, 0, 0);
  std::vector<std::pair<Cell, Cell>> out;
  for (std::size_t k = 0; k < n; ++k) {
    const Cell a{s.between(0, kSide - 1), s.between(0, kSide - 1)};
    const Cell d{s.between(-max_length, max_length), s.between(-max_length, max_length)};
    const Cell b{std::clamp(a.x + d.x, 0, kSide - 1), std::clamp(a.y + d.y, 0, kSide - 1)};
    out.emplace_back(a, b);
  }
  return out;
}

void BM_SupercoverCells(benchmark::State& state) {
  const auto segs = segments(1024, static_cast<std::int32_t>(state.range(0)));
  std::int64_t cells = 0;
  for (auto _ : state) {
    for (const auto& [a, b] : segs)
      antkit::kernel::for_each_supercover_cell(a, b, [&cells](Cell c) {
        benchmark::DoNotOptimize(c);
        ++cells;
      });
  }
  state.SetItemsProcessed(cells);
}
BENCHMARK(BM_SupercoverCells)->Arg(16)->Arg(1023);

void BM_SupercoverVector(benchmark::State& state) {
  const auto segs = segments(1024, static_cast<std::int32_t>(state.range(0)));
  std::int64_t cells = 0;
  for (auto _ : state) {
    for (const auto& [a, b] : segs) {
      auto v = antkit::kernel::supercover(a, b);
      cells += static_cast<std::int64_t>(v.size());
      benchmark::DoNotOptimize(v.data());
    }
  }
  state.SetItemsProcessed(cells);
}
BENCHMARK(BM_SupercoverVector)->Arg(16)->Arg(1023);

void BM_BresenhamCells(benchmark::State& state) {
  const auto segs = segments(1024, static_cast<std::int32_t>(state.range(0)));
  std::int64_t cells = 0;
  for (auto _ : state) {
    for (const auto& [a, b] : segs)
      antkit::kernel::for_each_bresenham_cell(a, b, [&cells](Cell c) {
        benchmark::DoNotOptimize(c);
        ++cells;
      });
  }
  state.SetItemsProcessed(cells);
}
BENCHMARK(BM_BresenhamCells)->Arg(16)->Arg(1023);

// Line of sight on an all-free grid: every query walks its whole supercover. Items are the cells
// examined (the supercover minus its two ends).
void BM_LineOfSightFreeCells(benchmark::State& state) {
  const OccupancyGrid grid(kSide, kSide, Occupancy::Free);
  const auto segs = segments(1024, static_cast<std::int32_t>(state.range(0)));
  std::int64_t examined_per_pass = 0;
  for (const auto& [a, b] : segs)
    examined_per_pass +=
        a == b ? 0 : static_cast<std::int64_t>(antkit::kernel::supercover(a, b).size()) - 2;
  std::int64_t passes = 0;
  for (auto _ : state) {
    bool all = true;
    for (const auto& [a, b] : segs) all = antkit::kernel::line_of_sight(grid, a, b) && all;
    benchmark::DoNotOptimize(all);
    ++passes;
  }
  state.SetItemsProcessed(passes * examined_per_pass);
}
BENCHMARK(BM_LineOfSightFreeCells)->Arg(16)->Arg(1023);

// Queries per second on a grid with 20 % of its cells blocked (early exit at the first block).
void BM_LineOfSightQueries20pct(benchmark::State& state) {
  OccupancyGrid grid(kSide, kSide, Occupancy::Free);
  Stream s(2026, 0, 0, 0, 1);
  for (auto& v : grid.cells()) v = s.chance(1, 5) ? Occupancy::Blocked : Occupancy::Free;
  const auto segs = segments(4096, static_cast<std::int32_t>(state.range(0)));
  std::int64_t queries = 0;
  for (auto _ : state) {
    std::int64_t seen = 0;
    for (const auto& [a, b] : segs) seen += antkit::kernel::line_of_sight(grid, a, b) ? 1 : 0;
    benchmark::DoNotOptimize(seen);
    queries += static_cast<std::int64_t>(segs.size());
  }
  state.SetItemsProcessed(queries);
}
BENCHMARK(BM_LineOfSightQueries20pct)->Arg(16)->Arg(1023);

// Two random-walk trails of n points each (steps of up to 8 units in a 1000-unit square): segment
// pairs tested per second, bucketed versus the plain pair loop.
std::vector<FxPoint> trail(std::size_t n, std::uint64_t robot) {
  Stream s(2026, 1, 0, robot, 0);
  std::vector<FxPoint> pts;
  std::int32_t x = 500 << 16, y = 500 << 16;
  for (std::size_t k = 0; k < n; ++k) {
    pts.push_back({Fx::from_raw(x), Fx::from_raw(y)});
    x = std::clamp(x + s.between(-(8 << 16), 8 << 16), 0, 1000 << 16);
    y = std::clamp(y + s.between(-(8 << 16), 8 << 16), 0, 1000 << 16);
  }
  return pts;
}

void BM_CountProperCrossings(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto a = trail(n, 0), b = trail(n, 1);
  for (auto _ : state) benchmark::DoNotOptimize(antkit::kernel::count_proper_crossings(a, b));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>((n - 1) * (n - 1)));
}
BENCHMARK(BM_CountProperCrossings)->Arg(1000)->Arg(10000);

void BM_PairLoopProperCrossings(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto a = trail(n, 0), b = trail(n, 1);
  for (auto _ : state) {
    std::uint64_t count = 0;
    for (std::size_t i = 0; i + 1 < n; ++i)
      for (std::size_t j = 0; j + 1 < n; ++j)
        count += antkit::kernel::properly_cross({a[i], a[i + 1]}, {b[j], b[j + 1]}) ? 1u : 0u;
    benchmark::DoNotOptimize(count);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>((n - 1) * (n - 1)));
}
BENCHMARK(BM_PairLoopProperCrossings)->Arg(1000);

} // namespace
