#pragma once
// The JSON of a result, as `antkit ... --format json` prints it and the Python package returns it
// (python/: each result object is this JSON as a dict). One function per result; the key lists and
// meanings are documented at the command (cli/check.cpp, cli/stc.cpp, cli/replay.cpp,
// cli/buffon.cpp, cli/buffon_from_logs.cpp). Numbers stay integers where the result counts, and
// absent values are null, never left out. (The choices a command makes from its options, which
// the two shells share too, are options.hpp.)
#include <antkit/buffon/area_measurement.hpp>
#include <antkit/devices/odometry.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/stc/world.hpp>
#include <antkit/testing/run_audit.hpp>
#include <antkit/testing/stc_audit.hpp>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace antkit::commands {

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

// `antkit buffon-from-logs`'s JSON (the result of options.hpp's buffon_from_logs); `width` the band
// width in body diameters.
[[nodiscard]] nlohmann::json buffon_from_logs_json(const devices::BuffonFromLogs& result,
                                                   double width);

// One visit's {"steps", "length", "truncated", "hash"} (buffon-from-logs, rs-from-log).
[[nodiscard]] nlohmann::json trail_json(const devices::LoggedTrail& trail);

} // namespace antkit::commands
