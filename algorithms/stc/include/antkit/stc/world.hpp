#pragma once
// The simulated body the STC controllers run in (DESIGN.md: a body turns commands into motion and
// produces the next observation), and one function that runs a variant to the end.
//
// The world holds the sub-cell map, the robot's sub-cell, the marks on the floor (sub-cell marks
// for `ant`, lit edges for `ant-edge`) and how often each sub-cell was entered. Marker noise lives
// here, on the sensing side: each mark bit the robot reads is misread (a missed mark or a phantom)
// with probability noise.ppm / 1'000'000, drawn from the keyed stream
// (seed, kNoiseExperiment, trial, robot 0, kNoisePurpose). The controllers stay deterministic
// functions of what they read.
//
// Trace hash (DESIGN.md rule 5), over the canonical little-endian stream:
//   u32 width, u32 height (sub-cells), i32 start.x, i32 start.y, then per position of the tour
//   (the start first) i32 x, i32 y.
// Only positions enter it, so two variants that produce the same tour have the same hash; that is
// invariant 5 read off one number.
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/random.hpp>
#include <antkit/stc/ant.hpp>
#include <antkit/stc/online.hpp>
#include <antkit/stc/subcell.hpp>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace antkit::stc {

enum class Variant : std::uint8_t { Offline, Online, Ant, AntEdge, Full };

inline constexpr std::array<Variant, 5> kVariants{Variant::Offline, Variant::Online, Variant::Ant,
                                                  Variant::AntEdge, Variant::Full};
[[nodiscard]] std::string_view variant_name(Variant v) noexcept;
[[nodiscard]] std::optional<Variant> parse_variant(std::string_view name) noexcept;
// Variants whose tour enters every sub-cell exactly once (all but `full`).
[[nodiscard]] constexpr bool is_exact(Variant v) noexcept {
  return v != Variant::Full;
}

// Keys of the noise stream.
inline constexpr std::uint64_t kNoiseExperiment = 3;       // issue 3
inline constexpr std::uint64_t kNoisePurpose = 0x6D61726B; // "mark"

struct NoiseModel {
  std::uint32_t ppm = 0; // misread probability, parts per million (0 .. 1'000'000)
  std::uint64_t seed = 0;
  std::uint64_t trial = 0;
};

// What the robot leaves when a command says `mark`: a mark on the sub-cell it leaves (`ant`), or
// the lit edge behind it (`ant-edge`, the paper's real robot).
enum class Marker : std::uint8_t { WholeSubCell, Edge };

class StcWorld {
public:
  StcWorld() = default;
  StcWorld(const kernel::OccupancyGrid& map, SubCell start, NoiseModel noise = {},
           Marker marker = Marker::WholeSubCell) {
    reset(map, start, noise, marker);
  }
  // Starts over on a map (reusing the buffers: the exhaustive tests run millions of tours).
  // The start must be a free sub-cell inside the cell area (the runners check).
  void reset(const kernel::OccupancyGrid& map, SubCell start, NoiseModel noise = {},
             Marker marker = Marker::WholeSubCell);

  [[nodiscard]] CellObservation observe_cells() const noexcept;
  [[nodiscard]] MarkObservation observe_marks() noexcept;
  [[nodiscard]] EdgeObservation observe_edges() noexcept;

  // Carries out a command: leaves the mark, then moves. Returns false, without moving, for Stop
  // and for a move off the cell area or into a sub-cell that is not free.
  bool apply(const Command& command) noexcept;

  [[nodiscard]] SubCell position() const noexcept { return position_; }
  // Sub-cells reachable from the robot's position: 4 x the free cells 4-connected to its cell
  // (whole_cells), or the free sub-cells of the cell area 4-connected to it.
  [[nodiscard]] std::int64_t reachable_subcells(bool whole_cells);
  [[nodiscard]] bool sub_free(SubCell s) const noexcept;
  [[nodiscard]] bool marked(SubCell s) const noexcept {
    return ((cell_marks(cell_of(s)) >> quadrant_of(s)) & 1) != 0;
  }
  // The 12-bit edge mask of a cell (bits as documented in ant.hpp).
  [[nodiscard]] std::uint16_t cell_edges(Cell c) const noexcept;
  // Lights the edge of sub-cell s (inside the cell area) in direction d.
  void light_edge(SubCell s, int d) noexcept;
  // Sub-cells entered at least once, and entries into a sub-cell entered before.
  [[nodiscard]] std::int64_t covered() const noexcept { return covered_; }
  [[nodiscard]] std::int64_t repeats() const noexcept { return repeats_; }
  [[nodiscard]] std::int32_t width() const noexcept { return width_; }
  [[nodiscard]] std::int32_t height() const noexcept { return height_; }

private:
  [[nodiscard]] std::size_t index(SubCell s) const noexcept {
    return static_cast<std::size_t>(s.y) * static_cast<std::size_t>(width_) +
           static_cast<std::size_t>(s.x);
  }
  // Index into the cell arrays, which have a one-cell border.
  [[nodiscard]] std::size_t cell_index(Cell c) const noexcept {
    return static_cast<std::size_t>(c.y + 1) * stride_ + static_cast<std::size_t>(c.x + 1);
  }
  [[nodiscard]] std::uint8_t cell_marks(Cell c) const noexcept;
  std::uint32_t misread(std::uint32_t bits, int count) noexcept;
  void enter(SubCell s) noexcept;

  std::int32_t width_ = 0, height_ = 0;
  CellGridShape shape_{};
  std::size_t stride_ = 2;
  std::array<std::size_t, 4> offset_{}; // cell index steps E, N, W, S
  Marker marker_ = Marker::WholeSubCell;
  std::vector<std::uint8_t> free_;      // per sub-cell, inside the cell area only
  std::vector<std::uint8_t> cell_free_; // per cell, 0 on the border
  // The floor, per cell (so that one observation reads five bytes, not twenty): bit q of marks_
  // is sub-cell q's mark; edges_ holds each cell's twelve edges as documented in ant.hpp (an
  // exterior edge is stored in both cells it separates).
  std::vector<std::uint8_t> marks_;
  // Bit 7 of marks_ and bit 15 of edges_ copy cell_free_ (never lit: marks use bits 0-3, edges
  // 0-11), so an observation reads the neighbours' freedom from the words it loads anyway instead
  // of five more bytes from cell_free_ (observe_cells was 15 % of an ant-edge run).
  std::vector<std::uint16_t> edges_;
  std::vector<std::uint8_t> entered_; // per sub-cell
  std::vector<std::uint8_t> scratch_;
  std::vector<Cell> queue_;
  std::int64_t covered_ = 0, repeats_ = 0;
  SubCell position_{};
  NoiseModel noise_{};
  kernel::Stream stream_{0};
};

struct RunOptions {
  NoiseModel noise{};
  // Moves after which a run is cut off; 0: 16 per sub-cell of the map (an exact tour needs one,
  // `full` fewer than 4). Only a noisy run can get there.
  std::int64_t max_moves = 0;
  bool record_path = true;
  // Called with every position of the tour as it is made, the start first (the path streamed:
  // with record_path false, nothing per position is kept). Empty: not called.
  std::function<void(SubCell)> on_position;
};

struct RunResult {
  Variant variant = Variant::Offline;
  std::vector<SubCell> path;           // the start first (empty unless record_path)
  std::int64_t positions = 0;          // entries in the path, the start included
  std::int64_t reachable_subcells = 0; // exact variants: 4 x free cells 4-connected to the start
                                       // cell; full: free sub-cells 4-connected to the start
  std::int64_t covered = 0;            // reachable sub-cells entered at least once
  std::int64_t repeats = 0;            // entries into a sub-cell entered before
  bool returned_to_start = false;      // the last sub-cell is the start or 4-adjacent to it
  bool closed = false;                 // the controller stopped (rather than being cut off)
  bool refused = false;                // the controller asked for an impossible move
  std::uint64_t hash = 0;
};

// Runs one variant from `start` to the end of its tour. Offline takes the fast path of offline.hpp
// (the depth-first search emits the tour as it builds the tree: no world, no controller; about a
// quarter of a byte per sub-cell beyond the map and a one-bit-per-sub-cell count of the sub-cells
// entered): the same positions, and so the same hash, as the OfflineStc controller driven step by
// step (tests hold the two against each other). Throws kernel::InputError for a start
// outside the cell area, in a blocked sub-cell, or (exact variants) in a cell that is not free.
// Noise applies to the marker variants (`ant`, `ant-edge`); the others read no marks.
RunResult run_stc(const kernel::OccupancyGrid& map, SubCell start, Variant variant,
                  const RunOptions& options = {});

// The trace hash above of a tour given as its positions, the start first (what a robot that
// reports its path, such as the marker-floor robot, compares with run_stc's hash).
std::uint64_t tour_hash(std::int32_t width, std::int32_t height, std::span<const SubCell> path);

// The same, reusing a world's buffers.
RunResult run_stc(StcWorld& world, const kernel::OccupancyGrid& map, SubCell start, Variant variant,
                  const RunOptions& options = {});

// Free sub-cells 4-connected to `start` inside the cell area (full), or 4 x the free cells
// 4-connected to its cell (exact variants).
std::int64_t reachable_subcells(const kernel::OccupancyGrid& map, SubCell start, Variant variant);

// The start `antkit stc` takes when none is given: the first place, in row-major order, of the
// largest 4-connected region the variant can cover (ties: the region found first): the NW
// sub-cell of its first free cell for the exact variants, its first free sub-cell for full. (The
// first free cell of a map may well be an island of one cell; the largest region is what a user
// asking for "coverage of this map" means.) nullopt when the map has no such place.
std::optional<SubCell> default_start(const kernel::OccupancyGrid& map, Variant variant);

} // namespace antkit::stc
