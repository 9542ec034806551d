// Fuzz target: the WKT reader (geometry/src/wkt.cpp) and everything an accepted arena feeds.
// Bad input must be an InputError; an accepted arena must round-trip exactly through the writer
// (a mismatch traps, so libFuzzer reports it), measure, convert to fixed-point walls and
// rasterize without failing any other way.
#include <algorithm>
#include <antkit/geometry/arena.hpp>
#include <antkit/geometry/arena_raster.hpp>
#include <antkit/geometry/wkt.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace antkit::geometry;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const Arena arena = read_wkt(text, "fuzz");
    const std::string written = write_wkt(arena);
    if (!(read_wkt(written, "round-trip") == arena)) __builtin_trap();
    if (!(arena.area() > 0) || arena.area_exact().empty()) __builtin_trap();
    (void)arena.perimeter();
    try {
      if (arena.walls_fx().size() != arena.vertex_count()) __builtin_trap();
    } catch (const antkit::kernel::InputError&) {
      // A coordinate just below 32768 can round up to 2^31 raw units: refused, not wrapped.
    }
    // A power-of-two cell size that gives at most about 64 cells across, so every input
    // rasterizes quickly.
    const auto box = arena.bbox();
    const double extent = std::max(box.xmax - box.xmin, box.ymax - box.ymin);
    std::int64_t num = 1, den = 1;
    while (static_cast<double>(num) / static_cast<double>(den) * 64 < extent && num < (1 << 20))
      num *= 2;
    while (static_cast<double>(num) / static_cast<double>(den) * 32 > extent && den < (1 << 19))
      den *= 2;
    const auto raster = rasterize(arena, CellSize(num, den), std::size_t{1} << 16);
    if (raster.grid.empty()) __builtin_trap();
  } catch (const antkit::kernel::InputError&) {
  }
  return 0;
}
