// The marker-floor robot's optics: calibration, its file, the unwarp and the renderer's rays
// (stc_floor/optics.hpp).
#include <antkit/devices/stc_floor/optics.hpp>
#include <antkit/kernel/angle.hpp>
#include <antkit/kernel/fixed.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/kernel/int_ops.hpp>

namespace antkit::devices::stc_floor {

namespace {

using kernel::int128;

// The mirror's rim: rays steeper than 1.5 rad from the vertical (86 degrees) do not reach the
// floor within the mirror (a choice; with the default height of 3 sub-cells the rim sees 42
// sub-cells away, far beyond the 5 cells the robot reads).
constexpr std::int64_t kMaxPhi = 98304; // 1.5 rad in Q16

std::int64_t isqrt(std::int64_t n) {
  std::int64_t rest = 0;
  return kernel::isqrt_floor<std::int64_t, 62>(n, rest);
}

std::int64_t div_round(int128 n, int128 d) { // d > 0, to nearest, halves away from zero
  const int128 q = (n >= 0 ? n + d / 2 : n - d / 2) / d;
  return static_cast<std::int64_t>(q);
}

std::int64_t floor_div(std::int64_t n, std::int64_t d) { // d > 0
  return n >= 0 ? n / d : -((-n + d - 1) / d);
}

// phi (Q16 radians) of a floor point at rho (Q16 sub-cells) under a mirror at height h.
std::int64_t phi_of(std::int64_t rho, std::int64_t h) {
  if (rho > INT32_MAX || h > INT32_MAX) return kMaxPhi; // beyond any floor the mirror sees
  const kernel::Angle a = kernel::atan2(kernel::Fx::from_raw(static_cast<std::int32_t>(rho)),
                                        kernel::Fx::from_raw(static_cast<std::int32_t>(h)));
  return a.radians<kernel::Fx>().raw();
}

// The 12 corners in half sub-cells from the robot's centre (the table in optics.hpp, doubled).
constexpr std::array<std::array<std::int32_t, 2>, 12> kCornersHalf{{{5, 1},
                                                                    {5, -3},
                                                                    {1, -3},
                                                                    {1, -7},
                                                                    {-3, -7},
                                                                    {-3, -3},
                                                                    {-7, -3},
                                                                    {-7, 1},
                                                                    {-3, 1},
                                                                    {-3, 5},
                                                                    {1, 5},
                                                                    {1, 1}}};

} // namespace

Calibration ideal_calibration(const Optics& optics, std::int32_t unwarped_size,
                              std::int32_t pixels_per_subcell) {
  Calibration c;
  c.optics = optics;
  c.unwarped_size = unwarped_size;
  c.pixels_per_subcell = pixels_per_subcell;
  const std::int64_t centre = std::int64_t{unwarped_size} * kOne / 2;
  for (std::size_t i = 0; i < 12; ++i)
    c.corners[i] = {centre + kCornersHalf[i][0] * pixels_per_subcell * kOne / 2,
                    centre + kCornersHalf[i][1] * pixels_per_subcell * kOne / 2};
  return c;
}

void validate(const Optics& o, const std::string& where) {
  auto fail = [&](const std::string& m) { throw kernel::InputError(where, m); };
  if (o.panorama_width < 16 || o.panorama_width > 4096 || o.panorama_height < 16 ||
      o.panorama_height > 4096)
    fail("the panorama must be 16 to 4096 pixels wide and high");
  if (o.lens_centre.x < 0 || o.lens_centre.y < 0 || o.lens_centre.x > o.panorama_width * kOne ||
      o.lens_centre.y > o.panorama_height * kOne)
    fail("the lens centre must lie inside the panorama");
  if (o.mirror_height < kOne / 16 || o.mirror_height > 1024 * kOne)
    fail("the mirror height must be 1/16 to 1024 sub-cells");
  if (o.pixels_per_radian < kOne || o.pixels_per_radian > 65536 * kOne)
    fail("pixels per radian must be 1 to 65536");
}

void validate(const Calibration& c, const std::string& where) {
  auto fail = [&](const std::string& m) { throw kernel::InputError(where, m); };
  validate(c.optics, where);
  if (c.unwarped_size < 16 || c.unwarped_size > 4096)
    fail("the unwarped image must be 16 to 4096 pixels");
  if (c.pixels_per_subcell < 4 || c.pixels_per_subcell > c.unwarped_size / 2)
    fail("pixels per sub-cell must be 4 to half the unwarped size");
  for (std::size_t i = 0; i < 12; ++i)
    if (c.corners[i].x < 0 || c.corners[i].y < 0 || c.corners[i].x > c.unwarped_size * kOne ||
        c.corners[i].y > c.unwarped_size * kOne)
      fail("corner " + std::to_string(i + 1) + " lies outside the unwarped image");
}

std::int64_t parse_q16(const std::string& where, std::string_view text) {
  auto bad = [&] {
    throw kernel::InputError(where, "'" + std::string(text) +
                                        "': expected a decimal number such as 120 or 3.25");
  };
  std::size_t i = 0;
  const bool negative = !text.empty() && text[0] == '-';
  if (negative) ++i;
  std::int64_t whole = 0, frac = 0, scale = 1;
  std::size_t digits = 0, fdigits = 0;
  while (i < text.size() && text[i] >= '0' && text[i] <= '9') {
    if (++digits > 12) bad();
    whole = whole * 10 + (text[i++] - '0');
  }
  if (i < text.size() && text[i] == '.') {
    ++i;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') {
      if (++fdigits > 9) bad();
      frac = frac * 10 + (text[i++] - '0');
      scale *= 10;
    }
    if (fdigits == 0) bad();
  }
  if (digits == 0 || i != text.size()) bad();
  const std::int64_t q = whole * kOne + (frac * kOne * 2 + scale) / (2 * scale);
  return negative ? -q : q;
}

PointQ16 parse_point(const std::string& where, std::string_view text) {
  const std::size_t comma = text.find(',');
  if (comma == std::string_view::npos)
    throw kernel::InputError(where, "'" + std::string(text) + "': expected X,Y");
  return {parse_q16(where, text.substr(0, comma)), parse_q16(where, text.substr(comma + 1))};
}

Calibration clicked_calibration(Optics optics, PointQ16 lens_centre, std::int32_t unwarped_size,
                                std::int32_t pixels_per_subcell,
                                const std::array<PointQ16, 12>& corners) {
  Calibration c;
  c.optics = optics;
  c.optics.lens_centre = lens_centre;
  c.unwarped_size = unwarped_size;
  c.pixels_per_subcell = pixels_per_subcell;
  c.corners = corners;
  validate(c, "calibration");
  return c;
}

PointQ16 project(const Optics& o, PointQ16 floor) {
  // rho and the direction in Q16 sub-cells; r = k * phi in Q16 pixels.
  const std::int64_t rho = isqrt(floor.x * floor.x + floor.y * floor.y); // floor in Q16: < 2^30
  if (rho == 0) return o.lens_centre;
  const std::int64_t phi = phi_of(rho, o.mirror_height);
  const std::int64_t r = static_cast<std::int64_t>((int128{o.pixels_per_radian} * phi) >> 16);
  return {o.lens_centre.x + div_round(int128{floor.x} * r, rho),
          o.lens_centre.y + div_round(int128{floor.y} * r, rho)};
}

Unwarp::Unwarp(const Calibration& c)
    : size_(c.unwarped_size), pan_w_(c.optics.panorama_width), pan_h_(c.optics.panorama_height) {
  validate(c, "calibration");
  lut_.assign(static_cast<std::size_t>(size_) * static_cast<std::size_t>(size_), -1);
  const std::int64_t scale2 = 2 * std::int64_t{c.pixels_per_subcell};
  for (std::int32_t v = 0; v < size_; ++v)
    for (std::int32_t u = 0; u < size_; ++u) {
      // The pixel's centre in half pixels from the image centre, then in Q16 sub-cells.
      const std::int64_t a = 2 * std::int64_t{u} + 1 - size_, b = 2 * std::int64_t{v} + 1 - size_;
      const PointQ16 floor{div_round(int128{a} * kOne, scale2),
                           div_round(int128{b} * kOne, scale2)};
      const std::int64_t rho = isqrt(floor.x * floor.x + floor.y * floor.y);
      if (phi_of(rho, c.optics.mirror_height) >= kMaxPhi) continue;
      const PointQ16 p = project(c.optics, floor);
      const std::int64_t i = floor_div(p.x, kOne), j = floor_div(p.y, kOne);
      if (i < 0 || j < 0 || i >= pan_w_ || j >= pan_h_) continue;
      lut_[static_cast<std::size_t>(v) * static_cast<std::size_t>(size_) +
           static_cast<std::size_t>(u)] = static_cast<std::int32_t>(j * pan_w_ + i);
    }
}

Image Unwarp::apply(const Image& panorama) const {
  if (!panorama.valid() || panorama.channels != 1 || panorama.width != pan_w_ ||
      panorama.height != pan_h_)
    throw kernel::InputError("unwarp", "expected a gray panorama of " + std::to_string(pan_w_) +
                                           " x " + std::to_string(pan_h_) + " pixels");
  Image out(size_, size_, 1);
  for (std::size_t k = 0; k < lut_.size(); ++k)
    if (lut_[k] >= 0) out.pixels[k] = panorama.pixels[static_cast<std::size_t>(lut_[k])];
  return out;
}

Image rotate_quarter(const Image& img, int k) {
  if (!img.valid() || img.width != img.height)
    throw kernel::InputError("rotate", "expected a square image");
  k &= 3;
  if (k == 0) return img;
  const std::int32_t s = img.width;
  Image out(s, s, img.channels);
  for (std::int32_t v = 0; v < s; ++v)
    for (std::int32_t u = 0; u < s; ++u) {
      std::int32_t x = u, y = v;
      for (int t = 0; t < k; ++t) { // (x, y) -> (y, s - 1 - x)
        const std::int32_t nx = y;
        y = s - 1 - x;
        x = nx;
      }
      for (std::int32_t ch = 0; ch < img.channels; ++ch) out.at(x, y, ch) = img.at(u, v, ch);
    }
  return out;
}

std::vector<FloorRay> panorama_rays(const Optics& o) {
  std::vector<FloorRay> rays(static_cast<std::size_t>(o.panorama_width) *
                             static_cast<std::size_t>(o.panorama_height));
  for (std::int32_t j = 0; j < o.panorama_height; ++j)
    for (std::int32_t i = 0; i < o.panorama_width; ++i) {
      const std::int64_t px = (2 * std::int64_t{i} + 1) * kOne / 2 - o.lens_centre.x;
      const std::int64_t py = (2 * std::int64_t{j} + 1) * kOne / 2 - o.lens_centre.y;
      const std::int64_t r = isqrt(px * px + py * py);
      FloorRay& ray =
          rays[static_cast<std::size_t>(j) * static_cast<std::size_t>(o.panorama_width) +
               static_cast<std::size_t>(i)];
      if (r == 0) {
        ray.visible = true;
        continue;
      }
      const std::int64_t phi = div_round(int128{r} * kOne, o.pixels_per_radian);
      if (phi >= kMaxPhi) continue;
      const kernel::Angle a =
          kernel::Angle::from_radians(kernel::Fx::from_raw(static_cast<std::int32_t>(phi)));
      const std::int64_t s = kernel::sin<kernel::Fx>(a).raw(), c = kernel::cos<kernel::Fx>(a).raw();
      const std::int64_t rho = div_round(int128{o.mirror_height} * s, c);
      const std::int64_t x = div_round(int128{px} * rho, r), y = div_round(int128{py} * rho, r);
      if (x > INT32_MAX || x < -INT32_MAX || y > INT32_MAX || y < -INT32_MAX) continue;
      ray = {static_cast<std::int32_t>(x), static_cast<std::int32_t>(y), true};
    }
  return rays;
}

} // namespace antkit::devices::stc_floor
