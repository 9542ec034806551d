// The fast frontier search (issue 31: within 5 times A* where it was 65 times) makes the same
// decisions as the search it replaced (frontier_reference.hpp): both teams are stepped side by side
// on two copies of one world, and every command and every target must be the same, on random maps,
// team sizes, sensor ranges and weights (including weights for which the search cannot stop early).
#include "frontier_reference.hpp"

#include <antkit/kernel/input_error.hpp>
#include <antkit/uniform/frontier_coverage.hpp>
#include <antkit/uniform/scenario.hpp>
#include <antkit/uniform/world.hpp>
#include <array>
#include <catch2/catch.hpp>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>
#include <sstream>
#include <string>

using namespace antkit;
using namespace antkit::uniform;

namespace {

struct Lockstep {
  std::string difference; // empty when the teams agreed throughout
  std::uint64_t ticks = 0;
  bool complete = false;
};

Lockstep lockstep(const kernel::OccupancyGrid& map, const std::vector<Pose>& poses,
                  std::int32_t sensor, frontier::Weights weights, std::uint64_t seed,
                  std::uint64_t limit) {
  CoverageWorld fast_world(map, poses, sensor);
  CoverageWorld ref_world(map, poses, sensor);
  FrontierCoverage fast(seed, 3, fast_world, weights);
  testing::FrontierReference ref(seed, 3, ref_world, weights);
  Lockstep out;
  for (; out.ticks < limit && !fast_world.complete(); ++out.ticks) {
    bool acted = false;
    for (std::size_t i = 0; i < fast_world.robot_count(); ++i) {
      const Command a = fast.step({i, &fast_world});
      const Command b = ref.step({i, &ref_world});
      if (a != b || fast.target(i) != ref.target(i)) {
        std::ostringstream s;
        s << "tick " << out.ticks << ", robot " << i << ": the fast search says action "
          << static_cast<int>(a.action) << " bearing " << static_cast<int>(a.bearing)
          << ", the reference action " << static_cast<int>(b.action) << " bearing "
          << static_cast<int>(b.bearing)
          << (fast.target(i) != ref.target(i) ? " (targets differ)" : "");
        out.difference = s.str();
        return out;
      }
      if (a.action == Action::Step) {
        if (fast_world.move(i, a.bearing)) fast_world.view(i);
        if (ref_world.move(i, b.bearing)) ref_world.view(i);
      }
      if (a.action != Action::Stop) acted = true;
    }
    if (!acted) break;
  }
  out.complete = fast_world.complete();
  return out;
}

// Weights: the default, others for which the bounds hold, and some for which the search cannot
// stop early (w3 < 0, w2 = 0) or I does not help (w1 <= 0).
constexpr std::array<frontier::Weights, 9> kWeights{{{1, 1, 0},
                                                     {2, 1, 0},
                                                     {1, 3, 0},
                                                     {1, 1, 1},
                                                     {3, 2, 5},
                                                     {1, 1, -1},
                                                     {1, 0, 0},
                                                     {0, 1, 0},
                                                     {-1, 1, 0}}};

} // namespace

TEST_CASE("frontier: the fast search decides as the reference search on random worlds",
          "[uniform][property]") {
  rc::prop("same commands and targets, tick for tick", [] {
    const auto width = *rc::gen::inRange<std::int32_t>(3, 41);
    const auto height = *rc::gen::inRange<std::int32_t>(3, 41);
    const auto density =
        *rc::gen::element<std::uint32_t>(0u, 100'000u, 200'000u, 300'000u, 450'000u);
    const auto seed = *rc::gen::inRange<std::uint64_t>(0, 1'000'000);
    const auto robots = *rc::gen::inRange<std::size_t>(1, 6);
    const auto sensor = *rc::gen::inRange<std::int32_t>(1, 7);
    const auto weights = kWeights[*rc::gen::inRange<std::size_t>(0, kWeights.size())];
    const auto map = random_obstacles(width, height, density, seed, 0);
    std::vector<Pose> poses;
    try {
      poses = place_robots(map, robots, std::nullopt, seed, 0);
    } catch (const kernel::InputError&) {
      RC_DISCARD("the map's largest component holds fewer cells than robots");
    }
    const Lockstep run = lockstep(map, poses, sensor, weights, seed, 600);
    RC_LOG() << width << " x " << height << ", density " << density << " ppm, seed " << seed << ", "
             << robots << " robots, sensor " << sensor << ", weights " << weights.information << " "
             << weights.distance << " " << weights.nearness << ": " << run.ticks << " ticks\n";
    RC_ASSERT(run.difference == "");
  });
}

TEST_CASE("frontier: the fast search decides as the reference search - 128 x 128, 4 robots, "
          "20 % obstacles, every tick to full coverage",
          "[uniform][slow]") {
  const auto map = random_obstacles(128, 128, 200'000, 1, 0);
  const auto poses = place_robots(map, 4, std::nullopt, 1, 0);
  const Lockstep run = lockstep(map, poses, 5, {}, 1, 1'000'000);
  INFO(run.difference);
  CHECK(run.difference.empty());
  CHECK(run.complete);
  CHECK(run.ticks > 100);
}
