// Fuzz target: the ASCII map reader. Any input either parses or throws InputError; what parses
// (start and unknown cells included) must write back and re-read to the same map.
#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/map_io.hpp>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  antkit::maps::GridMap map;
  try {
    map = antkit::maps::parse_ascii(text, "fuzz.txt");
  } catch (const antkit::kernel::InputError&) {
    return 0;
  }
  const auto again = antkit::maps::parse_ascii(antkit::maps::write_ascii(map), "again.txt");
  if (!(again == map)) std::abort();
  // And through MovingAI, which keeps the cells but for unknown (written blocked).
  const auto movingai = antkit::maps::parse_movingai(antkit::maps::write_movingai(map), "m.map");
  if (movingai.cells.size() != map.cells.size()) std::abort();
  return 0;
}
