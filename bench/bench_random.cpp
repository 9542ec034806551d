// Random numbers per second from the keyed streams (items_per_second = numbers drawn).
#include <antkit/kernel/random.hpp>
#include <benchmark/benchmark.h>
#include <cstdint>

namespace {

using antkit::kernel::Stream;

constexpr std::int64_t kBatch = 4096;

void BM_StreamNextU32(benchmark::State& state) {
  Stream s(2026, 1, 2, 3, 4);
  for (auto _ : state)
    for (std::int64_t k = 0; k < kBatch; ++k) benchmark::DoNotOptimize(s.next_u32());
  state.SetItemsProcessed(state.iterations() * kBatch);
}
BENCHMARK(BM_StreamNextU32);

void BM_StreamNextU64(benchmark::State& state) {
  Stream s(2026, 1, 2, 3, 4);
  for (auto _ : state)
    for (std::int64_t k = 0; k < kBatch; ++k) benchmark::DoNotOptimize(s.next_u64());
  state.SetItemsProcessed(state.iterations() * kBatch);
}
BENCHMARK(BM_StreamNextU64);

// below(n) for n = 8 (never rejects), 10 and 3e9 (rejects about 30 % of words).
void BM_StreamBelow(benchmark::State& state) {
  Stream s(2026, 1, 2, 3, 4);
  const auto n = static_cast<std::uint32_t>(state.range(0));
  for (auto _ : state)
    for (std::int64_t k = 0; k < kBatch; ++k) benchmark::DoNotOptimize(s.below(n));
  state.SetItemsProcessed(state.iterations() * kBatch);
}
BENCHMARK(BM_StreamBelow)->Arg(8)->Arg(10)->Arg(3'000'000'000);

void BM_StreamChance(benchmark::State& state) {
  Stream s(2026, 1, 2, 3, 4);
  for (auto _ : state)
    for (std::int64_t k = 0; k < kBatch; ++k) benchmark::DoNotOptimize(s.chance(1, 3));
  state.SetItemsProcessed(state.iterations() * kBatch);
}
BENCHMARK(BM_StreamChance);

// Keying a fresh stream and drawing its first word: the cost of "one stream per trial".
void BM_StreamKeyAndFirstWord(benchmark::State& state) {
  std::uint64_t trial = 0;
  for (auto _ : state)
    for (std::int64_t k = 0; k < kBatch; ++k)
      benchmark::DoNotOptimize(Stream(2026, 1, trial++, 0, 0).next_u32());
  state.SetItemsProcessed(state.iterations() * kBatch);
}
BENCHMARK(BM_StreamKeyAndFirstWord);

} // namespace
