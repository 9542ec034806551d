// Fuzz target: the Cortex-M image's input readers (issue 27), run on the host as the chip runs
// them. The chip's program is chosen by the magic, as mcu/src/main.cpp chooses it:
// - STC (stc/mcu_input.hpp): an accepted header's floor and memory fit the image's arena;
// - Buffon and RS (buffon/mcu_input.hpp, rs_mcu_input.hpp): an accepted header's walls fit the
//   arena; when the bytes hold them, the walls are read and the trial (run_fixed_trial) or the
//   walk (prepare_fixed_rs, run_fixed_rs) runs in a buffer of the arena's size, at most 64 steps,
//   and either runs or says why not (any wall, body and width: the world's checks refuse);
// - the wanderer (uniform/wanderer_mcu_input.hpp): an accepted header's plan fits the arena; when
//   the file's length is the header's, the bits, rays and cells between are read into the arena as
//   the chip lays them out, check_mcu_wanderer_records runs, and records it accepts run
//   StepTurnWorld for at most 256 ticks, every read on the map (the replay binary runs under the
//   sanitizers in the debug preset).
#include "fuzz_bytes.hpp"

#include <antkit/buffon/fixed_trial.hpp>
#include <antkit/buffon/mcu_digest_input.hpp>
#include <antkit/buffon/mcu_input.hpp>
#include <antkit/buffon/randomized_search.hpp>
#include <antkit/buffon/rs_mcu_input.hpp>
#include <antkit/stc/mcu_input.hpp>
#include <antkit/uniform/step_turn.hpp>
#include <antkit/uniform/step_turn_world.hpp>
#include <antkit/uniform/wanderer_mcu_input.hpp>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace {

using namespace antkit;

bool has_magic(const std::uint8_t* data, std::size_t size, const char (&magic)[8]) {
  return size >= 8 && std::memcmp(data, magic, 8) == 0;
}

// The arena, 8-byte aligned, as the chip's static buffer.
std::vector<std::uint64_t>& arena() {
  static std::vector<std::uint64_t> words(buffon::kMcuArenaBytes / 8);
  return words;
}
std::uint8_t* arena_bytes() {
  return reinterpret_cast<std::uint8_t*>(arena().data());
}

std::vector<kernel::FxSegment> walls_of(const std::uint8_t* data, std::size_t size,
                                        std::size_t header, std::uint32_t walls) {
  std::vector<kernel::FxSegment> out;
  if (size < header + std::size_t{walls} * buffon::kMcuWallBytes) return out;
  for (std::uint32_t i = 0; i < walls; ++i) out.push_back(buffon::read_mcu_wall(data + header, i));
  return out;
}

void buffon_trial(const std::uint8_t* data, std::size_t size) {
  buffon::McuBuffonRun run;
  if (buffon::read_mcu_buffon_header(data, size, run) != buffon::McuBuffonError::None) return;
  ANTKIT_FUZZ_REQUIRE(run.walls >= 1 &&
                      run.walls <= buffon::kMcuArenaBytes / buffon::kMcuWallBytes);
  ANTKIT_FUZZ_REQUIRE(run.steps >= 1 && run.steps <= buffon::kMcuMaxSteps);
  const auto walls = walls_of(data, size, buffon::kMcuBuffonHeaderBytes, run.walls);
  if (walls.empty()) return;
  const std::uint64_t at = buffon::mcu_walls_bytes(run.walls);
  buffon::FixedTrialResult r;
  const char* why = buffon::run_fixed_trial(walls, run.body, run.width, run.seed, 0,
                                            run.steps < 64 ? run.steps : 64,
                                            {arena_bytes() + at, buffon::kMcuArenaBytes - at}, r);
  if (why == nullptr) ANTKIT_FUZZ_REQUIRE(at + r.bytes <= buffon::kMcuArenaBytes);
}

void rs_walk(const std::uint8_t* data, std::size_t size) {
  buffon::McuRsRun run;
  if (buffon::read_mcu_rs_header(data, size, run) != buffon::McuBuffonError::None) return;
  const auto walls = walls_of(data, size, buffon::kMcuRsHeaderBytes, run.walls);
  if (walls.empty()) return;
  const std::uint64_t at = buffon::mcu_walls_bytes(run.walls);
  buffon::FixedRs rs;
  if (buffon::prepare_fixed_rs(walls, run.body, run.seed, 0,
                               {arena_bytes() + at, buffon::kMcuArenaBytes - at}, rs) != nullptr)
    return;
  const buffon::FixedRsResult r =
      buffon::run_fixed_rs(rs, run.seed, 0, run.steps < 64 ? run.steps : 64);
  ANTKIT_FUZZ_REQUIRE(at + r.bytes <= buffon::kMcuArenaBytes);
}

void wanderer(const std::uint8_t* data, std::size_t size) {
  uniform::McuWandererRun run;
  if (uniform::read_mcu_wanderer_header(data, size, run) != uniform::McuWandererError::None) return;
  const uniform::McuWandererPlan plan = uniform::plan_mcu_wanderer(run);
  ANTKIT_FUZZ_REQUIRE(plan.total <= uniform::kMcuWandererArenaBytes);
  if (size != uniform::mcu_wanderer_file_bytes(run)) return; // the chip refuses another length
  std::uint8_t* a = arena_bytes();
  const std::uint64_t bits = uniform::StepTurnWorld::bytes(run.width, run.height);
  const std::uint8_t* p = data + uniform::kMcuWandererHeaderBytes;
  std::memcpy(a + plan.free_at, p, bits);
  std::memset(a + plan.viewed_at, 0, bits);
  p += bits;
  auto* rays = reinterpret_cast<uniform::StepTurnRay*>(a + plan.rays_at);
  auto* between = reinterpret_cast<uniform::StepTurnOffset*>(a + plan.between_at);
  for (std::uint32_t i = 0; i < run.rays; ++i, p += uniform::kMcuRayBytes)
    rays[i] = uniform::read_mcu_ray(p);
  for (std::uint32_t i = 0; i < run.between; ++i, p += uniform::kMcuOffsetBytes)
    between[i] = uniform::read_mcu_offset(p);
  if (uniform::check_mcu_wanderer_records(run, a + plan.free_at, {rays, run.rays},
                                          {between, run.between}) != nullptr)
    return;
  uniform::StepTurnWorld world;
  world.init(run.width, run.height, a + plan.free_at, a + plan.viewed_at, {rays, run.rays},
             {between, run.between}, run.start, run.bearing, run.viewable);
  uniform::StepTurnCore core(run.seed, run.trial, 0);
  const uniform::StepTurnResult r =
      uniform::run_step_turn(world, core, run.limit < 256 ? run.limit : 256);
  ANTKIT_FUZZ_REQUIRE(r.viewed <= std::uint64_t{bits} * 8);
}

void stc_floor(const std::uint8_t* data, std::size_t size) {
  stc::McuRun run;
  if (stc::read_mcu_header(data, size, run) != stc::McuInputError::None) return;
  ANTKIT_FUZZ_REQUIRE(stc::mcu_bytes(run) <= stc::kMcuFloorBytes);
  ANTKIT_FUZZ_REQUIRE(run.width >= 2 && run.height >= 2 && run.width <= stc::kMcuMaxSide &&
                      run.height <= stc::kMcuMaxSide);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (has_magic(data, size, buffon::kMcuBuffonMagic) ||
      has_magic(data, size, buffon::kMcuBuffonDigestMagic)) {
    // The digest program reads the trial's header with its own magic (mcu_digest_input.hpp).
    std::vector<std::uint8_t> copy(data, data + size);
    std::memcpy(copy.data(), buffon::kMcuBuffonMagic, 8);
    buffon_trial(copy.data(), copy.size());
  } else if (has_magic(data, size, buffon::kMcuRsMagic)) {
    rs_walk(data, size);
  } else if (has_magic(data, size, uniform::kMcuWandererMagic)) {
    wanderer(data, size);
  } else {
    stc_floor(data, size);
  }
  return 0;
}
