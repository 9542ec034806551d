#pragma once
// Frontier coverage: the fourth algorithm of issue 6 ("go beyond the paper"), the target choice of
// Sheng et al. (2006) as paper 001 states it, g = w1 * I - w2 * D + w3 * lambda, run on paper 004's
// shared map of viewed cells. One team controller (DESIGN.md): stepped once per robot per tick, in
// robot index order.
//
// The frontier, in the uniform world's sense: a viewed free cell with an unviewed 8-neighbour. The
// set is kept incrementally in an antkit::frontier::FrontierMap (viewed free -> Free, viewed and
// not free -> Occupied, unviewed -> Unexplored): the controller re-reads only the sensor footprint
// of a robot whose cell changed since it last looked, so no step scans the whole map.
//
// A robot without a target runs a breadth-first search from its cell over viewed free cells with
// the world's moves (8 neighbours, no corner cutting, CoverageWorld::passable_step), never
// entering another robot's cell, and takes the frontier cell of highest g, where
//   I       the unviewed viewable free cells within the uniform sensor of the candidate (Euclidean
//           distance r, line of sight: CoverageWorld::in_view) that are not within sensor distance
//           of a claimed centre (another robot's cell or its target);
//   D       the number of moves of the search's shortest path;
//   lambda  frontier::FrontierPlanner::nearness (minus the Chebyshev distance to the nearest
//           other robot).
// It claims the target (no two robots share one: another robot's target is never a candidate) and
// walks the path, one cell per tick.
//
// Choices where the issue and papers are silent:
//   * I counts only cells the robot would actually see from the candidate (in_view, which reads
//     the true map, as A* plans on the true map), and only free cells that count for coverage.
//     Paper 001's I counts unexplored cells in a square; here that would make a robot chase cells
//     hidden behind a wall for ever. With this I, every arrival at a target with I > 0 views a new
//     cell, so the run makes progress; and while coverage is incomplete some frontier cell has
//     I > 0 (a viewed free cell 4-adjacent to an unviewed viewable one sees it at distance 1).
//   * Candidates have D >= 1 and I > 0. If the claims leave no candidate, the robot searches again
//     ignoring the claims (an idle robot can block a corridor the others need, as for A*).
//   * Weights w1 = w2 = 1, w3 = 0 (paper 001's recommendation; frontier::Weights' defaults).
//   * Ties in g go to the cell the search meets first (nearer first, then the kernel's neighbour
//     order E, NE, N, NW, W, SW, S, SE). The search stops once no farther cell can win: I is at
//     most the footprint size minus one, so a cell at distance D has g <= w1 * (rays - 1) - w2 * D.
//   * Speed, with the same decisions (issue 31). Every viewed free cell c (a Free cell of the
//     frontier map, so every possible candidate) keeps a bound on its I without claims: at first
//     unseen(c), the viewable cells of its footprint still unexplored here (a cell the world has
//     viewed is never unexplored here, so I(c) <= unseen(c)); then, whenever a search measures c,
//     its I exactly; a cell of its footprint being viewed marks the bound stale but keeps it a
//     bound (I only falls) and lowers it to unseen(c) when that is smaller. The Free cells are
//     kept in lists per bound. A candidate whose w1 * bound - w2 * D cannot beat the best g is not
//     evaluated; a candidate's count stops once it cannot reach the I that would beat the best;
//     and the search stops at the first depth where no cell left can win: none of this level's
//     frontier cells by its bound, and no frontier cell not yet reached by its bound and the
//     lower bound max(depth + 1, Chebyshev distance) on its D (a stale bound that stands in the
//     way is measured first). The claims are stamped on a grid once per search. Nothing the
//     search chooses changes: tests/uniform/test_frontier_speed.cpp steps this controller beside
//     the previous one, command for command, and the golden hashes hold.
//   * The target is dropped and a new one searched when its I (claims ignored) falls to 0, when
//     the path is used up, or when the next cell holds a robot. A robot that finds no target
//     around the other robots waits; after kPatience such ticks it steps to a random enterable
//     neighbour (its own keyed stream, StreamPurpose::Unstick), as A* does in a standoff.
//   * A sensor distance of 0 is refused (kernel::InputError, where "sensor distance"): a robot that
//   sees
//     only its own cell has no frontier cell from which a new one is seen.
//   * A step along the path turns the robot to face it for free: its moves are its steps.
#include <antkit/frontier/frontier_map.hpp>
#include <antkit/frontier/planner.hpp>
#include <antkit/kernel/random.hpp>
#include <antkit/uniform/controllers.hpp>
#include <antkit/uniform/world.hpp>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace antkit::uniform {

class FrontierCoverage {
public:
  using Observation = uniform::Observation;
  using Command = uniform::Command;
  static constexpr std::uint32_t kPatience = 3;

  // Throws kernel::InputError (where "sensor distance") when the world's sensor distance is 0.
  FrontierCoverage(std::uint64_t seed, std::uint64_t trial, const CoverageWorld& world,
                   frontier::Weights weights = {});
  Command step(const Observation& obs);

  [[nodiscard]] std::optional<kernel::Cell> target(std::size_t robot) const noexcept {
    return robots_[robot].target;
  }
  [[nodiscard]] const frontier::FrontierMap& frontiers() const noexcept { return map_; }
  // I of a candidate for robot `robot` (claims of the other robots counted when `claims`).
  [[nodiscard]] std::int32_t information(const CoverageWorld& world, std::size_t robot,
                                         kernel::Cell candidate, bool claims) const;
  // Counters for reports and benchmarks.
  [[nodiscard]] std::uint64_t plans() const noexcept { return plans_; }
  [[nodiscard]] std::uint64_t expanded() const noexcept { return expanded_; }
  [[nodiscard]] std::uint64_t unsticks() const noexcept { return unsticks_; }

private:
  struct Robot {
    std::optional<kernel::Cell> target;
    std::vector<std::uint8_t> path; // bearings still to take, from path[next]
    std::size_t next = 0;
    std::uint32_t waited = 0;
    kernel::Stream unstick;
    std::optional<kernel::Cell> seen_from; // where the controller last read its footprint
  };
  void refresh(const CoverageWorld& world);
  bool plan(std::size_t i, const CoverageWorld& world, bool claims);
  // Starts keeping unseen(c) for a cell that has just become Free in map_.
  void track(const CoverageWorld& world, std::uint32_t index, kernel::Cell c);
  // Moves a tracked cell (by index) to bound n.
  void set_bound(std::uint32_t index, std::uint32_t n);
  // I of a tracked cell without claims (returned, and made its exact bound) and with them when
  // `claims` (in claimed).
  std::int32_t measure(const CoverageWorld& world, std::uint32_t index, kernel::Cell c, bool claims,
                       std::int32_t& claimed);
  // Calls f(index) for every cell of the footprint around `centre` that is on the map.
  template <class F>
  void for_each_footprint_cell(const CoverageWorld& world, kernel::Cell centre, F&& f) const;
  // I of a candidate with the claims stamped in claimed_ (generation claim_generation_), given
  // its unseen count; once I cannot reach `need` any more, some smaller count.
  [[nodiscard]] std::int32_t stamped_information(const CoverageWorld& world, kernel::Cell candidate,
                                                 bool claims, std::uint32_t unseen,
                                                 std::int64_t need) const;

  frontier::Weights weights_;
  frontier::FrontierMap map_;
  std::vector<Robot> robots_;
  kernel::Grid<std::uint32_t> stamp_;
  kernel::Grid<std::uint8_t> parent_; // bearing of the move that reached the cell
  std::uint32_t generation_ = 0;
  kernel::Grid<std::uint32_t> unseen_; // unseen(c), for the Free cells of map_
  kernel::Grid<std::uint32_t> bound_;  // >= I of the Free cell without claims; 0 elsewhere
  kernel::Grid<std::uint8_t> exact_;   // 1: bound_ is that I now (measured, nothing viewed since)
  std::vector<std::vector<std::uint32_t>> bound_cells_; // the Free cells (indices), per bound
  kernel::Grid<std::uint32_t> bound_slot_;              // a cell's place in its list
  std::vector<std::uint32_t> scan_cursor_; // per bound: cells of its list a search ruled out
  std::vector<std::uint64_t> scan_search_; // the search that set each cursor
  std::uint64_t search_ = 0;               // searches so far
  bool searching_ = false;                 // inside plan(): cursors are live
  std::uint32_t bound_top_ = 0;            // >= the largest bound of a Free cell
  kernel::Grid<std::uint32_t> claimed_;    // == claim_generation_: within a claimed centre's range
  std::uint32_t claim_generation_ = 0;
  kernel::Grid<std::uint8_t> viewable_;  // CoverageWorld::is_viewable, read once
  std::vector<std::ptrdiff_t> ray_step_; // each ray's offset as a step of the cell index
  std::vector<std::uint32_t> queue_;     // cell indices
  std::vector<kernel::Cell> partners_;
  std::uint64_t plans_ = 0;
  std::uint64_t expanded_ = 0;
  std::uint64_t unsticks_ = 0;
};

} // namespace antkit::uniform
