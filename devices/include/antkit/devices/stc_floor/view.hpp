#pragma once
// What the marker-floor robot reads from one frame (paper 002, "Identifying visited sub-cells",
// "Finding the green dots", "Obstacles Detection", "Angle Detection"): the pipeline from a raw RGB
// panorama to the observation the ant-like controllers consume, and the rotation measurement.
//
//   see():   dark-frame subtraction -> red / green split -> unwarp of both -> the canonical frame
//            (the image turned so that the robot stands in quadrant 0, optics.hpp) -> for each of
//            the 5 cells, its 12 sub-cell edges (stc/ant.hpp's edge masks) read by the dot finder
//            in a crop around each edge's midpoint (the paper's "crop the relevant section of the
//            image, and look for dots in it"), and each neighbour cell's red light by the same
//            finder in a crop around the cell's centre -> the masks turned back to world
//            directions.
//   The edges' midpoints come from the clicked corners: each cell is the quadrilateral of its 4
//   corners, and a point (s, t) of the unit square maps bilinearly into it, so a calibration that
//   bends the cells bends the crops with them.
//
//   measure_turn(): the paper's angle detection, measured without its line. The paper fits a line
//   through the three newest (brightest) marks before and after a turn, and the line turns by the
//   robot's turn (camera.hpp, line_heading, is that stage). On the rendered floor this was too
//   coarse for the calibration: without fading all marks are equally bright, so the three
//   brightest are not the newest and often lie nearly on a point or a square, and their line's
//   angle then moved by up to 4 degrees between two frames of a perfect quarter turn. So we take
//   up to eight marks within 3 sub-cells of the robot, their intensity centroids, match each to
//   the mark after the turn nearest to where a quarter turn puts it, and take the least-squares
//   rotation about the robot's axis between the two sets (atan2 of the summed cross and dot
//   products): the same quantity, the deviation of the turn from a quarter, from every mark.
//
// Frames of reference: the robot's heading h and quadrant q are what it believes (the pilot's
// dead reckoning on the grid: world directions 0 = E, 1 = N, 2 = W, 3 = S). Image up is the
// heading, so the robot stands in image quadrant k = q - h + 1; turning the unwarped image by -k
// quarter turns gives the canonical frame, in which index c (a direction or a quadrant) is world
// index c + q.
#include <antkit/devices/stc_floor/camera.hpp>
#include <antkit/devices/stc_floor/optics.hpp>
#include <antkit/stc/ant.hpp>
#include <cstdint>
#include <optional>

namespace antkit::devices::stc_floor {

struct ViewParams {
  std::uint8_t red_threshold = 100;   // split_channels: red above this is an obstacle light
  std::int32_t window = 5;            // the dot finder's square (unwarped pixels)
  std::uint32_t mark_min_sum = 1000;  // a mark's window sum (mean 40 a pixel at window 5)
  std::int32_t edge_crop = 6;         // half side of the crop around an edge's midpoint
  std::uint32_t light_min_sum = 1600; // an obstacle light's window sum (mean 64)
  std::int32_t cell_crop = 12;        // half side of the crop around a cell's centre
  friend bool operator==(const ViewParams&, const ViewParams&) = default;
};

// The defaults above are for 24 pixels to a sub-cell; this scales the window and crops.
[[nodiscard]] ViewParams default_view(const Calibration& c);

struct Seen {
  stc::EdgeObservation edges; // world directions and quadrants
  Image marks;                // the unwarped marks image, image frame (for measure_turn)
};

class View {
public:
  // Throws kernel::InputError for an invalid calibration or parameters.
  View(const Calibration& c, ViewParams params);
  // `frame` and `dark`: RGB panoramas of the calibration's size. q: the robot's quadrant, h its
  // heading (both mod 4). Throws kernel::InputError("frame") for frames of the wrong shape.
  [[nodiscard]] Seen see(const Image& frame, const Image& dark, int q, int h) const;
  // The canonical reading of unwarped marks and obstacles images (the last stage of see()).
  [[nodiscard]] stc::EdgeObservation read_cells(const Image& marks, const Image& obstacles) const;
  // The unwarped marks image of a frame (image frame), for measure_turn.
  [[nodiscard]] Image marks_image(const Image& frame, const Image& dark) const;
  [[nodiscard]] const Calibration& calibration() const noexcept { return calibration_; }
  [[nodiscard]] const ViewParams& params() const noexcept { return params_; }

private:
  Calibration calibration_;
  ViewParams params_;
  Unwarp unwarp_;
  // Per cell (0 current, 1 + d the neighbour in canonical direction d): its 12 edge midpoints and
  // its centre, in Q16 unwarped pixels.
  std::array<std::array<PointQ16, 12>, 5> edge_points_{};
  std::array<PointQ16, 5> centres_{};
};

// An observation in canonical indices turned to world indices (index c -> c + q): the free
// neighbours, the neighbour order and each 4-bit group of every edge mask.
[[nodiscard]] stc::EdgeObservation to_world(const stc::EdgeObservation& canonical, int q) noexcept;

// The deviation of a commanded quarter turn (sign +1 counter-clockwise, -1 clockwise) measured
// from the unwarped marks images taken before and after it, in binary-angle units (2^-32 turn):
// positive when the robot turned less than a quarter counter-clockwise (the correction to make,
// counter-clockwise positive). nullopt when fewer than two marks could be matched.
// Throws kernel::InputError("turn") unless both are square gray images of one size.
[[nodiscard]] std::optional<std::int64_t> measure_turn(const Image& before, const Image& after,
                                                       int sign, const ViewParams& params,
                                                       std::int32_t pixels_per_subcell);

} // namespace antkit::devices::stc_floor
