#pragma once
// The marker-floor robot's body and floor, simulated, and the camera frames it would take
// (paper 002, "The Robot"; issue 14's emulator): a phosphorescent floor in the dark on which the
// robot's back UV LEDs leave glowing marks that fade, red lights in the cells that are obstacles,
// and a robot that drives one sub-cell at a time and turns on the spot for a commanded time at a
// rate that may be off and may drift like a weakening battery. capture() renders what the upward
// camera sees in the mirror (optics.hpp's model, the true optics), with a fixed dark-current
// pattern and per-frame sensor noise. Everything is integer arithmetic and keyed streams
// (kernel/random.hpp), so a run's frames are bit-identical on every machine.
//
// The floor, in sub-cells (map coordinates: x right, y down; sub-cell (x, y) covers
// [x, x + 1) x [y, y + 1)). Choices, each named because the paper does not give numbers:
//   * A mark is a disc of radius 0.12 sub-cell where the LEDs shone: half a sub-cell behind the
//     robot's centre, so on the edge behind it when the robot is on the grid. Green, at
//     `mark_level` when fresh, halving every `fade_half_life_ms` (linear between halvings; 0: no
//     fading). The paper's camera lost marks "after about a minute": a half-life of 20 s puts the
//     default detection threshold (a fifth of a fresh mark) at about 46 s.
//   * Each edge of the grid holds the newest mark laid nearest to it (a relit edge glows afresh).
//   * An obstacle is a red light of radius 0.25 sub-cell at the centre of every cell (2 x 2
//     sub-cells) that is not free, and of every cell beyond the map's cell area (the board's
//     walls), as the paper's obstacles are red lights.
//   * Time: a forward move takes its LED time and then `drive_ms`; a turn the commanded time; a
//     frame `capture_ms`. The LEDs are lit for the first part of the move, before it drives (the
//     paper: "it turns on the lights for a few seconds before proceeding").
//   * Turning: a command of t ms turns t / quarter_turn_ms quarter turns times the rate
//     1 + (rotation_error_ppm - drift_ppm_per_minute * minutes since the start) / 10^6 (at least
//     a tenth of nominal).
//   * Driving: one sub-cell along the true heading. The move is refused (the robot bumps and
//     stays) when the sub-cell its centre would reach is outside the cell area or not free.
//   * The dark frame (capture(true)) is the camera with the floor unlit: the dark-current pattern
//     plus sensor noise, what the paper subtracts.
#include <antkit/devices/stc_floor/camera.hpp>
#include <antkit/devices/stc_floor/optics.hpp>
#include <antkit/kernel/angle.hpp>
#include <antkit/kernel/grid.hpp>
#include <antkit/kernel/random.hpp>
#include <antkit/stc/subcell.hpp>
#include <cstdint>
#include <vector>

namespace antkit::devices::stc_floor {

// The experiment number of the marker-floor robot's keyed streams (issue 14).
inline constexpr std::uint64_t kFloorExperiment = 14;

struct FloorOptions {
  Optics optics;                         // the camera's true optics
  std::uint64_t seed = 1;                // the noise and dark-pattern streams
  std::int32_t noise = 0;                // per pixel, channel and frame: uniform in [-noise, noise]
  std::int32_t dark_offset = 12;         // the fixed pattern: uniform in [0, dark_offset]
  std::int64_t fade_half_life_ms = 0;    // 0: marks do not fade
  std::int32_t rotation_error_ppm = 0;   // the turn rate against nominal at the start
  std::int32_t drift_ppm_per_minute = 0; // how fast the turn rate falls
  std::int32_t quarter_turn_ms = 1500;   // nominal
  std::int32_t drive_ms = 1000;
  std::int32_t capture_ms = 100;
  std::uint8_t mark_level = 200, light_level = 230;
  std::int64_t mark_radius = kOne * 12 / 100, light_radius = kOne / 4;
};

class FloorWorld {
public:
  // `start` must be a free sub-cell of the map's cell area; `heading` a direction 0..3 (E, N, W,
  // S). Throws kernel::InputError otherwise ("start sub-cell", "start heading"), or for options out
  // of range ("camera noise", "dark offset", "fade half-life", "rotation error", "drift").
  FloorWorld(const kernel::OccupancyGrid& map, stc::SubCell start, int heading,
             FloorOptions options);

  // Lights the LEDs for led_ms (0: not at all) and then drives one sub-cell. False when the move
  // is refused (the LEDs were still lit).
  bool forward(std::int32_t led_ms);
  void rotate(std::int32_t ms); // counter-clockwise for ms > 0
  void leds(bool on);           // LEDs on lay a mark where they shine, now
  [[nodiscard]] Image capture(bool dark);

  // The truth.
  [[nodiscard]] PointQ16 position() const noexcept { return pos_; }
  [[nodiscard]] kernel::Angle heading() const noexcept { return heading_; }
  [[nodiscard]] std::int64_t clock_ms() const noexcept { return clock_ms_; }
  [[nodiscard]] const std::vector<stc::SubCell>& path() const noexcept { return path_; }
  [[nodiscard]] std::int64_t covered() const noexcept { return covered_; }
  [[nodiscard]] std::int64_t repeats() const noexcept { return repeats_; }
  [[nodiscard]] std::int64_t frames() const noexcept { return frames_; }
  // The largest distance so far of the robot's centre from the centre of the sub-cell it is in
  // (Q16 sub-cells), and of its heading from the nearest quarter turn (binary-angle units).
  [[nodiscard]] std::int64_t max_offset() const noexcept { return max_offset_; }
  [[nodiscard]] std::int64_t max_heading_error() const noexcept { return max_heading_error_; }
  [[nodiscard]] const FloorOptions& options() const noexcept { return o_; }

private:
  struct Slot {
    PointQ16 at;
    std::int64_t time = -1; // -1: unlit
  };
  void lay_mark();
  void note_pose();
  [[nodiscard]] bool cell_free(std::int64_t cx, std::int64_t cy) const noexcept;
  [[nodiscard]] std::uint8_t mark_intensity(const Slot& s, PointQ16 w) const noexcept;
  Slot* slot(std::int64_t x, std::int64_t y, bool vertical) noexcept;

  FloorOptions o_;
  std::int32_t width_, height_; // sub-cells
  stc::CellGridShape shape_;
  std::vector<std::uint8_t> free_sub_, free_cell_;
  std::vector<Slot> vertical_, horizontal_; // (width + 1) x (height + 1) each
  std::vector<FloorRay> rays_;
  std::vector<std::uint8_t> dark_pattern_;
  PointQ16 pos_;
  kernel::Angle heading_;
  std::int64_t clock_ms_ = 0, frames_ = 0;
  std::vector<stc::SubCell> path_;
  std::vector<std::uint8_t> entered_;
  std::int64_t covered_ = 0, repeats_ = 0, max_offset_ = 0, max_heading_error_ = 0;
};

} // namespace antkit::devices::stc_floor
