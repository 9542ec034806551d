#pragma once
// CRC-32 as zlib, PNG and MCAP compute it (reflected polynomial 0xEDB88320, initial and final value
// 0xFFFFFFFF). Chained: crc32(b, crc32(a)) == crc32(a + b); crc32("") == 0. The MCAP writer's and
// reader's record CRCs and the marker-floor robot's frame CRC (devices/stc_floor/link.hpp).
//
// On x86-64 with PCLMULQDQ (checked at run time) inputs of 64 bytes and more are folded with
// carry-less multiplication, about ten times the tables' speed; elsewhere, and for short inputs,
// slicing by 8. Both give the same value for every input (tests/io/test_crc32.cpp compares them).
#include <cstdint>
#include <string_view>

namespace antkit::io {

std::uint32_t crc32(std::string_view bytes, std::uint32_t crc = 0) noexcept;

// The CRC-32 of a concatenation from the CRCs of its parts:
//   crc32_combine(crc32(a), crc32(b), b.size()) == crc32(a + b),
// so that the MCAP writer and reader pass over a chunk's bytes once for both the chunk's CRC and
// the data section's. Arithmetic in GF(2)[x] modulo the CRC's polynomial, bit-reflected as the
// CRC is (bit 31 is x^0): appending n zero bytes to a message multiplies its register by x^(8n).
std::uint32_t crc32_combine(std::uint32_t crc_a, std::uint32_t crc_b,
                            std::uint64_t length_b) noexcept;

// Slicing by 8 alone, on every machine: the reference the folded CRC is tested against.
std::uint32_t crc32_portable(std::string_view bytes, std::uint32_t crc = 0) noexcept;

} // namespace antkit::io
