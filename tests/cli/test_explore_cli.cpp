// `antkit explore` through the real executable: the JSON it promises, determinism, the SVG, and
// bad input (exit 2, one clear message, no output file).
#include "run_antkit.hpp"
#include "scratch_dir.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

using antkit::test::run_antkit;

TEST_CASE("explore: JSON with the promised fields consistent with each other", "[cli]") {
  for (const char* algo : {"fast-wall-follow", "frontier"}) {
    const auto r = run_antkit(std::string("explore --size 25x25 --obstacles 5 --seed 3 --algo ") +
                              algo + " --format json");
    REQUIRE(r.status == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["algo"] == algo);
    CHECK(j["eme"].get<std::uint64_t>() ==
          j["moves"][0].get<std::uint64_t>() + j["moves"][1].get<std::uint64_t>());
    CHECK(j["steps"].get<std::uint64_t>() >= j["moves"][0].get<std::uint64_t>());
    REQUIRE(j["cells"].size() == 25);
    std::size_t explored = 0;
    for (const auto& row : j["cells"]) {
      const auto s = row.get<std::string>();
      CHECK(s.size() == 25);
      CHECK(s.find_first_not_of("FSLBNO") == std::string::npos);
      explored += 25 - static_cast<std::size_t>(std::count(s.begin(), s.end(), 'F')) -
                  static_cast<std::size_t>(std::count(s.begin(), s.end(), 'N'));
    }
    CHECK(j["explored"].get<std::size_t>() == explored);
    CHECK(j["explored"].get<std::size_t>() + j["unobservable"].get<std::size_t>() == 625);
    CHECK(j["hash"].get<std::string>().size() == 16);
    // Same command, same bytes.
    const auto again =
        run_antkit(std::string("explore --size 25x25 --obstacles 5 --seed 3 --algo ") + algo +
                   " --format json");
    CHECK(again.out == r.out);
  }
}

TEST_CASE("explore: the frontier baseline with and without line-of-sight sweeping", "[cli]") {
  const auto on = run_antkit("explore --size 20x15 --blocks 1 --algo frontier --format json");
  const auto off =
      run_antkit("explore --size 20x15 --blocks 1 --algo frontier --los off --format json");
  REQUIRE(on.status == 0);
  REQUIRE(off.status == 0);
  const auto jon = nlohmann::json::parse(on.out), joff = nlohmann::json::parse(off.out);
  CHECK(jon["hash"] != joff["hash"]);
  // Without sweeping, no cell is ever LOS, S+LOS or NLOS.
  for (const auto& row : joff["cells"])
    CHECK(row.get<std::string>().find_first_of("LBN") == std::string::npos);
}

TEST_CASE("explore: --start and a map file with a start cell", "[cli]") {
  const antkit::test::ScratchDir dir("explore-cli");
  const auto map = dir / "room.txt";
  std::ofstream(map) << "......\n.#..#.\n......\n..S...\n";
  const auto r =
      run_antkit("explore --map " + map.string() + " --algo fast-wall-follow --format json");
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["cells"][1].get<std::string>()[1] == 'O');
  CHECK(j["unobservable"] == 0);
  const auto s = run_antkit("explore --size 10x10 --start 5,5 --algo frontier --format json");
  CHECK(s.status == 0);
}

TEST_CASE("explore: --svg and --png write a picture", "[cli]") {
  const antkit::test::ScratchDir dir("explore-cli");
  const auto path = dir / "antkit-explore-cli.svg";
  const auto png = dir / "antkit-explore-cli.png";
  const auto r = run_antkit("explore --size 12x9 --obstacles 4 --algo fast-wall-follow --svg " +
                            path.string() + " --png " + png.string());
  REQUIRE(r.status == 0);
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(text.find("<svg") != std::string::npos);
  CHECK(text.find("rgb(0%,89.803922%,100%)") != std::string::npos);               // A, #00e5ff
  CHECK(text.find("rgb(55.294118%,33.333333%,14.117647%)") != std::string::npos); // S, #8d5524
  CHECK(std::filesystem::file_size(png) > 1000);
}

TEST_CASE("explore: bad input exits 2 with one clear message and no output file", "[cli]") {
  const antkit::test::ScratchDir dir("explore-bad");
  const auto svg = dir / "antkit-explore-bad.svg";
  for (const std::string args : {
           "explore --size 25x25 --algo fast-wall-follow --los off",
           "explore --size 25 --algo frontier",
           "explore --size 0x9 --algo frontier",
           "explore --size 5x5 --obstacles 1 --blocks 1 --algo frontier",
           "explore --size 5x5 --obstacles 100 --algo frontier",
           "explore --size 5x5 --blocks 9 --algo frontier",
           "explore --size 9x9 --start 3 --algo frontier",
           "explore --size 9x9 --start 20,1 --algo frontier",
           "explore --size 9x9 --algo wander",
           "explore --algo frontier",
           "explore --map /no/such/map.map --algo frontier",
           "explore --size 9x9 --algo frontier --w2 99999999999",
       }) {
    const auto r = run_antkit(args + " --svg " + svg.string());
    INFO(args << "\n" << r.err);
    CHECK(r.status == 2);
    CHECK(r.err.rfind("antkit: error: ", 0) == 0);
    CHECK(r.out.empty());
    CHECK_FALSE(std::filesystem::exists(svg));
  }
}

TEST_CASE("explore-tables: Tables 2 and 3 as CSV and Markdown with ours beside the paper's",
          "[cli]") {
  const antkit::test::ScratchDir scratch("explore-tables");
  const auto dir = scratch / "out";
  const auto r = run_antkit("explore-tables --format json --out " + dir.string());
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  REQUIRE(j["table3"].size() == 7);
  // The empty room: every repetition is the same run, and the paper's numbers sit beside ours.
  CHECK(j["table3"][0]["paper_fwf_steps"] == 47);
  CHECK(j["table3"][0]["paper_sheng_steps"] == 158.7);
  for (const char* name : {"table2.csv", "table2.md", "table3.csv", "table3.md"})
    CHECK(std::filesystem::exists(dir / name));
  std::ifstream csv(dir / "table2.csv");
  std::size_t lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  CHECK(lines == 1 + 4 * 10 + 2 * 5); // header, four columns of 10, two of 5
  // Same seed, same tables.
  const auto again = run_antkit("explore-tables --format json --out " + dir.string());
  CHECK(again.out == r.out);
  std::filesystem::remove_all(dir);
  const auto bad = run_antkit("explore-tables --out /proc/no-such-dir/x");
  CHECK(bad.status == 2);
  CHECK(bad.err.rfind("antkit: error: ", 0) == 0);
}
