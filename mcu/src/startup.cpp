// The Cortex-M image's start: the vector table (initial stack pointer and reset handler; every
// fault ends the emulation with status 3 and a message; SysTick counts its wraps, ticks.cpp), then
// the C++ run-time set-up done by hand (no C library start files: -nostartfiles): the FPU switched
// on, .data copied from flash, .bss cleared, static constructors run, main called, its status
// returned through semihosting.
#include "semihost.hpp"

#include <cstdint>

extern "C" {
extern std::uint32_t _data_load, _data_start, _data_end, _bss_start, _bss_end, _stack_top;
extern void (*__init_array_start[])();
extern void (*__init_array_end[])();
[[noreturn]] void antkit_reset();
[[noreturn]] void antkit_fault();
void antkit_systick(); // ticks.cpp
}

int main();

namespace {
using Handler = void (*)();
}

extern "C" __attribute__((section(".vectors"), used)) const Handler antkit_vectors[16] = {
    reinterpret_cast<Handler>(&_stack_top),
    antkit_reset,
    antkit_fault, // NMI
    antkit_fault, // HardFault
    antkit_fault, // MemManage
    antkit_fault, // BusFault
    antkit_fault, // UsageFault
    nullptr,
    nullptr,
    nullptr,
    nullptr,
    antkit_fault, // SVCall
    antkit_fault, // DebugMonitor
    nullptr,
    antkit_fault, // PendSV
    antkit_systick,
};

extern "C" void antkit_reset() {
  // CPACR: full access to CP10 and CP11, the FPU (the image is built for -mfloat-abi=hard).
  auto* const cpacr = reinterpret_cast<volatile std::uint32_t*>(0xE000ED88u);
  *cpacr = *cpacr | (0xFu << 20);
  asm volatile("dsb\n isb" ::: "memory");
  for (std::uint32_t *from = &_data_load, *to = &_data_start; to < &_data_end;) *to++ = *from++;
  for (std::uint32_t* p = &_bss_start; p < &_bss_end;) *p++ = 0;
  for (auto* f = __init_array_start; f < __init_array_end; ++f) (*f)();
  antkit::mcu::exit(static_cast<std::uint32_t>(main()));
}

extern "C" void antkit_fault() {
  static const char message[] = "antkit mcu: processor fault\n";
  antkit::mcu::semihost(antkit::mcu::Sys::Write0, message);
  antkit::mcu::exit(3);
}
