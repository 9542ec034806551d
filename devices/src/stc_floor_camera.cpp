#include <algorithm>
#include <antkit/devices/stc_floor/camera.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/kernel/int_ops.hpp>
#include <string>

namespace antkit::devices::stc_floor {

namespace {
using kernel::int128;
constexpr std::int64_t kMaxPixels = std::int64_t{1} << 26; // 8192 x 8192: far above any camera
} // namespace

Image::Image(std::int32_t w, std::int32_t h, std::int32_t c, std::uint8_t fill)
    : width(w), height(h), channels(c) {
  if (!(w >= 1 && h >= 1 && (c == 1 || c == 3) && std::int64_t{w} * h <= kMaxPixels))
    throw kernel::InputError("image", "a " + std::to_string(w) + " x " + std::to_string(h) +
                                          " image of " + std::to_string(c) +
                                          " channels; expected 1 or 3 channels and at most 2^26 "
                                          "pixels");
  pixels.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) *
                    static_cast<std::size_t>(c),
                fill);
}

bool Image::valid() const noexcept {
  return width >= 1 && height >= 1 && (channels == 1 || channels == 3) &&
         std::int64_t{width} * height <= kMaxPixels &&
         pixels.size() == static_cast<std::size_t>(width) * static_cast<std::size_t>(height) *
                              static_cast<std::size_t>(channels);
}

Image subtract_dark(const Image& frame, const Image& dark) {
  if (!frame.valid() || !dark.valid() || frame.width != dark.width || frame.height != dark.height ||
      frame.channels != dark.channels)
    throw kernel::InputError("dark frame",
                             "the dark frame must have the frame's size and channels");
  Image out = frame;
  for (std::size_t i = 0; i < out.pixels.size(); ++i)
    out.pixels[i] = frame.pixels[i] > dark.pixels[i]
                        ? static_cast<std::uint8_t>(frame.pixels[i] - dark.pixels[i])
                        : std::uint8_t{0};
  return out;
}

Channels split_channels(const Image& frame, std::uint8_t red_threshold) {
  if (!frame.valid() || frame.channels != 3)
    throw kernel::InputError("frame", "expected an RGB frame (3 channels)");
  Channels c{Image(frame.width, frame.height, 1), Image(frame.width, frame.height, 1)};
  for (std::size_t k = 0; k < c.marks.pixels.size(); ++k) {
    const std::uint8_t r = frame.pixels[3 * k], g = frame.pixels[3 * k + 1];
    if (r > red_threshold)
      c.obstacles.pixels[k] = r;
    else
      c.marks.pixels[k] = g;
  }
  return c;
}

std::vector<Mark> find_marks(const Image& gray, std::int32_t window, std::uint32_t min_sum,
                             std::int32_t max_marks) {
  if (!gray.valid() || gray.channels != 1)
    throw kernel::InputError("marks", "expected a gray image (1 channel)");
  if (window < 1 || window > std::min(gray.width, gray.height))
    throw kernel::InputError("marks", "a window of " + std::to_string(window) +
                                          " pixels; expected 1 to the image's shorter side");
  Image work = gray;
  const auto w = static_cast<std::size_t>(gray.width), h = static_cast<std::size_t>(gray.height);
  const auto win = static_cast<std::size_t>(window);
  std::vector<std::uint64_t> sums((w + 1) * (h + 1), 0); // integral image, one row and column of 0
  std::vector<Mark> marks;
  for (std::int32_t m = 0; m < max_marks; ++m) {
    for (std::size_t y = 0; y < h; ++y) {
      std::uint64_t row = 0;
      for (std::size_t x = 0; x < w; ++x) {
        row += work.pixels[y * w + x];
        sums[(y + 1) * (w + 1) + x + 1] = sums[y * (w + 1) + x + 1] + row;
      }
    }
    std::uint64_t best = 0;
    std::size_t bx = 0, by = 0;
    bool found = false;
    for (std::size_t y = 0; y + win <= h; ++y)
      for (std::size_t x = 0; x + win <= w; ++x) {
        const std::uint64_t s = sums[(y + win) * (w + 1) + x + win] - sums[y * (w + 1) + x + win] -
                                sums[(y + win) * (w + 1) + x] + sums[y * (w + 1) + x];
        if (!found || s > best) {
          best = s;
          bx = x;
          by = y;
          found = true;
        }
      }
    if (!found || best < min_sum) break;
    marks.push_back({static_cast<std::int32_t>(bx), static_cast<std::int32_t>(by),
                     static_cast<std::uint32_t>(std::min<std::uint64_t>(best, UINT32_MAX))});
    for (std::size_t y = by; y < by + win; ++y)
      std::fill_n(work.pixels.begin() + static_cast<std::ptrdiff_t>(y * w + bx), win, 0);
  }
  return marks;
}

std::optional<kernel::Angle> line_heading(std::span<const Mark> marks, std::int32_t window) {
  std::vector<std::array<std::int64_t, 2>> points;
  points.reserve(marks.size());
  for (const Mark& m : marks) points.push_back({m.cx2(window), m.cy2(window)});
  return line_axis(points);
}

std::optional<kernel::Angle> line_axis(std::span<const std::array<std::int64_t, 2>> points) {
  if (points.size() < 2) return std::nullopt;
  // y up.
  int128 sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
  for (const auto& p : points) {
    const int128 x = p[0], y = -int128{p[1]};
    sx += x, sy += y, sxx += x * x, syy += y * y, sxy += x * y;
  }
  const int128 n = static_cast<int128>(points.size());
  // The centred second moments times n^2: the axis of least second moment across the line is
  // the major axis, at half the angle of (Sxx - Syy, 2 Sxy).
  int128 a = n * sxx - sx * sx - (n * syy - sy * sy), b = 2 * (n * sxy - sx * sy);
  if (a == 0 && b == 0) return std::nullopt; // one point, or no preferred direction
  // kernel::atan2 takes 32-bit integers and depends on the ratio only: halve both until they fit.
  while (a > INT32_MAX || a < -INT32_MAX || b > INT32_MAX || b < -INT32_MAX) {
    a /= 2;
    b /= 2;
  }
  const kernel::Angle doubled =
      kernel::atan2(static_cast<std::int32_t>(b), static_cast<std::int32_t>(a));
  return kernel::Angle::from_raw(doubled.raw() / 2);
}

std::int64_t heading_change(kernel::Angle before, kernel::Angle after) noexcept {
  const std::uint32_t half = kernel::Angle::kHalfTurn;
  const std::int64_t d = (std::int64_t{after.raw()} - std::int64_t{before.raw()}) & (half - 1);
  return d > kernel::Angle::kQuarterTurn ? d - half : d;
}

std::int64_t calibrate_rotation(std::int64_t t, std::int64_t turned,
                                std::uint32_t max_change_ppm) noexcept {
  if (turned <= 0 || t <= 0) return t;
  const int128 quarter = kernel::Angle::kQuarterTurn;
  int128 next = (int128{t} * quarter * 2 + turned) / (int128{turned} * 2); // rounded to nearest
  const int128 million = 1000000;
  const int128 hi = int128{t} * (million + max_change_ppm) / million;
  const int128 lo =
      (int128{t} * million + (million + max_change_ppm) - 1) / (million + max_change_ppm);
  next = std::clamp(next, lo, hi);
  return static_cast<std::int64_t>(std::min<int128>(next, INT64_MAX));
}

} // namespace antkit::devices::stc_floor
