#include <antkit/devices/log_schema.hpp>

namespace antkit::devices {

bool can_replay_schema(std::uint32_t version) noexcept {
  return version >= kOldestLogSchema && version <= kLogSchemaVersion;
}

} // namespace antkit::devices
