#pragma once
// `antkit check stc --path TOUR --mcap FILE`: a checked tour as MCAP for Foxglove (issue 42,
// "--mcap where a run has a timeline"), beside the check's report. The tour has no clock: position
// k is at k * kStcStepNs from time 0 (sequence = k), as `antkit stc --mcap` writes a tour.
// Channels (schema encoding jsonschema, message encoding json; devices::mcap_schema's texts):
//   /map    foxglove.Grid          at time 0: the sub-cells the check holds the tour against,
//                                  "occupied" (0 free, 100 otherwise), UINT8, frame "map" (the
//                                  map's resolution and origin; with --cells each cell is 2 x 2
//                                  sub-cells of half its side)
//   /pose   foxglove.PoseInFrame   every position: the sub-cell's centre, facing the way it last
//                                  moved (positions off the map too, where they would be)
//   /trail  foxglove.PosesInFrame  every ceil(n / 100)-th position and the last, each at most 1000
//                                  poses (foxglove::trail_due, trail_poses)
//   /log    foxglove.Log           what was checked (INFO, time 0); the verdict: the first broken
//                                  rule as an ERROR at its position's time (a rule about the whole
//                                  tour, such as a missed sub-cell, at the last position's), or
//                                  INFO at the last position when every rule holds
// A bag's tour goes out with `antkit bag export --check stc` instead.
#include <antkit/commands/stc_mcap.hpp>
#include <antkit/testing/stc_audit.hpp>
#include <filesystem>

namespace antkit::commands {

struct CheckedStcMcap {
  testing::StcCheckReport report; // testing::check_stc_files' report
  McapWritten written;
};

// Reads the request's map and tour once, checks them as testing::check_stc_files does and writes
// the tour and the verdict to `out`, whole or not at all. InputError ("--mcap") for a tour of more
// than kStcMcapMaxSubcells positions (a message each), before anything is written; the check's own
// refusals (a malformed map or tour, a start off the map) likewise. A tour that breaks a rule is
// written (the verdict is in the file and the report).
CheckedStcMcap check_stc_mcap(const testing::StcCheckRequest& request,
                              const std::filesystem::path& out);

} // namespace antkit::commands
