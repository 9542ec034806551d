#pragma once
// The host's writer of the Cortex-M image's step-turn wanderer input: the bytes
// wanderer_mcu_input.hpp reads on the chip, with its memory plan checked first, so a run too large
// for the chip is refused on the host before QEMU starts. Used by `antkit dev wanderer-mcu-input`
// (scripts/run-on-mcu.sh wanderer) and by the determinism matrix's cortex-m4 configuration
// (determinism/scenarios.cpp's uniform/rw/1robots scenarios). Host only.
#include <antkit/uniform/world.hpp>
#include <cstdint>
#include <vector>

namespace antkit::uniform {

// An input for the chip and the bytes its run plans in the chip's arena (plan_mcu_wanderer).
struct McuWandererInput {
  std::vector<std::uint8_t> bytes;
  std::uint64_t plan = 0;
};

// The input of one wanderer run in `world` (one robot: its pose is the start; the world's map,
// viewable cells and sensor footprint travel with it) with keyed streams (seed, trial) and a time
// limit of `limit` ticks: what `antkit cover --algo rw --robots 1` runs on the host. Throws
// kernel::InputError "robots" unless the world holds one robot, and "map" when the map's bits and
// the footprint do not fit the chip's arena (the message gives each part and the limit).
McuWandererInput mcu_wanderer_input(const CoverageWorld& world, std::uint64_t seed,
                                    std::uint64_t trial, std::uint64_t limit);

} // namespace antkit::uniform
