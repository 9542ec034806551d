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
#include <antkit/devices/link.hpp>
#include <antkit/devices/record_loop.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/devices/stc_floor/link.hpp>
#include <antkit/devices/stc_floor/pilot.hpp>
#include <antkit/kernel/grid.hpp>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace antkit::devices::stc_floor {

// A grid map file as a run reads it (record's and emulate's --map): its cells and the start the
// file names, if any ('S' in an ASCII map); `file` names it in messages.
struct MapPlace {
  kernel::OccupancyGrid cells;
  std::optional<kernel::Cell> start;
  std::string file;
};
// Reads a map file (maps' map_io: MovingAI, ROS, ASCII); kernel::InputError naming it.
MapPlace read_map_place(const std::string& file);

// The robot's report of a run (Session::report, RecordSummary::device_report): its tour,
// believed, in map sub-cells.
struct Tour final : DeviceReport {
  kernel::Cell start{};
  std::vector<kernel::Cell> path; // the start first
  bool closed = false;            // the controller stopped: the tour is over
  bool returned_to_start = false; // closed, next to the start
  std::int64_t covered = 0, repeats = 0;
  std::int64_t turn_ms = 0; // the last T
  // With a map: the sub-cells the tour must enter, and the tour's hash as antkit stc's.
  std::optional<std::int64_t> reachable_subcells;
  std::optional<std::uint64_t> tour_hash;
  std::shared_ptr<const MapPlace> map; // the map read for the run, when one was given
};

// The tour in a run's summary: null unless the run was this robot's and its port opened.
[[nodiscard]] const Tour* tour_of(const RecordSummary& summary) noexcept;

// The replay of a log whose header names robot "stc-floor" (replay() in replay.hpp calls it).
ReplayResult replay_log(LogReader& reader, const std::string& path,
                        std::optional<std::int64_t> until);

} // namespace antkit::devices::stc_floor
