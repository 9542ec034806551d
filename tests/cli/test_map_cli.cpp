// `antkit map info` and `antkit map convert`, run as the real executable: the published counts of
// shared maps, conversions that round-trip, and bad input -> exit 2, one
// `antkit: error: FILE:LINE:COL: ...` line, nothing on stdout and no output file left behind.
#include "run_antkit.hpp"
#include "scratch_dir.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <unistd.h>

using antkit::test::run_antkit;
using antkit::test::shared_map;

namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A fresh scratch directory per test case, removed when the test case ends (scratch_dir.hpp).
struct TempDir {
  antkit::test::ScratchDir scratch{"map-cli"};
  std::filesystem::path path = scratch.path();
  std::string write(const std::string& name, const std::string& content) const {
    std::ofstream(path / name, std::ios::binary) << content;
    return (path / name).string();
  }
  [[nodiscard]] std::size_t entries() const {
    return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(path),
                                                  std::filesystem::directory_iterator()));
  }
};

} // namespace

TEST_CASE("antkit map info --format json gives a shared map's published counts", "[cli][maps]") {
  struct Case {
    const char* map;
    int width, height, free, blocked, unknown, components, largest;
  };
  for (const auto& c :
       {Case{"movingai/Berlin_1_256.map", 256, 256, 47540, 17996, 0, 10, 46880},
        Case{"movingai/warehouse-10-20-10-2-1.map", 161, 63, 5699, 4444, 0, 1, 5699},
        Case{"ros/willow-2010-02-18-0.10.yaml", 566, 608, 109207, 544, 234377, 187, 108671}}) {
    INFO(c.map);
    const auto r = run_antkit("map info " + shared_map(c.map) + " --format json");
    REQUIRE(r.status == 0);
    CHECK(r.err.empty());
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j.at("width") == c.width);
    CHECK(j.at("height") == c.height);
    CHECK(j.at("free") == c.free);
    CHECK(j.at("blocked") == c.blocked);
    CHECK(j.at("unknown") == c.unknown);
    CHECK(j.at("components") == c.components);
    CHECK(j.at("largest_component") == c.largest);
  }
}

TEST_CASE("antkit map info prints a table by default", "[cli][maps]") {
  const auto r = run_antkit("map info " + shared_map("ros/lab.yaml"));
  REQUIRE(r.status == 0);
  CHECK(r.out.find("components         13\n") != std::string::npos);
  CHECK(r.out.find("free               40037\n") != std::string::npos);
  CHECK(r.out.find("resolution         0.05\n") != std::string::npos);
}

TEST_CASE("antkit map convert: MovingAI -> ASCII -> MovingAI gives back the benchmark file",
          "[cli][maps]") {
  TempDir dir;
  // room-32-32-4 uses only `.` and `@`, the characters the writer uses, so the bytes come back.
  const auto original = shared_map("movingai/room-32-32-4.map");
  const auto ascii = (dir.path / "room.txt").string();
  const auto back = (dir.path / "room.map").string();
  auto r = run_antkit("map convert " + original + " " + ascii + " --format json");
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j.at("format") == "ascii");
  CHECK(j.at("unknown_written_as_blocked") == 0);
  r = run_antkit("map convert " + ascii + " " + back);
  REQUIRE(r.status == 0);
  CHECK(slurp(back) == slurp(original));
  CHECK(dir.entries() == 2); // no temporary files left beside the outputs
}

TEST_CASE(
    "antkit map convert: a ROS map to ASCII keeps unknown cells, to MovingAI says it lost them",
    "[cli][maps]") {
  TempDir dir;
  const auto txt = (dir.path / "world.txt").string();
  auto r = run_antkit("map convert " + shared_map("ros/turtlebot3_world.yaml") + " " + txt);
  REQUIRE(r.status == 0);
  r = run_antkit("map info " + txt + " --format json");
  REQUIRE(r.status == 0);
  auto j = nlohmann::json::parse(r.out);
  CHECK(j.at("free") == 7903);
  CHECK(j.at("blocked") == 870);
  CHECK(j.at("unknown") == 138683);
  CHECK(j.at("components") == 6);

  r = run_antkit("map convert " + txt + " " + (dir.path / "world.map").string() + " --format json");
  REQUIRE(r.status == 0);
  j = nlohmann::json::parse(r.out);
  CHECK(j.at("unknown_written_as_blocked") == 138683);
  r = run_antkit("map info " + (dir.path / "world.map").string() + " --format json");
  j = nlohmann::json::parse(r.out);
  CHECK(j.at("blocked") == 870 + 138683);
  CHECK(j.at("unknown") == 0);
}

TEST_CASE("antkit map: bad input exits 2 with FILE:LINE:COL and writes nothing", "[cli][maps]") {
  TempDir dir;
  const std::string yaml_rest = "resolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n"
                                "occupied_thresh: 0.65\nfree_thresh: 0.196\n";
  dir.write("short.pgm", "P5\n4 4\n255\nabc");
  dir.write("huge.pgm", "P5\n1048576 1048576\n255\n");
  struct Case {
    std::string input;    // the file to read
    std::string location; // what the message must start with after "antkit: error: "
  };
  const std::vector<Case> cases{
      {dir.write("rows.map", "type octile\nheight 2\nwidth 2\nmap\n..\n.\n"),
       (dir.path / "rows.map").string() + ":6:2: row 1 has 1 cells; expected 2"},
      {dir.write("char.txt", "..\n.x\n"),
       (dir.path / "char.txt").string() + ":2:2: unexpected cell 'x'"},
      {dir.write("number.yaml", "image: short.pgm\nresolution: 0,05\norigin: [0, 0, 0]\n"
                                "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n"),
       (dir.path / "number.yaml").string() + ":2:13: bad resolution '0,05'"},
      {dir.write("missing.yaml", "image: gone.pgm\n" + yaml_rest),
       (dir.path / "missing.yaml").string() + ":1:8: cannot read the image 'gone.pgm'"},
      {dir.write("short.yaml", "image: short.pgm\n" + yaml_rest),
       (dir.path / "short.pgm").string() + ":4:4: truncated PGM"},
      {dir.write("huge.yaml", "image: huge.pgm\n" + yaml_rest),
       (dir.path / "huge.pgm").string() + ":2:1: map size 1048576 x 1048576 = 1099511627776 cells "
                                          "is over the cap"},
      {dir.write("huge.map", "type octile\nheight 999999999\nwidth 3\nmap\n"),
       (dir.path / "huge.map").string() + ":3:1: map size 3 x 999999999 is outside"},
  };
  const auto before = dir.entries();
  for (const auto& c : cases) {
    for (const char* out : {"out.map", "out.txt"}) {
      INFO(c.input << " -> " << out);
      const auto r = run_antkit("map convert " + c.input + " " + (dir.path / out).string());
      CHECK(r.status == 2);
      CHECK(r.out.empty());
      CHECK(r.err.rfind("antkit: error: " + c.location, 0) == 0);
      CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
      CHECK_FALSE(std::filesystem::exists(dir.path / out));
    }
    const auto r = run_antkit("map info " + c.input);
    CHECK(r.status == 2);
    CHECK(r.err.rfind("antkit: error: " + c.location, 0) == 0);
  }
  CHECK(dir.entries() == before); // no output and no temporary file appeared
}

TEST_CASE("antkit map: names that are not maps, and an existing output that must survive",
          "[cli][maps]") {
  TempDir dir;
  const auto good = shared_map("movingai/empty-32-32.map");
  auto r = run_antkit("map info " + dir.write("map.png", "x"));
  CHECK(r.status == 2);
  CHECK(r.err.find("unknown map extension '.png'") != std::string::npos);
  r = run_antkit("map convert " + good + " " + (dir.path / "out.yaml").string());
  CHECK(r.status == 2);
  CHECK(r.err.find("read-only") != std::string::npos);
  r = run_antkit("map info " + (dir.path / "nothing.map").string());
  CHECK(r.status == 2);
  CHECK(r.err.find("cannot open for reading") != std::string::npos);
  r = run_antkit("map info");
  CHECK(r.status == 2);
  r = run_antkit("map info " + dir.path.string() + "/");
  CHECK(r.status == 2);

  // A failed conversion leaves an existing output file exactly as it was.
  const auto out = dir.write("keep.txt", "#S#\n");
  r = run_antkit("map convert " + dir.write("bad.map", "type octile\n") + " " + out);
  CHECK(r.status == 2);
  CHECK(slurp(out) == "#S#\n");
}

TEST_CASE("antkit map info and convert take the map as --map too, as the other subcommands do",
          "[cli][maps]") {
  TempDir dir;
  const auto map = shared_map("movingai/room-32-32-4.map");
  const auto positional = run_antkit("map info " + map + " --format json");
  const auto named = run_antkit("map info --map " + map + " --format json");
  REQUIRE(positional.status == 0);
  REQUIRE(named.status == 0);
  CHECK(named.out == positional.out);
  const auto out = (dir.path / "room.txt").string();
  const auto converted = run_antkit("map convert --map " + map + " --out " + out);
  REQUIRE(converted.status == 0);
  const auto again = run_antkit("map info --map " + out + " --format json");
  REQUIRE(again.status == 0);
  const auto a = nlohmann::json::parse(positional.out), b = nlohmann::json::parse(again.out);
  CHECK(a["free"] == b["free"]);
  CHECK(a["blocked"] == b["blocked"]);
  CHECK(a["components"] == b["components"]);
  // Both forms at once are one map given twice: refused as bad usage.
  CHECK(run_antkit("map info " + map + " --map " + map).status == 2);
}
