#pragma once
// The marker-floor robot of paper 002 (issue 14), its camera pipeline: the first stages, each a
// small pure function over an 8-bit image, deterministic (integers only: every stage feeds a
// decision of the robot).
//
//   subtract_dark    the paper's noise handling: a frame taken in complete darkness is subtracted
//                    from every snapshot, per channel, saturating at 0;
//   split_channels   the paper's filter into two images: obstacles (red lights) keep a pixel's red
//                    value where red > threshold, marks (the green glowing dots) keep the green
//                    value where red <= threshold;
//   find_marks       the paper's dot finder: the square of a mark's size with the highest sum,
//                    kept when its sum reaches a threshold, then blacked out, repeated;
//   line_heading     the paper's angle detection: a least-squares line through the newest marks
//                    (three in the paper), its direction as a binary angle (kernel/angle.hpp,
//                    2^-32 turn, exact integer arithmetic; integer moments rather than Eigen's
//                    floating point, as it feeds a decision). The pilot measures its turns with
//                    view.hpp's measure_turn instead, which says why;
//   calibrate_rotation  the paper's T <- 90/d * T, with a bound on how far one correction may
//                    move T.
// The mirror unwarp and its calibration are optics.hpp; the five cells' sub-cell state and the
// rotation measurement view.hpp; the rendered floor floor.hpp; the robot's link link.hpp; the
// program that drives it pilot.hpp.
#include <antkit/kernel/angle.hpp>
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace antkit::devices::stc_floor {

// An image, row-major from the top-left pixel, `channels` bytes per pixel (3: R, G, B; 1: gray).
struct Image {
  std::int32_t width = 0, height = 0, channels = 1;
  std::vector<std::uint8_t> pixels; // width * height * channels bytes

  Image() = default;
  Image(std::int32_t w, std::int32_t h, std::int32_t c, std::uint8_t fill = 0);
  [[nodiscard]] std::uint8_t at(std::int32_t x, std::int32_t y, std::int32_t c = 0) const noexcept {
    return pixels[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                   static_cast<std::size_t>(x)) *
                      static_cast<std::size_t>(channels) +
                  static_cast<std::size_t>(c)];
  }
  std::uint8_t& at(std::int32_t x, std::int32_t y, std::int32_t c = 0) noexcept {
    return pixels[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                   static_cast<std::size_t>(x)) *
                      static_cast<std::size_t>(channels) +
                  static_cast<std::size_t>(c)];
  }
  // Whether the sizes agree with the pixels (every stage checks its inputs with it).
  [[nodiscard]] bool valid() const noexcept;
};

// frame - dark per byte, 0 where dark is brighter. Throws kernel::InputError("dark frame") when
// the two differ in size or channels, or either is not valid().
[[nodiscard]] Image subtract_dark(const Image& frame, const Image& dark);

struct Channels {
  Image marks;     // gray: green where red <= red_threshold, else 0
  Image obstacles; // gray: red where red > red_threshold, else 0
};
// Throws kernel::InputError("frame") unless `frame` is a valid 3-channel image.
[[nodiscard]] Channels split_channels(const Image& frame, std::uint8_t red_threshold);

struct Mark {
  std::int32_t x = 0, y = 0; // the top-left pixel of the window
  std::uint32_t sum = 0;     // the window's sum of gray values
  // The window's centre, doubled (so that it is an integer for any window size).
  [[nodiscard]] std::int64_t cx2(std::int32_t window) const noexcept { return 2 * x + window; }
  [[nodiscard]] std::int64_t cy2(std::int32_t window) const noexcept { return 2 * y + window; }
};

// Up to `max_marks` marks, brightest first: each the window x window square (wholly inside the
// image) with the largest sum, the first in row-major order among equals, kept when its sum is at
// least `min_sum`; its pixels are then set to 0 in a copy of the image before the next search.
// Throws kernel::InputError("marks") for an invalid or non-gray image, or a window outside
// [1, min(width, height)].
[[nodiscard]] std::vector<Mark> find_marks(const Image& gray, std::int32_t window,
                                           std::uint32_t min_sum, std::int32_t max_marks);

// The direction of the least-squares line through the marks' centres (total least squares: the
// axis of least second moment), as a binary angle in [0, half a turn) measured counter-clockwise
// from +x with y pointing up (image rows grow downward). nullopt for fewer than two distinct
// centres. Exact: integer moments, kernel::atan2.
[[nodiscard]] std::optional<kernel::Angle> line_heading(std::span<const Mark> marks,
                                                        std::int32_t window);
// The same over any integer points (x right, y down, one scale for both): line_heading is this
// over the marks' doubled centres.
[[nodiscard]] std::optional<kernel::Angle>
line_axis(std::span<const std::array<std::int64_t, 2>> points);

// The turn between two line headings, folded into (-quarter turn, quarter turn]: the deviation a
// rotation left (line directions are defined modulo half a turn).
[[nodiscard]] std::int64_t heading_change(kernel::Angle before, kernel::Angle after) noexcept;

// The paper's rotation calibration: a rotation commanded for `t` time units turned `turned`
// (binary-angle units, > 0); the time for a quarter turn is t * quarter / turned, rounded to
// nearest, but moved by at most a factor 1 + max_change_ppm / 10^6 either way (one bad reading
// must not wreck T). Returns t unchanged when turned <= 0.
[[nodiscard]] std::int64_t calibrate_rotation(std::int64_t t, std::int64_t turned,
                                              std::uint32_t max_change_ppm) noexcept;

} // namespace antkit::devices::stc_floor
