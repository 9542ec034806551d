#pragma once
// One Buffon trial on the chip (buffon_run.cpp).
#include <cstddef>
#include <cstdint>

namespace antkit::mcu {

// Runs the trial whose input (buffon/mcu_input.hpp) is open as `file`, of which the first `got`
// bytes were already read into `head`, in the `bytes` of `arena` (8-byte aligned). Prints the JSON
// object or the refusal; returns the exit status (0 ran, 2 bad input).
int run_buffon(const char* path, std::int32_t file, std::int32_t size, const std::uint8_t* head,
               std::size_t got, std::uint8_t* arena, std::size_t bytes);

} // namespace antkit::mcu
