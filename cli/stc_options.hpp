#pragma once
// What `antkit stc`, `antkit stc-noise` and `antkit dev stc-mcu-input` read from the same options
// (--map, --variant, --start, --noise, --seed), refused the same way (exit 2, located): one
// reading, so the plumbing refuses what `antkit stc` refuses.
#include <antkit/algorithms/options.hpp>
#include <antkit/commands/options.hpp>
#include <antkit/kernel/grid.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/stc/start.hpp>
#include <antkit/stc/world.hpp>
#include <cstdint>
#include <optional>
#include <string>

namespace antkit::cli {

// The start sub-cell: --start if given, else the map's own start or the variant's default (the
// refusal names --start, or the map file when the start was not given).
inline kernel::Cell read_stc_start(const maps::GridMap& map, stc::Variant variant,
                                   const std::string& start, const std::string& map_file) {
  return stc::choose_start(map.cells, variant,
                           start.empty() ? std::nullopt
                                         : std::optional(algorithms::parse_cell("--start", start)),
                           map.start, map_file);
}

struct StcRequest {
  stc::Variant variant;
  stc::NoiseModel noise;
  maps::GridMap map;
  kernel::Cell start;
};

// The variant, the marker noise (when given), the map and the start, in that order.
inline StcRequest read_stc_request(const std::string& map_file, const std::string& variant,
                                   const std::string& start, const std::string& noise,
                                   std::uint64_t seed) {
  StcRequest r{commands::stc_variant(variant, "--variant"), {}, {}, {}};
  if (!noise.empty()) r.noise = commands::stc_noise(r.variant, noise, seed, "--noise");
  r.map = maps::load_map(map_file);
  r.start = read_stc_start(r.map, r.variant, start, map_file);
  return r;
}

} // namespace antkit::cli
