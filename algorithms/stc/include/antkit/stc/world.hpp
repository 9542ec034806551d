#pragma once
// The simulated body the STC controllers run in (DESIGN.md: a body turns commands into motion and
// produces the next observation), and one function that runs a variant to the end.
//
// The world owns the storage of the floor (floor.hpp: the sub-cell map, the robot's sub-cell, the
// marks on the floor, sub-cell marks for `ant` and lit edges for `ant-edge`, which sub-cells were
// entered, and the marker noise) and steps it with the floor's functions, the very ones the
// Cortex-M image runs (mcu/). The trace hash of a tour is defined in floor.hpp (tour_hash_begin,
// tour_hash_add): only positions enter it, so two variants that produce the same tour have the same
// hash; that is invariant 5 read off one number.
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/random.hpp>
#include <antkit/stc/ant.hpp>
#include <antkit/stc/floor.hpp>
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

// Fills `bits` (floor_size(map.width(), map.height()).bit_bytes bytes) with the map's free
// sub-cells of the cell area, in the layout of Floor's free_bits.
void fill_free_bits(const kernel::OccupancyGrid& map, std::span<std::uint8_t> bits) noexcept;

class StcWorld {
public:
  StcWorld() = default;
  StcWorld(const kernel::OccupancyGrid& map, SubCell start, NoiseModel noise = {},
           Marker marker = Marker::WholeSubCell) {
    reset(map, start, noise, marker);
  }
  // StcWorld owns the floor's storage; copying it would leave the copy's floor on this one's.
  StcWorld(const StcWorld&) = delete;
  StcWorld& operator=(const StcWorld&) = delete;
  StcWorld(StcWorld&&) noexcept = default; // the vectors' buffers, and so the floor's, move along
  StcWorld& operator=(StcWorld&&) noexcept = default;
  // Starts over on a map (reusing the buffers: the exhaustive tests run millions of tours).
  // The start must be a free sub-cell inside the cell area (the runners check).
  void reset(const kernel::OccupancyGrid& map, SubCell start, NoiseModel noise = {},
             Marker marker = Marker::WholeSubCell);

  // The floor's step (floor.hpp), over this world's storage.
  [[nodiscard]] Floor& floor() noexcept { return floor_; }
  [[nodiscard]] CellObservation observe_cells() const noexcept { return floor_.observe_cells(); }
  [[nodiscard]] MarkObservation observe_marks() noexcept { return floor_.observe_marks(); }
  [[nodiscard]] EdgeObservation observe_edges() noexcept { return floor_.observe_edges(); }
  bool apply(const Command& command) noexcept { return floor_.apply(command); }
  [[nodiscard]] SubCell position() const noexcept { return floor_.position(); }
  [[nodiscard]] bool sub_free(SubCell s) const noexcept { return floor_.sub_free(s); }
  [[nodiscard]] bool marked(SubCell s) const noexcept { return floor_.marked(s); }
  [[nodiscard]] std::uint16_t cell_edges(Cell c) const noexcept { return floor_.cell_edges(c); }
  void light_edge(SubCell s, int d) noexcept { floor_.light_edge(s, d); }
  [[nodiscard]] std::int64_t covered() const noexcept { return floor_.covered(); }
  [[nodiscard]] std::int64_t repeats() const noexcept { return floor_.repeats(); }
  [[nodiscard]] std::int32_t width() const noexcept { return floor_.width(); }
  [[nodiscard]] std::int32_t height() const noexcept { return floor_.height(); }

  // Sub-cells reachable from the robot's position: 4 x the free cells 4-connected to its cell
  // (whole_cells), or the free sub-cells of the cell area 4-connected to it.
  [[nodiscard]] std::int64_t reachable_subcells(bool whole_cells);

private:
  std::vector<std::uint8_t> free_bits_, entered_bits_, marks_;
  std::vector<std::uint16_t> edges_;
  Floor floor_;
  std::vector<std::uint8_t> scratch_;
  std::vector<Cell> queue_;
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

// Whether a run's own counts say its tour kept the invariants of its variant: it closed, ended
// back at (or beside) the start, and covered every reachable sub-cell, with no repeat for the exact
// variants (full may repeat). A noise-free run always should (`antkit stc` exits 1 otherwise).
[[nodiscard]] inline bool keeps_invariants(const RunResult& r) noexcept {
  return r.closed && r.returned_to_start && r.covered == r.reachable_subcells &&
         (r.variant == Variant::Full || r.repeats == 0);
}

// Throws kernel::InputError("start", ...) unless `start` is a place `variant` can start from: a
// free sub-cell of the cell area, in a free cell for the exact variants (run_stc checks this
// first).
void check_start(const kernel::OccupancyGrid& map, SubCell start, Variant variant);

// The Cortex-M image's input for one run of `ant` or `ant-edge` (mcu_input.hpp): the start is
// checked as run_stc checks it (InputError "start"); InputError "variant" for another variant, and
// "map" when its floor would not fit the image's arena (the message gives both sizes).
std::vector<std::uint8_t> mcu_input(const kernel::OccupancyGrid& map, SubCell start,
                                    Variant variant, NoiseModel noise = {});

// The trace hash (floor.hpp) of a tour given as its positions, the start first (what a robot that
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
