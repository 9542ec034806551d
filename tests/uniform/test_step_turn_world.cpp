// The chip's one-robot world (step_turn_world.hpp) on the host (issue 27): over the map's bits and
// the host's SensorFootprint, StepTurnWorld with StepTurnCore must give run_coverage's random
// wanderer result for one robot, hash for hash, since both run coverage_rules.hpp's rules and
// coverage_ticks.hpp's loop.
#include <antkit/uniform/coverage.hpp>
#include <antkit/uniform/scenario.hpp>
#include <antkit/uniform/step_turn_world.hpp>
#include <catch2/catch.hpp>
#include <cstdint>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>
#include <vector>

using namespace antkit;
using namespace antkit::uniform;

TEST_CASE("StepTurnWorld with StepTurnCore is run_coverage's random wanderer for one robot",
          "[uniform][property]") {
  rc::prop("random maps, sensors, seeds and limits", [] {
    const auto w = *rc::gen::inRange(1, 24);
    const auto h = *rc::gen::inRange(1, 24);
    const auto ppm = *rc::gen::inRange<std::uint32_t>(0, 400'000);
    const auto seed = *rc::gen::inRange<std::uint64_t>(1, 1000);
    const auto trial = *rc::gen::inRange<std::uint64_t>(0, 4);
    const auto sensor = *rc::gen::inRange(0, 6);
    const auto limit = *rc::gen::inRange<std::uint64_t>(0, 4000);
    RC_PRE(obstacle_count(w, h, ppm) <
           static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h));
    const kernel::OccupancyGrid map = random_obstacles(w, h, ppm, seed, trial);
    const std::vector<Pose> poses = place_robots(map, 1, std::nullopt, seed, trial);
    CoverageWorld host(map, poses, sensor);
    const CoverageResult want = run_coverage(host, Algorithm::RandomWanderer, seed, trial, limit);

    std::vector<std::uint8_t> free_bits(StepTurnWorld::bytes(w, h), 0), viewed(free_bits.size());
    for (std::size_t k = 0; k < map.size(); ++k)
      if (map.cells()[k] == kernel::Occupancy::Free)
        free_bits[k / 8] = static_cast<std::uint8_t>(free_bits[k / 8] | (1u << (k % 8)));
    const SensorFootprint footprint(sensor);
    std::vector<StepTurnRay> rays;
    for (const auto& r : footprint.rays())
      rays.push_back({static_cast<std::int16_t>(r.offset.x), static_cast<std::int16_t>(r.offset.y),
                      r.first, r.count});
    std::vector<StepTurnOffset> between;
    for (const kernel::Cell c : footprint.between())
      between.push_back({static_cast<std::int16_t>(c.x), static_cast<std::int16_t>(c.y)});
    CoverageWorld fresh(map, poses, sensor);
    StepTurnWorld chip;
    chip.init(w, h, free_bits.data(), viewed.data(), rays, between, poses[0].cell, poses[0].bearing,
              fresh.viewable());
    StepTurnCore wanderer(seed, trial, 0);
    const StepTurnResult got = run_step_turn(chip, wanderer, limit);
    RC_ASSERT(got.hash == want.hash);
    RC_ASSERT(got.movements == want.movements);
    RC_ASSERT(got.moves == want.moves);
    RC_ASSERT(got.viewed == want.viewed);
    RC_ASSERT(got.viewable == want.viewable);
    RC_ASSERT(static_cast<int>(got.stop) == static_cast<int>(want.stop));
    RC_ASSERT(chip.cell() == host.robot(0).cell);
    RC_ASSERT(chip.bearing() == host.robot(0).bearing);
  });
}
