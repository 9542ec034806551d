#pragma once
// The marker-floor robot's own results (device_report.hpp), the device "stc-floor": the tour of a
// recorded run (`antkit record`'s "tour" block) and the truth of an emulated floor (`antkit
// emulate`'s "floor" block), and the map file both are read against.
#include <antkit/devices/device_report.hpp>
#include <antkit/devices/record_loop.hpp>
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
// believed, in map sub-cells. Its block, "tour", has the keys of `antkit stc` for the same
// meaning: start, path (the start first), reachable_subcells (with a map only), covered, repeats,
// returned_to_start, hash (the tour's, as antkit stc's; null without a map); and turn_ms. The run's
// verdict ("stc-tour": the oracle of `antkit check stc` with the map) adds tour_ok and
// first_violation (experiments/recorded_run.hpp).
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

  static constexpr std::string_view kVerdict = "stc-tour";
  [[nodiscard]] std::string_view key() const noexcept override { return "tour"; }
  [[nodiscard]] ReportFields fields() const override;
  [[nodiscard]] std::string_view verdict() const noexcept override { return kVerdict; }
};

// The tour in a run's summary: null unless the run was this robot's and its port opened.
[[nodiscard]] const Tour* tour_of(const RecordSummary& summary) noexcept;

// The emulator's report (EmulateReport::device_report): the truth of its last session, block
// "floor": map (the file), start, frames rendered, positions the body took (the start first), the
// sub-cells it entered (covered), repeats, reachable_subcells (from the start, as ant-edge), the
// largest distance from a sub-cell's centre (max_offset_subcells) and heading error
// (max_heading_error_degrees), and the floor's clock (clock_s).
struct FloorTruth final : DeviceReport {
  std::string map;
  kernel::Cell start{};
  std::int64_t frames = 0, positions = 0;
  std::int64_t covered = 0, repeats = 0, reachable_subcells = 0;
  double max_offset_subcells = 0, max_heading_error_degrees = 0, clock_s = 0;

  [[nodiscard]] std::string_view key() const noexcept override { return "floor"; }
  [[nodiscard]] ReportFields fields() const override;
};

} // namespace antkit::devices::stc_floor
