#pragma once
// Randomized Search's core (issue 27; paper 000, Section 8.1, checkpoints.hpp): a raster of bytes
// over storage the caller gives, the body's footprint stamped on it, and one RS walk of a fixed
// number of steps in a buffer. Freestanding: no allocation, no exception, errors returned. The
// host's run_checkpoints, rs_footprint, rs_cost_to_precision and run_rs (checkpoints.cpp) mark
// through ByteRasterCore and rs_mark; the Cortex-M image (mcu/src/rs_run.cpp) lays a walk out
// with prepare_fixed_rs and runs run_fixed_rs, whose steps are visit.hpp's, twice: with the C++
// cores and with the C API's behaviour and hash (antkit/c/antkit.h) as its parts; both must give
// run_rs's cells, length and hash.
//
// The trace hash of an RS walk (run_rs, run_fixed_rs): TraceHash(seed), the trial, every step's
// hash_visit_step (visit.hpp), then the marked cells and the blocked steps.
#include <antkit/buffon/visit.hpp>
#include <antkit/buffon/world.hpp>
#include <antkit/kernel/hash.hpp>
#include <cstddef>
#include <cstdint>
#include <span>

namespace antkit::buffon {

// RS's cell side: 0.1 units (a choice: 1/10 of the body), raw Q15.16.
inline constexpr std::int64_t kRsCellRaw = Fx::from_ratio(1, 10).raw();
// The visit whose streams RS walks: visit 3 of the trial (visits 1 and 2 are Buffon's).
inline constexpr int kRsVisit = 3;

namespace detail {
constexpr std::int64_t floor_div(std::int64_t a, std::int64_t b) noexcept {
  const std::int64_t q = a / b;
  return (a % b != 0 && ((a < 0) != (b < 0))) ? q - 1 : q;
}
} // namespace detail

// Cells of side `cell` (raw) from (x0, y0), one byte each, row-major, in storage the caller binds.
struct ByteRasterCore {
  std::int64_t x0 = 0, y0 = 0, cell = 1, cols = 0, rows = 0;
  std::uint8_t* v = nullptr;

  // The grid over [lo, hi]; false (and nothing usable) when it has more than 2^32 cells.
  bool init(FxPoint lo, FxPoint hi, std::int64_t cell_raw) noexcept {
    x0 = lo.x.raw(), y0 = lo.y.raw(), cell = cell_raw;
    cols = (std::int64_t{hi.x.raw()} - x0) / cell_raw + 1;
    rows = (std::int64_t{hi.y.raw()} - y0) / cell_raw + 1;
    return cols * rows <= (std::int64_t{1} << 32);
  }
  [[nodiscard]] std::uint64_t cells() const noexcept {
    return static_cast<std::uint64_t>(cols * rows);
  }
  // `storage` holds cells() bytes, each set to `fill`.
  void bind(std::uint8_t* storage, std::uint8_t fill) noexcept {
    v = storage;
    for (std::uint64_t k = 0; k < cells(); ++k) v[k] = fill;
  }
  // Calls f(cell value) for every cell whose centre is within `radius` of c, row by row, each
  // row's cells left to right. A cell is in when dx2^2 + dy2^2 <= 4 radius^2, its centre's offsets
  // from c doubled (so that no half appears).
  template <class F>
  void disk(FxPoint c, std::int64_t radius, F&& f) noexcept {
    const std::int64_t cx = c.x.raw() - x0, cy = c.y.raw() - y0;
    const std::int64_t a0 = detail::floor_div(cx - radius, cell);
    const std::int64_t a1 = detail::floor_div(cx + radius, cell);
    const std::int64_t b0 = detail::floor_div(cy - radius, cell);
    const std::int64_t b1 = detail::floor_div(cy + radius, cell);
    const std::int64_t i0 = a0 < 0 ? 0 : a0, i1 = a1 < cols - 1 ? a1 : cols - 1;
    const std::int64_t j0 = b0 < 0 ? 0 : b0, j1 = b1 < rows - 1 ? b1 : rows - 1;
    const std::int64_t four_r2 = 4 * radius * radius;
    constexpr std::int64_t kColumns = 32;
    if (i1 - i0 >= kColumns) { // a disk wider than the row spans below keep: cell by cell
      for (std::int64_t j = j0; j <= j1; ++j) {
        const std::int64_t dy2 = (2 * j + 1) * cell - 2 * cy;
        for (std::int64_t i = i0; i <= i1; ++i) {
          const std::int64_t dx2 = (2 * i + 1) * cell - 2 * cx;
          if (dx2 * dx2 + dy2 * dy2 <= four_r2) f(v[static_cast<std::size_t>(j * cols + i)]);
        }
      }
      return;
    }
    // The same test, by rows: dx2^2 once per column, and in each row the columns with
    // dx2^2 <= 4 radius^2 - dy2^2. dx2^2 falls and then rises across the columns (dx2 is linear
    // in i), so those columns are one run: found by walking in from both ends (a few columns: a
    // count of all of them without branches measured slower), then visited with no test (the
    // same cells, in the same order, as testing each).
    std::int64_t sq[kColumns];
    const std::int64_t n = i1 - i0 + 1;
    for (std::int64_t k = 0; k < n; ++k) {
      const std::int64_t dx2 = (2 * (i0 + k) + 1) * cell - 2 * cx;
      sq[k] = dx2 * dx2;
    }
    for (std::int64_t j = j0; j <= j1; ++j) {
      const std::int64_t dy2 = (2 * j + 1) * cell - 2 * cy;
      const std::int64_t room = four_r2 - dy2 * dy2;
      std::int64_t lo = 0, hi = n - 1;
      while (lo <= hi && sq[lo] > room) ++lo;
      while (hi >= lo && sq[hi] > room) --hi;
      std::uint8_t* const row = v + j * cols + i0;
      for (std::int64_t k = lo; k <= hi; ++k) f(row[k]);
    }
  }
  // The cell holding c, or 0xFF off the grid.
  [[nodiscard]] std::uint8_t at(FxPoint c) const noexcept {
    const std::int64_t i = detail::floor_div(c.x.raw() - x0, cell);
    const std::int64_t j = detail::floor_div(c.y.raw() - y0, cell);
    if (i < 0 || j < 0 || i >= cols || j >= rows) return 0xFF;
    return v[static_cast<std::size_t>(j * cols + i)];
  }
};

// RS's one rule ("mark only the unmarked areas" under the body): marks the cells (0 -> 1) whose
// centre lies within the body's radius of `position`; returns how many were newly marked.
inline std::uint64_t rs_mark(ByteRasterCore& raster, FxPoint position) noexcept {
  std::uint64_t fresh = 0;
  raster.disk(position, kBodyRadius.raw(), [&fresh](std::uint8_t& cell) {
    fresh += cell == 0 ? 1 : 0;
    cell = 1;
  });
  return fresh;
}

struct FixedRsResult {
  std::uint64_t cells = 0, blocked = 0, hash = 0;
  std::int64_t length_raw = 0;
  std::uint64_t bytes = 0; // of the buffer used (the world's buckets and the raster)
};

// The buffer an RS walk over a world of layout `world` needs: the buckets, then the raster of
// `raster_cells` bytes, each part 8-byte aligned.
[[nodiscard]] constexpr std::uint64_t fixed_rs_bytes(const WorldLayout& world,
                                                     std::uint64_t raster_cells) noexcept {
  const std::uint64_t members_at = ((world.buckets + 1) * 4 + 7) & ~std::uint64_t{7};
  const std::uint64_t raster_at =
      (members_at + world.members * sizeof(BucketWall) + 7) & ~std::uint64_t{7};
  return raster_at + raster_cells;
}

// An RS walk's world, raster and start laid out in a buffer (prepare_fixed_rs).
struct FixedRs {
  WorldCore world;
  ByteRasterCore raster;
  Pose start{};
  std::uint64_t bytes = 0; // of the buffer used
};

// Lays out an RS walk over `walls` with `body` in `buffer` (8-byte aligned; the walls are read, not
// copied): the world's buckets and the raster of cells of side kRsCellRaw over the walls' box,
// all unmarked, and the start of visit kRsVisit of trial `trial`. Returns null, or why it cannot
// (an invalid world or start, a raster or plan larger than the buffer).
[[nodiscard]] inline const char* prepare_fixed_rs(std::span<const FxSegment> walls, BodyParams body,
                                                  std::uint64_t seed, std::uint64_t trial,
                                                  std::span<std::uint8_t> buffer,
                                                  FixedRs& rs) noexcept {
  WorldLayout layout;
  if (const WorldError e = WorldCore::plan(walls, body, layout); e != WorldError::None)
    return describe(e);
  if (!rs.raster.init(layout.lower, layout.upper, kRsCellRaw))
    return "RS's raster has more than 2^32 cells";
  rs.bytes = fixed_rs_bytes(layout, rs.raster.cells());
  if (rs.bytes > buffer.size()) return "the walk's plan is larger than the buffer";
  const std::uint64_t members_at = ((layout.buckets + 1) * 4 + 7) & ~std::uint64_t{7};
  rs.world.build(walls, body, layout,
                 {reinterpret_cast<std::uint32_t*>(buffer.data()),
                  static_cast<std::size_t>(layout.buckets + 1)},
                 {reinterpret_cast<BucketWall*>(buffer.data() + members_at),
                  static_cast<std::size_t>(layout.members)});
  rs.raster.bind(buffer.data() + (rs.bytes - rs.raster.cells()), 0);
  VisitStreams streams(seed, kExperiment, trial, kRsVisit);
  if (const WorldError e = rs.world.place_start(streams.start, rs.start); e != WorldError::None)
    return describe(e);
  return nullptr;
}

// RS for `steps` steps (visit kRsVisit of trial `trial`, seed `seed`, experiment kExperiment) in
// a prepared layout: visit.hpp's steps with Parts' behaviour and hash (VisitParts: the C++ cores;
// the Cortex-M image also passes the C API's), the cells marked from the start on, and the walk's
// trace hash.
template <class Parts = VisitParts>
[[nodiscard]] FixedRsResult run_fixed_rs(FixedRs& rs, std::uint64_t seed, std::uint64_t trial,
                                         std::int64_t steps) noexcept {
  VisitStreams streams(seed, kExperiment, trial, kRsVisit);
  typename Parts::Behaviour behaviour = Parts::behaviour(seed, trial, kRsVisit);
  typename Parts::Hash hash = Parts::hash(seed);
  hash.add_u64(trial);
  FixedRsResult r;
  const VisitEnd end = run_visit_steps(rs.world, behaviour, streams.noise, rs.start, steps, hash,
                                       [&](FxPoint p) { r.cells += rs_mark(rs.raster, p); });
  r.length_raw = end.length_raw;
  r.blocked = end.blocked;
  hash.add_u64(r.cells).add_u64(r.blocked);
  r.hash = hash.finish();
  r.bytes = rs.bytes;
  return r;
}

} // namespace antkit::buffon
