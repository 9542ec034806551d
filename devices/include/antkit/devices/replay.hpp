#pragma once
// Replay of a hardware log (DESIGN.md, the controller contract): the controller named in the
// header, rebuilt with the header's parameters and seed, is fed every recorded observation and
// must answer every recorded command and state hash. The recorded bytes are decoded again with
// this build's codec, and the observation (and odometry) they give must be the recorded one, so
// a codec change that alters what the robot saw is caught too.
//
// Checks per step, in this order, the first difference ending the replay:
//   obs[i]   the observation decoded from the step's first valid proximity reply in `io` (the one
//            the controller saw; a wanderer's move reads the sensors again, once per period)
//   odo[i]   the odometry decoded from the step's last valid counter reply (robots with encoders)
//   cmd[i]   the controller's command for the recorded observation
//   state    the controller's state hash
// A record whose `io` holds no valid proximity reply diverges at field "io".
#include <antkit/devices/log.hpp>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace antkit::devices {

struct Divergence {
  std::int64_t step = 0;
  std::string field;
  std::string expected; // what the log says
  std::string actual;   // what this build computes
};

struct ReplayResult {
  std::int64_t steps = 0; // records replayed identically
  bool identical = true;
  std::optional<Divergence> first_divergence;
  bool truncated = false;      // the log's last line was cut (a crash or power cut while writing)
  std::optional<LogStop> stop; // the stop record, when the log has one
  std::uint64_t hash = 0;      // RunHash over the replayed steps (record()'s hash when identical)
  LogHeader header;
};

// The loop every robot's replay shares: reads the records before `until`; check() compares one
// record with this build (filling cmd with the command it computes) and returns the first
// difference, which ends the replay; the identical records are folded into the run hash.
ReplayResult replay_records(LogReader& reader, std::optional<std::int64_t> until,
                            const std::function<std::optional<Divergence>(
                                const LogRecord& r, std::vector<std::int64_t>& cmd)>& check);

// Recorded against computed values: false, with the first difference as `field[i]` in `out`
// (unless out already holds one), when they differ.
bool compare_fields(std::span<const std::int64_t> expected, std::span<const std::int64_t> actual,
                    std::int64_t step, const char* field, std::optional<Divergence>& out);

// `until`: replay only the steps before this one (all when absent). Throws kernel::InputError for a
// malformed log (its line and reason), an unknown robot or controller, or another schema version.
ReplayResult replay(const std::string& path, std::optional<std::int64_t> until = std::nullopt);

} // namespace antkit::devices
