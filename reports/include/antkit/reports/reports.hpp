#pragma once
// The JSON of a result, as `antkit ... --format json` prints it and the Python package returns it
// (python/: each result object is this JSON as a dict). One function per result; the key lists and
// meanings are documented at the command (cli/check.cpp, cli/stc.cpp, cli/replay.cpp,
// cli/buffon.cpp, cli/buffon_from_logs.cpp). Numbers stay integers where the result counts, and
// absent values are null, never left out.
#include <antkit/buffon/area_measurement.hpp>
#include <antkit/devices/odometry.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/stc/world.hpp>
#include <antkit/testing/run_audit.hpp>
#include <antkit/testing/stc_audit.hpp>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace antkit::reports {

// A sub-cell or cell as [x, y].
[[nodiscard]] nlohmann::json cell_json(kernel::Cell c);

// An STC tour's first broken rule: null when the tour passes, else {"rule", "step" (null for a
// whole-tour rule), "subcell" [x, y], "detail"} (`check stc`, `record --device stc-floor`).
[[nodiscard]] nlohmann::json first_violation_json(const testing::StcAudit& audit);

// `check stc`, `check explore`, `check cover`; `map` names the map ("map" key; null when empty).
[[nodiscard]] nlohmann::json check_stc_json(const testing::StcCheckReport& report,
                                            const std::string& map);
[[nodiscard]] nlohmann::json check_explore_json(const testing::ExploreCheckReport& report,
                                                const std::string& map);
[[nodiscard]] nlohmann::json check_cover_json(const testing::CoverCheckReport& report,
                                              const std::string& map);

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

// `antkit stc`'s fields other than "path" (which the command streams): variant, width, height,
// start, reachable_subcells, covered, repeats, returned_to_start, hash, and with marker noise
// noise_ppm and seed.
struct StcNoiseFields {
  std::uint32_t ppm = 0;
  std::uint64_t seed = 0;
};
[[nodiscard]] nlohmann::json stc_json(const stc::RunResult& result, std::int32_t width,
                                      std::int32_t height, kernel::Cell start,
                                      std::optional<StcNoiseFields> noise = std::nullopt);

// `antkit buffon`: a measurement's JSON, "arena" ({"spec", "area"}: the arena as given and its
// exact area), "trials", "summary" and "hash", with the keys the measurement's params ask for
// (precision, rule). The command adds the summary's "budget_note" itself (it quotes the precision
// as typed).
[[nodiscard]] nlohmann::json buffon_json(const buffon::AreaMeasurement& measurement,
                                         const buffon::AreaMeasurementParams& params,
                                         const std::string& spec, double area);

// `antkit replay`.
[[nodiscard]] nlohmann::json replay_json(const devices::ReplayResult& result);

// `antkit buffon-from-logs`: the measurement from two logs (devices::buffon_from_logs) with the
// pheromone band `width` in body diameters, in [0.01, 10] (else an InputError(width_where)), and
// the arena's true area from its spec or WKT file (arena_spec_area) when `arena` or the headers
// name one.
[[nodiscard]] devices::BuffonFromLogs buffon_from_logs(const std::string& visit1,
                                                       const std::string& visit2, double width,
                                                       const std::string& arena,
                                                       const std::string& width_where);
// Its JSON; `width` the band width in body diameters.
[[nodiscard]] nlohmann::json buffon_from_logs_json(const devices::BuffonFromLogs& result,
                                                   double width);
// An arena argument names a WKT file when it ends in ".wkt" (any case), else it is a named spec:
// the rule is the name's, not the file system's, so a typo in a spec never silently reads a stray
// file. arena_spec_area: its exact area (the WKT polygon's or the built spec's); `where` names the
// option in an InputError.
[[nodiscard]] double arena_spec_area(const std::string& spec, const std::string& where);
[[nodiscard]] bool is_wkt_path(const std::string& name);

// One visit's {"steps", "length", "truncated", "hash"} (buffon-from-logs, rs-from-log).
[[nodiscard]] nlohmann::json trail_json(const devices::LoggedTrail& trail);

} // namespace antkit::reports
