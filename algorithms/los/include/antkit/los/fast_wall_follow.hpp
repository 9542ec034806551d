#pragma once
// Fast wall-follow exploration with two cooperating robots (paper 001, Section II, steps 1-7), as
// one team controller for the pair (DESIGN.md contract).
//
//   1. A is the WallFollower, B the TroubleShooter; both start at a wall.
//   2. A follows the walls clockwise, B counter-clockwise, sweeping the line of sight each step.
//      When the line of sight is lost, both move one step back to get it again.
//   3. B moves toward A to discover the cause of the obstruction; the line of sight holds.
//   4. When B reaches the cause, it follows it clockwise if the cause is on its right hand side,
//      counter-clockwise if on its left; A resumes following the walls. Loss of sight: both step
//      back, then 3 again.
//   5. If B meets A on the way, it stops there; A follows the walls until sight is lost, steps
//      back, and 3 again.
//   6. 3-4 repeat until A has detected all the environment walls.
//   7. The rest is explored with frontier cells and line of sight (FrontierCompletion).
//
// Wall following is Moore-neighbour tracing on the shared map: a robot remembers one blocked
// neighbour (its "wall"; off-grid cells count as blocked, assumption 8) and rotates away from it
// until the first known-free neighbour, which it moves to; the blocked cell passed last becomes its
// new wall. Rotating clockwise from the wall keeps the wall on the left hand (Hand::Left), which
// goes clockwise around the inside of the environment's outer walls and counter-clockwise around
// an obstacle; Hand::Right is the mirror. So A traces with Hand::Left, B first with Hand::Right,
// and on a cause with the hand on whose side the cause lies (step 4: a cause on the right hand is
// followed clockwise, which is Hand::Right around an obstacle).
//
// Choices where the paper is ambiguous, documented here and beside the code:
//   * Step 1: a robot with no blocked neighbour first walks to a wall: A to the west, B to the
//     south (the paper's robots start at the lower-left corner); the first one there waits.
//   * Step 2: the line is lost when this tick's observation has no line of sight and the previous
//     one had. A robot steps back only if it moved in the last tick; its tracing state is restored.
//   * Step 3: B walks toward A along the line that joins them after the step back (its supercover
//     cells are free, since the line of sight holds), taking 8-connected shortcuts along it. The
//     "cause" is a known obstacle cell on the lost line (the supercover that lacked sight); B has
//     reached it when it is one of B's eight neighbours. Which side: the sign of the cross product
//     of (A - B) and (cause - B); a cause straight ahead counts as on the right (clockwise).
//     If sight is lost during B's walk, B stops (step 5) instead of stepping back.
//   * Neighbouring robots are never out of sight (each scan sees the other, assumption 1), so
//     no step back happens between neighbours even if the line grazes a blocked corner.
//   * A loss that repeats the previous one exactly (A at the same point of its trace, B on the
//     same cell) does not make them step back again: B stays (step 5) and A goes on; otherwise the
//     same back-and-forth would repeat for ever.
//   * Step 4: B follows the cause until its tracing state repeats (it has gone once around the
//     cause), then stays as in step 5; the blocked cells it kept its hand on are then never taken
//     as a cause again, so a later walk toward A passes them by. A cause found again on the same
//     obstacle continues the same way around (a step back undoes B's last tracing state).
//     When a tracing state repeats with steps back in between, that is still once around.
//   * Step 5: B "meets" A when they are neighbours, or when the walk ends.
//   * Step 6: A has detected all the walls when its tracing state (cell, wall) repeats (the trace
//     has closed its loop), when its next cell is one B walked while following the walls
//     counter-clockwise in step 2 (the rest of the boundary was followed by B already), or when B
//     stands on A's next cell for two ticks running (they have met head-on, each having traced
//     the walls from the other end). As a guard against a
//     back-and-forth that never ends, the stage also ends when A's trace has not advanced past its
//     furthest point for 4 (W + H) + 64 ticks. Then step 7.
//   * The whole run stops, in any stage, as soon as no frontier cell is left (rule 6 as the issue
//     states it: what can be observed is explored).
//   * A move whose target is off the grid or a cell the map holds as an obstacle is never
//     emitted: the robot stays instead. A consistent body never makes the trace ask for one (the
//     golden hashes are unchanged by this guard), but a body that does not go where it was told
//     (a robot observed away from the cell its trace put it on) would otherwise be sent off the
//     grid; fuzz/controller_los.cpp found that.
#include <antkit/frontier/planner.hpp>
#include <antkit/kernel/grid.hpp>
#include <antkit/los/exploration_map.hpp>
#include <antkit/los/frontier_team.hpp>
#include <antkit/los/team.hpp>
#include <array>
#include <cstdint>
#include <vector>

namespace antkit::los {

// The side on which a tracing robot keeps its wall.
enum class Hand : std::uint8_t { Left = 0, Right = 1 };

struct WallTracer {
  kernel::Cell position{};
  std::int8_t wall = -1; // neighbour index of the remembered blocked cell; -1: not on a wall yet
  Hand hand = Hand::Left;
};

// The first move of Moore tracing from `t` on `map` (a neighbour index, or -1 when every neighbour
// is blocked); `next` receives the tracer after that move.
int trace_step(const ExplorationMap& map, const WallTracer& t, WallTracer& next);
// The wall to start tracing with at `at`: the first blocked neighbour (in the kernel's order) whose
// neighbour on the rotation side is free, or -1 when no neighbour is blocked.
int initial_wall(const ExplorationMap& map, kernel::Cell at, Hand hand);

struct FastWallFollowOptions {
  frontier::Weights weights{}; // for step 7
};

class FastWallFollow {
public:
  using Observation = TeamObservation;
  using Command = TeamCommand;

  enum class Stage : std::uint8_t { WallFollowing = 0, FrontierCompletion = 1, Finished = 2 };
  enum class TroubleShooter : std::uint8_t {
    FollowWalls = 0, // step 2: counter-clockwise along the walls
    Seek = 1,        // step 3: toward the wall follower, looking for the cause
    FollowCause = 2, // step 4: following the cause on its side
    Stay = 3         // step 5: met the partner; waits
  };

  FastWallFollow(std::int32_t width, std::int32_t height, FastWallFollowOptions options = {});
  TeamCommand step(const TeamObservation& observation);

  [[nodiscard]] const ExplorationMap& map() const noexcept { return map_; }
  void clear_changes() noexcept { map_.clear_changes(); }
  [[nodiscard]] Stage stage() const noexcept { return stage_; }
  [[nodiscard]] TroubleShooter trouble_shooter() const noexcept { return mode_; }
  // Events of the wall-following stage, for reports and tests.
  [[nodiscard]] std::uint32_t sight_losses() const noexcept { return losses_; }
  [[nodiscard]] std::uint32_t causes_found() const noexcept { return causes_; }
  [[nodiscard]] std::uint32_t meetings() const noexcept { return meetings_; }
  [[nodiscard]] std::uint64_t wall_stage_ticks() const noexcept { return wall_ticks_; }

private:
  std::array<std::int8_t, 2> wall_step(const TeamObservation& obs);
  std::array<std::int8_t, 2> end_wall_stage(kernel::Cell a, kernel::Cell b);
  void build_seek_path(kernel::Cell from, kernel::Cell to);
  int find_cause(kernel::Cell b) const;

  std::int32_t width_, height_;
  ExplorationMap map_;
  FrontierCompletion completion_;
  Stage stage_ = Stage::WallFollowing;
  TroubleShooter mode_ = TroubleShooter::FollowWalls;

  std::array<WallTracer, 2> tracer_{};
  std::array<WallTracer, 2> previous_tracer_{};
  std::array<kernel::Cell, 2> last_position_{};
  bool first_tick_ = true;
  bool sight_before_ = false;
  bool seek_pending_ = false;
  bool loop_closed_ = false;

  // The lost line, marked in a stamped grid so that a membership test is O(1).
  kernel::Grid<std::uint32_t> lost_mark_;
  std::uint32_t lost_generation_ = 0;
  std::vector<kernel::Cell> seek_path_;
  std::size_t seek_next_ = 0;

  // A's progress along its trace, and the tracing states it has been in (one bit per wall index).
  kernel::Grid<std::uint8_t> visited_;
  std::int64_t trace_index_ = 0;
  std::int64_t max_index_ = 0;
  std::uint64_t wall_ticks_ = 0;
  std::uint64_t last_progress_tick_ = 0;
  std::uint64_t progress_limit_;
  int blocked_ticks_ = 0;
  std::int64_t last_loss_index_ = -1;
  kernel::Cell last_loss_b_{-1, -1};
  // B's tracing states around the current cause, stamped per cause.
  kernel::Grid<std::uint32_t> b_stamp_;
  kernel::Grid<std::uint8_t> b_visited_;
  std::uint32_t b_generation_ = 0;
  // The blocked cells B has kept its hand on around the current cause, and those of every cause
  // it has gone around (never a cause again).
  kernel::Grid<std::uint32_t> wall_stamp_;
  kernel::Grid<std::uint8_t> circled_;
  std::vector<kernel::Cell> loop_walls_;
  // The cells B walked while following the walls counter-clockwise (step 2).
  kernel::Grid<std::uint8_t> b_traced_;

  std::uint32_t losses_ = 0, causes_ = 0, meetings_ = 0;
};

} // namespace antkit::los
