#pragma once
// One step-turn wanderer in paper 004's world, over storage the caller gives (issue 27): what
// `antkit cover --algo rw` runs for one robot (CoverageWorld, world.hpp, with coverage.hpp's tick
// loop), freestanding, so that the Cortex-M image (mcu/src/wanderer_run.cpp) runs it. The world's
// rules are not restated here: the move, the turn, the view and the hashed state are
// coverage_rules.hpp's, which CoverageWorld calls too; this file holds only the storage (the map's
// Free cells and the viewed cells as bits, the footprint the host computed and sent) and the one
// robot's pose. The ticks are coverage_ticks.hpp's run_ticks, which run_coverage runs too. The
// controller is StepTurnCore (step_turn.hpp), whose commands are RandomWanderer's for robot 0.
//
// Memory: the map's Free cells and the viewed cells as bits (1 bit per cell each), the footprint's
// rays (12 bytes each) and the cells between (4 bytes each). No allocation, no exception.
#include <antkit/kernel/grid.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/uniform/coverage_rules.hpp>
#include <antkit/uniform/coverage_ticks.hpp>
#include <antkit/uniform/step_turn.hpp>
#include <cstddef>
#include <cstdint>
#include <span>

namespace antkit::uniform {

// SensorFootprint::Ray with 16-bit offsets: the cells between are between[first, first + count).
struct StepTurnRay {
  std::int16_t dx = 0, dy = 0;
  std::uint32_t first = 0, count = 0;
  friend constexpr kernel::Cell offset_of(const StepTurnRay& r) noexcept { return {r.dx, r.dy}; }
};
struct StepTurnOffset {
  std::int16_t dx = 0, dy = 0;
  friend constexpr kernel::Cell offset_of(StepTurnOffset d) noexcept { return {d.dx, d.dy}; }
};

// Complete or TimeLimit (a wanderer never stops itself).
using StepTurnStop = TickStop;

struct StepTurnResult {
  std::uint64_t viewed = 0, viewable = 0, movements = 0, moves = 0, hash = 0;
  StepTurnStop stop = StepTurnStop::TimeLimit;
};

class StepTurnWorld {
public:
  // `free_bits`: bit k (LSB first) of byte k / 8 is 1 when cell k (row-major) is Free; `viewed`:
  // as many bytes, zeroed here. `viewable`: the free cells of the robot's 4-connected component
  // (CoverageWorld::viewable). The robot stands on a Free cell (the host checked it); it views
  // from there, as CoverageWorld's constructor has it view.
  void init(std::int32_t width, std::int32_t height, const std::uint8_t* free_bits,
            std::uint8_t* viewed, std::span<const StepTurnRay> rays,
            std::span<const StepTurnOffset> between, kernel::Cell start, std::uint8_t bearing,
            std::uint64_t viewable) noexcept {
    cells_ = Cells{width, height, free_bits, viewed};
    rays_ = rays, between_ = between, cell_ = start, bearing_ = bearing & 7u;
    viewable_ = viewable;
    for (std::uint64_t k = 0; k < bytes(width, height); ++k) viewed[k] = 0;
    counts_ = {};
    view();
  }
  [[nodiscard]] static constexpr std::uint64_t bytes(std::int32_t width,
                                                     std::int32_t height) noexcept {
    return (static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height) + 7) / 8;
  }

  [[nodiscard]] bool is_free(kernel::Cell c) const noexcept {
    return cells_.in_bounds(c) && cells_.free_at(c);
  }
  // CoverageWorld::can_step (no other robot to occupy the target).
  [[nodiscard]] bool can_step(std::uint8_t bearing) const noexcept {
    return passable_step_rule(cell_, bearing, [this](kernel::Cell c) { return is_free(c); });
  }
  [[nodiscard]] bool front_free() const noexcept { return can_step(bearing_); }

  // run_ticks' world (coverage_ticks.hpp), as CoverageWorld answers for robot 0 of 1.
  [[nodiscard]] static constexpr std::size_t robot_count() noexcept { return 1; }
  [[nodiscard]] bool complete() const noexcept { return counts_.free == viewable_; }
  [[nodiscard]] std::uint8_t bearing(std::size_t) const noexcept { return bearing_; }
  bool turn(std::size_t, int eighths) noexcept {
    bearing_ = turned_bearing(bearing_, eighths);
    return true;
  }
  // Faces `bearing`, then steps; false (nothing happens) when blocked.
  bool move(std::size_t, std::uint8_t bearing) noexcept {
    bearing &= 7u;
    if (!can_step(bearing)) return false;
    bearing_ = bearing;
    cell_ = cell_ + kernel::kNeighbours8[bearing];
    return true;
  }
  std::uint32_t view(std::size_t) noexcept { return view(); }

  // Marks what the robot views from its cell; returns how many cells were newly viewed.
  std::uint32_t view() noexcept {
    return view_from(cells_, cell_, rays_, between_.data(), counts_);
  }
  // CoverageWorld::hash_state for one robot.
  void hash_state(kernel::TraceHash& hash) const noexcept {
    hash_pose(hash, cell_, bearing_);
    hash_counts(hash, counts_);
  }

  [[nodiscard]] kernel::Cell cell() const noexcept { return cell_; }
  [[nodiscard]] std::uint8_t bearing() const noexcept { return bearing_; }
  [[nodiscard]] std::uint64_t viewed_free() const noexcept { return counts_.free; }
  [[nodiscard]] std::uint64_t viewable() const noexcept { return viewable_; }

private:
  // coverage_rules.hpp's storage over the bits: a line-of-sight sensor on one component, so every
  // viewed Free cell counts.
  struct Cells {
    std::int32_t w = 0, h = 0;
    const std::uint8_t* free = nullptr;
    std::uint8_t* seen = nullptr;
    [[nodiscard]] bool in_bounds(kernel::Cell c) const noexcept {
      return c.x >= 0 && c.y >= 0 && c.x < w && c.y < h;
    }
    [[nodiscard]] bool free_at(kernel::Cell c) const noexcept { return bit(free, index(c)); }
    [[nodiscard]] bool viewed(kernel::Cell c) const noexcept { return bit(seen, index(c)); }
    void mark_viewed(kernel::Cell c) const noexcept {
      seen[index(c) / 8] = static_cast<std::uint8_t>(seen[index(c) / 8] | (1u << (index(c) % 8)));
    }
    [[nodiscard]] bool counts_free(kernel::Cell c) const noexcept { return free_at(c); }
    [[nodiscard]] static constexpr bool sees_through() noexcept { return false; }
    [[nodiscard]] std::uint64_t index(kernel::Cell c) const noexcept {
      return static_cast<std::uint64_t>(c.y) * static_cast<std::uint64_t>(w) +
             static_cast<std::uint64_t>(c.x);
    }
    [[nodiscard]] static bool bit(const std::uint8_t* bits, std::uint64_t k) noexcept {
      return ((static_cast<unsigned>(bits[k / 8]) >> (k % 8)) & 1u) != 0;
    }
  };

  Cells cells_;
  std::span<const StepTurnRay> rays_;
  std::span<const StepTurnOffset> between_;
  kernel::Cell cell_{};
  std::uint8_t bearing_ = 0;
  std::uint64_t viewable_ = 0;
  ViewCounts counts_;
};

// run_coverage's run (coverage.hpp: run_ticks) for one robot of Algorithm::RandomWanderer (number
// 0) driven by `wanderer` (StepTurnCore, or anything whose step(front_free) answers as it does: the
// Cortex-M image passes the C API's antkit_step_turn_wanderer).
template <class Wanderer = StepTurnCore>
StepTurnResult run_step_turn(StepTurnWorld& world, Wanderer& wanderer,
                             std::uint64_t limit) noexcept {
  struct Team {
    StepTurnWorld& world;
    Wanderer& wanderer;
    Command command(std::size_t) noexcept { return wanderer.step(world.front_free()); }
  } team{world, wanderer};
  const TickRun run = run_ticks(world, team, 0, limit, [](std::uint64_t) {});
  StepTurnResult out;
  out.movements = run.movements;
  out.moves = run.moves;
  out.hash = run.hash;
  out.stop = run.stop;
  out.viewed = world.viewed_free();
  out.viewable = world.viewable();
  return out;
}

} // namespace antkit::uniform
