// The simulated Khepera and its walls (world.hpp).
#include <algorithm>
#include <antkit/buffon/world.hpp>
#include <antkit/kernel/fixed_random.hpp>
#include <antkit/kernel/input_error.hpp>

namespace antkit::buffon {

namespace {

__extension__ using i128 = __int128;

constexpr std::int64_t kUnit = 65536;
// A wall is registered in every bucket within this distance of it: body radius + sensor range +
// a longest step, rounded up (0.5 + 0.75 + 0.04 < 1.5).
constexpr std::int64_t kMargin = kUnit * 3 / 2;
constexpr std::int64_t kBucket = kUnit;
// Coordinates beyond this are rejected: keeps every difference and product in range below.
constexpr std::int64_t kMaxCoordinate = 16000 * kUnit;

// The six front sensors' directions (Khepera: +90, +45, +10, -10, -45, -90 degrees).
const std::array<Angle, 6> kSensorAngles{Angle::from_degrees(90),  Angle::from_degrees(45),
                                         Angle::from_degrees(10),  Angle::from_degrees(-10),
                                         Angle::from_degrees(-45), Angle::from_degrees(-90)};

std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  const std::int64_t q = a / b;
  return (a % b != 0 && ((a < 0) != (b < 0))) ? q - 1 : q;
}

// Squared distance from p to the closed segment s, compared exactly with rho^2: true when the
// distance is below rho.
bool closer_than(FxPoint p, const FxSegment& s, std::int64_t rho) {
  const i128 ax = s.a.x.raw(), ay = s.a.y.raw(), bx = s.b.x.raw(), by = s.b.y.raw();
  const i128 px = p.x.raw(), py = p.y.raw();
  const i128 abx = bx - ax, aby = by - ay, apx = px - ax, apy = py - ay;
  const i128 rho2 = i128{rho} * rho;
  const i128 dot = apx * abx + apy * aby;
  const i128 len2 = abx * abx + aby * aby;
  if (dot <= 0 || len2 == 0) return apx * apx + apy * apy < rho2;
  if (dot >= len2) {
    const i128 bpx = px - bx, bpy = py - by;
    return bpx * bpx + bpy * bpy < rho2;
  }
  const i128 cross = apx * aby - apy * abx;
  return cross * cross < rho2 * len2;
}

} // namespace

World::World(std::vector<FxSegment> walls, BodyParams body)
    : walls_(std::move(walls)), body_(body) {
  if (walls_.empty()) throw kernel::InputError("arena", "an arena needs at least one wall");
  if (walls_.size() >= (std::size_t{1} << 31)) throw kernel::InputError("arena", "too many walls");
  if (body_.speed <= Fx{} || body_.speed > Fx::from_ratio(1, 4))
    throw kernel::InputError("speed", "the speed per step must be in (0, 0.25] units");
  if (body_.noise < Fx{} || body_.noise > Fx::one())
    throw kernel::InputError("noise", "the sensor noise must be in [0, 1]");
  std::int64_t x0 = walls_[0].a.x.raw(), y0 = walls_[0].a.y.raw(), x1 = x0, y1 = y0;
  for (const auto& w : walls_)
    for (FxPoint q : {w.a, w.b}) {
      if (q.x.raw() < -kMaxCoordinate || q.x.raw() > kMaxCoordinate ||
          q.y.raw() < -kMaxCoordinate || q.y.raw() > kMaxCoordinate)
        throw kernel::InputError("arena", "wall coordinates must lie within +/-16000 units");
      x0 = std::min<std::int64_t>(x0, q.x.raw());
      y0 = std::min<std::int64_t>(y0, q.y.raw());
      x1 = std::max<std::int64_t>(x1, q.x.raw());
      y1 = std::max<std::int64_t>(y1, q.y.raw());
    }
  lo_ = {Fx::from_raw(static_cast<std::int32_t>(x0)), Fx::from_raw(static_cast<std::int32_t>(y0))};
  hi_ = {Fx::from_raw(static_cast<std::int32_t>(x1)), Fx::from_raw(static_cast<std::int32_t>(y1))};
  if ((x1 - x0) / kBucket > 4096 || (y1 - y0) / kBucket > 4096)
    throw kernel::InputError("arena", "the arena must fit in 4096 x 4096 units");

  grid_x0_ = floor_div(x0 - kMargin, kBucket);
  grid_y0_ = floor_div(y0 - kMargin, kBucket);
  grid_w_ = floor_div(x1 + kMargin, kBucket) - grid_x0_ + 1;
  grid_h_ = floor_div(y1 + kMargin, kBucket) - grid_y0_ + 1;
  const auto buckets = static_cast<std::size_t>(grid_w_ * grid_h_);
  // Register each wall in the buckets that meet its bounding box grown by kMargin (a superset of
  // the buckets within kMargin of it, which is all the queries need), counting first then filling.
  auto for_buckets = [&](const FxSegment& s, auto&& f) {
    const std::int64_t bx0 = floor_div(std::min(s.a.x.raw(), s.b.x.raw()) - kMargin, kBucket);
    const std::int64_t bx1 = floor_div(std::max(s.a.x.raw(), s.b.x.raw()) + kMargin, kBucket);
    const std::int64_t by0 = floor_div(std::min(s.a.y.raw(), s.b.y.raw()) - kMargin, kBucket);
    const std::int64_t by1 = floor_div(std::max(s.a.y.raw(), s.b.y.raw()) + kMargin, kBucket);
    for (std::int64_t by = by0; by <= by1; ++by)
      for (std::int64_t bx = bx0; bx <= bx1; ++bx)
        f(static_cast<std::size_t>((by - grid_y0_) * grid_w_ + (bx - grid_x0_)));
  };
  start_.assign(buckets + 1, 0);
  for (const auto& w : walls_) for_buckets(w, [&](std::size_t k) { ++start_[k + 1]; });
  for (std::size_t k = 0; k < buckets; ++k) start_[k + 1] += start_[k];
  members_.resize(start_[buckets]);
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < walls_.size(); ++i)
    for_buckets(walls_[i],
                [&](std::size_t k) { members_[fill[k]++] = static_cast<std::uint32_t>(i); });
}

template <class F>
void World::for_nearby(FxPoint p, F&& f) const {
  const std::int64_t bx = floor_div(p.x.raw(), kBucket) - grid_x0_;
  const std::int64_t by = floor_div(p.y.raw(), kBucket) - grid_y0_;
  if (bx < 0 || by < 0 || bx >= grid_w_ || by >= grid_h_) return; // far from every wall
  const auto k = static_cast<std::size_t>(by * grid_w_ + bx);
  for (std::uint32_t m = start_[k]; m < start_[k + 1]; ++m) f(walls_[members_[m]]);
}

Observation World::sense(const Pose& pose, kernel::Stream* noise) const {
  Observation obs;
  const FxPoint c = pose.position;
  bool any = false;
  for_nearby(c, [&any](const FxSegment&) { any = true; });
  for (std::size_t i = 0; i < 6 && any; ++i) {
    const Angle dir = pose.heading + kSensorAngles[i];
    const Fx cs = kernel::cos(dir), sn = kernel::sin(dir);
    const std::int64_t sx = c.x.raw() + (kBodyRadius * cs).raw();
    const std::int64_t sy = c.y.raw() + (kBodyRadius * sn).raw();
    const std::int64_t dx = (kSensorRange * cs).raw(), dy = (kSensorRange * sn).raw();
    // Nearest hit along the ray S + t D, t in [0, 1], as the smallest t = num / den.
    std::int64_t best_num = 1, best_den = 1;
    for_nearby(c, [&](const FxSegment& s) {
      const std::int64_t ex = std::int64_t{s.b.x.raw()} - s.a.x.raw();
      const std::int64_t ey = std::int64_t{s.b.y.raw()} - s.a.y.raw();
      const std::int64_t qx = std::int64_t{s.a.x.raw()} - sx, qy = std::int64_t{s.a.y.raw()} - sy;
      i128 den = i128{dx} * ey - i128{dy} * ex;
      i128 tn = i128{qx} * ey - i128{qy} * ex;
      i128 sn2 = i128{qx} * dy - i128{qy} * dx;
      if (den == 0) return; // parallel: a wall along the ray is seen through its ends
      if (den < 0) den = -den, tn = -tn, sn2 = -sn2;
      if (tn < 0 || tn > den || sn2 < 0 || sn2 > den) return;
      if (tn * best_den < i128{best_num} * den) {
        // Keep the fraction small: t as a Q16 fraction is all the reading needs.
        best_num = static_cast<std::int64_t>((tn << 16) / den);
        best_den = 65536;
      }
    });
    Fx reading = Fx::one() - Fx::from_raw(static_cast<std::int32_t>(best_num * 65536 / best_den));
    if (noise != nullptr && body_.noise > Fx{}) {
      reading = reading + kernel::uniform(*noise, -body_.noise, body_.noise);
      reading = reading < Fx{} ? Fx{} : (reading > Fx::one() ? Fx::one() : reading);
    }
    obs.ir[i] = reading;
  }
  if (!any && noise != nullptr && body_.noise > Fx{}) {
    // Noise is drawn every step whether or not a wall is near, so that the stream stays aligned.
    for (auto& reading : obs.ir) {
      const Fx v = kernel::uniform(*noise, -body_.noise, body_.noise);
      reading = v < Fx{} ? Fx{} : v;
    }
  }
  return obs;
}

bool World::clear(FxPoint p) const {
  bool ok = true;
  for_nearby(p, [&](const FxSegment& s) { ok = ok && !closer_than(p, s, kBodyRadius.raw()); });
  return ok;
}

bool World::move(Pose& pose, const Command& cmd) const {
  const Fx turn_rad = body_.speed * (cmd.right - cmd.left); // wheel base 1
  const Fx forward = body_.speed * (cmd.left + cmd.right) * Fx::from_ratio(1, 2);
  const Angle turn = Angle::from_radians(turn_rad);
  // Heading along the chord of the arc: the mean of the old and new headings.
  const Angle mid =
      pose.heading + Angle::from_raw(static_cast<std::uint32_t>(turn.signed_raw() / 2));
  pose.heading = pose.heading + turn;
  if (forward == Fx{}) return true;
  const FxPoint next{pose.position.x + forward * kernel::cos(mid),
                     pose.position.y + forward * kernel::sin(mid)};
  if (!clear(next)) return false;
  pose.position = next;
  return true;
}

Pose World::start_pose(kernel::Stream& stream) const {
  const std::int64_t cx = (std::int64_t{lo_.x.raw()} + hi_.x.raw()) / 2;
  bool found = false;
  std::int64_t best = 0;
  for (const auto& w : walls_) {
    const std::int64_t ax = w.a.x.raw(), bx = w.b.x.raw(), ay = w.a.y.raw(), by = w.b.y.raw();
    if ((ax < cx && bx < cx) || (ax > cx && bx > cx)) continue;
    std::int64_t y = std::min(ay, by);
    if (ax != bx) y = ay + (by - ay) * (cx - ax) / (bx - ax);
    if (!found || y < best) best = y, found = true;
  }
  if (!found) throw kernel::InputError("arena", "no wall below the arena's centre to start at");
  const FxPoint p{Fx::from_raw(static_cast<std::int32_t>(cx)),
                  Fx::from_raw(static_cast<std::int32_t>(best + kStartClearance.raw()))};
  if (!clear(p))
    throw kernel::InputError("arena", "the start position (0.83 above the central bottom wall) "
                                      "is not clear of the walls: the arena is too small or "
                                      "not closed there");
  const Fx deg = kernel::uniform(stream, Fx::from_int(-15), Fx::from_int(15));
  return Pose{p, Angle::quarter_turn() + Angle::from_degrees(deg)};
}

} // namespace antkit::buffon
