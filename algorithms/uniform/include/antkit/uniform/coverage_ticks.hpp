#pragma once
// Paper 004's tick loop, written once (issue 27): what run_coverage (coverage.hpp) runs for every
// algorithm on the host and run_step_turn (step_turn_world.hpp) runs for one step-turn wanderer on
// the Cortex-M image. Freestanding: a template over the world and the team, no allocation, no
// exception.
//
// A world answers robot_count(), complete(), bearing(i), turn(i, eighths), move(i, bearing) (faces
// the bearing, then steps; false and nothing happens when the rules forbid it), view(i) and
// hash_state(hash) as CoverageWorld does; a team answers command(i) -> Command for robot i.
#include <antkit/kernel/hash.hpp>
#include <antkit/uniform/step_turn.hpp>
#include <cstddef>
#include <cstdint>

namespace antkit::uniform {

// Why a run stopped; coverage.hpp's StopReason by number.
enum class TickStop : std::uint8_t { Complete = 0, NoMove = 1, TimeLimit = 2 };

struct TickRun {
  std::uint64_t movements = 0; // ticks
  std::uint64_t moves = 0;     // commands that changed a pose
  std::uint64_t hash = 0;
  TickStop stop = TickStop::TimeLimit;
};

// The trace hash is TraceHash(0) over the algorithm's number, the robot count, and the world's
// state before the first tick and after every tick. Before every tick the run stops when the world
// is complete or `limit` ticks have run; in a tick every robot, in index order, takes its team's
// command (a forward move or a step views from the new cell); a tick in which every robot stops
// ends the run (NoMove). after_action(movements, i) after robot i's command is applied, in every
// tick including the last (NoMove) one, `movements` being the ticks completed before it; and
// after_tick(movements) after the start (0) and every tick that counts. testing/'s
// check_uniform_run checks the world after every action through after_action, so the checker
// replays this loop rather than a copy of it.
template <class World, class Team, class AfterAction, class AfterTick>
TickRun run_ticks(World& world, Team& team, std::uint8_t algorithm, std::uint64_t limit,
                  AfterAction&& after_action, AfterTick&& after_tick) {
  TickRun out;
  kernel::TraceHash hash;
  hash.add_u8(algorithm).add_u64(world.robot_count());
  world.hash_state(hash);
  after_tick(std::uint64_t{0});
  for (;;) {
    if (world.complete()) {
      out.stop = TickStop::Complete;
      break;
    }
    if (out.movements >= limit) {
      out.stop = TickStop::TimeLimit;
      break;
    }
    bool acted = false;
    for (std::size_t i = 0; i < world.robot_count(); ++i) {
      const Command cmd = team.command(i);
      bool done = false;
      switch (cmd.action) {
      case Action::TurnLeft:
        done = world.turn(i, 1);
        break;
      case Action::TurnRight:
        done = world.turn(i, -1);
        break;
      case Action::Forward:
        done = world.move(i, world.bearing(i));
        if (done) world.view(i);
        break;
      case Action::Step:
        done = world.move(i, cmd.bearing);
        if (done) world.view(i);
        break;
      case Action::Wait:
      case Action::Stop:
        break;
      }
      if (done) ++out.moves;
      if (cmd.action != Action::Stop) acted = true;
      after_action(out.movements, i);
    }
    if (!acted) {
      out.stop = TickStop::NoMove;
      break;
    }
    ++out.movements;
    world.hash_state(hash);
    after_tick(out.movements);
  }
  out.hash = hash.finish();
  return out;
}

// The same run, with nothing to do after an action.
template <class World, class Team, class AfterTick>
TickRun run_ticks(World& world, Team& team, std::uint8_t algorithm, std::uint64_t limit,
                  AfterTick&& after_tick) {
  return run_ticks(
      world, team, algorithm, limit, [](std::uint64_t, std::size_t) {}, after_tick);
}

} // namespace antkit::uniform
