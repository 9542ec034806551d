// Fuzz target: the MovingAI .map reader. Any input either parses or throws InputError; what parses
// must write back and re-read to the same grid, and its free components must cover its free cells.
#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/components.hpp>
#include <antkit/maps/map_io.hpp>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  antkit::maps::GridMap map;
  try {
    map = antkit::maps::parse_movingai(text, "fuzz.map");
  } catch (const antkit::kernel::InputError&) {
    return 0;
  }
  // The reader produces Free and Blocked only, so the round trip is exact.
  const auto again = antkit::maps::parse_movingai(antkit::maps::write_movingai(map), "again.map");
  if (!(again == map)) std::abort();
  const auto components = antkit::maps::free_components(map.cells);
  const auto counts = antkit::maps::count_cells(map.cells);
  if (std::accumulate(components.sizes.begin(), components.sizes.end(), std::size_t{0}) !=
      counts.free)
    std::abort();
  return 0;
}
