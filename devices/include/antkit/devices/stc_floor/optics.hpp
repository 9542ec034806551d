#pragma once
// The marker-floor robot's optics (paper 002, "Image Transformation and Filtering" and "Initial
// Calibration"): an upward camera under a curved mirror sees a 360-degree panorama of the floor
// around the robot; the unwarp turns it into a top view at a uniform scale, in which the paper's 12
// corners of the 5 relevant cells are clicked once.
//
// The mirror model (the paper gives the idea, not the formula; this is our choice and its source):
// a pixel moves along the ray through the lens centre; a floor point at distance rho from the
// robot's axis is seen at the angle phi = atan(rho / h) from the vertical (h: the mirror's height
// over the floor), and its image lies at the radius r = k * phi from the lens centre (k: pixels per
// radian). This is the equiangular mirror (Chahl and Srinivasan, "Reflective surfaces for
// panoramic imaging", 1997), the usual choice for a robot's panoramic camera; the paper's ratio of
// the two distances from the angles phi and theta is r / rho here. Points at or beyond the horizon
// (phi >= 90 degrees) are not on the floor. The panorama keeps the floor's handedness (a real
// mirror's reflection is undone by the camera driver; the paper's transformed image is shown the
// right way round).
//
// Units, all integers so that every stage that feeds a decision is exact on every machine:
//   floor lengths  Q16 sub-cells (1.0 = the robot's size D, one sub-cell);
//   pixels         Q16 pixels, continuous: pixel (i, j) covers [i, i + 1) x [j, j + 1);
//   angles         kernel::Angle (2^-32 turn) and Q16 radians (kernel::Fx).
//
// The canonical frame of the calibration: the unwarped image is a square of `unwarped_size` pixels
// centred on the lens (the robot's centre), `pixels_per_subcell` pixels to a sub-cell, image up the
// robot's heading; the robot stands in the SE sub-cell (quadrant 0, stc/subcell.hpp) of its cell.
// The 12 corners are the vertices of the plus-shaped outline of the 5 cells, counter-clockwise as
// drawn from the east arm's outer south-east corner; in sub-cells from the robot's centre (x right,
// y down):
//    1 ( 2.5,  0.5)   2 ( 2.5, -1.5)   3 ( 0.5, -1.5)   4 ( 0.5, -3.5)
//    5 (-1.5, -3.5)   6 (-1.5, -1.5)   7 (-3.5, -1.5)   8 (-3.5,  0.5)
//    9 (-1.5,  0.5)  10 (-1.5,  2.5)  11 ( 0.5,  2.5)  12 ( 0.5,  0.5)
// Corners 3, 6, 9 and 12 are the current cell's; each arm is two of them and two outer ones. The
// robot in another quadrant sees the same layout turned by quarter turns about its centre, which
// is exact on the square image (rotate_quarter), so one calibration serves every pose.
#include <antkit/devices/stc_floor/camera.hpp>
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace antkit::devices::stc_floor {

struct PointQ16 {
  std::int64_t x = 0, y = 0;
  friend bool operator==(const PointQ16&, const PointQ16&) = default;
};

inline constexpr std::int64_t kOne = 65536; // 1.0 in Q16

struct Optics {
  std::int32_t panorama_width = 240, panorama_height = 240;
  PointQ16 lens_centre{120 * kOne, 120 * kOne}; // panorama pixels
  std::int64_t mirror_height = 3 * kOne;        // sub-cells
  std::int64_t pixels_per_radian = 100 * kOne;
  friend bool operator==(const Optics&, const Optics&) = default;
};

struct Calibration {
  Optics optics;
  std::int32_t unwarped_size = 216;
  std::int32_t pixels_per_subcell = 24;
  std::array<PointQ16, 12> corners{}; // unwarped pixels, the order above
  friend bool operator==(const Calibration&, const Calibration&) = default;
};

// The corners a perfect robot would click: the canonical layout above at the given scale.
[[nodiscard]] Calibration ideal_calibration(const Optics& optics = {},
                                            std::int32_t unwarped_size = 216,
                                            std::int32_t pixels_per_subcell = 24);

// Checks a calibration (sizes 16..4096, a lens centre inside the panorama, positive mirror height
// and pixels per radian, at least 4 pixels to a sub-cell, corners inside the unwarped image).
// Throws kernel::InputError(where, ...).
void validate(const Calibration& c, const std::string& where);
// The optics' part of it.
void validate(const Optics& o, const std::string& where);

// The calibration file (JSON, DESIGN.md: files and formats):
//   {"schema":1,"kind":"antkit stc-floor calibration",
//    "panorama":{"width":240,"height":240},"lens_centre":[120,120],
//    "mirror":{"height":3,"pixels_per_radian":100},
//    "unwarped":{"size":216,"pixels_per_subcell":24},
//    "corners":[[x,y], ... 12 pairs]}
// Numbers are decimals (pixels; sub-cells for the height), read to the nearest 1/65536. The
// writer prints each Q16 value exactly (up to 16 decimals). read_calibration refuses unknown,
// missing or repeated keys and values out of range, with the file, line and column.
[[nodiscard]] std::string calibration_json(const Calibration& c);
[[nodiscard]] Calibration parse_calibration(const std::string& name, const std::string& text);
[[nodiscard]] Calibration read_calibration(const std::string& path);

// Decimals as typed on a command line ("120", "-3.25", "0.5"; at most 12 digits before the point
// and 9 after it), to the nearest 1/65536 (halves away from zero), and points "X,Y" of them.
// Throws kernel::InputError(where, ...).
[[nodiscard]] std::int64_t parse_q16(const std::string& where, std::string_view text);
[[nodiscard]] PointQ16 parse_point(const std::string& where, std::string_view text);

// The calibration the paper's user clicks: the lens centre on the panorama, then the 12 corners
// on the unwarped image (the order above), with the optics' other parameters. validate()d.
[[nodiscard]] Calibration clicked_calibration(Optics optics, PointQ16 lens_centre,
                                              std::int32_t unwarped_size,
                                              std::int32_t pixels_per_subcell,
                                              const std::array<PointQ16, 12>& corners);

// The unwarp: a look-up table from each unwarped pixel to the panorama pixel that images its floor
// point (nearest pixel; -1 outside the panorama or beyond the horizon), computed once from the
// calibration's optics in integer arithmetic (kernel::atan2, Q16).
class Unwarp {
public:
  explicit Unwarp(const Calibration& c);
  // A gray panorama of the calibration's size to a gray unwarped image (0 where nothing maps).
  // Throws kernel::InputError("unwarp") for an image of another size or channel count.
  [[nodiscard]] Image apply(const Image& panorama) const;
  [[nodiscard]] std::int32_t size() const noexcept { return size_; }
  [[nodiscard]] std::int32_t source(std::int32_t u, std::int32_t v) const noexcept {
    return lut_[static_cast<std::size_t>(v) * static_cast<std::size_t>(size_) +
                static_cast<std::size_t>(u)];
  }

private:
  std::int32_t size_, pan_w_, pan_h_;
  std::vector<std::int32_t> lut_;
};

// The image turned by k quarter turns counter-clockwise as drawn (k mod 4), about its centre:
// pixel (u, v) goes to (v, S - 1 - u) per turn. Exact; throws kernel::InputError("rotate") for an
// image that is not square.
[[nodiscard]] Image rotate_quarter(const Image& img, int k);

// The renderer's side of the model: for every panorama pixel (row-major), the floor point its
// centre sees, in Q16 sub-cells from the robot's centre in the robot's frame (x to its right, y
// backwards: image up is the heading), or `visible` false beyond the horizon.
struct FloorRay {
  std::int32_t x = 0, y = 0;
  bool visible = false;
};
[[nodiscard]] std::vector<FloorRay> panorama_rays(const Optics& optics);

// Where a floor point (Q16 sub-cells in the robot's frame) appears in the panorama (Q16 pixels).
[[nodiscard]] PointQ16 project(const Optics& optics, PointQ16 floor);

} // namespace antkit::devices::stc_floor
