// antkit campaign's engine (testing/campaign): case i is case i whatever runs it, the outputs
// depend on the options only, a failing case shrinks to a minimal map with a command that
// reproduces it, and a time limit stops at a case boundary.
#include "scratch_dir.hpp"

#include <antkit/campaign/campaign.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/map_io.hpp>
#include <barrier>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <unistd.h>

namespace {

using namespace antkit;
namespace fs = std::filesystem;

campaign::Options options(campaign::Family f, std::uint64_t cases) {
  campaign::Options o;
  o.family = f;
  o.cases = cases;
  o.max_width = 10;
  o.max_height = 10;
  return o;
}

// One process on `threads` threads.
algorithms::Runner on(unsigned threads) {
  algorithms::Runner runner;
  runner.threads = threads;
  return runner;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

} // namespace

TEST_CASE("campaign: every family's cases keep their invariants, the same for any thread count",
          "[testing][campaign]") {
  for (const auto f : {campaign::Family::Stc, campaign::Family::Los, campaign::Family::Uniform,
                       campaign::Family::Buffon}) {
    INFO(campaign::family_name(f));
    const std::uint64_t n = f == campaign::Family::Buffon ? 24 : 150; // buffon's cases are long
    const auto one = campaign::run(options(f, n), on(1));
    const auto three = campaign::run(options(f, n), on(3));
    CHECK(one.failures.empty());
    CHECK(one.cases_run == n);
    CHECK(one.moves > 0u);
    CHECK(one.vacuous < n / 2);
    CHECK(one.moves == three.moves);
    CHECK(one.vacuous == three.vacuous);
    // Case i is case i: the first n cases are cases 0..k-1 and k..n-1 run apart.
    const std::uint64_t k = n * 3 / 5;
    const auto head = options(f, k);
    auto tail = options(f, n - k);
    tail.first = k;
    CHECK(campaign::run(head, on(2)).moves + campaign::run(tail, on(1)).moves == one.moves);
  }
}

TEST_CASE("campaign: a failing rule shrinks to the smallest map that breaks it",
          "[testing][campaign]") {
  // A rule about the width alone: the shrunk map is the narrowest that breaks it, one row high.
  auto o = options(campaign::Family::Los, 40);
  o.extra_rule = [](const kernel::OccupancyGrid& m) {
    return m.width() > 3 ? "wider than 3 cells" : "";
  };
  const auto r = campaign::run(o, on(2));
  REQUIRE(!r.failures.empty());
  for (const auto& f : r.failures) {
    CHECK(f.variant == "extra rule");
    CHECK(f.rule == "wider than 3 cells");
    CHECK(f.map.width() == 4);
    CHECK(f.map.height() == 1);
  }
  // The failures are reduced in case order, and are the same with one thread.
  const auto r1 = campaign::run(o, on(1));
  REQUIRE(r1.failures.size() == r.failures.size());
  for (std::size_t i = 0; i < r.failures.size(); ++i) {
    CHECK(r1.failures[i].case_index == r.failures[i].case_index);
    CHECK(r1.failures[i].map.cells() == r.failures[i].map.cells());
    if (i > 0) CHECK(r.failures[i - 1].case_index < r.failures[i].case_index);
  }
  // The outputs: a MovingAI map per failure that reads back as the shrunk map, and its command.
  const antkit::test::ScratchDir scratch("campaign");
  const fs::path dir = scratch / "out";
  const std::string summary = campaign::write_outputs(o, r, dir);
  CHECK(slurp(dir / "summary.json") == summary);
  const auto& f = r.failures.front();
  const std::string name = "case-" + std::to_string(f.case_index) + ".map";
  CHECK(maps::load_map(dir / name).cells.cells() == f.map.cells());
  CHECK(summary.find("\"command\": \"antkit explore --map " + name + " --algo fast-wall-follow") !=
        std::string::npos);
}

TEST_CASE("campaign: STC cases shrink too, and their command names the variant and the start",
          "[testing][campaign]") {
  auto o = options(campaign::Family::Stc, 30);
  o.variants = {"ant-edge"};
  o.extra_rule = [](const kernel::OccupancyGrid& m) {
    return m.height() >= 6 ? "six sub-cells high or more" : "";
  };
  const auto r = campaign::run(o);
  REQUIRE(!r.failures.empty());
  for (const auto& f : r.failures) {
    CHECK(f.map.height() == 6);
    CHECK(f.map.width() <= 3);
    CHECK(f.command == "antkit stc --map {MAP} --variant ant-edge --start " +
                           std::to_string(f.start.x) + "," + std::to_string(f.start.y));
  }
}

TEST_CASE("campaign: a time limit stops at a case boundary, and bad options are refused",
          "[testing][campaign]") {
  auto o = options(campaign::Family::Uniform, 100000);
  o.time_limit_s = 1e-9;
  const auto r = campaign::run(o);
  CHECK(r.stopped_by_time);
  CHECK(r.cases_run < o.cases);
  CHECK(r.cases_run % 64 == 0);
  // The ranks stop together: the runner's any (MPI's under mpirun) says whether any rank is late,
  // here another rank at the third batch boundary while this one has time left.
  o.time_limit_s = 1e9;
  algorithms::Runner runner;
  int boundaries = 0;
  runner.any = [&](bool late) { return late || ++boundaries == 3; };
  const auto told = campaign::run(o, runner);
  CHECK(told.stopped_by_time);
  CHECK(told.cases_run == 2 * 64);
  auto bad = options(campaign::Family::Stc, 10);
  bad.variants = {"zigzag"};
  CHECK_THROWS_WITH(campaign::run(bad),
                    "variants: 'zigzag' is not a stc variant; expected some of offline, online, "
                    "ant, ant-edge, full");
  bad = options(campaign::Family::Los, 0);
  CHECK_THROWS_AS(campaign::run(bad), kernel::InputError);
}

TEST_CASE("campaign: ranks split the cases and rank 0 returns the one-process result",
          "[testing][campaign]") {
  auto o = options(campaign::Family::Los, 200);
  o.extra_rule = [](const kernel::OccupancyGrid& m) { return m.width() > 8 ? "wide" : ""; };
  const auto whole = campaign::run(o);
  REQUIRE(!whole.failures.empty());
  // Three ranks simulated by three threads that share a gather (the real mpirun is
  // mpi.campaign.identical).
  constexpr int kRanks = 3;
  std::barrier sync(kRanks);
  std::mutex lock;
  std::vector<std::string> texts(kRanks);
  std::vector<campaign::Result> results(kRanks);
  std::vector<std::thread> pool;
  for (int r = 0; r < kRanks; ++r)
    pool.emplace_back([&, r] {
      algorithms::Runner runner;
      runner.rank = r;
      runner.ranks = kRanks;
      runner.gather = [&, r](const std::string& mine) {
        {
          const std::lock_guard<std::mutex> held(lock);
          texts[static_cast<std::size_t>(r)] = mine;
        }
        sync.arrive_and_wait();
        std::vector<std::string> all;
        if (r == 0) all = texts;
        sync.arrive_and_wait(); // nobody writes the next batch's text before rank 0 has read
        return all;
      };
      results[static_cast<std::size_t>(r)] = campaign::run(o, runner);
    });
  for (auto& t : pool) t.join();
  for (const auto& part : results) CHECK(part.cases_run == 200u);
  CHECK(results[1].failures.empty());
  CHECK(results[2].moves == 0u);
  const auto& merged = results[0];
  CHECK(merged.moves == whole.moves);
  CHECK(merged.vacuous == whole.vacuous);
  REQUIRE(merged.failures.size() == whole.failures.size());
  for (std::size_t i = 0; i < whole.failures.size(); ++i) {
    // Through text and back, as summary.json carries them.
    const auto f = campaign::deserialize(campaign::serialize(merged.failures[i]));
    CHECK(f.case_index == whole.failures[i].case_index);
    CHECK(f.map.cells() == whole.failures[i].map.cells());
    CHECK(f.start == whole.failures[i].start);
    CHECK(f.command == whole.failures[i].command);
    CHECK(f.rule == whole.failures[i].rule);
    CHECK(f.shrink_steps == whole.failures[i].shrink_steps);
  }
  // Several ranks without a gather is a programming error, not a silent partial result.
  algorithms::Runner lonely;
  lonely.ranks = 2;
  CHECK_THROWS_AS(campaign::run(o, lonely), std::logic_error);
}

TEST_CASE("campaign: a Buffon failure is written as its WKT arena with its command",
          "[testing][campaign]") {
  campaign::Options o;
  o.family = campaign::Family::Buffon;
  campaign::Result r;
  r.cases_run = 5;
  campaign::Failure f;
  f.case_index = 3;
  f.variant = "fixed";
  f.rule = "a planted rule";
  f.arena_wkt = "POLYGON ((0 0, 30 0, 30 30, 0 30, 0 0))";
  f.command = "antkit buffon --arena {MAP} --trials 1 --seed 9 --width 0.100 --steps 40";
  r.failures.push_back(campaign::deserialize(campaign::serialize(f)));
  const antkit::test::ScratchDir scratch("campaign-b");
  const fs::path dir = scratch / "out";
  const std::string summary = campaign::write_outputs(o, r, dir);
  CHECK(slurp(dir / "case-3.wkt") == f.arena_wkt + "\n");
  CHECK(summary.find("\"command\": \"antkit buffon --arena case-3.wkt --trials 1 --seed 9") !=
        std::string::npos);
}
