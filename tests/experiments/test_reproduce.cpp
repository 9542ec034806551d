// antkit::experiments::reproduce, called as a library: the files, the claims, their agreement
// with the tables they are decided from, and byte-identical output for any number of threads.
#include "scratch_dir.hpp"
#include "test_paths.hpp"

#include <antkit/experiments/claims.hpp>
#include <antkit/experiments/explore_tables.hpp>
#include <antkit/experiments/reproduce.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <unistd.h>

namespace ex = antkit::experiments;
namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::map<std::string, std::string> tree(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = slurp(e.path());
  return files;
}

ex::ReproduceOptions options(const fs::path& out) {
  ex::ReproduceOptions o;
  o.only = {"los", "stc"};
  o.out = out;
  o.maps_dir = fs::path(antkit::test::maps_dir());
  return o;
}

} // namespace

TEST_CASE("reproduce writes the report, the tables and the figures, and decides the claims") {
  const antkit::test::ScratchDir scratch("reproduce");
  const fs::path& dir = scratch.path();
  antkit::algorithms::Runner runner;
  runner.threads = 2;
  const auto report = ex::reproduce(options(dir), runner);

  // The claims of the papers asked for, from their tables, in order.
  std::vector<std::string> ids, expected;
  for (const auto& c : report.claims) ids.push_back(c.id);
  for (const auto* table : {&ex::claims_001(), &ex::claims_002()})
    for (const auto& spec : *table) expected.emplace_back(spec.id);
  CHECK(ids == expected);
  for (const char* f :
       {"README.md", "claims.json", "los/table2.csv", "los/table3.md", "los/figures5-6.png",
        "los/figures5-6.svg", "stc/tours.csv", "stc/noise.csv", "stc/noise.png", "stc/tour.png",
        "stc/tour.svg", "stc/floor_curves.csv"}) {
    INFO(f);
    REQUIRE(fs::exists(dir / f));
    CHECK(fs::file_size(dir / f) > 100);
  }
  CHECK(slurp(dir / "stc/tour.png").substr(1, 3) == "PNG");
  // The fading claim's one row: the 30 s half-life, the largest exact board, its tour's minutes.
  const std::string boards = slurp(dir / "stc/floor_boards.csv");
  CHECK(boards.rfind("fade_half_life_s,largest_exact_board_cells,tour_minutes,capped\n30,", 0) ==
        0);
  CHECK(report.files.size() == tree(dir).size());

  // Ant-like STC's tours are exact on every map: the claim holds (an invariant, not a statistic).
  for (const auto& c : report.claims)
    if (c.id == "002-1" || c.id == "002-full") CHECK(c.verdict == ex::Verdict::Holds);

  // 001-3 has a part per environment: fast wall-follow's mean E.M.E minus the frontier
  // baseline's (without sweeping), recounted from the tables, with an interval around it; the
  // claim's verdict is the partly convention over the parts' verdicts.
  const auto tables = ex::run_explore_tables(1, antkit::algorithms::Runner{});
  for (const auto& c : report.claims)
    if (c.id == "001-3") {
      REQUIRE(c.parts.size() == tables.runs.size());
      std::vector<ex::Verdict> verdicts;
      for (std::size_t e = 0; e < tables.runs.size(); ++e) {
        const auto& p = c.parts[e];
        CHECK(p.value ==
              Approx(ex::mean_of(tables.runs[e][0].eme) - ex::mean_of(tables.runs[e][1].eme)));
        CHECK(p.ci.lo <= p.value);
        CHECK(p.value <= p.ci.hi);
        CHECK(p.level == Approx(1 - 0.05 / 7));
        CHECK(p.verdict == ex::decide(p.ci, {ex::Side::Below, 0}));
        verdicts.push_back(p.verdict);
      }
      CHECK(c.verdict == ex::combine(verdicts));
    }

  // claims.json says what the report says; README.md has every claim, rule and hash.
  const auto j = nlohmann::json::parse(slurp(dir / "claims.json"));
  REQUIRE(j["claims"].size() == report.claims.size());
  for (std::size_t i = 0; i < report.claims.size(); ++i) {
    CHECK(j["claims"][i]["id"] == report.claims[i].id);
    CHECK(j["claims"][i]["verdict"] == ex::verdict_text(report.claims[i].verdict));
    CHECK(j["claims"][i]["parts"].size() == report.claims[i].parts.size());
  }
  const std::string readme = slurp(dir / "README.md");
  for (const auto& c : report.claims) CHECK(readme.find("| " + c.id + " |") != std::string::npos);
  for (const auto& e : report.experiments) {
    CHECK(e.hash != 0);
    CHECK(readme.find(antkit::kernel::hash_hex(e.hash)) != std::string::npos);
  }
  CHECK(readme.find("## Trace hashes") != std::string::npos);
}

TEST_CASE("reproduce writes the same bytes for any number of threads", "[property]") {
  const antkit::test::ScratchDir scratch("reproduce-t");
  const fs::path& base = scratch.path();
  std::map<std::string, std::string> first;
  for (const unsigned threads : {1u, 3u}) {
    const fs::path dir = base / std::to_string(threads);
    fs::create_directories(dir);
    antkit::algorithms::Runner runner;
    runner.threads = threads;
    (void)ex::reproduce(options(dir), runner);
    const auto files = tree(dir);
    if (first.empty())
      first = files;
    else
      for (const auto& [name, bytes] : files) {
        INFO(name);
        CHECK(bytes == first[name]);
      }
  }
}

TEST_CASE("reproduce refuses an unknown family") {
  ex::ReproduceOptions o;
  o.only = {"los", "sheng"};
  CHECK_THROWS_AS(ex::validate(o), antkit::kernel::InputError);
  o.only = {"buffon", "los", "stc", "uniform"};
  CHECK_NOTHROW(ex::validate(o));
}
