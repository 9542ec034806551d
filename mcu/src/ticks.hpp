#pragma once
// The Cortex-M4's SysTick as a 64-bit counter of processor clock ticks (the core clock source,
// wraps counted by its interrupt, startup.cpp). Under QEMU with -icount shift=0 the processor clock
// is virtual time driven by the instructions executed, so ticks measure instructions: what
// scripts/run-on-mcu.sh --icount reports. Without -icount they follow the host's clock and mean
// nothing.
#include <cstdint>

namespace antkit::mcu {

void ticks_start() noexcept;
// Ticks since ticks_start().
std::uint64_t ticks_now() noexcept;

} // namespace antkit::mcu
