// Fuzz target: the map_server yaml subset. Any input either parses or throws InputError; what
// parses is checked against the promises of parse_ros_yaml (finite positive resolution, thresholds
// in [0, 1] and ordered) and then turned into a map with a fixed 3 x 1 image.
#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/map_io.hpp>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  antkit::maps::RosMapYaml yaml;
  try {
    yaml = antkit::maps::parse_ros_yaml(text, "fuzz.yaml");
  } catch (const antkit::kernel::InputError&) {
    return 0;
  }
  if (!(yaml.resolution > 0) || !std::isfinite(yaml.resolution) || yaml.image.empty() ||
      !(yaml.free_thresh >= 0 && yaml.free_thresh <= yaml.occupied_thresh &&
        yaml.occupied_thresh <= 1) ||
      !std::isfinite(yaml.origin_x) || !std::isfinite(yaml.origin_y) ||
      !std::isfinite(yaml.origin_yaw))
    std::abort();
  antkit::maps::PgmImage image;
  image.width = 3;
  image.height = 1;
  image.pixels = {0, 205, 254};
  try {
    const auto map = antkit::maps::ros_map(yaml, image, "fuzz.yaml");
    if (map.cells.size() != 3 || map.resolution != yaml.resolution) std::abort();
  } catch (const antkit::kernel::InputError&) {
    if (yaml.mode == antkit::maps::RosMode::Trinary) std::abort(); // only scale/raw are refused
  }
  return 0;
}
