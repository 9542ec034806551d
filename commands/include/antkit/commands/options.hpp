#pragma once
// The choices a command makes from its options, shared by the two shells (the `antkit` command,
// cli/, and the Python package, python/) so that both read an option the same way: the STC variant
// by name, its marker noise, its start; the Buffon measurement from two logs; an arena named by a
// spec or a WKT file. Each names the option it reads in an InputError(where).
#include <antkit/devices/mcap_export.hpp>
#include <antkit/devices/odometry.hpp>
#include <antkit/kernel/grid.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/stc/floor.hpp>
#include <antkit/stc/world.hpp>
#include <cstdint>
#include <optional>
#include <string>

namespace antkit::commands {

// `antkit stc`'s variant by name, or an InputError(where) listing the variants.
[[nodiscard]] stc::Variant stc_variant(const std::string& name, const std::string& where);
// Marker noise for `variant`: `probability` as the command takes it (a decimal in [0, 1], at most
// six decimals: algorithms::parse_probability_ppm), drawn from `seed`'s stream; an
// InputError(where) for a variant that reads no marks (ant and ant-edge do).
[[nodiscard]] stc::NoiseModel stc_noise(stc::Variant variant, const std::string& probability,
                                        std::uint64_t seed, const std::string& where);

// The STC start: `given` if any (sub-cells), else the map's own start ('S' in an ASCII map), else
// stc::default_start (the largest region's first place). Throws InputError(map_name) when the map
// has no place to start.
[[nodiscard]] kernel::Cell choose_stc_start(const maps::GridMap& map, stc::Variant variant,
                                            std::optional<kernel::Cell> given,
                                            const std::string& map_name);

// `antkit buffon-from-logs`: the measurement from two logs (devices::buffon_from_logs) with the
// pheromone band `width` in body diameters, in [0.01, 10] (else an InputError(width_where)), and
// the arena's true area from its spec or WKT file (arena_spec_area) when `arena` or the headers
// name one; specs are compared as arenas (same_arena).
[[nodiscard]] devices::BuffonFromLogs buffon_from_logs(const std::string& visit1,
                                                       const std::string& visit2, double width,
                                                       const std::string& arena,
                                                       const std::string& width_where);

// An arena argument names a WKT file when it ends in ".wkt" (any case), else it is a named spec:
// the rule is the name's, not the file system's, so a typo in a spec never silently reads a stray
// file. arena_spec_area: its exact area (the WKT polygon's or the built spec's); `where` names the
// option in an InputError.
[[nodiscard]] double arena_spec_area(const std::string& spec, const std::string& where);
[[nodiscard]] bool is_wkt_path(const std::string& name);
// Whether two arena arguments name one arena: two specs of one family with the same parameters as
// numbers (`circle:d=20` and `circle:d=20.0`), or one WKT file (the same file, or the same text).
// Anything that does not parse is compared as text.
[[nodiscard]] bool same_arena(const std::string& a, const std::string& b);

// The MCAP export's options (`export mcap`, `replay --mcap`): a log header's arena, a spec or a WKT
// file, drawn from geometry's arena (its walls in body diameters).
[[nodiscard]] devices::McapOptions mcap_options();

} // namespace antkit::commands
