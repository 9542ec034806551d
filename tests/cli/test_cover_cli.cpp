// `antkit cover` and `antkit cover-experiment`, run as the real executable.
#include "run_antkit.hpp"
#include "scratch_dir.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

using antkit::test::run_antkit;
using antkit::test::shared_map;

namespace {
antkit::test::ScratchDir scratch_dir(const std::string& name) {
  return antkit::test::ScratchDir("cover-" + name);
}
std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
} // namespace

TEST_CASE("antkit cover --format json reports the issue's fields, and A* views everything",
          "[cli][uniform]") {
  const auto r = run_antkit("cover --size 40x30 --density 0.2 --seed 7 --algo astar --robots 3 "
                            "--sensor 4 --format json");
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key :
       {"algo", "robots", "coverage", "viewed", "viewable", "movements", "moves", "hash"})
    CHECK(j.contains(key));
  CHECK(j["algo"] == "astar");
  CHECK(j["robots"] == 3);
  CHECK(j["viewed"] == j["viewable"]);
  CHECK(j["coverage"].get<double>() == 100.0);
  CHECK(j["stop"] == "complete");
  CHECK(j["hash"].get<std::string>().size() == 16);
  // A* steps only: at most one move per robot per tick.
  CHECK(j["moves"].get<std::uint64_t>() <= 3 * j["movements"].get<std::uint64_t>());
  // 20 % of 1200 cells are blocked; what can be viewed is at most the rest.
  CHECK(j["viewable"].get<std::uint64_t>() <= 960);
}

TEST_CASE("antkit cover is reproducible and keyed by the seed", "[cli][uniform]") {
  const std::string args = "cover --size 30x30 --density 10% --algo rw --robots 2 --limit 300 "
                           "--format json --seed ";
  const auto a = nlohmann::json::parse(run_antkit(args + "3").out);
  const auto b = nlohmann::json::parse(run_antkit(args + "3").out);
  const auto c = nlohmann::json::parse(run_antkit(args + "4").out);
  CHECK(a == b);
  CHECK(a["hash"] != c["hash"]);
  CHECK(a["movements"] == 300);
  CHECK(a["stop"] == "time-limit");
}

TEST_CASE("antkit cover runs on a map file and draws an SVG", "[cli][uniform]") {
  const auto dir = scratch_dir("svg");
  const auto svg = dir / "cover.svg";
  const auto r = run_antkit("cover --map " + shared_map("movingai/random-32-32-20.map") +
                            " --algo astar-coord --robots 4 --format json --svg " + svg.string());
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["viewed"] == j["viewable"]);
  CHECK(j["width"] == 32);
  CHECK(slurp(svg).find("<svg") != std::string::npos);
}

TEST_CASE("antkit cover prints a table by default", "[cli][uniform]") {
  const auto r = run_antkit("cover --size 12x12 --density 0 --algo pm");
  REQUIRE(r.status == 0);
  CHECK(r.out.find("coverage") != std::string::npos);
  CHECK(r.out.find("movements") != std::string::npos);
}

TEST_CASE("antkit cover: bad input exits 2 with one clear message and no output",
          "[cli][uniform]") {
  const auto dir = scratch_dir("bad");
  const auto svg = dir / "never.svg";
  const std::vector<std::string> bad{
      "cover --size 10x10 --algo rw",
      "cover --size 10x10 --density 1.5 --algo rw",
      "cover --size 10x10 --density 0.1 --algo bfs",
      "cover --size 10 --density 0.1 --algo rw",
      "cover --size 0x10 --density 0.1 --algo rw",
      "cover --density 0.1 --algo rw",
      "cover --map /no/such/map.map --algo rw",
      "cover --map " + shared_map("movingai/empty-32-32.map") + " --density 0.1 --algo rw",
      "cover --size 10x10 --density 0.1 --algo rw --robots 0",
      "cover --size 10x10 --density 0.1 --algo rw --robots 2000",
      "cover --size 10x10 --density 0.1 --algo rw --sensor 300",
      "cover --size 10x10 --density 0.1 --algo rw --limit -2",
      "cover --size 2x2 --density 0.75 --algo rw --robots 2 --svg " + svg.string(),
      "cover --size 10x10 --density 0.1"};
  for (const auto& args : bad) {
    const auto r = run_antkit(args);
    INFO(args << "\n" << r.err);
    CHECK(r.status == 2);
    CHECK(r.err.rfind("antkit: error: ", 0) == 0);
    CHECK(r.out.empty());
  }
  CHECK_FALSE(std::filesystem::exists(svg));
}

TEST_CASE("antkit cover --algo frontier views everything reproducibly and refuses sensor 0",
          "[cli][uniform]") {
  const std::string args = "cover --size 40x30 --density 0.2 --seed 7 --algo frontier --robots 3 "
                           "--sensor 4 --format json";
  const auto r = run_antkit(args);
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["algo"] == "frontier");
  CHECK(j["robots"] == 3);
  CHECK(j["viewed"] == j["viewable"]);
  CHECK(j["stop"] == "complete");
  CHECK(j["moves"].get<std::uint64_t>() <= 3 * j["movements"].get<std::uint64_t>());
  const auto again = run_antkit(args);
  CHECK(nlohmann::json::parse(again.out)["hash"] == j["hash"]);
  const auto zero = run_antkit("cover --size 10x10 --density 0.1 --algo frontier --sensor 0");
  CHECK(zero.status == 2);
  CHECK(zero.err.find("--sensor") != std::string::npos);
  CHECK(zero.out.empty());
}

TEST_CASE("antkit cover-experiment (smoke): writes the tables beside the paper's",
          "[cli][uniform]") {
  const auto dir = scratch_dir("tables");
  const auto r = run_antkit("cover-experiment --runs 2 --size 24x24 --sensor 3 --jobs 2 --out " +
                            dir.string() + " --format json");
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["rows"].size() == 16);
  const auto csv = slurp(dir / "uniform_tables.csv");
  std::istringstream lines(csv);
  std::string line;
  std::size_t count = 0, astar_rows = 0;
  while (std::getline(lines, line)) {
    ++count;
    // A*, coordinated A* and frontier complete every run: complete_runs (column 8) == runs (column
    // 5).
    if (line.find(",astar,") != std::string::npos ||
        line.find(",astar-coord,") != std::string::npos ||
        line.find(",frontier,") != std::string::npos) {
      ++astar_rows;
      std::vector<std::string> cols;
      std::istringstream fields(line);
      for (std::string f; std::getline(fields, f, ',');) cols.push_back(f);
      REQUIRE(cols.size() >= 8);
      CHECK(cols[4] == "2");
      CHECK(cols[7] == "2");
    }
  }
  CHECK(count == 1 + 16 * 5);
  CHECK(astar_rows == 48);
  const auto md = slurp(dir / "uniform_tables.md");
  for (const char* title : {"Table 1", "Table 2", "Table 3", "Table 4", "Coordinated A*",
                            "Frontier against A* and coordinated A*"})
    CHECK(md.find(title) != std::string::npos);
  CHECK(md.find("2757.2") != std::string::npos); // the paper's Table 1, A*, one robot
  // One thread or two: the same numbers.
  const auto one = run_antkit("cover-experiment --runs 2 --size 24x24 --sensor 3 --jobs 1 --out " +
                              dir.string() + " --format json");
  CHECK(nlohmann::json::parse(one.out)["hash"] == j["hash"]);
  CHECK(run_antkit("cover-experiment --runs 0 --out " + dir.string()).status == 2);
  CHECK(run_antkit("cover-experiment --out /no/such/dir").status == 2);
}
