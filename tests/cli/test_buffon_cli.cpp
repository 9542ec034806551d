// `antkit buffon`: JSON shape, thread-count independence, bad input.
#include "run_antkit.hpp"
#include "scratch_dir.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

using antkit::test::run_antkit;

TEST_CASE("antkit buffon prints the issue's JSON") {
  const auto r = run_antkit("buffon --arena circle:d=20 --trials 3 --steps 2000 --format json");
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["arena"]["area"].get<double>() == Approx(3.14159265 * 100).epsilon(0.01));
  REQUIRE(j["trials"].size() == 3);
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& t = j["trials"][i];
    CHECK(t["trial"].get<int>() == static_cast<int>(i));
    for (const char* key :
         {"bc", "nbc", "length1", "length2", "crossings_exact", "area_closed_form", "hash"})
      CHECK(t.contains(key));
    CHECK(t["nbc"].get<double>() == Approx(t["bc"].get<double>() / t["length2"].get<double>()));
  }
  for (const char* key : {"nbc_median", "nbc_q1", "nbc_q3", "area_closed_form_median"})
    CHECK(j["summary"].contains(key));
  CHECK(j["summary"]["nbc_q1"].get<double>() <= j["summary"]["nbc_median"].get<double>());
  CHECK(j["hash"].get<std::string>().size() == 16);
}

TEST_CASE("antkit buffon output does not depend on --threads", "[property]") {
  const std::string args = "buffon --arena square:area=400 --trials 6 --steps 1500 --format json";
  const auto one = run_antkit(args + " --threads 1");
  const auto two = run_antkit(args + " --threads 2");
  const auto four = run_antkit(args + " --threads 4");
  REQUIRE(one.status == 0);
  CHECK(one.out == two.out);
  CHECK(one.out == four.out);
}

TEST_CASE("antkit buffon rejects bad arenas and parameters with exit 2") {
  for (const std::string args : {"--arena circle:d=-3", "--arena nosuch:x=1",
                                 "--arena /nonexistent/file.wkt", "--arena circle:d=20 --width 0",
                                 "--arena circle:d=20 --trials 0", "--arena circle:d=20 --steps -1",
                                 "--arena circle:d=20 --threads 0", "--arena circle:d=1.2"}) {
    const auto r = run_antkit("buffon " + args);
    INFO(args << "\n" << r.err);
    CHECK(r.status == 2);
    CHECK(r.err.rfind("antkit: error: ", 0) == 0);
    CHECK(r.out.empty());
  }
}

TEST_CASE("antkit buffon-experiment writes the figure's CSV, SVG and PNG") {
  const antkit::test::ScratchDir scratch("buffon-exp");
  const auto dir = scratch / "out";
  const auto r =
      run_antkit("buffon-experiment --figure 8 --trials 2 --steps 1500 --out " + dir.string());
  REQUIRE(r.status == 0);
  std::ifstream csv(dir / "figure8.csv");
  std::string header, line;
  std::getline(csv, header);
  CHECK(header.rfind("series,x,arena,width,area,trials,nbc_median,nbc_q1,nbc_q3", 0) == 0);
  int rows = 0;
  while (std::getline(csv, line)) ++rows;
  CHECK(rows == 4); // standard, ring, plus, obstacles
  CHECK(std::filesystem::file_size(dir / "figure8.svg") > 100);
  CHECK(std::filesystem::file_size(dir / "figure8.png") > 1000);
  CHECK(r.err.find("trace hash ") != std::string::npos);
  std::filesystem::remove_all(dir);

  const auto bad = run_antkit("buffon-experiment --figure 3 --out " + dir.string());
  CHECK(bad.status == 2);
  CHECK(bad.err.rfind("antkit: error: ", 0) == 0);
}
