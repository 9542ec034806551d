// `antkit stc` and `antkit stc-noise`, run as the real executable (issue 3).
#include "run_antkit.hpp"
#include "scratch_dir.hpp"

#include <antkit/maps/map_io.hpp>
#include <antkit/testing/stc.hpp>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

using antkit::test::run_antkit;
using antkit::test::shared_map;

namespace {

// One directory for the test process (ctest runs each test case in its own), removed when it ends.
const std::filesystem::path& scratch() {
  static const antkit::test::ScratchDir dir("stc-cli");
  return dir.path();
}

std::filesystem::path temp_file(const std::string& name, const std::string& text) {
  const auto path = scratch() / name;
  std::ofstream(path) << text;
  return path;
}

std::vector<antkit::kernel::Cell> path_of(const nlohmann::json& j) {
  std::vector<antkit::kernel::Cell> path;
  for (const auto& p : j.at("path")) path.push_back({p.at(0).get<int>(), p.at(1).get<int>()});
  return path;
}

const std::vector<std::string> kSharedMaps{"movingai/Berlin_1_256.map",
                                           "movingai/Boston_0_256.map",
                                           "movingai/brc202d.map",
                                           "movingai/den312d.map",
                                           "movingai/empty-32-32.map",
                                           "movingai/ht_chantry.map",
                                           "movingai/lak303d.map",
                                           "movingai/maze-32-32-2.map",
                                           "movingai/random-32-32-10.map",
                                           "movingai/random-32-32-20.map",
                                           "movingai/room-32-32-4.map",
                                           "movingai/room-64-64-8.map",
                                           "movingai/warehouse-10-20-10-2-1.map",
                                           "ros/lab.yaml",
                                           "ros/map_office_raw.yaml",
                                           "ros/turtlebot3_world.yaml",
                                           "ros/willow-2010-02-18-0.10.yaml"};

} // namespace

TEST_CASE("antkit stc covers every shared map with every variant - invariants checked on the "
          "printed path",
          "[cli][stc]") {
  antkit::testing::StcTourChecker checker;
  for (const auto& name : kSharedMaps) {
    const std::string file = shared_map(name);
    const auto map = antkit::maps::load_map(file);
    std::string exact_hash;
    for (const char* variant : {"offline", "online", "ant", "ant-edge", "full"}) {
      INFO(name << " " << variant);
      const auto r = run_antkit("stc --map " + file + " --variant " + variant + " --format json");
      REQUIRE(r.status == 0);
      const auto j = nlohmann::json::parse(r.out);
      const auto path = path_of(j);
      const antkit::kernel::Cell start{j.at("start").at(0).get<int>(),
                                       j.at("start").at(1).get<int>()};
      CHECK(j.at("width") == map.cells.width());
      CHECK(j.at("height") == map.cells.height());
      CHECK(j.at("returned_to_start") == true);
      CHECK(j.at("covered") == j.at("reachable_subcells"));
      const bool full = std::string(variant) == "full";
      const auto check = full ? checker.check_full(map.cells, start, path, j.at("repeats"))
                              : checker.check_exact(map.cells, start, path);
      INFO(check);
      CHECK(check.ok);
      if (!full) {
        CHECK(j.at("repeats") == 0);
        if (exact_hash.empty()) exact_hash = j.at("hash");
        CHECK(j.at("hash") == exact_hash); // invariant 5, through the command
      }
    }
  }
}

TEST_CASE("antkit stc: golden hash of a shared map and the default start", "[cli][stc][golden]") {
  // den312d: the largest free-cell region's first cell is (10, 1), NW sub-cell (20, 2).
  const auto r = run_antkit("stc --map " + shared_map("movingai/den312d.map") +
                            " --variant ant --format json");
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j.at("start") == nlohmann::json{20, 2});
  CHECK(j.at("hash") == "7ed67b0817467a5b");
  CHECK(j.at("reachable_subcells") == 1920);
}

TEST_CASE("antkit stc: the start comes from --start - or from the map's S", "[cli][stc]") {
  const auto file = temp_file("start.txt", "......\n......\n..S...\n......\n");
  auto r = run_antkit("stc --map " + file.string() + " --variant online --format json");
  REQUIRE(r.status == 0);
  CHECK(nlohmann::json::parse(r.out).at("start") == nlohmann::json{2, 2});
  r = run_antkit("stc --map " + file.string() + " --variant online --start 5,3 --format json");
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j.at("start") == nlohmann::json{5, 3});
  CHECK(j.at("path").size() == 24);
  CHECK(j.at("path").at(0) == nlohmann::json{5, 3});
}

TEST_CASE("antkit stc: bad input exits 2 with one clear message and no output", "[cli][stc]") {
  const auto ok = temp_file("ok.txt", "....#\n....#\n##..#\n##..#\n");
  const auto partial = temp_file("partial.txt", ".#.#\n#.#.\n.#.#\n#.#.\n");
  const auto malformed = temp_file("bad.map", "type octile\nheight 2\nwidth 3\nmap\n...\n..\n");
  const auto svg = scratch() / "never.svg";
  std::filesystem::remove(svg);
  struct Case {
    std::string args;
    std::string says;
  };
  const std::vector<Case> cases{
      {"stc --map " + malformed.string() + " --variant ant --svg " + svg.string(), "bad.map:"},
      {"stc --map /no/such/map.map --variant ant", "map.map"},
      {"stc --map " + ok.string() + " --variant ant --start 0,2", "inside an obstacle"},
      {"stc --map " + ok.string() + " --variant ant --start 9,9", "outside"},
      {"stc --map " + ok.string() + " --variant ant --start x", "--start"},
      {"stc --map " + partial.string() + " --variant offline", "no free cell"},
      {"stc --map " + partial.string() + " --variant ant --start 0,0", "blocked sub-cell"},
      {"stc --map " + ok.string() + " --variant sideways", "--variant"},
      {"stc --map " + ok.string() + " --variant offline --noise 0.1", "--noise"},
      {"stc --map " + ok.string() + " --variant ant --noise 1.5", "--noise"},
      {"stc --map " + ok.string() + " --variant ant --noise 0.0000001", "--noise"},
      {"stc-noise --map " + ok.string() + " --trials 0", "--trials"},
      {"stc-noise --map " + ok.string() + " --levels 0.1,,0.2", "--levels"},
  };
  for (const auto& c : cases) {
    INFO(c.args);
    const auto r = run_antkit(c.args);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(r.err.rfind("antkit: error: ", 0) == 0);
    CHECK(r.err.find(c.says) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  }
  CHECK_FALSE(std::filesystem::exists(svg));
  // full starts where the exact variants cannot.
  CHECK(run_antkit("stc --map " + partial.string() + " --variant full --start 0,0").status == 0);
}

TEST_CASE("antkit stc --svg and --png draw obstacles - tree and tour", "[cli][stc]") {
  const auto map = temp_file("svg.txt", "........\n........\n..##....\n..##....\n");
  const antkit::test::ScratchDir dir("stc-cli-svg");
  const auto svg = dir / "tour.svg", png = dir / "tour.png";
  const auto r = run_antkit("stc --map " + map.string() + " --variant ant --svg " + svg.string() +
                            " --png " + png.string());
  REQUIRE(r.status == 0);
  std::ifstream in(svg);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(text.find("<svg") != std::string::npos);
  CHECK(text.find("rgb(72%,72%,72%)") != std::string::npos); // the spanning tree's light grey
  CHECK(text.find("rgb(25%,25%,25%)") != std::string::npos); // obstacles
  // The tour's strokes run from the start's colour (dark violet) to the end's (yellow).
  CHECK(text.find("rgb(26.7") != std::string::npos);
  CHECK(text.find("rgb(99.3") != std::string::npos);
  std::ifstream p(png, std::ios::binary);
  std::string head(8, '\0');
  p.read(head.data(), 8);
  CHECK(head.substr(1, 3) == "PNG");
}

TEST_CASE("antkit stc streams the path - --path-out csv and bin read back by check stc",
          "[cli][stc]") {
  const std::string map = shared_map("movingai/den312d.map");
  const antkit::test::ScratchDir dir("stc-path");
  for (const char* variant : {"offline", "ant-edge", "full"}) {
    INFO(variant);
    const auto json = run_antkit("stc --map " + map + " --variant " + variant +
                                 " --format json --path-out " + (dir / "p.csv").string());
    REQUIRE(json.status == 0);
    const auto j = nlohmann::json::parse(json.out);
    const auto bin = run_antkit("stc --map " + map + " --variant " + variant + " --path-out " +
                                (dir / "p.bin").string());
    REQUIRE(bin.status == 0);
    // The binary form: 32 header bytes and two bits per move.
    const auto moves = j.at("path").size() - 1;
    CHECK(std::filesystem::file_size(dir / "p.bin") == 32 + (moves + 3) / 4);
    const std::string coverage = std::string(variant) == "full" ? " --coverage" : "";
    for (const char* f : {"p.csv", "p.bin"}) {
      INFO(f);
      const auto c = run_antkit("check stc --map " + map + " --path " + (dir / f).string() +
                                coverage + " --format json");
      REQUIRE(c.status == 0);
      const auto k = nlohmann::json::parse(c.out);
      CHECK(k.at("positions") == j.at("path").size());
      CHECK(k.at("covered") == j.at("covered"));
      CHECK(k.at("start") == j.at("start"));
    }
  }
  // A name that is neither .csv nor .bin is bad input: exit 2, nothing written, nothing printed.
  const auto bad = run_antkit("stc --map " + map + " --variant offline --format json --path-out " +
                              (dir / "p.txt").string());
  CHECK(bad.status == 2);
  CHECK(bad.out.empty());
  CHECK(bad.err.find("--path-out") != std::string::npos);
  CHECK(!std::filesystem::exists(dir / "p.txt"));
  // A start in an obstacle: refused before the JSON's first byte.
  const auto wall = run_antkit("stc --map " + map + " --variant offline --format json --start 0,0");
  CHECK(wall.status == 2);
  CHECK(wall.out.empty());
}

TEST_CASE("antkit stc --noise is reproducible by seed - stc-noise reports a curve", "[cli][stc]") {
  const std::string map = shared_map("movingai/random-32-32-10.map");
  const auto a =
      run_antkit("stc --map " + map + " --variant ant --noise 0.05 --seed 3 --format json");
  const auto b =
      run_antkit("stc --map " + map + " --variant ant --noise 0.05 --seed 3 --format json");
  REQUIRE(a.status == 0);
  CHECK(a.out == b.out);
  CHECK(nlohmann::json::parse(a.out).at("noise_ppm") == 50000);
  const auto r = run_antkit("stc-noise --map " + map +
                            " --variant ant-edge --levels 0,0.05 --trials 3 --format json");
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  REQUIRE(j.at("curve").size() == 2);
  CHECK(j.at("curve").at(0).at("coverage") == 1.0);
  CHECK(j.at("curve").at(0).at("complete_tours") == 1.0);
  CHECK(j.at("curve").at(1).at("coverage").get<double>() <= 1.0);
}
