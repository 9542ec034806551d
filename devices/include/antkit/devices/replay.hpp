#pragma once
// Replay of a hardware log (DESIGN.md, the controller contract): the controller named in the
// header, rebuilt with the header's parameters and seed, is fed every recorded observation and
// must answer every recorded command and state hash; and the body that record() runs (body.hpp)
// runs again over the log's exchanges instead of a port, so every byte the log holds is checked:
//   io[k].sent      every command is re-encoded by this build from what the step computed (the
//                   wheel speeds from the command, the counters' reads, the wanderer's moves) and
//                   must be the logged bytes, resends included;
//   io[k].received  every attempt's bytes are classified as the live link did (link.hpp: stale
//                   lines of another letter, then the reply or a fault; nothing after a reply);
//                   a reply the codec refuses makes the next exchange a resend of the same bytes;
//   obs[i]          the observation from the step's proximity reply;
//   cmd[i], state   the controller's command and state hash for the recorded observation;
//   odo[i]          the odometry: the counters' reply less the start's baseline, or for the
//                   Hemisson the travel reckoned again from the logged times of its exchanges
//                   (a Hemisson log without them is refused as bad input);
//   t_ns, io[k].t   never decreasing, each exchange's time within its step; the stop record's
//                   exchanges no earlier than the last step's end (so its t_ns is held from both
//                   sides), never decreasing;
//   stop            the stop record's reason in stop_reason()'s words, and its safe stop re-run
//                   over its exchanges: a stop acknowledged and read back at zero in the bytes may
//                   not be reported as failed, and one never acknowledged must say the robot may
//                   be moving.
// The first difference ends the replay; its message says what the log holds and what the replay
// derived. The rest of the log is then read unchecked, so that `stop` and `complete` still say
// whether the log is whole. A log without a stop record (a power cut on a line boundary, a
// header-only log) replays as far as it goes with complete == false: the run never said how it
// stopped.
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
  std::string expected; // what the log holds
  std::string actual;   // what the replay derived
  friend bool operator==(const Divergence&, const Divergence&) = default;
};

struct ReplayResult {
  std::int64_t steps = 0; // records replayed identically
  bool identical = true;
  std::optional<Divergence> first_divergence;
  bool truncated = false;      // the log's last line was cut (a crash or power cut while writing)
  std::optional<LogStop> stop; // the stop record, when the log has one
  bool complete = false;       // the log ends with its stop record (nothing cut, nothing missing)
  std::uint64_t hash = 0;      // RunHash over the replayed steps (record()'s hash when identical)
  LogHeader header;
  friend bool operator==(const ReplayResult&, const ReplayResult&) = default;
};

// The loop every robot's replay shares: reads the records before `until`, each one's t_ns no less
// than the one before; check() compares one record (and the log line it was read from, for its
// errors) with this build (filling cmd with the command it computes) and returns the first
// difference, which ends the replay; the identical records are folded into the run hash. When the
// whole log is asked for and the machine has a second hardware thread, the log is parsed there a
// batch of records ahead of the checks (the same result, errors at the same record).
// check_stop() then holds the stop record against the run, when every record replayed identically
// and the whole log was asked for.
namespace detail {
// Whether replay_records() reads ahead on a second thread: Auto (the default) when the whole log is
// asked for and the machine has two hardware threads or more; Never and Always (the whole log
// still) for the tests that hold both ways to the same results and for the benchmark.
// AlwaysAttempts: Always, and the reading thread reads every record's attempts too (the replay's
// link's reading of its exchanges); otherwise it reads them only while it is ahead of the checks,
// so that the work splits as the two threads' speeds do (the result does not depend on it).
enum class ReadAhead { Auto, Never, Always, AlwaysAttempts };
void set_read_ahead(ReadAhead mode) noexcept;
} // namespace detail

ReplayResult replay_records(
    LogReader& reader, std::optional<std::int64_t> until,
    const std::function<std::optional<Divergence>(const LogRecord& r, std::size_t line,
                                                  std::vector<std::int64_t>& cmd)>& check,
    const std::function<std::optional<Divergence>(const LogStop& stop)>& check_stop = {});

// Recorded against computed values: false, with the first difference as `field[i]` in `out`
// (unless out already holds one), when they differ.
bool compare_fields(std::span<const std::int64_t> expected, std::span<const std::int64_t> actual,
                    std::int64_t step, const char* field, std::optional<Divergence>& out);

// `until`: replay only the steps before this one (all when absent). Throws kernel::InputError for a
// malformed log (its line and reason), an unknown robot or controller, or another schema version.
ReplayResult replay(const std::string& path, std::optional<std::int64_t> until = std::nullopt);
// The same from a reader positioned after the header (a log in memory: the fuzz target); `path`
// names it in messages.
ReplayResult replay(LogReader& reader, const std::string& path,
                    std::optional<std::int64_t> until = std::nullopt);

} // namespace antkit::devices
