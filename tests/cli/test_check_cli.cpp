// `antkit check stc`, run as the real executable (issue 18): antkit's own tours pass, another
// planner's path converted from row/column pairs passes, and a damaged tour exits 1 with every
// violation counted in the report.
#include "run_antkit.hpp"
#include "scratch_dir.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <unistd.h>

using antkit::test::run_antkit;
using antkit::test::shared_map;
namespace fs = std::filesystem;

namespace {

// One directory for the test process (ctest runs each test case in its own), removed when it ends.
const fs::path& scratch() {
  static const antkit::test::ScratchDir dir("check-cli");
  return dir.path();
}

fs::path write(const std::string& name, const std::string& text) {
  const auto path = scratch() / name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

} // namespace

TEST_CASE("antkit check stc: every variant's own output passes its rule on shared maps",
          "[cli][check]") {
  for (const char* name :
       {"movingai/maze-32-32-2.map", "movingai/room-32-32-4.map", "ros/turtlebot3_world.yaml"}) {
    const std::string map = shared_map(name);
    for (const char* variant : {"offline", "ant-edge", "full"}) {
      INFO(name << " " << variant);
      const auto tour = run_antkit("stc --map " + map + " --variant " + variant + " --format json");
      REQUIRE(tour.status == 0);
      const auto file = write("tour.json", tour.out);
      const bool full = std::string(variant) == "full";
      const auto r = run_antkit("check stc --map " + map + " --path " + file.string() +
                                (full ? " --coverage" : "") + " --format json");
      INFO(r.err);
      REQUIRE(r.status == 0);
      const auto j = nlohmann::json::parse(r.out);
      const auto stc = nlohmann::json::parse(tour.out);
      CHECK(j.at("ok") == true);
      CHECK(j.at("rule") == (full ? "coverage" : "exactly-once"));
      CHECK(j.at("start") == stc.at("start"));
      CHECK(j.at("start_from") == "tour file");
      CHECK(j.at("reachable_subcells") == stc.at("reachable_subcells"));
      CHECK(j.at("covered") == stc.at("covered"));
      // Full-STC may end on its start (a repeat to antkit stc); the check reads a tour that ends
      // on its start as closed, that return not a repeat. Exact tours end next to the start.
      const bool closed = j.at("closed_form").get<bool>();
      CHECK((full || !closed));
      CHECK(j.at("repeats").get<int>() + (closed ? 1 : 0) == stc.at("repeats").get<int>());
      CHECK(j.at("first_violation").is_null());
      if (full) { // Full-STC does not promise exactly once: the strict rule refuses it
        const auto strict = run_antkit("check stc --map " + map + " --path " + file.string());
        CHECK(strict.status == 1);
        CHECK(strict.err.rfind("antkit: check failed: ", 0) == 0);
      }
    }
  }
}

TEST_CASE("antkit check stc: another planner's row/column pairs, converted to CSV, pass",
          "[cli][check]") {
  // A 4 x 4 free map (2 x 2 cells) and a tour around it given as (row, column) pairs, as many
  // planners print them; README's conversion swaps them into x,y lines.
  const auto map = write("square.txt", "....\n....\n....\n....\n");
  const int rows_cols[][2] = {{0, 0}, {0, 1}, {0, 2}, {0, 3}, {1, 3}, {2, 3}, {3, 3}, {3, 2},
                              {3, 1}, {3, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {1, 1}, {1, 0}};
  std::string csv = "x,y\n";
  for (const auto& rc : rows_cols)
    csv += std::to_string(rc[1]) + "," + std::to_string(rc[0]) + "\n";
  const auto path = write("tour.csv", csv);
  const auto r =
      run_antkit("check stc --map " + map.string() + " --path " + path.string() + " --format json");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j.at("reachable_subcells") == 16);
  CHECK(j.at("start") == nlohmann::json::array({0, 0}));
  CHECK(j.at("start_from") == "first position");
  CHECK(j.at("end_distance") == 1);
}

TEST_CASE("antkit check stc --order rc and a row,col header read a planner's pairs as it wrote "
          "them, and a transposed tour on a map that is not symmetric fails",
          "[cli][check]") {
  // 6 wide, 4 high, all free: the same (row, col) numbers read as x,y leave the map.
  const auto map = write("wide.txt", "......\n......\n......\n......\n");
  const auto xy = run_antkit("stc --map " + map.string() + " --variant offline --format json");
  REQUIRE(xy.status == 0);
  const auto tour = nlohmann::json::parse(xy.out).at("path");
  std::string rows_cols, json = "[";
  for (const auto& p : tour) {
    rows_cols += std::to_string(p[1].get<int>()) + "," + std::to_string(p[0].get<int>()) + "\n";
    json += (json.size() > 1 ? ",[" : "[") + std::to_string(p[1].get<int>()) + "," +
            std::to_string(p[0].get<int>()) + "]";
  }
  json += "]";
  const auto headed = write("headed.csv", "row,col\n" + rows_cols);
  const auto bare = write("bare.csv", rows_cols);
  const auto pairs = write("pairs.json", json);
  const auto check = [&](const std::filesystem::path& path, const std::string& extra) {
    return run_antkit("check stc --map " + map.string() + " --path " + path.string() +
                      " --format json" + extra);
  };
  const auto by_header = check(headed, "");
  INFO(by_header.err);
  REQUIRE(by_header.status == 0);
  CHECK(nlohmann::json::parse(by_header.out).at("order") == "rc");
  CHECK(nlohmann::json::parse(by_header.out).at("order_from") == "header");
  for (const auto& path : {bare, pairs}) {
    const auto by_option = check(path, " --order rc");
    REQUIRE(by_option.status == 0);
    CHECK(nlohmann::json::parse(by_option.out).at("order_from") == "--order");
    CHECK(check(path, "").status == 1); // read as x,y: transposed, off the map
  }
  CHECK(check(bare, " --order yx").status == 2);
}

TEST_CASE("antkit check stc --cells: the map and the start in robot-sized cells, the tour in "
          "sub-cells from any sub-cell of the start cell",
          "[cli][check]") {
  // 3 x 2 cells with one blocked; the planner's world is that map, its tour is in sub-cells.
  const auto cells = write("cells.txt", ".#.\n...\n");
  const auto subcells = write("subcells.txt", "..##..\n..##..\n......\n......\n");
  for (const std::string start : {"4,0", "5,1"}) {
    INFO(start);
    const auto made = run_antkit("stc --map " + subcells.string() +
                                 " --variant offline --format json --start " + start);
    REQUIRE(made.status == 0);
    const auto path = write("cells-tour.json", nlohmann::json::parse(made.out).at("path").dump());
    const auto r = run_antkit("check stc --cells --map " + cells.string() + " --path " +
                              path.string() + " --start 2,0 --format json");
    INFO(r.err);
    REQUIRE(r.status == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j.at("cells") == true);
    CHECK(j.at("start_cell") == nlohmann::json::array({2, 0}));
    CHECK(j.at("start") == nlohmann::json::parse("[" + start + "]"));
    CHECK(j.at("reachable_subcells") == 20);
    CHECK(j.at("width") == 6);
    // Another start cell: the tour does not start in it.
    CHECK(run_antkit("check stc --cells --map " + cells.string() + " --path " + path.string() +
                     " --start 0,1")
              .status == 1);
    // The start cell must be a free cell of the cells' map.
    CHECK(run_antkit("check stc --cells --map " + cells.string() + " --path " + path.string() +
                     " --start 1,0")
              .status == 2);
  }
}

TEST_CASE("antkit check stc: a damaged tour exits 1 and its report counts every violation",
          "[cli][check]") {
  const auto map = write("square.txt", "....\n....\n....\n....\n");
  // A tour of that square with one step off the map at (4, 1) (then a jump back), (3, 3) skipped
  // by a diagonal jump, (1, 2) doubled, and cut before its last two positions (1, 1), (0, 1).
  const auto path = write("damaged.csv", "0,0\n1,0\n2,0\n3,0\n3,1\n4,1\n3,2\n2,3\n1,3\n0,3\n"
                                         "0,2\n1,2\n1,2\n2,2\n2,1\n");
  const auto r =
      run_antkit("check stc --map " + map.string() + " --path " + path.string() + " --format json");
  REQUIRE(r.status == 1);
  CHECK(r.err == "antkit: check failed: " + path.string() +
                     ": invariant 2 moves broken at step 5, sub-cell (4, 1): not a free sub-cell "
                     "inside the cell area\n");
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j.at("ok") == false);
  CHECK(j.at("positions") == 15);
  CHECK(j.at("off_limits") == 1);
  CHECK(j.at("repeats") == 1);
  CHECK(j.at("illegal_moves") == 3); // (4,1)->(3,2), (3,2)->(2,3), (1,2)->(1,2)
  CHECK(j.at("missed") == 3);        // (3, 3), (1, 1), (0, 1)
  CHECK(j.at("missed_sample") == nlohmann::json::parse("[[0,1],[1,1],[3,3]]"));
  CHECK(j.at("end_distance") == 3);
  CHECK(j.at("first_violation").at("rule") == "2 moves");
  CHECK(j.at("first_violation").at("step") == 5);
}

TEST_CASE("antkit check cover: antkit cover's traces pass, recomputed coverage equal to the "
          "reported",
          "[cli][check]") {
  const std::string map = shared_map("movingai/room-32-32-4.map");
  for (const char* algo : {"rw", "pm", "astar", "astar-coord", "frontier"}) {
    INFO(algo);
    const auto trace = scratch() / "trace.csv";
    const auto run =
        run_antkit("cover --map " + map + " --algo " + algo +
                   " --robots 3 --sensor 4 --limit 500 --format json --trace " + trace.string());
    REQUIRE(run.status == 0);
    const auto r =
        run_antkit("check cover --map " + map + " --log " + trace.string() + " --format json");
    INFO(r.err);
    REQUIRE(r.status == 0);
    const auto j = nlohmann::json::parse(r.out);
    const auto c = nlohmann::json::parse(run.out);
    CHECK(j.at("ok") == true);
    CHECK(j.at("sensor") == 4);
    CHECK(j.at("sensor_from") == "trace");
    CHECK(j.at("viewed") == c.at("viewed"));
    CHECK(j.at("viewable") == c.at("viewable"));
    CHECK(j.at("claims_match") == true);
    CHECK(j.at("ticks") == c.at("movements").get<int>() + 1);
    CHECK(j.at("robots") == 3);
    // The same trace read with a larger sensor than the run's: the claim no longer holds
    // unless the run had already viewed everything.
    const auto wider = run_antkit("check cover --map " + map + " --log " + trace.string() +
                                  " --sensor 6 --format json");
    const auto w = nlohmann::json::parse(wider.out);
    CHECK(wider.status == (w.at("viewed") == c.at("viewed") ? 0 : 1));
  }
}

TEST_CASE("antkit check explore: antkit explore's states pass, and a wrong state exits 1",
          "[cli][check]") {
  const std::string map = shared_map("movingai/maze-32-32-2.map");
  for (const char* algo : {"fast-wall-follow", "frontier"}) {
    INFO(algo);
    const auto run = run_antkit("explore --map " + map + " --algo " + algo + " --format json");
    REQUIRE(run.status == 0);
    const auto cells = write("cells.json", run.out);
    const auto r =
        run_antkit("check explore --map " + map + " --cells " + cells.string() + " --format json");
    REQUIRE(r.status == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j.at("ok") == true);
    CHECK(j.at("known_free_not_free") == 0);
    CHECK(j.at("obstacle_but_free") == 0);
  }
  // Every cell marked S: each blocked cell of the maze is a violation.
  std::string rows;
  for (int y = 0; y < 32; ++y) rows += std::string(32, 'S') + "\n";
  const auto bad = write("all-s.txt", rows);
  const auto r =
      run_antkit("check explore --map " + map + " --cells " + bad.string() + " --format json");
  REQUIRE(r.status == 1);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j.at("known_free") == 1024);
  CHECK(j.at("known_free_not_free") == 1024 - j.at("free_cells").get<int>());
  CHECK(r.err.find("is marked S but is not free") != std::string::npos);
}
