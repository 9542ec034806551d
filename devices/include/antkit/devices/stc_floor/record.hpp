#pragma once
// Recording and replaying the marker-floor robot (issue 14): the pilot (pilot.hpp) drives a robot
// or its emulator over a serial link (link.hpp) and every step goes to a hardware log
// (log.hpp's JSON Lines, the same format as the other robots):
//   header   robot "stc-floor", the port, controller "ant" or "ant-edge", params start_x, start_y
//            (map sub-cells), heading (0..3), quarter_turn_ms (the first T), led_ms; seed 0
//   record   io: the step's exchanges (a frame's reply as its header line, whose CRC-32 is the
//            frame's digest); obs: the controller's observation (pilot.hpp); cmd: move, mark;
//            odo: the believed x, y (map sub-cells) and heading after the step, and T (ms);
//            state: the controller's state hash
// replay_stc_floor() rebuilds the controller from the header and feeds it every recorded
// observation: every command and state hash must come back, every frame header must still decode
// (this build's codec), and the believed position and heading must follow from the commands and
// the robot's F replies. T depends on the frames, which the log does not hold, so it is not
// re-derived.
#include <antkit/devices/adapter.hpp>
#include <antkit/devices/link.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/devices/stc_floor/link.hpp>
#include <antkit/devices/stc_floor/pilot.hpp>
#include <functional>
#include <optional>
#include <string>

namespace antkit::devices::stc_floor {

struct RecordOptions {
  std::string port;
  LineSettings line{115200, 8, 1, Parity::None}; // a choice: the XBee's link at its usual fast rate
  LinkOptions link;
  Calibration calibration = ideal_calibration();
  std::optional<ViewParams> view; // default_view(calibration) when absent
  PilotOptions pilot;
  std::string out;
  bool force = false; // replace `out` if it exists
};

struct RecordSummary {
  std::int64_t steps = 0;
  std::vector<stc::SubCell> path; // believed, the start first
  bool closed = false, refused = false;
  std::int64_t covered = 0, repeats = 0;
  std::int64_t turn_ms = 0;
  StopKind kind = StopKind::Error; // Done: the pilot ended (closed, refused or out of steps)
  std::string stop;      // "done" (the tour closed), "steps" (max_steps ran out), "refused", ...
  std::string safe_stop; // "" when acknowledged
  LinkStats link;
  std::uint64_t hash = 0; // RunHash over the steps (replay recomputes it)
};

using RecordProgress = std::function<void(std::int64_t step)>;

// Opens the port first (a bad --port leaves no log), then logs as it runs; SIGINT / SIGTERM stop
// it between steps. Throws kernel::InputError for bad options.
RecordSummary record(const RecordOptions& options, const RecordProgress& progress = {});

// The replay of a log whose header names robot "stc-floor" (replay() in replay.hpp calls it).
ReplayResult replay_log(LogReader& reader, const std::string& path,
                        std::optional<std::int64_t> until);

} // namespace antkit::devices::stc_floor
