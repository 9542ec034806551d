// Fuzz target: paper 001's two team controllers (los::FastWallFollow, los::FrontierTeam with and
// without the line sweep) fed observations read from the fuzzer's bytes. Two modes:
//  * a body: a true map read from the bytes and the simulated TwoRobotWorld carrying the commands
//    out, with the bytes deciding when the observation lies: scans flipped cell by cell, every
//    neighbour a wall, the line of sight inverted, a robot seen somewhere else on the grid, both
//    robots on one cell;
//  * no body: every observation straight from the bytes (positions anywhere on the grid, jumps,
//    shared cells, contradicting scans).
// Positions stay on the grid: that is the observation's precondition (ExplorationMap::sweep_line),
// and a body produces positions only from cells it stands on.
//
// Every step checks the command is valid for the body: each move is kStay or a neighbour index
// 0..7, and a move goes to a cell on the grid that the controller's own map does not hold as an
// obstacle (the controllers never ask to enter a cell they know to be blocked). A twin controller
// fed the same observations must answer the same commands.
#include "fuzz_bytes.hpp"

#include <antkit/kernel/grid.hpp>
#include <antkit/los/fast_wall_follow.hpp>
#include <antkit/los/frontier_team.hpp>
#include <antkit/los/team.hpp>
#include <cstddef>
#include <cstdint>
#include <optional>

namespace {

using namespace antkit;
using kernel::Cell;

constexpr std::size_t kMaxTicks = 3000;

Cell any_cell(fuzzing::Bytes& in, std::int32_t w, std::int32_t h) {
  return {static_cast<std::int32_t>(in.below(static_cast<unsigned>(w))),
          static_cast<std::int32_t>(in.below(static_cast<unsigned>(h)))};
}

// The bytes' lies about one observation (or none).
void perturb(fuzzing::Bytes& in, los::TeamObservation& o, std::int32_t w, std::int32_t h) {
  switch (in.below(16)) {
  case 0: // a scan flipped cell by cell
    for (auto& s : o.robots[in.below(2)].neighbours) s = static_cast<los::Sensed>(in.below(4));
    break;
  case 1: // walls all round
    for (auto& s : o.robots[in.below(2)].neighbours) s = los::Sensed::Obstacle;
    break;
  case 2:
    o.line_of_sight = !o.line_of_sight;
    break;
  case 3:
    o.robots[in.below(2)].position = any_cell(in, w, h);
    break;
  case 4:
    o.robots[1].position = o.robots[0].position;
    break; // robots on the same cell
  case 5:  // everything outside
    for (auto& s : o.robots[in.below(2)].neighbours) s = los::Sensed::Outside;
    break;
  default:
    break; // the truth
  }
}

template <class Team>
void check_command(const Team& team, const los::TeamObservation& o, const los::TeamCommand& c) {
  for (std::size_t r = 0; r < 2; ++r) {
    const int m = c.move[r];
    if (m == los::kStay) continue;
    ANTKIT_FUZZ_REQUIRE(0 <= m && m <= 7);
    const Cell to = o.robots[r].position + kernel::kNeighbours8[static_cast<std::size_t>(m)];
    ANTKIT_FUZZ_REQUIRE(team.map().in_bounds(to));
    ANTKIT_FUZZ_REQUIRE(team.map().at(to) != los::CellState::O);
  }
}

template <class Team>
void run(fuzzing::Bytes& in, Team& a, Team& b, std::int32_t w, std::int32_t h, bool body) {
  kernel::OccupancyGrid truth(w, h, kernel::Occupancy::Free);
  std::optional<los::TwoRobotWorld> world;
  if (body) {
    for (std::int32_t y = 0; y < h; ++y)
      for (std::int32_t x = 0; x < w; ++x)
        if (in.below(4) == 0) truth[{x, y}] = kernel::Occupancy::Blocked;
    const Cell ra = any_cell(in, w, h);
    Cell rb = any_cell(in, w, h);
    if (rb == ra) rb = {(ra.x + 1) % w, ra.y};
    if (rb == ra) return; // a 1 x 1 grid holds one robot
    truth[ra] = kernel::Occupancy::Free;
    truth[rb] = kernel::Occupancy::Free;
    world.emplace(truth, ra, rb);
  }
  for (std::size_t tick = 0; tick < kMaxTicks && !in.empty(); ++tick) {
    los::TeamObservation o;
    if (world) {
      o = world->observe();
      perturb(in, o, w, h);
    } else {
      for (auto& r : o.robots) {
        r.position = any_cell(in, w, h);
        for (auto& s : r.neighbours) s = static_cast<los::Sensed>(in.below(4));
      }
      o.line_of_sight = (in.u8() & 1) != 0;
    }
    const los::TeamCommand c = a.step(o);
    const los::TeamCommand d = b.step(o);
    ANTKIT_FUZZ_REQUIRE(c.move == d.move && c.finished == d.finished);
    check_command(a, o, c);
    if (c.finished) break;
    if (world) world->apply(c);
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzzing::Bytes in(data, size);
  const unsigned which = in.below(3);
  const bool body = (in.u8() & 1) != 0;
  const auto w = static_cast<std::int32_t>(1 + in.below(24));
  const auto h = static_cast<std::int32_t>(1 + in.below(24));
  if (which == 0) {
    los::FastWallFollow a(w, h), b(w, h);
    run(in, a, b, w, h, body);
  } else {
    los::FrontierTeamOptions options;
    options.line_of_sight = which == 1;
    los::FrontierTeam a(w, h, options), b(w, h, options);
    run(in, a, b, w, h, body);
  }
  return 0;
}
