#pragma once
// Recording and replaying the marker-floor robot (issue 14), the device "stc-floor" (device.hpp:
// record() and replay() are the loops every robot shares): the pilot (pilot.hpp) drives a robot or
// its emulator over a serial link (link.hpp) and every step goes to a hardware log (log.hpp's JSON
// Lines, the same format as the other robots):
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
// Its map, its tour (the run's summary) and its emulator's truth: report.hpp.
#include <antkit/devices/link.hpp>
#include <antkit/devices/record_loop.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/devices/stc_floor/link.hpp>
#include <antkit/devices/stc_floor/pilot.hpp>
#include <antkit/devices/stc_floor/report.hpp>
#include <antkit/kernel/grid.hpp>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace antkit::devices::stc_floor {

// The replay of a log whose header names robot "stc-floor" (replay() in replay.hpp calls it).
ReplayResult replay_log(LogReader& reader, const std::string& path,
                        std::optional<std::int64_t> until);

} // namespace antkit::devices::stc_floor
