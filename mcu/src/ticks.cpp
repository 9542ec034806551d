#include "ticks.hpp"

namespace {
struct SysTick {
  volatile std::uint32_t ctrl, load, val, calib;
};
SysTick* const systick = reinterpret_cast<SysTick*>(0xE000E010u);
volatile std::uint32_t g_wraps = 0;
constexpr std::uint32_t kReload = 0x00FFFFFFu;
} // namespace

extern "C" void antkit_systick() {
  g_wraps = g_wraps + 1;
}

namespace antkit::mcu {

void ticks_start() noexcept {
  systick->ctrl = 0;
  g_wraps = 0;
  systick->load = kReload;
  systick->val = 0;
  systick->ctrl = 0x7; // the processor clock, the wrap interrupt, enabled
}

std::uint64_t ticks_now() noexcept {
  for (;;) { // read the wraps, the counter, the wraps again: no wrap in between
    const std::uint32_t before = g_wraps;
    const std::uint32_t val = systick->val;
    if (g_wraps == before)
      return std::uint64_t{before} * (kReload + 1) + (kReload - (val & kReload));
  }
}

} // namespace antkit::mcu
