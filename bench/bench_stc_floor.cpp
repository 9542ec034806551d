// The marker-floor camera pipeline (issue 14), frames per second on one core: dark frame, channel
// split and finding the three newest marks (the paper's angle detection) on a 320 x 240 RGB frame,
// the resolution of the paper's wireless web camera as we read its snapshots (the paper does not
// state it). items = frames.
#include <antkit/devices/stc_floor/camera.hpp>
#include <antkit/devices/stc_floor/floor.hpp>
#include <antkit/devices/stc_floor/pilot.hpp>
#include <antkit/devices/stc_floor/view.hpp>
#include <benchmark/benchmark.h>
#include <cstdint>

namespace {

namespace sf = antkit::devices::stc_floor;

void BM_StcFloorPipeline(benchmark::State& state) {
  const std::int32_t w = 320, h = 240;
  sf::Image frame(w, h, 3), dark(w, h, 3);
  std::uint32_t x = 12345;
  for (std::size_t i = 0; i < frame.pixels.size(); ++i) {
    x = x * 1664525u + 1013904223u; // a fixed dim noise floor
    frame.pixels[i] = static_cast<std::uint8_t>((x >> 24) & 31);
    dark.pixels[i] = static_cast<std::uint8_t>((x >> 16) & 7);
  }
  for (int k = 0; k < 3; ++k) // three green dots of 4 x 4 pixels
    for (int dy = 0; dy < 4; ++dy)
      for (int dx = 0; dx < 4; ++dx) frame.at(100 + 30 * k + dx, 120 + 10 * k + dy, 1) = 220;
  for (auto _ : state) {
    const auto c = sf::split_channels(sf::subtract_dark(frame, dark), 128);
    const auto marks = sf::find_marks(c.marks, 4, 16 * 120, 3);
    benchmark::DoNotOptimize(sf::line_heading(marks, 4));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_StcFloorPipeline);

// The whole reading of one rendered frame as the pilot does it (issue 14): dark frame, split,
// unwarp of both images, the canonical turn and the 5 cells' 60 edges and 4 lights, at the
// emulator's 240 x 240 panorama (216 x 216 unwarped, 24 pixels to a sub-cell). items = frames.
void BM_StcFloorSee(benchmark::State& state) {
  antkit::kernel::OccupancyGrid map(12, 12, antkit::kernel::Occupancy::Free);
  map[{6, 6}] = map[{7, 6}] = map[{6, 7}] = map[{7, 7}] = antkit::kernel::Occupancy::Blocked;
  sf::FloorWorld world(map, {4, 5}, 1, {});
  for (int k = 0; k < 3; ++k) world.forward(2000); // a few marks
  const auto dark = world.capture(true);
  const auto frame = world.capture(false);
  const sf::Calibration c = sf::ideal_calibration();
  const sf::View view(c, sf::default_view(c));
  for (auto _ : state) benchmark::DoNotOptimize(view.see(frame, dark, 1, 1));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_StcFloorSee);

// The emulator's rendering of one frame (240 x 240 RGB, the mirror model, marks, lights, the
// dark pattern), without and with sensor noise. items = frames.
void BM_StcFloorRender(benchmark::State& state) {
  antkit::kernel::OccupancyGrid map(12, 12, antkit::kernel::Occupancy::Free);
  sf::FloorOptions f;
  f.noise = static_cast<std::int32_t>(state.range(0));
  sf::FloorWorld world(map, {4, 5}, 1, f);
  for (int k = 0; k < 3; ++k) world.forward(2000);
  for (auto _ : state) benchmark::DoNotOptimize(world.capture(false));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_StcFloorRender)->Arg(0)->Arg(20);

// One step of the rendered robot in process: render, read, decide, turn (with its frames) and
// drive; a whole noise-free tour of a 6 x 6-cell board per iteration. items = steps.
void BM_StcFloorTour(benchmark::State& state) {
  antkit::kernel::OccupancyGrid map(12, 12, antkit::kernel::Occupancy::Free);
  const sf::Calibration c = sf::ideal_calibration();
  const sf::View view(c, sf::default_view(c));
  std::int64_t steps = 0;
  for (auto _ : state) {
    sf::FloorWorld world(map, {0, 0}, 1, {});
    sf::SimulatedRobot robot(world);
    sf::PilotOptions o;
    steps += sf::run_pilot(robot, view, o).steps;
  }
  state.SetItemsProcessed(steps);
}
BENCHMARK(BM_StcFloorTour)->Unit(benchmark::kMillisecond);

} // namespace
