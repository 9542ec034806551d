#pragma once
// `antkit cover --mcap FILE` and `antkit check cover --mcap FILE`: a coverage run (paper 004) as
// MCAP for Foxglove, from its trace (testing::CoverTrace: every robot's cell and bearing after
// every tick). Tick k is at k * kCoverTickNs from time 0 (sequence = tick). Channels:
//   /map           foxglove.Grid          at time 0: "occupied" (0 free, 100 otherwise), UINT8,
//                                         frame "map", 1 m a cell, row 0 the map's bottom row
//   /robotI/pose   foxglove.PoseInFrame   robot I's cell centre each tick, facing its bearing
//   /robotI/trail  foxglove.PosesInFrame  every ceil(n / 100)-th tick and the last, at most 1000
//                                         poses each
//   /log           foxglove.Log           what ran (INFO, time 0); with a check, its verdict: an
//                                         ERROR with the first broken rule at its tick, or INFO at
//                                         the last tick with the coverage recomputed
#include <antkit/commands/stc_mcap.hpp>
#include <antkit/testing/run_audit.hpp>
#include <filesystem>
#include <optional>
#include <string>

namespace antkit::commands {

inline constexpr std::uint64_t kCoverTickNs = 100000000; // 10 ticks a second

// Refuses (InputError "--mcap") a run of more than 2^22 robot-ticks (a message each), once the
// trace is known; writes `out` whole or not at all. `what` is the /log's first line.
McapWritten write_cover_mcap(const kernel::OccupancyGrid& map, const testing::CoverTrace& trace,
                             const testing::CoverCheckReport* check, const std::string& what,
                             const std::filesystem::path& out);

// The trace file `trace_file` (antkit cover --trace) on `map`, checked (testing::check_cover with
// `sensor`, or the trace's own; `check` when the caller has it already, else computed here) and
// written by write_cover_mcap. InputError for a trace that cannot be read (its line).
McapWritten cover_trace_mcap(const kernel::OccupancyGrid& map, const std::string& trace_file,
                             std::optional<std::int64_t> sensor,
                             const testing::CoverCheckReport* check, const std::string& what,
                             const std::filesystem::path& out);

} // namespace antkit::commands
