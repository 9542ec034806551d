// Fuzz target: the PGM reader (P5 and P2). Any input either parses or throws InputError; what
// parses has width x height samples, none above maxval, and classifies into a map of that size.
#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/components.hpp>
#include <antkit/maps/map_io.hpp>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  antkit::maps::PgmImage image;
  try {
    image = antkit::maps::parse_pgm(bytes, "fuzz.pgm");
  } catch (const antkit::kernel::InputError&) {
    return 0;
  }
  if (image.pixels.size() !=
      static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
    std::abort();
  for (const auto v : image.pixels)
    if (v > image.maxval) std::abort();
  antkit::maps::RosMapYaml yaml;
  yaml.image = "fuzz.pgm";
  yaml.resolution = 0.05;
  yaml.occupied_thresh = 0.65;
  yaml.free_thresh = 0.196;
  const auto map = antkit::maps::ros_map(yaml, image, "fuzz.yaml");
  const auto counts = antkit::maps::count_cells(map.cells);
  if (counts.free + counts.blocked + counts.unknown != image.pixels.size()) std::abort();
  (void)antkit::maps::free_components(map.cells);
  return 0;
}
