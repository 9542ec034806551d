#pragma once
// Hardware logs are JSON Lines (DESIGN.md, Files and formats): a header record, then one record per
// step. This is the schema version every writer puts in the header and every reader checks.
//
// Binary protocols (the e-puck2 in binary mode, `"robot":"epuck2"`, epuck2.hpp) need no other
// schema: an exchange's "sent" and "received" are JSON strings of one character per byte, and a
// byte outside printable ASCII is written \u00XX (its two hex digits, lower case), so every byte
// of a binary sequence and of its reply is kept exactly, in order (log.hpp, append_json_bytes). A
// step sequence [-'D' 300 -2][-'N'][-'Q'][0] is logged
// "\u00bc,\u0001\u00fe\u00ff\u00b2\u00af\u0000" (0x2C is ','); a resynchronisation is 36 "\u0000".
// Readers that want the bytes take each character's code point (0..255), as `antkit replay` and the
// Python module do.
//
// The versions (every writer writes the newest; readers replay all of them):
//   1  the first.
//   2  the same records; step 0 begins with the robot's identification at connect (the version
//      request, B or the e-puck's V; the e-puck2's resynchronisation and ASCII V; and the replies,
//      with any resends: record_loop.hpp, "First, at connect"), before the start's exchanges.
//      Replay runs it again on a schema-2 log, so a reply that does not identify the robot, or a
//      log without the request, diverges; a schema-1 log has none and replays as it was written.
//      The marker-floor robot, which is not identified, writes the same bytes under either.
#include <cstdint>

namespace antkit::devices {

inline constexpr std::uint32_t kLogSchemaVersion = 2;
inline constexpr std::uint32_t kOldestLogSchema = 1;

// True when a reader of this build can replay a log written with schema `version`: 1 to
// kLogSchemaVersion.
bool can_replay_schema(std::uint32_t version) noexcept;

} // namespace antkit::devices
