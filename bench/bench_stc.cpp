// Spanning Tree Coverage (issue 3): offline on 4096^2 sub-cells with 10 % blocked cells and on an
// empty 16384^2 map (target >= 100 M sub-cells/s on one core, <= 2 bytes per sub-cell beyond the
// map); online and ant on 4096^2 (target >= 20 M sub-cells/s). items/s below is sub-cells of the
// tour per second.
#include <antkit/kernel/random.hpp>
#include <antkit/stc/offline.hpp>
#include <antkit/stc/world.hpp>
#include <array>
#include <benchmark/benchmark.h>
#include <cstddef>
#include <cstdint>
#include <sys/resource.h>
#include <vector>

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

// The offline STC of before the run-at-a-time walk and the mask-and-table search (commit
// 23a7ad0), kept here only as the "before" of the comparison, measured in the same run as the
// shipped code: one byte per cell in 64 x 64 tiles, the search testing one neighbour at a time,
// the walk deciding once per sub-cell.
class LegacyTree {
public:
  static constexpr std::uint8_t kFree = 0x01, kParent = 0x03, kInTree = 0x04, kRoot = 0x08;
  static constexpr int kChild = 4;

  LegacyTree(const OccupancyGrid& map, SubCell start)
      : shape_(cell_shape(map)), tiles_x_((static_cast<std::size_t>(shape_.cells_x) + 65) >> 6),
        root_(cell_of(start)), q0_(quadrant_of(start)) {
    const std::size_t tiles_y = (static_cast<std::size_t>(shape_.cells_y) + 65) >> 6;
    state_.assign((tiles_x_ * tiles_y) << 12, 0);
    const auto width = static_cast<std::size_t>(map.width());
    const auto& sub = map.cells();
    for (std::int32_t cy = 0; cy < shape_.cells_y; ++cy) {
      const std::size_t top = static_cast<std::size_t>(2 * cy) * width, bottom = top + width;
      for (std::int32_t cx = 0; cx < shape_.cells_x; ++cx) {
        const auto x = static_cast<std::size_t>(2 * cx);
        const bool free = sub[top + x] == Occupancy::Free && sub[top + x + 1] == Occupancy::Free &&
                          sub[bottom + x] == Occupancy::Free &&
                          sub[bottom + x + 1] == Occupancy::Free;
        state_[index({cx, cy})] = free ? kFree : std::uint8_t{0};
      }
    }
    build();
  }

  template <class Visit>
  void tour(Visit&& visit) const {
    Cell cell = root_;
    std::size_t at = index(cell);
    int q = q0_;
    visit(subcell_of(cell, q));
    for (;;) {
      const std::uint8_t here = state_[at];
      const int d = q;
      bool cross = ((here >> (kChild + d)) & 1) != 0;
      if (!cross && (here & kRoot) == 0 && (here & kParent) == d) {
        if (dir_add(d, 3) == q0_ && step(cell, d) == root_) return;
        cross = true;
      }
      if (cross) {
        cell = step(cell, d);
        at = index(cell);
        q = dir_add(d, 3);
      } else {
        q = dir_add(d, 1);
        if (q == q0_ && cell == root_) return;
      }
      visit(subcell_of(cell, q));
    }
  }

private:
  [[nodiscard]] std::size_t index(Cell c) const noexcept {
    const auto x = static_cast<std::size_t>(c.x + 1), y = static_cast<std::size_t>(c.y + 1);
    return ((((y >> 6) * tiles_x_ + (x >> 6)) << 12) | ((y & 63) << 6) | (x & 63));
  }
  void build() {
    std::uint8_t* s = state_.data();
    Cell cur = root_;
    std::size_t at = index(cur);
    s[at] = static_cast<std::uint8_t>(kInTree | kRoot | dir_add(q0_, 3));
    int k = 0;
    for (;;) {
      const std::uint8_t here = s[at];
      const int base = here & kParent;
      const int limit = (here & kRoot) ? 4 : 3;
      bool descended = false;
      for (; k < limit; ++k) {
        const int d = dir_add(base, 1 + k);
        const Cell nb = step(cur, d);
        const std::size_t n = index(nb);
        if (s[n] != kFree) continue;
        s[n] = static_cast<std::uint8_t>(kInTree | opposite(d));
        s[at] = static_cast<std::uint8_t>(s[at] | (1u << (kChild + d)));
        cur = nb;
        at = n;
        k = 0;
        descended = true;
        break;
      }
      if (descended) continue;
      if (here & kRoot) break;
      const int e = opposite(base);
      cur = step(cur, base);
      at = index(cur);
      k = dir_add(e, -(s[at] & kParent) - 1) + 1;
    }
  }

  CellGridShape shape_;
  std::size_t tiles_x_;
  std::vector<std::uint8_t> state_;
  Cell root_;
  int q0_;
};

// The benchmark's consumer of the tour: a fold of the positions (so that none can be skipped)
// and their count.
struct Fold {
  std::uint64_t fold = 0;
  std::int64_t n = 0;
  void operator()(SubCell s) noexcept {
    fold += static_cast<std::uint64_t>(s.x) * 31u + static_cast<std::uint64_t>(s.y);
    ++n;
  }
};

// Offline STC from the map in memory: free cells, the tree and the tour. Argument 0: the shipped
// SpanningTree, the search emitting the tour as it builds the tree (one loop); 1: LegacyTree, the
// code before; 2: the shipped SpanningTree in two passes, the tree, then tour() walks it. All three
// walk the same tour (checked after the timing: the same fold of the same number of positions).
enum class OfflinePath { Fused = 0, Legacy = 1, TreeThenTour = 2 };

std::int64_t offline_once(OfflinePath path, const OccupancyGrid& map, std::uint64_t& fold) {
  Fold f;
  switch (path) {
  case OfflinePath::Fused: {
    const SpanningTree tree(map, {0, 0}, f);
    break;
  }
  case OfflinePath::Legacy: {
    const LegacyTree tree(map, {0, 0});
    tree.tour(f);
    break;
  }
  case OfflinePath::TreeThenTour: {
    const SpanningTree tree(map, {0, 0});
    tree.tour(f);
    break;
  }
  }
  fold = f.fold;
  return f.n;
}

void run_offline(benchmark::State& state, const OccupancyGrid& map) {
  const auto path = static_cast<OfflinePath>(state.range(0));
  std::uint64_t fold = 0, reference = 0;
  std::int64_t subcells = 0;
  for (auto _ : state) {
    subcells += offline_once(path, map, fold);
    benchmark::DoNotOptimize(fold);
  }
  // After the timed loop: the legacy code walks the same tour.
  const std::int64_t n = offline_once(
      path == OfflinePath::Legacy ? OfflinePath::Fused : OfflinePath::Legacy, map, reference);
  if (reference != fold || n * static_cast<std::int64_t>(state.iterations()) != subcells)
    state.SkipWithError("the shipped and the legacy offline tours differ");
  state.SetItemsProcessed(subcells);
  // The tree's one byte per cell (in 64 x 64 tiles, with a border) stays; the search's byte per
  // cell is released when the tree is built. The peak is what offline STC allocates beyond the map.
  const SpanningTree tree(map, {0, 0});
  state.counters["extra_bytes_per_subcell"] =
      static_cast<double>(tree.peak_bytes()) / static_cast<double>(map.size());
  state.counters["max_rss_MiB"] = static_cast<double>(max_rss_kib()) / 1024.0;
}

void BM_StcOffline4096Blocked10(benchmark::State& state) {
  run_offline(state, map_4096());
}
BENCHMARK(BM_StcOffline4096Blocked10)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("path")
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);

const OccupancyGrid& map_16384() {
  static const OccupancyGrid map(16384, 16384, Occupancy::Free); // 256 MiB, the map itself
  return map;
}

void BM_StcOffline16384Empty(benchmark::State& state) {
  run_offline(state, map_16384());
}
BENCHMARK(BM_StcOffline16384Empty)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("path")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

// The two phases apart (shipped code): the tree alone (free cells and search), and the walk of a
// tree built before the timing.
void BM_StcOfflineTreeOnly(benchmark::State& state) {
  const OccupancyGrid& map = state.range(0) == 0 ? map_4096() : map_16384();
  std::int64_t subcells = 0;
  for (auto _ : state) {
    const SpanningTree tree(map, {0, 0});
    subcells += 4 * tree.cells();
    benchmark::DoNotOptimize(tree.cells());
  }
  state.SetItemsProcessed(subcells);
  // The search's events: a descent into every cell but the root, and a return from it.
  state.counters["events"] = static_cast<double>(2 * (subcells / 4 / state.iterations() - 1));
}
BENCHMARK(BM_StcOfflineTreeOnly)
    ->Arg(0)
    ->Arg(1)
    ->ArgName("empty16384")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

// What bounds the search (issue 46): each of its events (a descent to a new cell or a return to
// the parent; two per cell of the tree) waits for the one before it through a chain of dependent
// operations: load the cell's byte, look the next direction up in a table with it, add that
// direction's step to the cell's index, load the next cell's byte. No reordering overlaps two
// links of such a chain. This is that chain alone, over one 4 KiB tile (so every load hits the
// first-level cache) with no other work: items = links. Its time per link against
// BM_StcOfflineTreeOnly's time per event (events = 2 x (cells - 1), its counter) is how close the
// search runs to the chain's floor, measured in one run.
void BM_StcSearchChainFloor(benchmark::State& state) {
  constexpr std::size_t kTile = 4096;
  std::vector<std::uint8_t> bytes(kTile);
  std::vector<std::int16_t> table(256 * 4);
  antkit::kernel::Stream stream(2026, 46, 0, 0, 0x636861696E); // "chain"
  for (auto& b : bytes) b = static_cast<std::uint8_t>(stream.next_u32());
  // Entries as the search's tables store them: 4 * step + direction, steps of one cell.
  for (auto& e : table) {
    const std::uint32_t d = stream.next_u32() & 3u;
    constexpr std::array<int, 4> kStep{1, -64, -1, 64};
    e = static_cast<std::int16_t>(4 * kStep[d] + static_cast<int>(d));
  }
  constexpr std::int64_t kLinks = std::int64_t{1} << 20;
  std::size_t at = 0;
  unsigned q = 0;
  for (auto _ : state) {
    for (std::int64_t k = 0; k < kLinks; ++k) {
      const int e = table[static_cast<std::size_t>(bytes[at]) * 4 + q];
      at = (at + static_cast<std::size_t>(static_cast<std::ptrdiff_t>(e >> 2))) & (kTile - 1);
      q = static_cast<unsigned>(e) & 3u;
    }
    benchmark::DoNotOptimize(at);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * kLinks);
}
BENCHMARK(BM_StcSearchChainFloor);

void BM_StcOfflineWalkOnly(benchmark::State& state) {
  const OccupancyGrid& map = state.range(0) == 0 ? map_4096() : map_16384();
  const SpanningTree tree(map, {0, 0});
  std::int64_t subcells = 0;
  for (auto _ : state) {
    Fold f;
    tree.tour(f);
    benchmark::DoNotOptimize(f.fold);
    subcells += f.n;
  }
  state.SetItemsProcessed(subcells);
}
BENCHMARK(BM_StcOfflineWalkOnly)
    ->Arg(0)
    ->Arg(1)
    ->ArgName("empty16384")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

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
