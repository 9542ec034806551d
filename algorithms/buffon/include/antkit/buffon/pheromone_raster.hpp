#pragma once
// The pheromone raster of visit 1 (measurement.hpp: its model, its cells and its memory layout),
// over words the caller provides (issue 27): RasterCore is freestanding (the Cortex-M image builds
// it from the same source, pheromone_raster.cpp, and keeps the bits in its own buffer); the host's
// PheromoneRaster (measurement.hpp) owns them in a vector and throws where init() returns an error.
#include <antkit/buffon/world.hpp>
#include <antkit/kernel/fixed.hpp>
#include <climits>
#include <cstdint>
#include <span>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace antkit::buffon {

enum class RasterError : std::uint8_t {
  None,
  Width,    // the trail width outside [0.01, 10] units
  TooLarge, // more than 2^27 words (1 GiB) of bits
};
// The input a raster error is about is always the trail width ("trail width").
[[nodiscard]] const char* describe(RasterError e) noexcept;

class RasterCore {
public:
  // Sets the raster's geometry over the box [lower, upper] for trail width `width`: Width when w is
  // not in [0.01, 10] units, TooLarge when the bits would exceed 2^27 words. The raster has no bits
  // until bind() gives it words() zeroed words.
  [[nodiscard]] RasterError init(FxPoint lower, FxPoint upper, Fx width) noexcept;
  // The 64-bit words the bits need.
  [[nodiscard]] std::uint64_t words() const noexcept {
    return static_cast<std::uint64_t>((cols_ + 63) / 64 * rows_);
  }
  // The bits: words() words, zeroed by the caller, which keeps them alive while the raster is used.
  void bind(std::span<std::uint64_t> bits) noexcept { bits_ = bits; }
  // Marks every cell whose centre is within w / 2 of `centre` (exact integer test).
  void lay(FxPoint centre) noexcept {
    Cell c;
    if (!locate(centre, c) || c.i < 2 || c.j < 2 || c.i + 2 >= cols_ || c.j + 2 >= rows_) {
      lay_exact(
          centre); // near the raster's edge (never in a closed arena) or w out of the fast range
      return;
    }
    // The disk lies in the 5 x 5 cells around the centre's cell (the constructor checks
    // 2 (w / 2) < 5 cell, so a cell three away has its centre beyond w / 2 in that axis). Cell
    // centres in doubled raw units avoid halves: the centre of cell i + d is at
    // 2 (i cell) + (2 d + 1) cell, so its doubled offset from the robot is (2 d + 1) cell - 2 o.
    std::int64_t sq[5], room[5];
    for (int d = 0; d < 5; ++d) {
      const std::int64_t dx2 = (2 * (d - 2) + 1) * cell_ - 2 * c.ox;
      const std::int64_t dy2 = (2 * (d - 2) + 1) * cell_ - 2 * c.oy;
      sq[d] = dx2 * dx2;
      room[d] = 4 * r2_ - dy2 * dy2; // a column is in row d's chord when sq <= room[d]
    }
    std::uint64_t masks[5];
#if defined(__SSE2__)
    if (narrow_) {
      // Every sq and room fits in 32 bits (the constructor checks (5 cell)^2 and 4 r^2 < 2^31):
      // four columns per comparison, the same integers compared exactly.
      const __m128i sq_lo =
          _mm_setr_epi32(static_cast<std::int32_t>(sq[0]), static_cast<std::int32_t>(sq[1]),
                         static_cast<std::int32_t>(sq[2]), static_cast<std::int32_t>(sq[3]));
      const __m128i sq_hi =
          _mm_setr_epi32(static_cast<std::int32_t>(sq[4]), INT32_MAX, INT32_MAX, INT32_MAX);
      for (int e = 0; e < 5; ++e) {
        const __m128i r = _mm_set1_epi32(static_cast<std::int32_t>(room[e]));
        // Columns with sq > room are out; the rest (sq <= room) are in.
        const int out_lo = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpgt_epi32(sq_lo, r)));
        const int out_hi = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpgt_epi32(sq_hi, r)));
        masks[e] = ~static_cast<std::uint64_t>(out_lo | (out_hi << 4)) & 0x1Fu;
      }
    } else
#endif
    {
      for (int e = 0; e < 5; ++e) {
        std::uint64_t mask = 0;
        for (int d = 0; d < 5; ++d) mask |= std::uint64_t{sq[d] <= room[e]} << d;
        masks[e] = mask;
      }
    }
    // Rows j - 2 .. j + 2, columns i - 2 .. i + 2: bits `shift` .. `shift` + 4 of five adjacent
    // words of one column band, which may straddle into the same rows of the next band.
    const auto first = static_cast<std::uint64_t>(c.i - 2);
    const unsigned shift = first & 63;
    std::uint64_t* const words = bits_.data() + word_index(c.i - 2, c.j - 2);
    for (int e = 0; e < 5; ++e) words[e] |= masks[e] << shift;
    // Only 4 of 64 shifts spill into the next band (which then exists: the columns up to i + 2
    // are in the raster): a well-predicted branch beats five stores.
    if (shift > 59) {
      std::uint64_t* const next = words + rows_;
      for (int e = 0; e < 5; ++e) next[e] |= masks[e] >> (64 - shift);
    }
  }
  [[nodiscard]] bool at(FxPoint centre) const noexcept {
    Cell c;
    if (!locate(centre, c)) return at_exact(centre);
    if (c.i >= cols_ || c.j >= rows_) return false;
    return bit(c.i, c.j);
  }
  [[nodiscard]] Fx cell() const noexcept {
    return Fx::from_raw(static_cast<std::int32_t>(cell_));
  }
  [[nodiscard]] std::int64_t columns() const noexcept {
    return cols_;
  }
  [[nodiscard]] std::int64_t rows() const noexcept {
    return rows_;
  }
  [[nodiscard]] std::uint64_t marked() const;
  // Same geometry and the same marked cells.
  friend bool operator==(const RasterCore& a, const RasterCore& b) noexcept;

  // The reference forms of lay() and at(): the plain loop over the disk's bounding cells with one
  // exact test each, and floor divisions. The fast paths fall back to them near the raster's edge
  // and the tests hold the fast paths against them.
  void lay_exact(FxPoint centre) noexcept;
  [[nodiscard]] bool at_exact(FxPoint centre) const noexcept;

private:
  struct Cell {
    std::int64_t i, j;   // the cell holding the point
    std::int64_t ox, oy; // the point's offset inside it, in [0, cell)
  };
  // Cell and offset of p when p is at or right of and above the raster's lower corner and less
  // than 2^32 raw from it; false otherwise (then the exact forms decide). Division by the cell
  // side by multiplication with floor(2^32 / cell): for n < 2^32 the product's high half is
  // floor(n / cell) or one less, and one comparison corrects it (exact; no division per step).
  bool locate(FxPoint p, Cell& out) const noexcept {
    const std::int64_t cx = std::int64_t{p.x.raw()} - x0_, cy = std::int64_t{p.y.raw()} - y0_;
    if (!fast_ || cx < 0 || cy < 0 || cx >= (std::int64_t{1} << 32) ||
        cy >= (std::int64_t{1} << 32))
      return false;
    auto divide = [this](std::int64_t n, std::int64_t& q, std::int64_t& rest) {
      q = static_cast<std::int64_t>((static_cast<std::uint64_t>(n) * reciprocal_) >> 32);
      rest = n - q * cell_;
      if (rest >= cell_) ++q, rest -= cell_;
    };
    divide(cx, out.i, out.ox);
    divide(cy, out.j, out.oy);
    return true;
  }
  // The word holding cell (i, j) (0 <= i < cols_, 0 <= j < rows_): column band i div 64, row j.
  [[nodiscard]] std::size_t word_index(std::int64_t i, std::int64_t j) const noexcept {
    return static_cast<std::size_t>((i >> 6) * rows_ + j);
  }
  [[nodiscard]] bool bit(std::int64_t i, std::int64_t j) const noexcept {
    return ((bits_[word_index(i, j)] >> (i & 63)) & 1u) != 0;
  }
  bool narrow_ = false; // (5 cell_)^2 and 4 r2_ below 2^31: lay() compares in 32-bit lanes

  std::int64_t x0_ = 0, y0_ = 0, cell_ = 1, half_width_ = 0, cols_ = 0, rows_ = 0;
  std::int64_t r2_ = 0;           // half_width_ squared
  std::uint64_t reciprocal_ = 0;  // floor(2^32 / cell_)
  bool fast_ = false;             // 2 half_width_ < 5 cell_: the 5 x 5 fast path of lay() applies
  std::span<std::uint64_t> bits_; // column bands of 64 cells, each `rows_` words (see above)
};

} // namespace antkit::buffon
