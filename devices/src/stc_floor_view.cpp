// What the marker-floor robot reads from a frame (stc_floor/view.hpp).
#include <algorithm>
#include <antkit/devices/stc_floor/view.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/kernel/int_ops.hpp>

namespace antkit::devices::stc_floor {

namespace {

// Each cell's corners (indices into Calibration::corners) as NW, NE, SE, SW: the current cell,
// then the neighbours E, N, W, S (optics.hpp's table).
constexpr std::array<std::array<std::uint8_t, 4>, 5> kCellCorners{
    {{5, 2, 11, 8}, {2, 1, 0, 11}, {4, 3, 2, 5}, {6, 5, 8, 7}, {8, 11, 10, 9}}};

// The 12 edges' midpoints in quarters of the cell (s east, t south), by mask bit (stc/ant.hpp):
// cross boxes (interior edge between e and e - 1), turn boxes (e's exterior edge in direction
// e - 1), then e's exterior edge in direction e.
constexpr std::array<std::array<std::int8_t, 2>, 12> kEdgeQuarters{{{2, 3},
                                                                    {3, 2},
                                                                    {2, 1},
                                                                    {1, 2},
                                                                    {3, 4},
                                                                    {4, 1},
                                                                    {1, 0},
                                                                    {0, 3},
                                                                    {4, 3},
                                                                    {3, 0},
                                                                    {0, 1},
                                                                    {1, 4}}};

PointQ16 bilinear(const std::array<PointQ16, 4>& q, std::int64_t s, std::int64_t t) {
  const std::int64_t w_nw = (4 - s) * (4 - t), w_ne = s * (4 - t), w_se = s * t, w_sw = (4 - s) * t;
  auto mix = [&](std::int64_t PointQ16::*c) {
    const std::int64_t n =
        w_nw * (q[0].*c) + w_ne * (q[1].*c) + w_se * (q[2].*c) + w_sw * (q[3].*c);
    return n >= 0 ? (n + 8) / 16 : -((-n + 8) / 16);
  };
  return {mix(&PointQ16::x), mix(&PointQ16::y)};
}

std::int64_t floor_px(std::int64_t q16) {
  return q16 >= 0 ? q16 / kOne : -((-q16 + kOne - 1) / kOne);
}

// Whether the dot finder finds a dot in the crop of half side `half` around `p`.
bool dot_near(const Image& img, PointQ16 p, std::int32_t half, std::int32_t window,
              std::uint32_t min_sum) {
  const std::int64_t cx = floor_px(p.x), cy = floor_px(p.y);
  const std::int64_t x0 = std::max<std::int64_t>(0, cx - half),
                     y0 = std::max<std::int64_t>(0, cy - half);
  const std::int64_t x1 = std::min<std::int64_t>(img.width, cx + half + 1),
                     y1 = std::min<std::int64_t>(img.height, cy + half + 1);
  if (x1 - x0 < window || y1 - y0 < window) return false; // out of view: nothing seen
  Image crop(static_cast<std::int32_t>(x1 - x0), static_cast<std::int32_t>(y1 - y0), 1);
  for (std::int64_t y = y0; y < y1; ++y)
    std::copy_n(img.pixels.begin() + static_cast<std::ptrdiff_t>(y * img.width + x0), x1 - x0,
                crop.pixels.begin() + static_cast<std::ptrdiff_t>((y - y0) * (x1 - x0)));
  return !find_marks(crop, window, min_sum, 1).empty();
}

std::uint16_t rotate_nibbles(std::uint16_t m, int q) { // q in 0..3
  const auto k = static_cast<unsigned>(q);
  std::uint16_t out = 0;
  for (unsigned g = 0; g < 3; ++g) {
    const unsigned n = (unsigned{m} >> (4 * g)) & 0xFu;
    const unsigned r = ((n << k) | (n >> (4 - k))) & 0xFu;
    out = static_cast<std::uint16_t>(out | (r << (4 * g)));
  }
  return out;
}

// The marks a turn is measured on (before it; twice as many are looked for after it).
constexpr std::int32_t kMeasureMarks = 8;

// The intensity centroid of a mark's window, in 1/256 pixels.
std::array<std::int64_t, 2> centroid(const Image& img, const Mark& m, std::int32_t window) {
  std::int64_t sx = 0, sy = 0, s = 0;
  for (std::int32_t y = m.y; y < m.y + window; ++y)
    for (std::int32_t x = m.x; x < m.x + window; ++x) {
      const std::int64_t v = img.at(x, y);
      sx += v * (2 * x + 1);
      sy += v * (2 * y + 1);
      s += v;
    }
  if (s == 0)
    return {256 * (2 * std::int64_t{m.x} + window) / 2, 256 * (2 * std::int64_t{m.y} + window) / 2};
  return {sx * 128 / s, sy * 128 / s};
}

// The least-squares rotation about the axis from points `from` to points `to` (pairs, 1/256
// pixels relative to the image centre, y down), counter-clockwise positive in binary-angle units.
std::optional<std::int64_t> rotation_between(kernel::int128 cross, kernel::int128 dot,
                                             std::size_t pairs) {
  if (pairs < 2 || (cross == 0 && dot <= 0)) return std::nullopt;
  while (cross > INT32_MAX || cross < -INT32_MAX || dot > INT32_MAX || dot < -INT32_MAX) {
    cross /= 2;
    dot /= 2;
  }
  return std::int64_t{
      kernel::atan2(static_cast<std::int32_t>(cross), static_cast<std::int32_t>(dot)).signed_raw()};
}

// One pair's terms of that sum: e the expected point, q the seen one; in the mathematical frame
// (y up) the cross product is e.x * (-q.y) - (-e.y) * q.x.
void add_pair(const std::array<std::int64_t, 2>& e, const std::array<std::int64_t, 2>& q,
              kernel::int128& cross, kernel::int128& dot) {
  cross += kernel::int128{e[0]} * -q[1] + kernel::int128{e[1]} * q[0];
  dot += kernel::int128{e[0]} * q[0] + kernel::int128{e[1]} * q[1];
}

} // namespace

ViewParams default_view(const Calibration& c) {
  ViewParams p;
  const std::int32_t s = c.pixels_per_subcell;
  p.window = std::max(1, (5 * s + 12) / 24);
  p.edge_crop = std::max(p.window, (s + 2) / 4);
  p.cell_crop = std::max(p.window, (s + 1) / 2);
  const auto area = static_cast<std::uint32_t>(p.window * p.window);
  p.mark_min_sum = 40 * area;
  p.light_min_sum = 64 * area;
  return p;
}

View::View(const Calibration& c, ViewParams params) : calibration_(c), params_(params), unwarp_(c) {
  if (params_.window < 1 || params_.window > c.unwarped_size || params_.edge_crop < 0 ||
      params_.cell_crop < 0 || params_.edge_crop > c.unwarped_size ||
      params_.cell_crop > c.unwarped_size)
    throw kernel::InputError("view", "the dot window and crops must fit the unwarped image");
  for (std::size_t cell = 0; cell < 5; ++cell) {
    std::array<PointQ16, 4> quad;
    for (std::size_t k = 0; k < 4; ++k) quad[k] = c.corners[kCellCorners[cell][k]];
    for (std::size_t e = 0; e < 12; ++e)
      edge_points_[cell][e] = bilinear(quad, kEdgeQuarters[e][0], kEdgeQuarters[e][1]);
    centres_[cell] = bilinear(quad, 2, 2);
  }
}

stc::EdgeObservation View::read_cells(const Image& marks, const Image& obstacles) const {
  auto edges = [&](std::size_t cell) {
    std::uint16_t mask = 0;
    for (std::size_t e = 0; e < 12; ++e)
      if (dot_near(marks, edge_points_[cell][e], params_.edge_crop, params_.window,
                   params_.mark_min_sum))
        mask = static_cast<std::uint16_t>(mask | (1u << e));
    return mask;
  };
  stc::EdgeObservation o;
  o.here = edges(0);
  for (std::size_t d = 0; d < 4; ++d) {
    // A neighbour with a red light is an obstacle and has no sub-cell state: its masks stay 0
    // (the controllers never read them; marks seen there lie on its border with this cell).
    if (dot_near(obstacles, centres_[d + 1], params_.cell_crop, params_.window,
                 params_.light_min_sum))
      continue;
    o.free_neighbours = static_cast<std::uint8_t>(o.free_neighbours | (1u << d));
    o.neighbour[d] = edges(d + 1);
  }
  return o;
}

Image View::marks_image(const Image& frame, const Image& dark) const {
  const Channels ch = split_channels(subtract_dark(frame, dark), params_.red_threshold);
  return unwarp_.apply(ch.marks);
}

Seen View::see(const Image& frame, const Image& dark, int q, int h) const {
  if (frame.width != calibration_.optics.panorama_width ||
      frame.height != calibration_.optics.panorama_height)
    throw kernel::InputError(
        "frame", "expected a panorama of " + std::to_string(calibration_.optics.panorama_width) +
                     " x " + std::to_string(calibration_.optics.panorama_height) + " pixels");
  const Channels ch = split_channels(subtract_dark(frame, dark), params_.red_threshold);
  Seen seen;
  seen.marks = unwarp_.apply(ch.marks);
  const int k = (q - h + 1) & 3;
  const Image marks = rotate_quarter(seen.marks, -k);
  const Image lights = rotate_quarter(unwarp_.apply(ch.obstacles), -k);
  seen.edges = to_world(read_cells(marks, lights), q);
  return seen;
}

stc::EdgeObservation to_world(const stc::EdgeObservation& c, int q) noexcept {
  q &= 3;
  stc::EdgeObservation w;
  const unsigned f = c.free_neighbours & 0xFu;
  w.free_neighbours = static_cast<std::uint8_t>(((f << q) | (f >> (4 - q))) & 0xFu);
  w.here = rotate_nibbles(c.here, q);
  for (int d = 0; d < 4; ++d)
    w.neighbour[static_cast<std::size_t>((d + q) & 3)] =
        rotate_nibbles(c.neighbour[static_cast<std::size_t>(d)], q);
  return w;
}

std::optional<std::int64_t> measure_turn(const Image& before, const Image& after, int sign,
                                         const ViewParams& params,
                                         std::int32_t pixels_per_subcell) {
  if (!before.valid() || !after.valid() || before.width != after.width ||
      before.height != after.height || before.width != before.height || before.channels != 1 ||
      after.channels != 1)
    throw kernel::InputError("turn", "expected two square gray images of one size");
  if (params.window > before.width) return std::nullopt;
  // Centres in 1/256 pixels relative to the image centre (the robot's axis), of the marks within
  // kReach sub-cells of it (resolved finely, and inside the view in both frames).
  constexpr std::int64_t kReach = 3;
  const std::int64_t c = 128 * std::int64_t{before.width};
  const std::int64_t unit = 256 * std::int64_t{pixels_per_subcell};
  auto centres = [&](const Image& img, std::int32_t count) {
    std::vector<std::array<std::int64_t, 2>> out;
    for (const Mark& m : find_marks(img, params.window, params.mark_min_sum, count)) {
      const auto p = centroid(img, m, params.window);
      const std::array<std::int64_t, 2> r{p[0] - c, p[1] - c};
      if (r[0] * r[0] + r[1] * r[1] <= kReach * kReach * unit * unit) out.push_back(r);
    }
    return out;
  };
  const auto b = centres(before, kMeasureMarks), a = centres(after, 2 * kMeasureMarks);
  // A counter-clockwise turn of the robot turns the floor clockwise in its image: (x, y) ->
  // (-y, x) with y down. Each mark before is matched to the nearest unused mark after within half
  // a sub-cell of where the quarter turn puts it.
  const std::int64_t reach2 = unit * unit / 4;
  std::vector<bool> used(a.size(), false);
  kernel::int128 cross = 0, dot = 0;
  std::size_t pairs = 0;
  for (const auto& p : b) {
    const std::array<std::int64_t, 2> e = sign > 0 ? std::array<std::int64_t, 2>{-p[1], p[0]}
                                                   : std::array<std::int64_t, 2>{p[1], -p[0]};
    std::int64_t best = reach2;
    std::size_t pick = a.size();
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::int64_t dx = a[i][0] - e[0], dy = a[i][1] - e[1];
      if (!used[i] && dx * dx + dy * dy < best) {
        best = dx * dx + dy * dy;
        pick = i;
      }
    }
    if (pick == a.size()) continue;
    used[pick] = true;
    // The least-squares rotation about the axis from the expected places to the seen ones:
    // seen - expected, the turn still to make.
    add_pair(e, a[pick], cross, dot);
    ++pairs;
  }
  return rotation_between(cross, dot, pairs);
}

} // namespace antkit::devices::stc_floor
