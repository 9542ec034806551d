#pragma once
// CRC-32 as zlib, PNG and MCAP compute it (reflected polynomial 0xEDB88320, initial and final value
// 0xFFFFFFFF), by slicing by 8. Chained: crc32(b, crc32(a)) == crc32(a + b); crc32("") == 0. The
// MCAP writer's record CRCs and the marker-floor robot's frame CRC (devices/stc_floor/link.hpp).
#include <cstdint>
#include <string_view>

namespace antkit::io {

std::uint32_t crc32(std::string_view bytes, std::uint32_t crc = 0) noexcept;

} // namespace antkit::io
