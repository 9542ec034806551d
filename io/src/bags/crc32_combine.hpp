#pragma once
// The CRC-32 (crc32.hpp) of a concatenation from the CRCs of its parts:
//   crc32_combine(crc32(a), crc32(b), b.size()) == crc32(a + b),
// so that the MCAP reader passes over an uncompressed chunk's bytes once for both the chunk's CRC
// and the data section's. Arithmetic in GF(2)[x] modulo the CRC's polynomial, bit-reflected as the
// CRC is (bit 31 is x^0): appending n zero bytes to a message multiplies its register by x^(8n).
#include <cstdint>

namespace antkit::io {

std::uint32_t crc32_combine(std::uint32_t crc_a, std::uint32_t crc_b,
                            std::uint64_t length_b) noexcept;

} // namespace antkit::io
