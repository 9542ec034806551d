// The marker-floor camera pipeline (issue 14), frames per second on one core: dark frame, channel
// split and finding the three newest marks (the paper's angle detection) on a 320 x 240 RGB frame,
// the resolution of the paper's wireless web camera as we read its snapshots (the paper does not
// state it). items = frames.
#include <antkit/devices/stc_floor/camera.hpp>
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

} // namespace
