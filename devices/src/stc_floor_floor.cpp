// The marker-floor robot's simulated body, floor and camera (stc_floor/floor.hpp).
#include <algorithm>
#include <antkit/devices/stc_floor/floor.hpp>
#include <antkit/kernel/fixed.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/kernel/int_ops.hpp>
#include <string>

namespace antkit::devices::stc_floor {

namespace {

using kernel::int128;

constexpr std::uint64_t kDarkPurpose = 0x6461726B;  // "dark"
constexpr std::uint64_t kNoisePurpose = 0x6E6F6973; // "nois"

std::int64_t floor_div(std::int64_t n, std::int64_t d) {
  return n >= 0 ? n / d : -((-n + d - 1) / d);
}
std::int64_t round_div(std::int64_t n, std::int64_t d) { // to nearest, halves up
  return floor_div(n + d / 2, d);
}
std::int64_t mul_q16(std::int64_t a, std::int64_t b) {
  return static_cast<std::int64_t>((int128{a} * b) >> 16);
}

} // namespace

FloorWorld::FloorWorld(const kernel::OccupancyGrid& map, stc::SubCell start, int heading,
                       FloorOptions options)
    : o_(options), width_(map.width()), height_(map.height()), shape_(stc::cell_shape(map)) {
  auto bad = [](const std::string& where, const std::string& m) {
    throw kernel::InputError(where, m);
  };
  if (o_.noise < 0 || o_.noise > 255) bad("camera noise", "expected 0 to 255");
  if (o_.dark_offset < 0 || o_.dark_offset > 255) bad("dark offset", "expected 0 to 255");
  if (o_.fade_half_life_ms < 0) bad("fade half-life", "expected a half-life >= 0");
  if (o_.rotation_error_ppm < -500000 || o_.rotation_error_ppm > 500000)
    bad("rotation error", "expected -500000 to 500000 ppm");
  if (o_.drift_ppm_per_minute < 0 || o_.drift_ppm_per_minute > 1000000)
    bad("drift", "expected 0 to 10^6 ppm a minute");
  if (o_.quarter_turn_ms < 1 || o_.drive_ms < 0 || o_.capture_ms < 0)
    bad("floor", "times must be positive");
  if (heading < 0 || heading > 3) bad("start heading", "expected 0 (E), 1 (N), 2 (W) or 3 (S)");
  validate(o_.optics, "optics");
  free_sub_.assign(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_), 0);
  for (std::int32_t y = 0; y < 2 * shape_.cells_y; ++y)
    for (std::int32_t x = 0; x < 2 * shape_.cells_x; ++x)
      free_sub_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
                static_cast<std::size_t>(x)] = map[{x, y}] == kernel::Occupancy::Free ? 1 : 0;
  free_cell_.assign(
      static_cast<std::size_t>(shape_.cells_x) * static_cast<std::size_t>(shape_.cells_y), 0);
  for (std::int32_t cy = 0; cy < shape_.cells_y; ++cy)
    for (std::int32_t cx = 0; cx < shape_.cells_x; ++cx)
      free_cell_[static_cast<std::size_t>(cy) * static_cast<std::size_t>(shape_.cells_x) +
                 static_cast<std::size_t>(cx)] = stc::cell_free(map, {cx, cy}) ? 1 : 0;
  if (start.x < 0 || start.y < 0 || start.x >= 2 * shape_.cells_x ||
      start.y >= 2 * shape_.cells_y ||
      free_sub_[static_cast<std::size_t>(start.y) * static_cast<std::size_t>(width_) +
                static_cast<std::size_t>(start.x)] == 0)
    bad("start sub-cell", "the start must be a free sub-cell of the map's cell area");
  const std::size_t slots =
      static_cast<std::size_t>(width_ + 1) * static_cast<std::size_t>(height_ + 1);
  vertical_.assign(slots, {});
  horizontal_.assign(slots, {});
  rays_ = panorama_rays(o_.optics);
  dark_pattern_.resize(rays_.size() * 3);
  kernel::Stream dark(o_.seed, kFloorExperiment, 0, 0, kDarkPurpose);
  for (auto& v : dark_pattern_) v = static_cast<std::uint8_t>(dark.between(0, o_.dark_offset));
  pos_ = {start.x * kOne + kOne / 2, start.y * kOne + kOne / 2};
  heading_ = kernel::Angle::quarter_turn() * heading;
  entered_.assign(free_sub_.size(), 0);
  path_.push_back(start);
  entered_[static_cast<std::size_t>(start.y) * static_cast<std::size_t>(width_) +
           static_cast<std::size_t>(start.x)] = 1;
  covered_ = 1;
}

bool FloorWorld::cell_free(std::int64_t cx, std::int64_t cy) const noexcept {
  if (cx < 0 || cy < 0 || cx >= shape_.cells_x || cy >= shape_.cells_y) return false;
  return free_cell_[static_cast<std::size_t>(cy) * static_cast<std::size_t>(shape_.cells_x) +
                    static_cast<std::size_t>(cx)] != 0;
}

FloorWorld::Slot* FloorWorld::slot(std::int64_t x, std::int64_t y, bool vertical) noexcept {
  if (x < 0 || y < 0 || x > width_ || y > height_) return nullptr;
  auto& v = vertical ? vertical_ : horizontal_;
  return &v[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_ + 1) +
            static_cast<std::size_t>(x)];
}

void FloorWorld::lay_mark() {
  const std::int64_t fx = kernel::cos<kernel::Fx>(heading_).raw(),
                     fy = -kernel::sin<kernel::Fx>(heading_).raw();
  const PointQ16 at{pos_.x - fx / 2, pos_.y - fy / 2};
  const bool vertical = std::abs(fx) >= std::abs(fy); // driving E/W: the edge behind is vertical
  Slot* s = vertical ? slot(round_div(at.x, kOne), floor_div(at.y, kOne), true)
                     : slot(floor_div(at.x, kOne), round_div(at.y, kOne), false);
  if (s != nullptr) *s = {at, clock_ms_};
}

void FloorWorld::note_pose() {
  const std::int64_t cx = floor_div(pos_.x, kOne) * kOne + kOne / 2,
                     cy = floor_div(pos_.y, kOne) * kOne + kOne / 2;
  const std::int64_t dx = pos_.x - cx, dy = pos_.y - cy;
  std::int64_t rest = 0;
  max_offset_ =
      std::max(max_offset_, kernel::isqrt_floor<std::int64_t, 62>(dx * dx + dy * dy, rest));
  const std::int64_t e = static_cast<std::int32_t>(heading_.raw() << 2) / 4; // to nearest quarter
  max_heading_error_ = std::max(max_heading_error_, std::abs(e));
}

bool FloorWorld::forward(std::int32_t led_ms) {
  if (led_ms > 0) {
    lay_mark();
    clock_ms_ += led_ms;
  }
  const std::int64_t fx = kernel::cos<kernel::Fx>(heading_).raw(),
                     fy = -kernel::sin<kernel::Fx>(heading_).raw();
  const PointQ16 to{pos_.x + fx, pos_.y + fy};
  const std::int64_t sx = floor_div(to.x, kOne), sy = floor_div(to.y, kOne);
  if (sx < 0 || sy < 0 || sx >= 2 * shape_.cells_x || sy >= 2 * shape_.cells_y ||
      free_sub_[static_cast<std::size_t>(sy) * static_cast<std::size_t>(width_) +
                static_cast<std::size_t>(sx)] == 0)
    return false;
  clock_ms_ += o_.drive_ms;
  pos_ = to;
  const stc::SubCell s{static_cast<std::int32_t>(sx), static_cast<std::int32_t>(sy)};
  auto& e = entered_[static_cast<std::size_t>(sy) * static_cast<std::size_t>(width_) +
                     static_cast<std::size_t>(sx)];
  if (e == 0)
    ++covered_;
  else
    ++repeats_;
  e = 1;
  path_.push_back(s);
  note_pose();
  return true;
}

void FloorWorld::rotate(std::int32_t ms) {
  const int128 minutes_ppm = int128{o_.drift_ppm_per_minute} * clock_ms_ / 60000;
  int128 rate = 1000000 + int128{o_.rotation_error_ppm} - minutes_ppm;
  rate = std::max<int128>(rate, 100000);
  const int128 units =
      int128{ms} * kernel::Angle::kQuarterTurn * rate / (int128{o_.quarter_turn_ms} * 1000000);
  heading_ += kernel::Angle::from_raw(
      static_cast<std::uint32_t>(static_cast<std::uint64_t>(static_cast<std::int64_t>(units))));
  clock_ms_ += ms < 0 ? -std::int64_t{ms} : ms;
  note_pose();
}

void FloorWorld::leds(bool on) {
  if (on) lay_mark();
}

std::uint8_t FloorWorld::mark_intensity(const Slot& s, PointQ16 w) const noexcept {
  if (s.time < 0) return 0;
  const std::int64_t dx = w.x - s.at.x, dy = w.y - s.at.y;
  if (dx * dx + dy * dy >= o_.mark_radius * o_.mark_radius) return 0;
  const std::int64_t age = clock_ms_ - s.time;
  if (o_.fade_half_life_ms == 0) return o_.mark_level;
  const std::int64_t n = age / o_.fade_half_life_ms, f = age % o_.fade_half_life_ms;
  if (n >= 16) return 0;
  const std::int64_t level = o_.mark_level >> n;
  return static_cast<std::uint8_t>(level * (2 * o_.fade_half_life_ms - f) /
                                   (2 * o_.fade_half_life_ms));
}

Image FloorWorld::capture(bool dark) {
  clock_ms_ += o_.capture_ms;
  Image img(o_.optics.panorama_width, o_.optics.panorama_height, 3);
  kernel::Stream noise(o_.seed, kFloorExperiment, static_cast<std::uint64_t>(++frames_), 0,
                       kNoisePurpose);
  const std::int64_t c = kernel::cos<kernel::Fx>(heading_).raw(),
                     s = kernel::sin<kernel::Fx>(heading_).raw();
  const std::int64_t r2 = o_.light_radius * o_.light_radius;
  for (std::size_t k = 0; k < rays_.size(); ++k) {
    std::int32_t scene_r = 0, scene_g = 0;
    const FloorRay& ray = rays_[k];
    if (!dark && ray.visible) {
      // Robot frame (x right, y back) to the floor (y down): x' = x s - y c, y' = x c + y s.
      const PointQ16 w{pos_.x + mul_q16(ray.x, s) - mul_q16(ray.y, c),
                       pos_.y + mul_q16(ray.x, c) + mul_q16(ray.y, s)};
      const std::int64_t fx = floor_div(w.x, kOne), fy = floor_div(w.y, kOne);
      const std::int64_t rx = round_div(w.x, kOne), ry = round_div(w.y, kOne);
      if (const Slot* v = slot(rx, fy, true))
        scene_g = std::max<std::int32_t>(scene_g, mark_intensity(*v, w));
      if (const Slot* h = slot(fx, ry, false))
        scene_g = std::max<std::int32_t>(scene_g, mark_intensity(*h, w));
      const std::int64_t cx = floor_div(w.x, 2 * kOne), cy = floor_div(w.y, 2 * kOne);
      if (!cell_free(cx, cy)) {
        const std::int64_t dx = w.x - (2 * cx + 1) * kOne, dy = w.y - (2 * cy + 1) * kOne;
        if (dx * dx + dy * dy < r2) scene_r = o_.light_level;
      }
    }
    for (std::size_t ch = 0; ch < 3; ++ch) {
      std::int32_t v = dark_pattern_[3 * k + ch];
      if (o_.noise > 0) v += noise.between(-o_.noise, o_.noise);
      v += ch == 0 ? scene_r : ch == 1 ? scene_g : 0;
      img.pixels[3 * k + ch] = static_cast<std::uint8_t>(std::clamp(v, 0, 255));
    }
  }
  return img;
}

} // namespace antkit::devices::stc_floor
