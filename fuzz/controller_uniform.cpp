// Fuzz target: paper 004's team controllers (uniform::RandomWanderer, PrimaryMovement,
// AStarCoverage plain and coordinated, FrontierCoverage) on a world read from the fuzzer's bytes:
// a map up to 20 x 20 (free, blocked and unknown cells), one to six robots anywhere (a start off
// the free cells, or two robots on one cell, must be a located kernel::InputError), a sensor range
// 0..5 (frontier coverage rejects 0 with an InputError). The controllers read the shared world, so
// the observations no simulator would produce come from a body that does not do as it is told:
// the bytes make it drop a command, push a robot one cell aside, turn it, or view from a robot
// that did not move.
//
// Every step checks the command is valid for the body: the action is one of the six, a Step's
// bearing is 0..7, and a Forward or a Step is one the world allows at that moment (the target on
// the map, free, not occupied, no corner cut: the controllers check before they ask). A twin team
// on a twin world, fed the same perturbations, must answer the same commands.
#include "fuzz_bytes.hpp"

#include <antkit/kernel/grid.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/uniform/controllers.hpp>
#include <antkit/uniform/frontier_coverage.hpp>
#include <antkit/uniform/scenario.hpp>
#include <antkit/uniform/world.hpp>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace {

using namespace antkit;
using kernel::Cell;
using uniform::Action;

constexpr std::size_t kMaxTicks = 400;

void check(const uniform::CoverageWorld& world, std::size_t i, const uniform::Command& c) {
  ANTKIT_FUZZ_REQUIRE(static_cast<unsigned>(c.action) <= static_cast<unsigned>(Action::Stop));
  const auto& pose = world.robot(i);
  ANTKIT_FUZZ_REQUIRE(c.action != Action::Forward || world.can_step(pose.cell, pose.bearing));
  ANTKIT_FUZZ_REQUIRE(c.action != Action::Step ||
                      (c.bearing <= 7 && world.can_step(pose.cell, c.bearing)));
}

void carry_out(uniform::CoverageWorld& world, std::size_t i, const uniform::Command& c) {
  switch (c.action) {
  case Action::TurnLeft:
    world.turn(i, 1);
    break;
  case Action::TurnRight:
    world.turn(i, -1);
    break;
  case Action::Forward:
    if (world.move(i, world.robot(i).bearing)) world.view(i);
    break;
  case Action::Step:
    if (world.move(i, c.bearing)) world.view(i);
    break;
  case Action::Wait:
  case Action::Stop:
    break;
  }
}

template <class Team>
void run(fuzzing::Bytes& in, Team& team_a, Team& team_b, uniform::CoverageWorld& a,
         uniform::CoverageWorld& b) {
  for (std::size_t tick = 0; tick < kMaxTicks && !in.empty() && !a.complete(); ++tick) {
    for (std::size_t i = 0; i < a.robot_count(); ++i) {
      const uniform::Command c = team_a.step({i, &a});
      ANTKIT_FUZZ_REQUIRE(c == team_b.step({i, &b}));
      check(a, i, c);
      const unsigned lie = in.below(16);
      switch (lie) {
      case 0:
        break;  // the command is dropped
      case 1: { // pushed one cell aside, then the command
        const auto bearing = static_cast<std::uint8_t>(in.below(8));
        a.move(i, bearing);
        b.move(i, bearing);
        carry_out(a, i, c);
        carry_out(b, i, c);
        break;
      }
      case 2: // turned, and the command dropped
        a.turn(i, 3);
        b.turn(i, 3);
        break;
      case 3: // a view without a move
        a.view(i);
        b.view(i);
        break;
      default:
        carry_out(a, i, c);
        carry_out(b, i, c);
        break;
      }
    }
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzzing::Bytes in(data, size);
  const unsigned which = in.below(5);
  const auto w = static_cast<std::int32_t>(1 + in.below(20));
  const auto h = static_cast<std::int32_t>(1 + in.below(20));
  kernel::OccupancyGrid map(w, h, kernel::Occupancy::Free);
  const unsigned density = in.below(5);
  for (std::int32_t y = 0; y < h; ++y)
    for (std::int32_t x = 0; x < w; ++x)
      if (in.below(8) < density)
        map[{x, y}] = in.u8() & 1 ? kernel::Occupancy::Blocked : kernel::Occupancy::Unknown;
  std::vector<uniform::Pose> robots(1 + in.below(6));
  for (auto& r : robots) {
    r.cell = {static_cast<std::int32_t>(in.below(22)) - 1,
              static_cast<std::int32_t>(in.below(22)) - 1};
    r.bearing = static_cast<std::uint8_t>(in.below(8));
  }
  const auto range = static_cast<std::int32_t>(in.below(6));
  const std::uint64_t seed = in.u8();
  std::optional<uniform::CoverageWorld> a, b;
  try {
    a.emplace(map, robots, range);
    b.emplace(map, robots, range);
  } catch (const kernel::InputError& e) {
    ANTKIT_FUZZ_REQUIRE(!e.where().empty());
    return 0;
  }
  const std::size_t n = robots.size();
  switch (which) {
  case 0: {
    uniform::RandomWanderer ta(seed, 0, n), tb(seed, 0, n);
    run(in, ta, tb, *a, *b);
    break;
  }
  case 1: {
    uniform::PrimaryMovement ta(n), tb(n);
    run(in, ta, tb, *a, *b);
    break;
  }
  case 2:
  case 3: {
    uniform::AStarCoverage ta(seed, 0, n, which == 3), tb(seed, 0, n, which == 3);
    run(in, ta, tb, *a, *b);
    break;
  }
  default: {
    try {
      uniform::FrontierCoverage ta(seed, 0, *a), tb(seed, 0, *b);
      run(in, ta, tb, *a, *b);
    } catch (const kernel::InputError& e) {
      ANTKIT_FUZZ_REQUIRE(range == 0 && !e.where().empty());
    }
    break;
  }
  }
  return 0;
}
