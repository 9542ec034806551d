// `antkit campaign`, run as the real executable (issue 18): the output files depend on the options
// only (not on threads or time), timings go to standard output, a time limit says how many cases
// ran.
#include "run_antkit.hpp"
#include "scratch_dir.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <unistd.h>

using antkit::test::run_antkit;
namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

} // namespace

TEST_CASE("antkit campaign: the same summary for any thread count, timings on stdout only",
          "[cli][campaign]") {
  const antkit::test::ScratchDir scratch("campaign-cli");
  for (const char* family : {"stc", "los", "uniform"}) {
    INFO(family);
    const auto a = scratch / (std::string(family) + "-1"),
               b = scratch / (std::string(family) + "-2");
    const std::string common =
        std::string("campaign ") + family + " --cases 80 --max-size 8x8 --seed 7 --format json";
    const auto r1 = run_antkit(common + " --threads 1 --out " + a.string());
    const auto r2 = run_antkit(common + " --threads 2 --out " + b.string());
    REQUIRE(r1.status == 0);
    REQUIRE(r2.status == 0);
    CHECK(slurp(a / "summary.json") == slurp(b / "summary.json"));
    const auto summary = nlohmann::json::parse(slurp(a / "summary.json"));
    CHECK(summary.at("cases_run") == 80);
    CHECK(summary.at("seed") == 7);
    CHECK(summary.at("failures").empty());
    CHECK(!summary.contains("seconds"));
    const auto out = nlohmann::json::parse(r1.out);
    CHECK(out.at("cases_run") == 80);
    CHECK(out.at("cases_per_second").get<double>() > 0);
    CHECK(out.at("moves_checked") == summary.at("moves_checked"));
    CHECK(r1.err.empty()); // no progress bar when standard error is not a terminal
  }
}

TEST_CASE("antkit campaign: a time limit stops at a case boundary and says how many ran",
          "[cli][campaign]") {
  const antkit::test::ScratchDir scratch("campaign-cli");
  const auto dir = scratch / "timed";
  const auto r = run_antkit("campaign uniform --cases 100000000 --time 0.2 --format json --out " +
                            dir.string());
  REQUIRE(r.status == 0);
  const auto summary = nlohmann::json::parse(slurp(dir / "summary.json"));
  CHECK(summary.at("stopped_by_time") == true);
  const auto ran = summary.at("cases_run").get<std::uint64_t>();
  CHECK(ran < 100000000u);
  CHECK(r.err == "antkit campaign: the time limit stopped the campaign after " +
                     std::to_string(ran) + " of 100000000 cases\n");
}
