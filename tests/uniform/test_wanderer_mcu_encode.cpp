// The host's writer of the chip's wanderer input (uniform/wanderer_mcu_encode.hpp) against the
// chip's reader (wanderer_mcu_input.hpp): what the host writes, the chip reads back, and the run
// the chip makes from those bytes alone (StepTurnWorld over the bits, rays and cells between read
// back, as mcu/src/wanderer_run.cpp lays them out) is run_coverage's random wanderer, hash for
// hash.
#include <antkit/kernel/input_error.hpp>
#include <antkit/uniform/coverage.hpp>
#include <antkit/uniform/scenario.hpp>
#include <antkit/uniform/step_turn.hpp>
#include <antkit/uniform/step_turn_world.hpp>
#include <antkit/uniform/wanderer_mcu_encode.hpp>
#include <antkit/uniform/wanderer_mcu_input.hpp>
#include <catch2/catch.hpp>
#include <cstdint>
#include <optional>
#include <rapidcheck/catch.h>
#include <string>
#include <vector>

using namespace antkit;
using namespace antkit::uniform;

TEST_CASE("the chip reads back what mcu_wanderer_input writes, and runs the host's wanderer",
          "[property][mcu]") {
  rc::prop("random maps, sensors, seeds and limits", [] {
    const auto w = *rc::gen::inRange(1, 40);
    const auto h = *rc::gen::inRange(1, 40);
    const auto ppm = *rc::gen::inRange<std::uint32_t>(0, 400'000);
    const auto seed = *rc::gen::inRange<std::uint64_t>(1, 1000);
    const auto trial = *rc::gen::inRange<std::uint64_t>(0, 4);
    const auto sensor = *rc::gen::inRange(0, 8);
    const auto limit = *rc::gen::inRange<std::uint64_t>(0, 4000);
    RC_PRE(obstacle_count(w, h, ppm) <
           static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h));
    const kernel::OccupancyGrid map = random_obstacles(w, h, ppm, seed, trial);
    const std::vector<Pose> poses = place_robots(map, 1, std::nullopt, seed, trial);
    const CoverageWorld fresh(map, poses, sensor);
    const McuWandererInput in = mcu_wanderer_input(fresh, seed, trial, limit);

    McuWandererRun run;
    const std::uint8_t* b = in.bytes.data();
    RC_ASSERT(read_mcu_wanderer_header(b, in.bytes.size(), run) == McuWandererError::None);
    RC_ASSERT(in.bytes.size() == mcu_wanderer_file_bytes(run));
    RC_ASSERT(in.plan == plan_mcu_wanderer(run).total);
    RC_ASSERT(run.seed == seed);
    RC_ASSERT(run.trial == trial);
    RC_ASSERT(run.limit == limit);
    RC_ASSERT(run.viewable == fresh.viewable());
    RC_ASSERT(run.width == w);
    RC_ASSERT(run.height == h);
    RC_ASSERT(run.start == poses[0].cell);
    RC_ASSERT(run.bearing == poses[0].bearing);
    RC_ASSERT(run.sensor == static_cast<std::uint32_t>(sensor));
    RC_ASSERT(run.rays == fresh.footprint().rays().size());
    RC_ASSERT(run.between == fresh.footprint().between().size());

    // The chip's world from the bytes alone.
    const std::size_t bits = StepTurnWorld::bytes(run.width, run.height);
    std::vector<std::uint8_t> free_bits(b + kMcuWandererHeaderBytes,
                                        b + kMcuWandererHeaderBytes + bits);
    std::vector<std::uint8_t> viewed(bits);
    std::vector<StepTurnRay> rays;
    const std::uint8_t* p = b + kMcuWandererHeaderBytes + bits;
    for (std::uint32_t i = 0; i < run.rays; ++i, p += kMcuRayBytes) rays.push_back(read_mcu_ray(p));
    std::vector<StepTurnOffset> between;
    for (std::uint32_t i = 0; i < run.between; ++i, p += kMcuOffsetBytes)
      between.push_back(read_mcu_offset(p));
    StepTurnWorld chip;
    chip.init(run.width, run.height, free_bits.data(), viewed.data(), rays, between, run.start,
              run.bearing, run.viewable);
    StepTurnCore wanderer(run.seed, run.trial, 0);
    const StepTurnResult got = run_step_turn(chip, wanderer, run.limit);

    CoverageWorld host(map, poses, sensor);
    const CoverageResult want = run_coverage(host, Algorithm::RandomWanderer, seed, trial, limit);
    RC_ASSERT(got.hash == want.hash);
    RC_ASSERT(got.viewed == want.viewed);
    RC_ASSERT(got.moves == want.moves);
  });
}

TEST_CASE("mcu_wanderer_input refuses what the chip cannot run, in the library's words",
          "[unit][mcu]") {
  const auto error = [](const CoverageWorld& world) {
    try {
      (void)mcu_wanderer_input(world, 1, 0, 100);
    } catch (const kernel::InputError& e) {
      return e.where() + ": " + e.message();
    }
    return std::string("no error");
  };
  const kernel::OccupancyGrid open = random_obstacles(12, 9, 0, 1, 0);
  CHECK(error(CoverageWorld(open, place_robots(open, 2, std::nullopt, 1, 0), 2)) ==
        "robots: the Cortex-M image runs one wanderer, not 2");
  // 700 x 700 cells: two bit planes of 61 250 bytes each exceed the 114 688-byte arena.
  const kernel::OccupancyGrid big = random_obstacles(700, 700, 0, 1, 0);
  const std::string e = error(CoverageWorld(big, place_robots(big, 1, std::nullopt, 1, 0), 1));
  CHECK(e.rfind("map: too large for the chip: the run needs", 0) == 0);
  CHECK(e.find("the chip's arena holds 114688 bytes") != std::string::npos);
}
