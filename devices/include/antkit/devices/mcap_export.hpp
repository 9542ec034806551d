#pragma once
// A hardware log (log.hpp) as an MCAP file that Foxglove opens (issue 42, "Out"): io/mcap.hpp's
// writer, channels with Foxglove's own schemas (schema encoding jsonschema, message encoding json;
// the schema texts are antkit's, naming the fields antkit fills) and antkit's own.
//
// Topics of `antkit export mcap` (prefix ""), every message at the recorded time of its step
// (t_ns as log and publish time; in the messages {sec, nsec}), sequence = step:
//   /pose          foxglove.PoseInFrame    the pose after each step: the serial robots' dead
//                                          reckoning of the logged odometry (odometry.hpp; metres
//                                          to the nanometre, nearest, as a plain decimal: the
//                                          reckoning's own step is 1/65536 of a diameter, near a
//                                          micrometre; frame "odom": the start at the origin,
//                                          heading +x);
//                                          stc-floor's believed sub-cell and heading (frame "map",
//                                          one unit a sub-cell)
//   /trail         foxglove.PosesInFrame   the trail so far, every 1 % of the steps and at the
//                                          last: every k-th pose from the first (k chosen so that
//                                          at most 1000 are kept over the run), then the step's
//   /arena         foxglove.SceneUpdate    the arena's walls at time 0 as one line list (frame
//                                          "arena", metres), when the header names an arena and
//                                          the caller can build it (McapOptions::arena_walls); the
//                                          emulator's start pose is not logged, so "arena" and
//                                          "odom" are not registered to each other
//   /log           foxglove.Log            the header (INFO, time 0) and the stop record (INFO at
//                                          the last step's time; WARNING when the run did not end
//                                          "done"); the replay's verdict (below)
//   /antkit/step   antkit.Step             {timestamp, step, obs, cmd, odo, state (16 hex digits)}
//   /antkit/io     antkit.Exchanges        {timestamp, step, io: [{sent, received (base64),
//                                          t_ns (null when not logged)}]}
// A replay (`antkit replay --mcap`) writes the recorded run under /recorded/... (all of the
// above but /arena and /log), the replayed run under /replayed/step (antkit.ReplayedStep: the
// steps the replay reproduced, then at the first divergence {step, field, recorded, replayed}),
// the arena, and on /log the first divergence as an ERROR at that step's time (or an INFO saying
// the replay is identical).
// Each chunk holds the messages of 1024 steps (the first and last chunks: the run's opening and
// closing messages); the chunks are formatted on McapOptions::threads threads and written in
// order. The bytes depend on the log alone (no clock, fixed library string "antkit", not the
// thread count).
#include <antkit/devices/replay.hpp>
#include <antkit/kernel/segment.hpp>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace antkit::devices {

struct McapOptions {
  // The walls of the header's arena spec in body diameters (geometry's builder: this library does
  // not link the CGAL arenas, so the command passes it). Unset: no /arena channel.
  std::function<std::vector<kernel::FxSegment>(const std::string& spec)> arena_walls;
  // Threads that format the messages (0: one per hardware thread). The bytes do not depend on it.
  unsigned threads = 0;
};

struct McapSummary {
  std::uint64_t bytes = 0;
  std::uint64_t messages = 0;
  std::vector<std::pair<std::string, std::uint64_t>> channels; // topic, messages (channel order)
};

// Throws kernel::InputError for a log that cannot be read (its line and column) and for an `out`
// that cannot be written; `out` is written whole or not at all (io::write_file_atomic).
McapSummary export_mcap(const std::string& log, const std::string& out,
                        const McapOptions& options = {});

// The recorded run of `log` and its replay `result` (replay(log)) side by side.
McapSummary export_replay_mcap(const std::string& log, const ReplayResult& result,
                               const std::string& out, const McapOptions& options = {});

// The bytes export_mcap (replay == nullptr) or export_replay_mcap writes, in memory, from a reader
// positioned after the header (`name` names the log in errors); `summary`, when given, receives the
// counts.
std::string mcap_of_log(LogReader& reader, const std::string& name, const McapOptions& options = {},
                        const ReplayResult* replay = nullptr, McapSummary* summary = nullptr);

std::string base64(std::string_view bytes);
// The JSON Schema text of a channel's schema: foxglove.PoseInFrame, PosesInFrame, SceneUpdate, Log
// and Grid (the fields antkit fills, named and typed as @foxglove/schemas' jsonschema), and
// antkit.Step, ReplayedStep and Exchanges (any other name: Exchanges').
std::string mcap_schema(std::string_view name);

} // namespace antkit::devices
