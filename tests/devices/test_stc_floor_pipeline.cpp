// The marker-floor robot (issue 14) through its rendered camera: optics, calibration file, the
// five cells' reading, and whole noise-free runs against the simulated ant-edge controller.
#include "test_paths.hpp"

#include <antkit/devices/stc_floor/floor.hpp>
#include <antkit/devices/stc_floor/optics.hpp>
#include <antkit/devices/stc_floor/pilot.hpp>
#include <antkit/devices/stc_floor/view.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/stc/world.hpp>
#include <antkit/uniform/scenario.hpp>
#include <catch2/catch.hpp>
#include <filesystem>
#include <rapidcheck/catch.h>
#include <thread>

namespace sf = antkit::devices::stc_floor;
namespace stc = antkit::stc;
using antkit::kernel::Occupancy;
using antkit::kernel::OccupancyGrid;

namespace {

OccupancyGrid open_board(std::int32_t cells_x, std::int32_t cells_y) {
  return OccupancyGrid(2 * cells_x, 2 * cells_y, Occupancy::Free);
}

struct FloorRun {
  sf::PilotResult pilot;
  stc::RunResult simulated;
  std::int64_t truth_covered = 0, truth_repeats = 0;
  std::vector<stc::SubCell> truth_path;
  std::int64_t observation_mismatches = 0;
  std::string first_mismatch;
};

// Runs the pilot through the rendered floor, with a simulated StcWorld kept in lockstep: at every
// step the camera's observation must be the world's (noise-free).
FloorRun run_floor(const OccupancyGrid& map, stc::SubCell start, stc::Variant v,
                   sf::FloorOptions floor = {}) {
  FloorRun out;
  const sf::Calibration cal = sf::ideal_calibration(floor.optics);
  const sf::View view(cal, sf::default_view(cal));
  sf::FloorWorld body(map, start, 1, floor);
  sf::SimulatedRobot robot(body);
  sf::PilotOptions o;
  o.controller = v;
  o.start = start;
  o.max_steps = 4 * map.width() * map.height() + 16;
  stc::StcWorld twin(map, start, {}, stc::Marker::Edge);
  const sf::FloorController shape(v, stc::quadrant_of(start));
  out.pilot = sf::run_pilot(robot, view, o, [&](const sf::PilotStep& s) {
    // A neighbour that is not free has no sub-cell state for the camera (view.hpp): the world's
    // masks of such a cell (marks on its border) are set aside, as the controllers ignore them.
    auto world = twin.observe_edges();
    for (std::size_t d = 0; d < 4; ++d)
      if (((world.free_neighbours >> d) & 1) == 0) world.neighbour[d] = 0;
    const auto expected = shape.observation(world);
    if (expected != s.obs && out.observation_mismatches++ == 0) {
      out.first_mismatch = "step " + std::to_string(s.step) + ":";
      for (std::size_t i = 0; i < expected.size(); ++i)
        out.first_mismatch += " " + std::to_string(expected[i]) + "/" + std::to_string(s.obs[i]);
    }
    stc::Command c{static_cast<stc::Move>(s.cmd[0]), s.cmd[1] != 0};
    if (c.move != stc::Move::Stop) twin.apply(c);
  });
  out.simulated = stc::run_stc(map, start, v);
  out.truth_covered = body.covered();
  out.truth_repeats = body.repeats();
  out.truth_path = body.path();
  return out;
}

// A map cut to at most `cells` x `cells` cells: the window of that many sub-cells around the
// map's default start (a choice: the corners and centres of the shared maps are often walls).
OccupancyGrid cut(const OccupancyGrid& map, std::int32_t cells) {
  const std::int32_t w = std::min(map.width(), 2 * cells), h = std::min(map.height(), 2 * cells);
  // Centred on the map's default start (its largest region), kept inside the map, on even
  // coordinates so that the cells stay the map's own.
  const auto start = stc::default_start(map, stc::Variant::AntEdge).value_or(stc::SubCell{0, 0});
  const std::int32_t x0 = std::clamp(start.x - w / 2, 0, map.width() - w) & ~1;
  const std::int32_t y0 = std::clamp(start.y - h / 2, 0, map.height() - h) & ~1;
  OccupancyGrid out(w, h, Occupancy::Blocked);
  for (std::int32_t y = 0; y < h; ++y)
    for (std::int32_t x = 0; x < w; ++x) out[{x, y}] = map[{x0 + x, y0 + y}];
  return out;
}

// A keyed random board: `cells` x `cells` cells with `percent` % of the sub-cells blocked.
OccupancyGrid random_board(std::int32_t cells, std::uint32_t percent, std::uint64_t key) {
  return antkit::uniform::random_obstacles(2 * cells, 2 * cells, percent * 10000, key, 0);
}

void require_exact(const FloorRun& r, const OccupancyGrid& map) {
  INFO(r.first_mismatch);
  CHECK(r.observation_mismatches == 0);
  REQUIRE(r.pilot.closed);
  CHECK_FALSE(r.pilot.refused);
  CHECK(r.pilot.path == r.simulated.path);
  CHECK(r.truth_path == r.simulated.path);
  CHECK(stc::tour_hash(map.width(), map.height(), r.pilot.path) == r.simulated.hash);
  CHECK(r.truth_covered == r.simulated.reachable_subcells);
  CHECK(r.truth_repeats == 0);
  CHECK(r.pilot.corrections == 0);
}

} // namespace

TEST_CASE("stc floor: the ideal calibration file round-trips exactly", "[devices]") {
  const sf::Calibration c = sf::ideal_calibration();
  CHECK(sf::parse_calibration("c.json", sf::calibration_json(c)) == c);
  CHECK(c.corners[11] == sf::PointQ16{(108 + 12) * sf::kOne, (108 + 12) * sf::kOne});
}

TEST_CASE("stc floor: any calibration round-trips through its file", "[devices][property]") {
  rc::prop("calibration_json then parse_calibration", [] {
    sf::Calibration c = sf::ideal_calibration();
    c.optics.lens_centre = {*rc::gen::inRange<std::int64_t>(0, 240 * sf::kOne),
                            *rc::gen::inRange<std::int64_t>(0, 240 * sf::kOne)};
    c.optics.mirror_height = *rc::gen::inRange<std::int64_t>(sf::kOne / 16, 100 * sf::kOne);
    for (auto& p : c.corners)
      p = {*rc::gen::inRange<std::int64_t>(0, 216 * sf::kOne),
           *rc::gen::inRange<std::int64_t>(0, 216 * sf::kOne)};
    RC_ASSERT(sf::parse_calibration("c.json", sf::calibration_json(c)) == c);
  });
}

TEST_CASE("stc floor: a bad calibration file is refused with where and why", "[devices]") {
  const std::string good = sf::calibration_json(sf::ideal_calibration());
  auto refused = [](const std::string& text, const std::string& what) {
    try {
      (void)sf::parse_calibration("c.json", text);
    } catch (const antkit::kernel::InputError& e) {
      INFO(e.what());
      CHECK(std::string(e.what()).find(what) != std::string::npos);
      return true;
    }
    return false;
  };
  CHECK(refused("{\"schema\":1,", "c.json:1:"));
  std::string s = good;
  s.replace(s.find("\"schema\":1"), 10, "\"schema\":2");
  CHECK(refused(s, "schema"));
  sf::Calibration far = sf::ideal_calibration();
  far.corners[0].x = 9999 * sf::kOne;
  CHECK(refused(sf::calibration_json(far), "corner 1"));
  s = good;
  s.replace(s.find("\"height\":3"), 10, "\"hight\":3");
  CHECK(refused(s, "mirror"));
}

TEST_CASE("stc floor: a floor point projects to the pixel whose ray sees it", "[devices]") {
  const sf::Optics o;
  const auto rays = sf::panorama_rays(o);
  std::int64_t worst = 0, visible = 0;
  for (std::int32_t j = 0; j < o.panorama_height; ++j)
    for (std::int32_t i = 0; i < o.panorama_width; ++i) {
      const auto& r = rays[static_cast<std::size_t>(j * o.panorama_width + i)];
      if (!r.visible) continue;
      ++visible;
      const sf::PointQ16 p = sf::project(o, {r.x, r.y});
      const std::int64_t dx = p.x - (2 * i + 1) * sf::kOne / 2,
                         dy = p.y - (2 * j + 1) * sf::kOne / 2;
      worst = std::max({worst, std::abs(dx), std::abs(dy)});
    }
  CHECK(visible > 40000);
  CHECK(worst < sf::kOne / 64); // the two directions of the model agree within 1/64 pixel
}

TEST_CASE("stc floor: quarter turns of an image compose and return exactly",
          "[devices][property]") {
  rc::prop("rotate_quarter", [] {
    const auto n = *rc::gen::inRange(1, 12);
    sf::Image img(n, n, 1);
    img.pixels = *rc::gen::container<std::vector<std::uint8_t>>(img.pixels.size(),
                                                                rc::gen::arbitrary<std::uint8_t>());
    const int a = *rc::gen::inRange(0, 4), b = *rc::gen::inRange(0, 4);
    RC_ASSERT(sf::rotate_quarter(sf::rotate_quarter(img, a), b).pixels ==
              sf::rotate_quarter(img, a + b).pixels);
    RC_ASSERT(sf::rotate_quarter(img, 4).pixels == img.pixels);
  });
}

TEST_CASE("stc floor: to_world turns every index of an observation by q", "[devices][property]") {
  rc::prop("to_world", [] {
    stc::EdgeObservation o;
    o.free_neighbours = *rc::gen::inRange<std::uint8_t>(0, 16);
    o.here = *rc::gen::inRange<std::uint16_t>(0, 4096);
    for (auto& m : o.neighbour) m = *rc::gen::inRange<std::uint16_t>(0, 4096);
    const int q = *rc::gen::inRange(0, 4);
    const auto w = sf::to_world(o, q);
    for (int c = 0; c < 4; ++c) {
      const int d = (c + q) & 3;
      RC_ASSERT(((w.free_neighbours >> d) & 1) == ((o.free_neighbours >> c) & 1));
      for (int g = 0; g < 3; ++g) {
        RC_ASSERT(((w.here >> (4 * g + d)) & 1) == ((o.here >> (4 * g + c)) & 1));
        for (int n = 0; n < 4; ++n)
          RC_ASSERT(((w.neighbour[static_cast<std::size_t>((n + q) & 3)] >> (4 * g + d)) & 1) ==
                    ((o.neighbour[static_cast<std::size_t>(n)] >> (4 * g + c)) & 1));
      }
    }
    RC_ASSERT(sf::to_world(sf::to_world(o, q), 4 - q) == o);
  });
}

TEST_CASE("stc floor: a noise-free rendered run on an open board is the simulated ant-edge tour",
          "[devices]") {
  const auto map = open_board(4, 3);
  for (const stc::SubCell start : {stc::SubCell{0, 0}, stc::SubCell{3, 2}, stc::SubCell{7, 5}}) {
    INFO("start " << start.x << "," << start.y);
    require_exact(run_floor(map, start, stc::Variant::AntEdge), map);
    require_exact(run_floor(map, start, stc::Variant::Ant), map);
  }
}

TEST_CASE("stc floor: noise-free rendered runs on random boards are the simulated tours",
          "[devices]") {
  // Ten keyed boards, 3 to 7 cells a side, 5 % to 25 % of the sub-cells blocked.
  int ran = 0;
  for (std::uint64_t key = 1; key <= 10; ++key) {
    const auto cells = static_cast<std::int32_t>(3 + key % 5);
    const auto percent = static_cast<std::uint32_t>(5 + 5 * (key % 5));
    const auto map = random_board(cells, percent, key);
    const auto start = stc::default_start(map, stc::Variant::AntEdge);
    INFO("board " << key << ": " << cells << " cells a side, " << percent << " % blocked");
    if (!start) continue; // no free cell at all: counted below
    require_exact(run_floor(map, *start, stc::Variant::AntEdge), map);
    ++ran;
  }
  CHECK(ran >= 8);
}

TEST_CASE("stc floor: on every shared map cut to 24 x 24 cells the rendered robot's tour is the "
          "simulated ant-edge tour",
          "[devices][slow]") {
  std::vector<std::filesystem::path> files;
  for (const auto& dir : {"movingai", "ros"})
    for (const auto& e :
         std::filesystem::directory_iterator(std::filesystem::path(antkit::test::maps_dir()) / dir))
      if (e.path().extension() == ".map" || e.path().extension() == ".yaml")
        files.push_back(e.path());
  std::sort(files.begin(), files.end());
  REQUIRE(files.size() == 17);
  std::vector<FloorRun> runs(files.size());
  std::vector<OccupancyGrid> maps(files.size());
  for (std::size_t i = 0; i < files.size(); ++i)
    maps[i] = cut(antkit::maps::load_map(files[i]).cells, 24);
  // Two threads: the runs are independent and each is deterministic.
  auto work = [&](std::size_t first) {
    for (std::size_t i = first; i < files.size(); i += 2)
      if (const auto start = stc::default_start(maps[i], stc::Variant::AntEdge))
        runs[i] = run_floor(maps[i], *start, stc::Variant::AntEdge);
  };
  std::thread other(work, 1);
  work(0);
  other.join();
  std::int64_t subcells = 0;
  for (std::size_t i = 0; i < files.size(); ++i) {
    INFO(files[i].filename().string());
    REQUIRE(stc::default_start(maps[i], stc::Variant::AntEdge));
    require_exact(runs[i], maps[i]);
    subcells += runs[i].truth_covered;
  }
  WARN("17 maps, " << subcells << " sub-cells covered through the rendered camera");
}

TEST_CASE("stc floor: camera noise and a dark offset the dark frame removes change nothing",
          "[devices]") {
  const auto map = random_board(5, 10, 7);
  const auto start = *stc::default_start(map, stc::Variant::AntEdge);
  sf::FloorOptions noisy;
  noisy.noise = 20;
  noisy.dark_offset = 60;
  noisy.seed = 3;
  require_exact(run_floor(map, start, stc::Variant::AntEdge, noisy), map);
}

TEST_CASE("stc floor: a clicked calibration a pixel off still reads the cells", "[devices]") {
  const auto map = open_board(4, 4);
  sf::Calibration c = sf::ideal_calibration();
  for (std::size_t i = 0; i < 12; ++i) {
    c.corners[i].x += (i % 3 == 0 ? 1 : -1) * sf::kOne;
    c.corners[i].y += (i % 2 == 0 ? 1 : -1) * sf::kOne / 2;
  }
  const sf::View view(c, sf::default_view(c));
  sf::FloorWorld world(map, {2, 3}, 1, {});
  sf::SimulatedRobot robot(world);
  sf::PilotOptions o;
  o.start = {2, 3};
  const auto r = sf::run_pilot(robot, view, o);
  CHECK(r.closed);
  CHECK(r.path == stc::run_stc(map, {2, 3}, stc::Variant::AntEdge).path);
}

// A 5 x 5-cell open board whose turn rate falls by 2 % a minute, from the corner.
struct Drifting {
  sf::FloorWorld world;
  sf::PilotResult run;
  explicit Drifting(std::int64_t tolerance) : world(open_board(5, 5), {0, 0}, 1, drifting()) {
    sf::SimulatedRobot robot(world);
    const sf::Calibration c = sf::ideal_calibration();
    const sf::View view(c, sf::default_view(c));
    sf::PilotOptions o;
    o.start = {0, 0};
    o.tolerance = tolerance;
    o.max_steps = 400;
    run = sf::run_pilot(robot, view, o);
  }
  static sf::FloorOptions drifting() {
    sf::FloorOptions f;
    f.drift_ppm_per_minute = 20000;
    return f;
  }
};

TEST_CASE("stc floor: the rotation calibration follows a weakening battery", "[devices]") {
  // The paper sets the first T by hand ("a time that lets the robot do the first rotation
  // accurate enough") and calibrates the turns after it: here T starts right.
  const Drifting d(sf::PilotOptions{}.tolerance);
  const double minutes = static_cast<double>(d.world.clock_ms()) / 60000.0;
  const double truth = 1500.0 / (1.0 - 0.02 * minutes); // the true quarter-turn time at the end
  INFO("after " << minutes << " minutes T = " << d.run.turn_ms << " ms, the truth " << truth);
  CHECK(minutes > 5);
  CHECK(std::abs(static_cast<double>(d.run.turn_ms) - truth) < 0.02 * truth);
  CHECK(d.run.turn_ms > 1500);
  CHECK(d.run.corrections > 0);
  CHECK(d.run.closed);
  CHECK(d.world.covered() == 100);
  CHECK(d.world.repeats() == 0);
}

TEST_CASE("stc floor: without its calibration the same robot leaves the grid", "[devices]") {
  const Drifting d(std::int64_t{1} << 40); // never corrects
  CHECK(d.run.corrections == 0);
  CHECK(d.run.turn_ms == 1500);
  CHECK((d.world.covered() < 100 || d.world.repeats() > 0));
}

TEST_CASE("stc floor: marks that fade too fast for the board make the robot repeat, "
          "and it still stops",
          "[devices]") {
  const auto map = open_board(6, 6);
  sf::FloorOptions f;
  f.fade_half_life_ms = 4000;
  sf::FloorWorld world(map, {0, 0}, 1, f);
  sf::SimulatedRobot robot(world);
  const sf::Calibration c = sf::ideal_calibration();
  const sf::View view(c, sf::default_view(c));
  sf::PilotOptions o;
  o.start = {0, 0};
  o.max_steps = 400;
  const auto r = sf::run_pilot(robot, view, o);
  CHECK(r.steps <= 400);
  CHECK(world.repeats() > 0);
}

TEST_CASE("stc floor: command-line decimals are read to the nearest 1/65536", "[devices]") {
  CHECK(sf::parse_q16("x", "120") == 120 * sf::kOne);
  CHECK(sf::parse_q16("x", "-3.25") == -3 * sf::kOne - sf::kOne / 4);
  CHECK(sf::parse_q16("x", "0.00001") == 1);  // 0.655 -> 1
  CHECK(sf::parse_q16("x", "0.000007") == 0); // 0.459 -> 0
  CHECK(sf::parse_point("x", "1.5,2") == sf::PointQ16{3 * sf::kOne / 2, 2 * sf::kOne});
  for (const char* bad : {"", "-", "1.", ".5", "1,2", "1e3", "+1", "1234567890123", "0.1234567891"})
    CHECK_THROWS_AS(sf::parse_q16("x", bad), antkit::kernel::InputError);
  CHECK_THROWS_AS(sf::parse_point("x", "1"), antkit::kernel::InputError);
}
