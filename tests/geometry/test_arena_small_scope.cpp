// Exhaustive small-scope checks: every triangle on a small half-unit lattice (so that vertices and
// edges fall on cell centres and scanlines as often as they can), alone and as a hole, rasterized
// at two cell sizes and held against the exact oracle; every one round-trips through WKT.
#include "arena_generators.hpp"

#include <antkit/geometry/arena.hpp>
#include <antkit/geometry/arena_cgal.hpp>
#include <antkit/geometry/arena_raster.hpp>
#include <antkit/geometry/wkt.hpp>
#include <catch2/catch.hpp>
#include <vector>

using namespace antkit::geometry;

TEST_CASE("every lattice triangle in [0, 2]^2 (step 1/2) rasterizes as the oracle says",
          "[raster][proof]") {
  std::vector<ExactPoint> lattice;
  for (int x = 0; x <= 4; ++x)
    for (int y = 0; y <= 4; ++y) lattice.emplace_back(ExactNumber(x, 2), ExactNumber(y, 2));
  std::size_t triangles = 0, disagreements = 0, bad_round_trips = 0;
  for (std::size_t i = 0; i < lattice.size(); ++i)
    for (std::size_t j = i + 1; j < lattice.size(); ++j)
      for (std::size_t k = j + 1; k < lattice.size(); ++k) {
        if (CGAL::collinear(lattice[i], lattice[j], lattice[k])) continue;
        const std::vector<ExactPoint> pts{lattice[i], lattice[j], lattice[k]};
        const ExactPolygon triangle(pts.begin(), pts.end());
        // The triangle alone, and as a hole in the square [-1, 3]^2 around it.
        const std::vector<ExactPoint> box{{-1, -1}, {3, -1}, {3, 3}, {-1, 3}};
        const std::vector<ExactPolygon> holes{triangle};
        const Arena alone = make_arena(ExactPolygonWithHoles(triangle), "t");
        const Arena holed = make_arena(
            ExactPolygonWithHoles(ExactPolygon(box.begin(), box.end()), holes.begin(), holes.end()),
            "t");
        ++triangles;
        for (const Arena& a : {alone, holed}) {
          if (!(read_wkt(write_wkt(a)) == a)) ++bad_round_trips;
          for (const CellSize cell : {CellSize(1, 1), CellSize(1, 2)}) {
            const auto r = rasterize(a, cell);
            const ExactNumber c(static_cast<long>(cell.num()),
                                static_cast<unsigned long>(cell.den()));
            for (std::int32_t y = 0; y < r.grid.height(); ++y)
              for (std::int32_t x = 0; x < r.grid.width(); ++x) {
                const ExactPoint centre(
                    (ExactNumber(static_cast<long>(r.frame.col0 + x)) + ExactNumber(1, 2)) * c,
                    (ExactNumber(static_cast<long>(r.frame.row0 - y)) - ExactNumber(1, 2)) * c);
                const bool free = antkit::test::strictly_inside(exact_polygon(a), centre);
                if (free != (r.grid[{x, y}] == antkit::kernel::Occupancy::Free)) ++disagreements;
              }
          }
        }
      }
  // C(25, 3) = 2300 triples, minus the collinear ones.
  CHECK(triangles > 2000);
  CHECK(disagreements == 0);
  CHECK(bad_round_trips == 0);
}
