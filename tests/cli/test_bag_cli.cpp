// `antkit bag info` and `antkit buffon-from-logs --topic` on ROS 2 bags written by independent
// writers under node (tests/support/write_bags.mjs): walk 1 along the x axis, walk 2 a zigzag
// crossing it nine times, in every storage; the JSON is the same whichever storage holds a walk.
#include "mcap_reader.hpp"
#include "ros_bags.hpp"
#include "run_antkit.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <numbers>

using antkit::test::run_antkit;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

// A 4 x 2 free map, 0.5 m cells, its lower-left corner at (-1, -2) m: write_bags.mjs's tours and
// two-robot runs lie on it.
void write_free_map(const std::string& d) {
  std::ofstream(d + "/free.yaml") << "image: free.pgm\nresolution: 0.5\norigin: [-1.0, -2.0, 0.0]\n"
                                     "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
  std::ofstream(d + "/free.pgm", std::ios::binary)
      << std::string("P5\n4 2\n255\n") + std::string(8, '\xfe');
}

std::string bags() {
  const std::string dir = antkit::test::ros_bags_dir();
  if (dir.empty()) WARN("SKIPPED: node (Node.js 20) is not installed: no test bags are written");
  return dir;
}

} // namespace

TEST_CASE("antkit bag info: topics, types, counts, time range", "[cli][bag]") {
  const std::string d = bags();
  if (d.empty()) return;
  const auto r = run_antkit("bag info '" + d + "/walk1.mcap' --format json");
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["storage"] == "mcap");
  CHECK(j["messages"] == 66);
  CHECK(j["topics"].size() == 6);
  CHECK(j["topics"][3]["topic"] == "/odom");
  CHECK(j["topics"][3]["type"] == "nav_msgs/msg/Odometry");
  CHECK(j["topics"][3]["messages"] == 11);
  CHECK(j["duration_s"] == 1.0);
  const auto t = run_antkit("bag info '" + d + "/walk2_bag'");
  REQUIRE(t.status == 0);
  CHECK_THAT(t.out, Contains("sqlite3") && Contains("/odom"));
}

TEST_CASE("antkit buffon-from-logs --topic: two bags' walks, the exact crossings and the area",
          "[cli][bag]") {
  const std::string d = bags();
  if (d.empty()) return;
  const double l1 = 10, l2 = 9 * std::sqrt(5.0);
  const double area = 2 * l1 * l2 / (std::numbers::pi * 9);
  for (const auto& [one, two] :
       {std::pair<std::string, std::string>{"walk1.mcap", "walk2_zstd.mcap"},
        {"walk1.db3", "walk2_lz4.mcap"},
        {"walk1.mcap", "walk2_bag"}}) {
    CAPTURE(one, two);
    const auto r = run_antkit("buffon-from-logs --topic /odom --width 0.1 '" + d + "/" + one +
                              "' '" + d + "/" + two + "' --format json");
    REQUIRE(r.status == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["crossings_exact"] == 9);
    CHECK(j["visit1"]["length"].get<double>() == Approx(l1));
    CHECK(j["visit2"]["length"].get<double>() == Approx(l2));
    CHECK(j["visit1"]["poses"] == 11);
    CHECK(j["area_m2"].get<double>() == Approx(area));
    CHECK(j["area_corrected_m2"].get<double>() == Approx(area));
    CHECK(j["erosion_factor"] == 1.0);
    CHECK(j["area_raw_ci"].size() == 2);
    CHECK(j["wall_encounters"].is_null());
    CHECK(j["robot"].is_null());
    CHECK(j["unit"] == "m");
  }
  // The same walks from the poses' other topics.
  const auto tf = run_antkit("buffon-from-logs --topic /tf --child-frame base_link '" + d +
                             "/walk1.mcap' '" + d + "/walk2_zstd.mcap' --format json");
  CHECK(tf.status == 2); // walk 2's bag has no /tf
  CHECK_THAT(tf.err, Contains("topic /tf is not in the bag (its topics: /odom)"));
}

TEST_CASE("antkit buffon-from-logs --topic: refusals exit 2, located", "[cli][bag][errors]") {
  const std::string d = bags();
  if (d.empty()) return;
  const std::string w1 = "'" + d + "/walk1.mcap'";
  const std::string w2 = "'" + d + "/walk2_lz4.mcap'";
  const auto same = run_antkit("buffon-from-logs --topic /odom " + w1 + " " + w1);
  CHECK(same.status == 2);
  CHECK_THAT(same.err, Contains("the same bag as"));
  const auto stamp = run_antkit("buffon-from-logs --topic /odom --stamp sideways " + w1 + " " + w2);
  CHECK(stamp.status == 2);
  CHECK_THAT(stamp.err, StartsWith("antkit: error: --stamp: 'sideways' (expected bag or header)"));
  const auto width = run_antkit("buffon-from-logs --topic /odom --width 20 " + w1 + " " + w2);
  CHECK(width.status == 2);
  CHECK_THAT(width.err, StartsWith("antkit: error: --width:"));
  const auto type = run_antkit("buffon-from-logs --topic /chatter " + w1 + " " + w2);
  CHECK(type.status == 2);
  CHECK_THAT(type.err, Contains("std_msgs/msg/String"));
  CHECK(type.out.empty());
}

TEST_CASE("antkit check stc --bag: a bag's poses as a tour on a ROS map", "[cli][bag]") {
  const std::string d = bags();
  if (d.empty()) return;
  write_free_map(d);
  const std::string map = " --map '" + d + "/free.yaml' --topic /pose --format json --bag '" + d;
  // Four poses at the corners' cells: the cells between them filled in, every cell once.
  const auto ok = run_antkit("check stc" + map + "/tour.mcap'");
  REQUIRE(ok.status == 0);
  const auto j = nlohmann::json::parse(ok.out);
  CHECK(j["ok"] == true);
  CHECK(j["positions"] == 8);
  CHECK(j["poses"] == 4);
  CHECK(j["covered"] == 8);
  CHECK(j["first_violation_time_ns"].is_null());
  // (0,0) -> (3,0) -> (1,0): cell (2,0) entered again at step 4, a quarter of the way from the
  // second pose (0.1 s) to the third (0.2 s).
  const auto bad = run_antkit("check stc" + map + "/tour_repeat.mcap'");
  CHECK(bad.status == 1);
  const auto b = nlohmann::json::parse(bad.out);
  CHECK(b["first_violation"]["step"] == 4);
  CHECK(b["first_violation"]["subcell"] == nlohmann::json::array({2, 0}));
  CHECK(b["first_violation_time_ns"] == 1700000000125000000LL);
  CHECK_THAT(bad.err, Contains("entered a second time at bag time 1700000000125000000 ns"));
  // Poses off the map: exit 2, located, nothing on standard output.
  const auto off = run_antkit("check stc --map '" + d + "/free.yaml' --topic /odom --bag '" + d +
                              "/walk1.mcap'");
  CHECK(off.status == 2);
  CHECK_THAT(off.err, Contains("leaves the map"));
  CHECK(off.out.empty());
}

TEST_CASE("antkit check cover --bag: each topic one robot, collisions at their bag time",
          "[cli][bag]") {
  const std::string d = bags();
  if (d.empty()) return;
  write_free_map(d);
  const std::string args = " --map '" + d + "/free.yaml' --topic /r0/pose --topic /r1/pose";
  // Row 0 and row 1 swept in opposite directions: three steps each, no two robots on one cell,
  // and with sensor 0 each robot views the cells it stands on: all 8.
  const auto ok =
      run_antkit("check cover" + args + " --sensor 0 --format json --bag '" + d + "/cover.mcap'");
  INFO(ok.err);
  REQUIRE(ok.status == 0);
  const auto j = nlohmann::json::parse(ok.out);
  CHECK(j["ok"] == true);
  CHECK(j["robots"] == 2);
  CHECK(j["ticks"] == 7); // the start, then 3 steps of each robot
  CHECK(j["moves"] == 6);
  CHECK(j["collisions"] == 0);
  CHECK(j["viewed"] == 8);
  CHECK(j["viewable"] == 8);
  CHECK(j["topics"].size() == 2);
  CHECK(j["topics"][1]["topic"] == "/r1/pose");
  CHECK(j["first_violation_time_ns"].is_null());
  // Head on along one row: at tick 3 (0.05 s) r0 steps onto (2,0), where r1 stands.
  const auto bad = run_antkit("check cover" + args + " --sensor 1 --format json --bag '" + d +
                              "/cover_collide.mcap'");
  CHECK(bad.status == 1);
  const auto b = nlohmann::json::parse(bad.out);
  CHECK(b["collisions"].get<int>() >= 1);
  CHECK(b["first_violation_time_ns"] == 1700000000050000000LL);
  CHECK_THAT(b["first_violation"].get<std::string>(), Contains("tick 3"));
  CHECK_THAT(bad.err, Contains("at bag time 1700000000050000000 ns"));
  // Refusals: exit 2, located, nothing on standard output.
  for (const auto& [extra, says] : std::vector<std::pair<std::string, std::string>>{
           {" --bag '" + d + "/cover.mcap'", "--bag needs --sensor"},
           {" --sensor 1 --log x.trace --bag '" + d + "/cover.mcap'", "one run"},
           {" --sensor 999 --bag '" + d + "/cover.mcap'", "sensor"},
           {" --sensor 1 --topic /r0/pose --bag '" + d + "/cover.mcap'", "given twice"},
           {" --sensor 1 --topic /odom --bag '" + d + "/walk1.mcap'", "/r0/pose"}}) {
    const auto r = run_antkit("check cover" + args + extra);
    INFO(extra);
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Contains(says));
    CHECK(r.out.empty());
  }
}

TEST_CASE("antkit bag export: the poses, the map and the check's verdict at its bag time",
          "[cli][bag]") {
  const std::string d = bags();
  if (d.empty()) return;
  write_free_map(d);
  const std::string out = d + "/collide.mcap";
  const auto r = run_antkit("bag export '" + d + "/cover_collide.mcap' --map '" + d +
                            "/free.yaml' --topic /r0/pose --topic /r1/pose --check cover "
                            "--sensor 1 --format json --out '" +
                            out + "'");
  INFO(r.err);
  CHECK(r.status == 1); // the check fails; the file is whole
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["check_ok"] == false);
  CHECK(j["channels"]["/map"] == 1);
  CHECK(j["channels"]["/robot1/pose"] == 2);
  // /log's ERROR is the collision, at its bag time (check cover --bag's first_violation_time_ns).
  std::ifstream in(out, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto file = antkit::test::mcap::read(bytes); // every CRC, index and offset checked
  std::size_t errors = 0;
  for (const auto& m : file.messages)
    if (file.channels.at(m.channel_id).topic == "/log" &&
        nlohmann::json::parse(m.data)["level"] == 4) {
      ++errors;
      CHECK(m.log_time == 1700000000050000000ULL);
      CHECK_THAT(nlohmann::json::parse(m.data)["message"].get<std::string>(),
                 Contains("another robot stands on this cell"));
    }
  CHECK(errors == 1);
  // The same bytes twice (no clock in them); a refused check writes nothing.
  (void)run_antkit("bag export '" + d + "/cover_collide.mcap' --map '" + d +
                   "/free.yaml' --topic /r0/pose --topic /r1/pose --check cover "
                   "--sensor 1 --out '" +
                   d + "/collide2.mcap'");
  std::ifstream in2(d + "/collide2.mcap", std::ios::binary);
  CHECK(std::string((std::istreambuf_iterator<char>(in2)), std::istreambuf_iterator<char>()) ==
        bytes);
  const auto refused = run_antkit("bag export '" + d + "/cover.mcap' --map '" + d +
                                  "/free.yaml' --topic /r0/pose --topic /r1/pose --check stc "
                                  "--out '" +
                                  d + "/refused.mcap'");
  CHECK(refused.status == 2);
  CHECK_THAT(refused.err, Contains("one --topic"));
  CHECK_FALSE(std::filesystem::exists(d + "/refused.mcap"));
}
