// antkit campaign's throughput (issue 18's target: an STC campaign on maps up to 32 x 32 cells
// checks at least 5 M sub-cell moves per second per core, generation, all four exact variants and
// every check included). Items are sub-cell moves (tour positions) checked; one thread.
//   BM_CampaignStcExact   offline, online, ant, ant-edge (the measure)
//   BM_CampaignStcAll     the same and full (the command's default)
//   BM_StcExactRunsOnly   the four runs alone on the same cases, no generation or checks: what
//                         the checking costs on top
//   BM_StcGenerateOnly    rapidcheck generating those cases, nothing else (items: the cases'
//                         positions in the four exact tours, so that the rates compare)
#include <antkit/campaign/campaign.hpp>
#include <antkit/stc/world.hpp>
#include <antkit/testing/generators.hpp>
#include <benchmark/benchmark.h>

namespace {

using namespace antkit;

void run_campaign(benchmark::State& state, std::vector<std::string> variants) {
  campaign::Options o;
  o.family = campaign::Family::Stc;
  o.cases = 200;
  o.variants = std::move(variants);
  std::uint64_t moves = 0;
  for (auto _ : state) {
    const auto r = campaign::run(o);
    moves += r.moves;
    benchmark::DoNotOptimize(r.failures.size());
    ++o.first; // a new set of cases each time (mostly overlapping: the same cost per case)
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(moves));
}

void BM_CampaignStcExact(benchmark::State& state) {
  run_campaign(state, {"offline", "online", "ant", "ant-edge"});
}
BENCHMARK(BM_CampaignStcExact)->Unit(benchmark::kMillisecond);

void BM_CampaignStcAll(benchmark::State& state) {
  run_campaign(state, {});
}
BENCHMARK(BM_CampaignStcAll)->Unit(benchmark::kMillisecond);

rc::Gen<testing::gen::StcCase> campaign_generator() { // the campaign's, at 32 x 32 cells
  return rc::gen::oneOf(
      testing::gen::stc_case({.max_cells_x = 32, .max_cells_y = 32, .partial_cells = true}),
      testing::gen::stc_case_from(testing::gen::any_grid_map({.max_width = 32, .max_height = 32})));
}

void BM_StcGenerateOnly(benchmark::State& state) {
  const auto gen = campaign_generator();
  std::uint64_t positions = 0, i = 0;
  for (auto _ : state) {
    const auto c = gen(rc::Random(++i), 100).value();
    positions +=
        static_cast<std::uint64_t>(stc::reachable_subcells(c.map, c.start, stc::Variant::Offline));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(4 * positions));
}
BENCHMARK(BM_StcGenerateOnly);

void BM_StcExactRunsOnly(benchmark::State& state) {
  // The campaign's own generator for 200 cases, generated once.
  std::vector<testing::gen::StcCase> cases;
  const auto gen = campaign_generator();
  for (std::uint64_t i = 0; i < 200; ++i) cases.push_back(gen(rc::Random(i + 1), 100).value());
  stc::StcWorld world;
  std::uint64_t moves = 0;
  for (auto _ : state)
    for (const auto& c : cases)
      for (const auto v : {stc::Variant::Offline, stc::Variant::Online, stc::Variant::Ant,
                           stc::Variant::AntEdge}) {
        const auto r = stc::run_stc(world, c.map, c.start, v);
        moves += static_cast<std::uint64_t>(r.positions);
        benchmark::DoNotOptimize(r.hash);
      }
  state.SetItemsProcessed(static_cast<std::int64_t>(moves));
}
BENCHMARK(BM_StcExactRunsOnly)->Unit(benchmark::kMillisecond);

} // namespace
