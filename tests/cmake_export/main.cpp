// Uses each installed layer once and checks an answer, so that a broken package fails here.
#include <antkit/algorithms/controller.hpp>
#include <antkit/devices/controllers.hpp>
#include <antkit/devices/protocol.hpp>
#include <antkit/experiments/explore_tables.hpp>
#include <antkit/experiments/plot.hpp>
#include <antkit/geometry/arena.hpp>
#include <antkit/kernel/grid.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/random.hpp>
#include <antkit/kernel/raster.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/stc/world.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
// The test suite's scratch directory (standard C++ only, no antkit): the files below go in a
// directory of this process's own, removed when main returns, pass or fail.
#include "scratch_dir.hpp"

bool consumer_property(); // property.cpp: rapidcheck over antkit::testing
// c_api.c: ant-like STC on a 6 x 4 room through the C API alone.
extern "C" std::uint64_t consumer_c_tour_hash(std::int64_t* covered);

int main() {
  const antkit::test::ScratchDir scratch("consumer");
  antkit::kernel::Grid<std::uint8_t> grid(4, 3, 0);
  grid[{1, 2}] = 7;
  antkit::kernel::Stream stream(1, 2, 3, 4, 5);
  const auto draw = stream.below(10);
  antkit::kernel::TraceHash hash;
  hash.add_u32(draw).add_u8(grid[{1, 2}]);
  // The supercover of a 3-cell horizontal segment is those 3 cells.
  const auto cells = antkit::kernel::supercover({0, 0}, {2, 0});
  // The geometry layer (CGAL behind it): the standard arena has the area of the circle of diameter
  // 100.
  const auto arena = antkit::geometry::make_circle(100.0);
  // The devices layer: a Khepera's proximity reply decoded and fed to the Buffon controller.
  const antkit::devices::Codec khepera(antkit::devices::RobotKind::Khepera);
  const auto readings = khepera.decode_proximity("n,0,0,0,1023,0,0,0,0\r\n");
  auto controller =
      antkit::devices::make_controller(antkit::devices::make_spec("buffon", 1, {}, "consumer"));
  std::vector<std::int64_t> obs, cmd;
  if (readings) {
    controller->observe(khepera.robot(), *readings.value, obs);
    controller->step(khepera.robot(), obs, cmd);
  }
  const bool devices_ok = readings && obs.size() == 6 && obs[3] == 65536 && cmd.size() == 4;
  const bool ok = devices_ok && grid.size() == 12 && draw < 10 && cells.size() == 3 &&
                  std::abs(arena.area() - antkit::geometry::standard_area()) < 1e-2 &&
                  antkit::algorithms::version_number() >= 100;
  std::printf(
      "consumer: grid %zu cells, draw %u, supercover %zu cells, arena area %.4f, hash %s: %s\n",
      grid.size(), draw, cells.size(), arena.area(),
      antkit::kernel::hash_hex(hash.finish()).c_str(), ok ? "ok" : "FAILED");
  // The experiments layer: paper 001's tables (fast wall-follow in the empty room takes the
  // paper's 47 steps, give or take) and a figure drawn with Cairo to SVG and PNG.
  const auto tables = antkit::experiments::run_explore_tables(1, antkit::algorithms::Runner{});
  const double empty_room = antkit::experiments::mean_of(tables.runs[0][0].steps);
  antkit::experiments::Figure figure;
  figure.title = "consumer";
  figure.panels.push_back(
      {"steps",
       "",
       {{"fast wall-follow",
         "#1e5bd8",
         false,
         false,
         {{0, empty_room, std::nullopt, std::nullopt}, {1, 50, std::nullopt, std::nullopt}}}},
       {}});
  const auto& dir = scratch.path();
  antkit::experiments::save_figure(figure, dir / "antkit-consumer.svg",
                                   dir / "antkit-consumer.png");
  antkit::experiments::release_drawing_caches();
  const bool experiments_ok = empty_room > 30 && empty_room < 70 && tables.hash != 0 &&
                              std::filesystem::file_size(dir / "antkit-consumer.png") > 1000;
  std::printf("consumer: antkit::experiments, empty room %.1f steps: %s\n", empty_room,
              experiments_ok ? "ok" : "FAILED");
  // The maps layer (no CGAL) and the file writer under it (antkit::io): an ASCII map saved whole
  // and read back.
  const auto map = antkit::maps::parse_ascii("S.#\n...\n", "consumer.txt");
  antkit::maps::save_map(dir / "antkit-consumer.txt", map);
  const bool maps_ok =
      antkit::maps::load_map(dir / "antkit-consumer.txt") == map && map.cells.size() == 6;
  std::printf("consumer: antkit::maps, a map saved and read back: %s\n", maps_ok ? "ok" : "FAILED");
  const bool property_ok = consumer_property() && experiments_ok;
  std::printf("consumer: antkit::testing property: %s\n", property_ok ? "ok" : "FAILED");
  // The C API (antkit::c) from C: the same tour, hash and coverage as the C++ run.
  std::int64_t c_covered = 0;
  const std::uint64_t c_hash = consumer_c_tour_hash(&c_covered);
  const auto cpp =
      antkit::stc::run_stc(antkit::kernel::OccupancyGrid(6, 4, antkit::kernel::Occupancy::Free),
                           {0, 0}, antkit::stc::Variant::Ant);
  const bool c_ok = c_hash == cpp.hash && c_covered == 24 && cpp.covered == 24;
  std::printf("consumer: antkit::c from C, tour hash %s: %s\n",
              antkit::kernel::hash_hex(c_hash).c_str(), c_ok ? "ok" : "FAILED");
  return ok && property_ok && c_ok && maps_ok ? 0 : 1;
}
