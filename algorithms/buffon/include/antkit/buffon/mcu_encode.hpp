#pragma once
// The host's writers of the Cortex-M image's Buffon and Randomized Search inputs: the bytes that
// mcu_input.hpp, mcu_digest_input.hpp and rs_mcu_input.hpp read on the chip, with the same memory
// plan checked first, so a run too large for the chip is refused on the host before QEMU starts.
// Used by `antkit dev buffon-mcu-input` and `dev rs-mcu-input` (scripts/run-on-mcu.sh) and by the
// determinism matrix's cortex-m4 configuration (determinism/scenarios.cpp). Host only.
//
// Errors (kernel::InputError, in the library's words): "steps per visit" ("steps" for RS) outside
// [1, kMcuMaxSteps], which the chip would refuse; "arena" when the walls, the world's buckets
// and the raster do not fit the chip's arena whatever the steps (the message gives each part and
// the limit); "steps per visit" when the arena fits but visit 1's trail and crossing index for
// that many steps do not (the message says about how many fit).
#include <antkit/buffon/world.hpp>
#include <antkit/kernel/fixed.hpp>
#include <cstdint>
#include <vector>

namespace antkit::buffon {

// An input for the chip and the bytes its run plans in the chip's arena (at most kMcuArenaBytes).
struct McuInput {
  std::vector<std::uint8_t> bytes;
  std::uint64_t plan = 0;
  std::uint64_t walls = 0;
};

// Which of the chip's Buffon programs reads the input: one trial, printed in full (mcu_input.hpp,
// `antkit buffon --trials 1`'s trial), or four trials' digest (mcu_digest_input.hpp, the
// determinism matrix's buffon/<arena>/seed<S>). The bytes differ only in the magic.
enum class McuBuffonProgram : std::uint8_t { Trial, Digest };

// Trial 0's input: `world`'s walls and body (its noise and speed), the pheromone trail `width`,
// `seed` and `steps` per visit.
McuInput mcu_buffon_input(const World& world, Fx width, std::uint64_t seed, std::int64_t steps,
                          McuBuffonProgram program = McuBuffonProgram::Trial);

// One RS walk's input (trial 0's walk, checkpoints.hpp run_rs): `world`'s walls and body, `seed`
// and `steps`. "arena" when the walls, buckets and RS's raster do not fit the chip.
McuInput mcu_rs_input(const World& world, std::uint64_t seed, std::int64_t steps);

} // namespace antkit::buffon
