// The pheromone raster over the caller's words (pheromone_raster.hpp). Freestanding: the Cortex-M
// image compiles this file too.
#include <algorithm>
#include <antkit/buffon/pheromone_raster.hpp>

namespace antkit::buffon {

namespace {
std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  const std::int64_t q = a / b;
  return (a % b != 0 && ((a < 0) != (b < 0))) ? q - 1 : q;
}
} // namespace

const char* describe(RasterError e) noexcept {
  switch (e) {
  case RasterError::None:
    return "ok";
  case RasterError::Width:
    return "the trail width must be in [0.01, 10] units";
  case RasterError::TooLarge:
    return "the pheromone raster would exceed 2^27 words (1 GiB); use a wider trail or a smaller "
           "arena";
  }
  return "unknown raster error";
}

RasterError RasterCore::init(FxPoint lower, FxPoint upper, Fx width) noexcept {
  if (width < Fx::from_ratio(1, 100) || width > Fx::from_int(10)) return RasterError::Width;
  cell_ = std::max<std::int64_t>(1, width.raw() / 4);
  half_width_ = width.raw() / 2;
  x0_ = lower.x.raw();
  y0_ = lower.y.raw();
  cols_ = (std::int64_t{upper.x.raw()} - x0_) / cell_ + 1;
  rows_ = (std::int64_t{upper.y.raw()} - y0_) / cell_ + 1;
  // The bands round the columns up to a multiple of 64: the limit is on the words allocated.
  if ((cols_ + 63) / 64 * rows_ > (std::int64_t{1} << 27)) return RasterError::TooLarge;
  r2_ = half_width_ * half_width_;
  reciprocal_ = (std::uint64_t{1} << 32) / static_cast<std::uint64_t>(cell_);
  fast_ = 2 * half_width_ < 5 * cell_; // holds for every width in range (cell >= 163 raw)
  // w up to about 0.56 units (every width of the paper's figures).
  narrow_ = 25 * cell_ * cell_ < (std::int64_t{1} << 31) && 4 * r2_ < (std::int64_t{1} << 31);
  bits_ = {};
  return RasterError::None;
}

void RasterCore::lay_exact(FxPoint c) noexcept {
  const std::int64_t cx = c.x.raw() - x0_, cy = c.y.raw() - y0_;
  const std::int64_t i0 = std::max<std::int64_t>(0, floor_div(cx - half_width_, cell_));
  const std::int64_t i1 = std::min<std::int64_t>(cols_ - 1, floor_div(cx + half_width_, cell_));
  const std::int64_t j0 = std::max<std::int64_t>(0, floor_div(cy - half_width_, cell_));
  const std::int64_t j1 = std::min<std::int64_t>(rows_ - 1, floor_div(cy + half_width_, cell_));
  for (std::int64_t j = j0; j <= j1; ++j) {
    // Cell centres in doubled raw units avoid halves: centre = (2 j + 1) cell / 2.
    const std::int64_t dy2 = (2 * j + 1) * cell_ - 2 * cy;
    for (std::int64_t i = i0; i <= i1; ++i) {
      const std::int64_t dx2 = (2 * i + 1) * cell_ - 2 * cx;
      if (dx2 * dx2 + dy2 * dy2 > 4 * r2_) continue;
      bits_[word_index(i, j)] |= std::uint64_t{1} << (i & 63);
    }
  }
}

bool RasterCore::at_exact(FxPoint c) const noexcept {
  const std::int64_t i = floor_div(c.x.raw() - x0_, cell_);
  const std::int64_t j = floor_div(c.y.raw() - y0_, cell_);
  if (i < 0 || j < 0 || i >= cols_ || j >= rows_) return false;
  return bit(i, j);
}

std::uint64_t RasterCore::marked() const {
  std::uint64_t n = 0;
  for (std::uint64_t w : bits_) n += static_cast<std::uint64_t>(__builtin_popcountll(w));
  return n;
}

bool operator==(const RasterCore& a, const RasterCore& b) noexcept {
  return a.narrow_ == b.narrow_ && a.x0_ == b.x0_ && a.y0_ == b.y0_ && a.cell_ == b.cell_ &&
         a.half_width_ == b.half_width_ && a.cols_ == b.cols_ && a.rows_ == b.rows_ &&
         a.r2_ == b.r2_ && a.reciprocal_ == b.reciprocal_ && a.fast_ == b.fast_ &&
         std::equal(a.bits_.begin(), a.bits_.end(), b.bits_.begin(), b.bits_.end());
}

} // namespace antkit::buffon
