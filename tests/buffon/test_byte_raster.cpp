// ByteRasterCore::disk (randomized_search.hpp), which RS's footprint and the checkpoints' first
// visit stamp with: the cells it visits, and their order, are those of the definition, every cell
// of the box tested (a cell is in when its centre is within the radius: dx2^2 + dy2^2 <= 4 r^2 on
// the doubled offsets), for row runs and for the wide disks visited cell by cell.
#include <antkit/buffon/randomized_search.hpp>
#include <catch2/catch.hpp>
#include <cstdint>
#include <rapidcheck/catch.h>
#include <vector>

namespace buffon = antkit::buffon;
using antkit::kernel::Fx;
using antkit::kernel::FxPoint;

namespace {

// The cells the definition takes, row by row, each row left to right, as indices.
std::vector<std::int64_t> by_definition(const buffon::ByteRasterCore& g, FxPoint c,
                                        std::int64_t radius) {
  std::vector<std::int64_t> out;
  const std::int64_t cx = c.x.raw() - g.x0, cy = c.y.raw() - g.y0;
  for (std::int64_t j = 0; j < g.rows; ++j)
    for (std::int64_t i = 0; i < g.cols; ++i) {
      const std::int64_t dx2 = (2 * i + 1) * g.cell - 2 * cx;
      const std::int64_t dy2 = (2 * j + 1) * g.cell - 2 * cy;
      if (dx2 * dx2 + dy2 * dy2 <= 4 * radius * radius) out.push_back(j * g.cols + i);
    }
  return out;
}

std::vector<std::int64_t> visited(buffon::ByteRasterCore& g, std::vector<std::uint8_t>& storage,
                                  FxPoint c, std::int64_t radius) {
  std::vector<std::int64_t> out;
  g.disk(c, radius, [&](std::uint8_t& cell) { out.push_back(&cell - storage.data()); });
  return out;
}

} // namespace

TEST_CASE("ByteRasterCore::disk visits exactly the definition's cells, in its order",
          "[buffon][property]") {
  rc::prop("random grids, centres (on and off the grid) and radii", [] {
    const std::int64_t cell = *rc::gen::inRange<std::int64_t>(1, 20000);
    const std::int64_t cols = *rc::gen::inRange<std::int64_t>(1, 60);
    const std::int64_t rows = *rc::gen::inRange<std::int64_t>(1, 60);
    const std::int32_t x0 = *rc::gen::inRange(-100000, 100000);
    const std::int32_t y0 = *rc::gen::inRange(-100000, 100000);
    buffon::ByteRasterCore g;
    REQUIRE(g.init({Fx::from_raw(x0), Fx::from_raw(y0)},
                   {Fx::from_raw(static_cast<std::int32_t>(x0 + (cols - 1) * cell)),
                    Fx::from_raw(static_cast<std::int32_t>(y0 + (rows - 1) * cell))},
                   cell));
    std::vector<std::uint8_t> storage(g.cells());
    g.bind(storage.data(), 0);
    // Radii from none to wider than the row runs keep (more than 32 columns).
    const std::int64_t radius = *rc::gen::inRange<std::int64_t>(0, 40 * cell);
    const auto coord = [&](std::int32_t origin, std::int64_t n) {
      return Fx::from_raw(static_cast<std::int32_t>(
          origin + *rc::gen::inRange<std::int64_t>(-3 * cell - radius, (n + 3) * cell + radius)));
    };
    const FxPoint c{coord(x0, cols), coord(y0, rows)};
    RC_ASSERT(visited(g, storage, c, radius) == by_definition(g, c, radius));
  });
  SECTION("RS's footprint: the body's radius on cells of 0.1, centres across a cell") {
    buffon::ByteRasterCore g;
    REQUIRE(g.init({Fx::from_raw(0), Fx::from_raw(0)},
                   {Fx::from_raw(static_cast<std::int32_t>(20 * buffon::kRsCellRaw)),
                    Fx::from_raw(static_cast<std::int32_t>(20 * buffon::kRsCellRaw))},
                   buffon::kRsCellRaw));
    std::vector<std::uint8_t> storage(g.cells());
    g.bind(storage.data(), 0);
    const std::int64_t r = buffon::kBodyRadius.raw();
    std::size_t compared = 0;
    for (std::int64_t ox = 0; ox < buffon::kRsCellRaw; ox += 97)
      for (std::int64_t oy = 0; oy < buffon::kRsCellRaw; oy += 89) {
        const FxPoint c{Fx::from_raw(static_cast<std::int32_t>(10 * buffon::kRsCellRaw + ox)),
                        Fx::from_raw(static_cast<std::int32_t>(10 * buffon::kRsCellRaw + oy))};
        const auto got = visited(g, storage, c, r);
        REQUIRE(got == by_definition(g, c, r));
        CHECK(got.size() >= 69); // about pi 5^2 cells of 0.1 under a body of radius 0.5
        CHECK(got.size() <= 89);
        ++compared;
      }
    CHECK(compared == 68 * 74);
  }
}
