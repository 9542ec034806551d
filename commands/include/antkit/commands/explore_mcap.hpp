#pragma once
// `antkit explore --mcap FILE`: paper 001's two-robot line-of-sight exploration as MCAP for
// Foxglove (issue 42, "--mcap where a run has a timeline"). Tick k (the k-th observation, before
// its moves) is at k * kExploreTickNs from time 0, sequence = k; a completed run has steps + 1
// ticks (the last one's observation completes the map). Channels (schema encoding jsonschema,
// message encoding json; devices::mcap_schema's texts), frame "map", 1 m a cell, y up from the
// map's bottom row:
//   /map           foxglove.Grid          at time 0: "occupied" (0 free, 100 otherwise), UINT8
//   /robotA/pose   foxglove.PoseInFrame   A (the wall follower) each tick: its cell's centre,
//   /robotB/pose                          facing the way it last moved; B (the trouble shooter)
//   /robotA/trail  foxglove.PosesInFrame  every ceil(n / 100)-th tick and the last, at most 1000
//   /robotB/trail                         poses each (foxglove::trail_due, trail_poses)
//   /explored      foxglove.Grid          at the last tick: the controller's map, field "state",
//                                         UINT8, los::CellState's numbers (F 0, S 1, LOS 2,
//                                         S+LOS 3, NLOS 4, O 5): the JSON's "cells"
//   /log           foxglove.Log           what ran (INFO, time 0); each tick where the pair's line
//                                         of sight is lost or regained (INFO, at that tick); the
//                                         result at the last tick (INFO; ERROR when the run ran
//                                         out of ticks)
// The map's states are not written every tick (a whole grid a message); /explored is the end.
#include <antkit/commands/stc_mcap.hpp>
#include <antkit/los/explore.hpp>
#include <array>
#include <filesystem>
#include <string>

namespace antkit::commands {

inline constexpr std::uint64_t kExploreTickNs = 100000000; // 10 ticks a second

// Runs los::explore(truth, start[0], start[1], options), keeping each tick's cells and line of
// sight, and writes the run to `out`, whole or not at all; `what` is the /log's first line.
// InputError ("--mcap") for a run of more than kStcMcapMaxSubcells robot-ticks (a message each),
// found when the run ends and before anything is written. `written`, when given, receives the
// counts.
los::ExploreResult explore_mcap(const kernel::OccupancyGrid& truth,
                                const std::array<kernel::Cell, 2>& start,
                                const los::ExploreOptions& options, const std::string& what,
                                const std::filesystem::path& out, McapWritten* written = nullptr);

} // namespace antkit::commands
