#pragma once
// `antkit stc --mcap FILE`: an STC tour as MCAP for Foxglove (issue 42, "--mcap where a run has a
// timeline"). The tour has no clock: step k is at k * kStcStepNs from time 0 (sequence = step).
// Channels (schema encoding jsonschema, message encoding json; devices::mcap_schema's texts):
//   /map    foxglove.Grid          at time 0: "occupied" (0 free, 100 otherwise), UINT8, frame
//                                  "map" (the map's resolution and origin; 1 m a sub-cell and the
//                                  origin at 0 for maps that do not say)
//   /tree   foxglove.SceneUpdate   at time 0: the spanning tree the tour goes round, a line list
//                                  from cell centre to cell centre wherever the tour changes cell
//   /pose   foxglove.PoseInFrame   every step: the sub-cell's centre, facing the way it last moved
//   /trail  foxglove.PosesInFrame  every ceil(n / 100)-th step and the last (at most 101
//                                  messages), each at most 1000 poses
//   /log    foxglove.Log           the run (INFO, time 0); an exact variant's first repeat (ERROR
//   at
//                                  its step); the invariants at the end (INFO, or ERROR broken)
#include <antkit/devices/mcap_export.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/stc/world.hpp>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace antkit::commands {

inline constexpr std::uint64_t kStcStepNs = 100000000; // 10 steps a second
inline constexpr std::int64_t kStcMcapMaxSubcells = std::int64_t{1} << 22;

struct McapWritten {
  std::uint64_t bytes = 0, messages = 0;
  std::vector<std::pair<std::string, std::uint64_t>> channels; // topic, messages
};

// InputError("--mcap") for a map of more than kStcMcapMaxSubcells sub-cells (a message a step):
// checked before the run.
void check_stc_mcap_size(const kernel::OccupancyGrid& map);
// Writes `r` (run with its path kept) on `map` to `out`, whole or not at all (InputError naming
// `out` when it cannot be written).
McapWritten write_stc_mcap(const maps::GridMap& map, const stc::RunResult& r,
                           const std::string& map_name, const std::filesystem::path& out);

} // namespace antkit::commands
