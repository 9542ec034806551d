#pragma once
// The determinism matrix's Buffon scenarios on the Cortex-M image (scripts/determinism.sh, its
// cortex-m4 configuration): determinism/scenarios.cpp's buffon/<arena>/seed<S> hashes
// run_trials over trials 0 .. 3 into TraceHash(0), one word per trial's hash in trial order. Its
// input to the chip is mcu_input.hpp's, byte for byte, but for the magic "ANTKBUF4": the chip
// runs those four trials (run_fixed_trial) and prints their digest last, as "hash". Freestanding.
#include <antkit/buffon/mcu_input.hpp>
#include <cstdint>

namespace antkit::buffon {

inline constexpr char kMcuBuffonDigestMagic[8] = {'A', 'N', 'T', 'K', 'B', 'U', 'F', '4'};
inline constexpr std::uint64_t kMcuBuffonDigestTrials = 4;

} // namespace antkit::buffon
