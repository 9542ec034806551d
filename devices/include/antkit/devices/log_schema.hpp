#pragma once
// Hardware logs are JSON Lines (DESIGN.md, Files and formats): a header record, then one record per
// step. This is the schema version every writer puts in the header and every reader checks.
#include <cstdint>

namespace antkit::devices {

inline constexpr std::uint32_t kLogSchemaVersion = 1;

// True when a reader of this build can replay a log written with schema `version`.
bool can_replay_schema(std::uint32_t version) noexcept;

} // namespace antkit::devices
