#pragma once
// One Buffon trial (buffon_run.cpp), one Randomized Search walk (rs_run.cpp) or one step-turn
// wanderer run (wanderer_run.cpp) on the chip.
#include <antkit/kernel/segment.hpp>
#include <cstddef>
#include <cstdint>

namespace antkit::mcu {

// Runs the trial whose input (buffon/mcu_input.hpp) is open as `file`, of which the first `got`
// bytes were already read into `head`, in the `bytes` of `arena` (8-byte aligned). Prints the JSON
// object or the refusal; returns the exit status (0 ran, 2 bad input).
int run_buffon(const char* path, std::int32_t file, std::int32_t size, const std::uint8_t* head,
               std::size_t got, std::uint8_t* arena, std::size_t bytes);

// The same for an RS walk (buffon/rs_mcu_input.hpp).
int run_rs(const char* path, std::int32_t file, std::int32_t size, const std::uint8_t* head,
           std::size_t got, std::uint8_t* arena, std::size_t bytes);

// One step-turn wanderer run (wanderer_run.cpp; uniform/wanderer_mcu_input.hpp), likewise.
int run_wanderer(const char* path, std::int32_t file, std::int32_t size, const std::uint8_t* head,
                 std::size_t got, std::uint8_t* arena, std::size_t bytes);

// Reads `count` walls (buffon/mcu_input.hpp's 16 bytes each) into `walls`: first those among the
// `got` bytes of `head` after its 40-byte header, then the file's. False when the file ends first.
bool read_walls(std::int32_t file, const std::uint8_t* head, std::size_t got, std::uint32_t count,
                kernel::FxSegment* walls);

} // namespace antkit::mcu
