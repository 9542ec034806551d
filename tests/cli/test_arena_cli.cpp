// `antkit arena`: the real executable's report, its files, and its refusals of bad input.
#include "run_antkit.hpp"
#include "scratch_dir.hpp"

#include <algorithm>
#include <antkit/geometry/arena_raster.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/geometry/wkt.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

using antkit::test::run_antkit;
namespace fs = std::filesystem;

namespace {

// A fresh scratch directory per test case, removed when the test case ends (scratch_dir.hpp).
struct Scratch {
  antkit::test::ScratchDir scratch{"arena-cli"};
  fs::path dir = scratch.path();
  std::string path(const std::string& name) const { return (dir / name).string(); }
  // Nothing but the files a test put there itself (no output, no temporary left behind).
  std::size_t files() const {
    return static_cast<std::size_t>(
        std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
  }
};

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

} // namespace

TEST_CASE("antkit arena SPEC --format json reports the exact measures", "[cli][arena]") {
  const auto r = run_antkit("arena circle:d=100 --format json");
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  const auto expected = antkit::geometry::build_arena_spec("circle:d=100").arena;
  CHECK(j.at("area").get<double>() == expected.area());
  CHECK(j.at("area_exact").get<std::string>() == expected.area_exact());
  CHECK(j.at("perimeter").get<double>() == expected.perimeter());
  CHECK(j.at("vertices").get<int>() == 256);
  CHECK(j.at("holes").get<int>() == 0);
  REQUIRE(j.at("bbox").size() == 4);
  CHECK(j.at("bbox")[0].get<double>() == Approx(-50).epsilon(1e-4));
  CHECK(j.at("bbox")[3].get<double>() == Approx(50).epsilon(1e-4));
  // Within the stated bound of pi * 50^2.
  CHECK(std::fabs(j.at("area").get<double>() - 7853.981633974483) <=
        j.at("perimeter").get<double>() / 65536);
}

TEST_CASE("antkit arena prints a table by default", "[cli][arena]") {
  const auto r = run_antkit("arena obstacles");
  REQUIRE(r.status == 0);
  CHECK(r.out.find("area_exact") != std::string::npos);
  CHECK(r.out.find("holes       7") != std::string::npos);
}

TEST_CASE("antkit arena --raster writes the rasterized grid as a MovingAI map", "[cli][arena]") {
  Scratch s;
  const auto map = s.path("standard.map");
  const auto r =
      run_antkit("arena barrier-plus:len=0.4 --raster 2.5 --out " + map + " --format json");
  REQUIRE(r.status == 0);
  const auto grid =
      antkit::geometry::rasterize(antkit::geometry::build_arena_spec("barrier-plus:len=0.4").arena,
                                  antkit::geometry::CellSize(5, 2))
          .grid;
  std::string expected = "type octile\nheight " + std::to_string(grid.height()) + "\nwidth " +
                         std::to_string(grid.width()) + "\nmap\n";
  std::size_t free = 0;
  for (std::int32_t y = 0; y < grid.height(); ++y) {
    for (std::int32_t x = 0; x < grid.width(); ++x) {
      const bool f = grid[{x, y}] == antkit::kernel::Occupancy::Free;
      free += f ? 1 : 0;
      expected += f ? '.' : '@';
    }
    expected += '\n';
  }
  CHECK(slurp(map) == expected);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j.at("raster").at("free_cells").get<std::size_t>() == free);
  CHECK(j.at("raster").at("width").get<int>() == grid.width());
  CHECK(s.files() == 1);
}

TEST_CASE("antkit arena --out-wkt writes WKT that reads back to the same arena", "[cli][arena]") {
  Scratch s;
  const auto wkt = s.path("ring.wkt");
  REQUIRE(run_antkit("arena ring --out-wkt " + wkt).status == 0);
  CHECK(antkit::geometry::read_wkt_file(wkt) == antkit::geometry::build_arena_spec("ring").arena);
  const auto a = run_antkit("arena ring --format json");
  const auto c = run_antkit("arena " + wkt + " --format json");
  REQUIRE(c.status == 0);
  CHECK(nlohmann::json::parse(c.out).at("area_exact") ==
        nlohmann::json::parse(a.out).at("area_exact"));
}

TEST_CASE("antkit arena: bad input exits 2 with one clear message and no output file",
          "[cli][arena]") {
  Scratch s;
  const auto bad_wkt = s.path("bad.wkt");
  std::ofstream(bad_wkt)
      << "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0),\n (20 20, 21 20, 21 21, 20 21))\n";
  const auto bowtie = s.path("bowtie.wkt");
  std::ofstream(bowtie) << "POLYGON ((0 0, 1 1, 1 0, 0 1, 0 0))";
  const auto multi = s.path("multi.wkt");
  std::ofstream(multi) << "MULTIPOLYGON (((0 0, 1 0, 1 1, 0 0)), ((5 5, 6 5, 6 6, 5 5)))";
  const auto out = s.path("out.map");
  const auto out_wkt = s.path("out.wkt");
  const std::size_t inputs = s.files();

  struct Case {
    std::string args;
    std::string where; // the start of the message after "antkit: error: "
  };
  const std::vector<Case> cases{
      {"arena hexagon", "SPEC:1:1: unknown arena family"},
      {"arena circle:d=abc", "SPEC:1:10: bad number"},
      {"arena circle:d=0.1", "SPEC:1:10: diameter"},
      {"arena barrier-i:len=0.99", "SPEC:1:15: barrier length"},
      {"arena ellipse:area=7854", "SPEC:1:1: ellipse needs e="},
      {"arena " + bad_wkt, bad_wkt + ":2:2: ring is not closed"},
      {"arena " + bowtie, bowtie + ":1:9: outer boundary is not simple"},
      {"arena " + multi, multi + ":1:37: MULTIPOLYGON with more than one polygon"},
      {"arena " + s.path("missing.wkt"), s.path("missing.wkt") + ": cannot open"},
      {"arena standard --raster 0", "--raster: cell size '0' is zero"},
      {"arena standard --raster -1", ""},
      {"arena standard --raster abc", "--raster: cell size 'abc'"},
      {"arena standard --raster 0.00001", "--raster: a raster of"},
  };
  for (const auto& c : cases) {
    INFO(c.args);
    const auto r = run_antkit(c.args + " --out " + out + " --out-wkt " + out_wkt +
                              (c.args.find("--raster") == std::string::npos ? " --raster 1" : ""));
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(r.err.rfind("antkit: error: " + c.where, 0) == 0);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') <= 2);
    CHECK_FALSE(fs::exists(out));
    CHECK_FALSE(fs::exists(out_wkt));
    CHECK(s.files() == inputs);
  }
}

TEST_CASE("antkit arena: --raster and --out go together", "[cli][arena]") {
  Scratch s;
  CHECK(run_antkit("arena standard --raster 1").status == 2);
  CHECK(run_antkit("arena standard --out " + s.path("x.map")).status == 2);
  CHECK(s.files() == 0);
}
