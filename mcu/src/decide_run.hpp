#pragma once
// The ant-like STC decision on the chip over its whole input domain (decide_run.cpp; issue 41).
#include <cstdint>

namespace antkit::mcu {

// The number of inputs of the decision: 4 quadrants x 2 `done` x 16^6 masks (free, here and the
// four neighbours'), numbered as proofs/tie/ant_stc_tie.cpp enumerates them (decide_run.cpp).
inline constexpr std::uint32_t kDecideInputs = 4u * 2u * (1u << 24);

// Runs the decision on inputs [first, first + count) of that numbering and prints their digest
// as JSON; `flip` (an input number, or -1) changes the chip's answer on that input (the tooth).
// `args` is the rest of the semihosting command line: "FIRST COUNT [FLIP]". Returns the exit status
// (0 ran, 2 bad arguments).
int run_decide(const char* args);

} // namespace antkit::mcu
