// The simulated Khepera and its walls (world.hpp): WorldCore, freestanding (the Cortex-M image
// compiles this file too: no allocation, no exception). The host's World is world_host.cpp.
#include <algorithm>
#include <antkit/buffon/world.hpp>
#include <antkit/kernel/fixed_random.hpp>
#include <array>

namespace antkit::buffon {

namespace {

using i128 = kernel::int128; // int_ops.hpp: __int128, or soft::Int on 32-bit targets

constexpr std::int64_t kUnit = 65536;
// A wall is registered in every bucket within this distance of it: body radius + sensor range +
// a longest step, rounded up (0.5 + 0.75 + 0.04 < 1.5).
constexpr std::int64_t kMargin = kUnit * 3 / 2;
constexpr std::int64_t kBucket = kUnit;
// Coordinates beyond this are rejected: keeps every difference and product in range below.
constexpr std::int64_t kMaxCoordinate = 16000 * kUnit;

// The front sensors at +/-10 degrees (Khepera: +90, +45, +10, -10, -45, -90; the others are
// derived from the heading's and +45's sine and cosine in sense()).
constexpr Angle kPlus10 = Angle::from_degrees(10);
constexpr Angle kMinus10 = Angle::from_degrees(-10);

std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  const std::int64_t q = a / b;
  return (a % b != 0 && ((a < 0) != (b < 0))) ? q - 1 : q;
}

// Squared distance from p to the closed segment s, compared exactly with rho^2: true when the
// distance is below rho.
bool closer_than(FxPoint p, const BucketWall& s, std::int64_t rho) {
  const i128 ax = s.ax, ay = s.ay, bx = s.bx, by = s.by;
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

// The nearest hit of the ray S + t D (t in [0, 1]) with wall w, folded into the running minimum
// best_num / best_den. Exact in 64 bits: the constructor keeps the arena within 4097 units (2^28.01
// raw) and a queried point lies within 4 units of the walls' bounding box, so every coordinate
// difference q is below 2^28.1 raw, |D| <= 49152 < 2^15.6 and a wall's extent e below 2^28.01:
// den = D x e and sn2 = q x D stay below 2^44.7, tn = q x e below 2^57.2, and once tn <= den the
// products tn * best_den and best_num * den (best_den, best_num <= 2^16 den) stay below 2^61
// (the same values as the 128-bit arithmetic this replaced, which the golden hashes confirm).
//
// The result does not depend on the order of the walls: the minimum is kept as
// floor(2^16 t) / 2^16, and a later wall replaces it only when its exact t is smaller, so the
// final value is floor(2^16 t_min) whatever the order (or 1 when no wall is hit with t < 1). That
// is why the queries may skip walls that cannot be hit.
inline void ray_hit(const BucketWall& w, std::int64_t sx, std::int64_t sy, std::int64_t dx,
                    std::int64_t dy, std::int64_t& best_num, std::int64_t& best_den) {
  const std::int64_t ex = std::int64_t{w.bx} - w.ax, ey = std::int64_t{w.by} - w.ay;
  const std::int64_t qx = std::int64_t{w.ax} - sx, qy = std::int64_t{w.ay} - sy;
  std::int64_t den = dx * ey - dy * ex;
  std::int64_t tn = qx * ey - qy * ex;
  std::int64_t sn2 = qx * dy - qy * dx;
  if (den == 0) return; // parallel: a wall along the ray is seen through its ends
  if (den < 0) den = -den, tn = -tn, sn2 = -sn2;
  if (tn < 0 || tn > den || sn2 < 0 || sn2 > den) return;
  if (tn * best_den < best_num * den) {
    // Keep the fraction small: t as a Q16 fraction is all the reading needs.
    best_num = (tn << 16) / den;
    best_den = 65536;
  }
}

} // namespace

const char* describe(WorldError e) noexcept {
  switch (e) {
  case WorldError::None:
    return "ok";
  case WorldError::NoWalls:
    return "an arena needs at least one wall";
  case WorldError::TooManyWalls:
    return "too many walls";
  case WorldError::Speed:
    return "the speed per step must be in (0, 0.25] units";
  case WorldError::Noise:
    return "the sensor noise must be in [0, 1]";
  case WorldError::Coordinates:
    return "wall coordinates must lie within +/-16000 units";
  case WorldError::TooLarge:
    return "the arena must fit in 4096 x 4096 units";
  case WorldError::NoStartWall:
    return "no wall below the arena's centre to start at";
  case WorldError::StartBlocked:
    return "the start position (0.83 above the central bottom wall) is not clear of the walls: "
           "the arena is too small or not closed there";
  }
  return "unknown world error";
}

const char* error_where(WorldError e) noexcept {
  return e == WorldError::Speed ? "speed" : e == WorldError::Noise ? "noise" : "arena";
}

namespace {
// The grid of buckets over the walls' box grown by kMargin (plan and build agree on it).
struct Grid {
  std::int64_t x0, y0, x1, y1; // the walls' box, raw
  std::int64_t gx0, gy0, w, h; // the bucket grid: origin (in buckets) and size
};

WorldError grid_of(std::span<const FxSegment> walls, BodyParams body, Grid& g) noexcept {
  if (walls.empty()) return WorldError::NoWalls;
  if (walls.size() >= (std::size_t{1} << 31)) return WorldError::TooManyWalls;
  if (body.speed <= Fx{} || body.speed > Fx::from_ratio(1, 4)) return WorldError::Speed;
  if (body.noise < Fx{} || body.noise > Fx::one()) return WorldError::Noise;
  std::int64_t x0 = walls[0].a.x.raw(), y0 = walls[0].a.y.raw(), x1 = x0, y1 = y0;
  for (const auto& w : walls)
    for (FxPoint q : {w.a, w.b}) {
      if (q.x.raw() < -kMaxCoordinate || q.x.raw() > kMaxCoordinate ||
          q.y.raw() < -kMaxCoordinate || q.y.raw() > kMaxCoordinate)
        return WorldError::Coordinates;
      x0 = std::min<std::int64_t>(x0, q.x.raw());
      y0 = std::min<std::int64_t>(y0, q.y.raw());
      x1 = std::max<std::int64_t>(x1, q.x.raw());
      y1 = std::max<std::int64_t>(y1, q.y.raw());
    }
  if ((x1 - x0) / kBucket > 4096 || (y1 - y0) / kBucket > 4096) return WorldError::TooLarge;
  g.x0 = x0, g.y0 = y0, g.x1 = x1, g.y1 = y1;
  g.gx0 = floor_div(x0 - kMargin, kBucket);
  g.gy0 = floor_div(y0 - kMargin, kBucket);
  g.w = floor_div(x1 + kMargin, kBucket) - g.gx0 + 1;
  g.h = floor_div(y1 + kMargin, kBucket) - g.gy0 + 1;
  return WorldError::None;
}

// The buckets (columns bx0..bx1, rows by0..by1, absolute) that meet the bounding box of s grown by
// kMargin: a superset of the buckets within kMargin of it, which is all the queries need.
struct BucketBox {
  std::int64_t bx0, bx1, by0, by1;
};
BucketBox buckets_of(const FxSegment& s) noexcept {
  return {floor_div(std::min(s.a.x.raw(), s.b.x.raw()) - kMargin, kBucket),
          floor_div(std::max(s.a.x.raw(), s.b.x.raw()) + kMargin, kBucket),
          floor_div(std::min(s.a.y.raw(), s.b.y.raw()) - kMargin, kBucket),
          floor_div(std::max(s.a.y.raw(), s.b.y.raw()) + kMargin, kBucket)};
}
} // namespace

WorldError WorldCore::plan(std::span<const FxSegment> walls, BodyParams body,
                           WorldLayout& layout) noexcept {
  Grid g{};
  if (const WorldError e = grid_of(walls, body, g); e != WorldError::None) return e;
  layout.buckets = static_cast<std::uint64_t>(g.w * g.h);
  layout.lower = {Fx::from_raw(static_cast<std::int32_t>(g.x0)),
                  Fx::from_raw(static_cast<std::int32_t>(g.y0))};
  layout.upper = {Fx::from_raw(static_cast<std::int32_t>(g.x1)),
                  Fx::from_raw(static_cast<std::int32_t>(g.y1))};
  layout.members = 0;
  for (const auto& w : walls) {
    const BucketBox b = buckets_of(w);
    layout.members += static_cast<std::uint64_t>((b.bx1 - b.bx0 + 1) * (b.by1 - b.by0 + 1));
  }
  return WorldError::None;
}

void WorldCore::build(std::span<const FxSegment> walls, BodyParams body, const WorldLayout& layout,
                      std::span<std::uint32_t> start, std::span<BucketWall> members) noexcept {
  Grid g{};
  (void)grid_of(walls, body, g); // None: plan() said so
  walls_ = walls;
  body_ = body;
  lo_ = {Fx::from_raw(static_cast<std::int32_t>(g.x0)),
         Fx::from_raw(static_cast<std::int32_t>(g.y0))};
  hi_ = {Fx::from_raw(static_cast<std::int32_t>(g.x1)),
         Fx::from_raw(static_cast<std::int32_t>(g.y1))};
  grid_x0_ = g.gx0, grid_y0_ = g.gy0, grid_w_ = g.w, grid_h_ = g.h;
  const auto buckets = static_cast<std::size_t>(layout.buckets);
  auto for_buckets = [&](const FxSegment& s, auto&& f) {
    const BucketBox b = buckets_of(s);
    for (std::int64_t by = b.by0; by <= b.by1; ++by)
      for (std::int64_t bx = b.bx0; bx <= b.bx1; ++bx)
        f(static_cast<std::size_t>((by - grid_y0_) * grid_w_ + (bx - grid_x0_)));
  };
  // Counting first, then filling without a second array: start[k] counts bucket k's walls, its
  // prefix sum is the end of bucket k, and the walls taken last to first are placed below it, so
  // that start[k] ends at the bucket's beginning and each bucket lists its walls in their order.
  for (std::size_t k = 0; k <= buckets; ++k) start[k] = 0;
  for (const auto& w : walls) for_buckets(w, [&](std::size_t k) { ++start[k]; });
  for (std::size_t k = 1; k < buckets; ++k) start[k] += start[k - 1];
  start[buckets] = buckets > 0 ? start[buckets - 1] : 0;
  for (std::size_t i = walls.size(); i-- > 0;) {
    const FxSegment& w = walls[i];
    const BucketWall entry{w.a.x.raw(),
                           w.a.y.raw(),
                           w.b.x.raw(),
                           w.b.y.raw(),
                           std::min(w.a.x.raw(), w.b.x.raw()),
                           std::min(w.a.y.raw(), w.b.y.raw()),
                           std::max(w.a.x.raw(), w.b.x.raw()),
                           std::max(w.a.y.raw(), w.b.y.raw())};
    for_buckets(w, [&](std::size_t k) { members[--start[k]] = entry; });
  }
  start_ = start;
  members_ = members;
}

// nearby() (world.hpp) shifts by 16 for the bucket.
static_assert(kBucket == std::int64_t{1} << 16);

Observation WorldCore::sense_walls(const Pose& pose, kernel::Stream* noise) const {
  Observation obs;
  const FxPoint c = pose.position;
  const std::int64_t cx = c.x.raw(), cy = c.y.raw();
  // Every ray lies within kReach of c (the body's edge plus the range, each product rounded by at
  // most half a raw unit): walls whose bounding box is farther cannot be hit. They are dropped
  // once here, and each ray then tests only the walls whose box meets its own box.
  constexpr std::int64_t kReach = kBodyRadius.raw() + kSensorRange.raw() + 2;
  const auto bucket = nearby(c);
  // The candidates are copied next to each other; the filters below are written without branches
  // (a comparison's outcome is added, not branched on) because which walls pass is close to
  // random from one step to the next and mispredicted branches were most of sense()'s time.
  constexpr std::size_t kMaxNear = 128;
  std::array<BucketWall, kMaxNear> near; // NOLINT: filled below up to `count`
  std::size_t count = 0;
  for (const auto& w : bucket) {
    const bool in = (w.x1 >= cx - kReach) & (w.x0 <= cx + kReach) & (w.y1 >= cy - kReach) &
                    (w.y0 <= cy + kReach);
    near[std::min(count, kMaxNear - 1)] = w;
    count += in ? 1u : 0u;
  }
  // More candidates than kMaxNear (not met in the paper's arenas): test the whole bucket, which
  // gives the same answer.
  const bool overflow = count > kMaxNear;
  if (count == 0) {
    // No wall within reach: every reading is 0 (what the rays would find).
  } else {
    // The sensors' directions share table lookups: +/-90 and +/-45 degrees are exact binary
    // angles (2^30 and 2^29 units), and sin_raw(x + half turn) = -sin_raw(x) exactly (the same
    // table entry, negated), so cos(h + 90) = -sin(h), sin(h + 90) = cos(h), cos(h - 90) = sin(h),
    // sin(h - 90) = -cos(h), cos(h - 45) = sin(h + 45) and sin(h - 45) = -cos(h + 45): eight
    // lookups instead of twelve, bit for bit the same values.
    static_assert(Angle::from_degrees(90).raw() == std::uint32_t{1} << 30);
    static_assert(Angle::from_degrees(45).raw() == std::uint32_t{1} << 29);
    const Angle h = pose.heading;
    const Fx ch = kernel::cos(h), sh = kernel::sin(h);
    const Angle h45 = h + Angle::from_degrees(45);
    const Fx c45 = kernel::cos(h45), s45 = kernel::sin(h45);
    const Angle h10 = h + kPlus10, hm10 = h + kMinus10;
    const std::array<Fx, 6> cosines{-sh, c45, kernel::cos(h10), kernel::cos(hm10), s45, sh};
    const std::array<Fx, 6> sines{ch, s45, kernel::sin(h10), kernel::sin(hm10), -c45, -ch};
    for (std::size_t i = 0; i < 6; ++i) {
      const Fx cs = cosines[i], sn = sines[i];
      const std::int64_t sx = cx + (kBodyRadius * cs).raw();
      const std::int64_t sy = cy + (kBodyRadius * sn).raw();
      const std::int64_t dx = (kSensorRange * cs).raw(), dy = (kSensorRange * sn).raw();
      const std::int64_t rx0 = std::min(sx, sx + dx), rx1 = std::max(sx, sx + dx);
      const std::int64_t ry0 = std::min(sy, sy + dy), ry1 = std::max(sy, sy + dy);
      // Nearest hit along the ray S + t D, t in [0, 1], as the smallest t = num / den.
      std::int64_t best_num = 1, best_den = 1;
      auto box_meets_ray = [&](const BucketWall& w) {
        return (w.x1 >= rx0) & (w.x0 <= rx1) & (w.y1 >= ry0) & (w.y0 <= ry1);
      };
      if (overflow) {
        for (const auto& w : bucket)
          if (box_meets_ray(w)) ray_hit(w, sx, sy, dx, dy, best_num, best_den);
      } else {
        std::array<std::uint8_t, kMaxNear> hits; // NOLINT: filled below up to `n`
        std::size_t n = 0;
        for (std::size_t k = 0; k < count; ++k) {
          hits[n] = static_cast<std::uint8_t>(k);
          n += box_meets_ray(near[k]) ? 1u : 0u;
        }
        for (std::size_t m = 0; m < n; ++m)
          ray_hit(near[hits[m]], sx, sy, dx, dy, best_num, best_den);
      }
      obs.ir[i] = Fx::one() - Fx::from_raw(static_cast<std::int32_t>(best_num * 65536 / best_den));
    }
  }
  if (noise != nullptr && body_.noise > Fx{}) {
    // Noise is drawn every step whether or not a wall is near, so that the stream stays aligned.
    // A reading with no wall in range is 0, and 0 + v clamped to [0, 1] is max(v, 0) as noise
    // is at most 1.
    for (auto& reading : obs.ir) {
      reading = reading + kernel::uniform(*noise, -body_.noise, body_.noise);
      reading = reading < Fx{} ? Fx{} : (reading > Fx::one() ? Fx::one() : reading);
    }
  }
  return obs;
}

Fx WorldCore::ray_reading_in_range(const Pose& pose, Angle offset, Fx range) const noexcept {
  const Angle a = pose.heading + offset;
  const Fx cs = kernel::cos(a), sn = kernel::sin(a);
  const std::int64_t sx = std::int64_t{pose.position.x.raw()} + (kBodyRadius * cs).raw();
  const std::int64_t sy = std::int64_t{pose.position.y.raw()} + (kBodyRadius * sn).raw();
  const std::int64_t dx = (range * cs).raw(), dy = (range * sn).raw();
  std::int64_t best_num = 1, best_den = 1;
  // The bucket of the centre holds every wall within kMargin >= body radius + kSensorRange of it
  // (build), so every wall the ray can meet.
  for (const auto& w : nearby(pose.position)) ray_hit(w, sx, sy, dx, dy, best_num, best_den);
  return Fx::one() - Fx::from_raw(static_cast<std::int32_t>(best_num * 65536 / best_den));
}

bool WorldCore::clear_walls(FxPoint p, std::span<const BucketWall> bucket) const {
  const std::int64_t px = p.x.raw(), py = p.y.raw(), rho = kBodyRadius.raw();
  for (const auto& w : bucket) {
    // A wall whose bounding box keeps rho away in x or y is at least rho away.
    if (w.x1 <= px - rho || w.x0 >= px + rho || w.y1 <= py - rho || w.y0 >= py + rho) continue;
    if (closer_than(p, w, rho)) return false;
  }
  return true;
}

WorldError WorldCore::place_start(kernel::Stream& stream, Pose& pose) const noexcept {
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
  if (!found) return WorldError::NoStartWall;
  const FxPoint p{Fx::from_raw(static_cast<std::int32_t>(cx)),
                  Fx::from_raw(static_cast<std::int32_t>(best + kStartClearance.raw()))};
  if (!clear(p)) return WorldError::StartBlocked;
  const Fx deg = kernel::uniform(stream, Fx::from_int(-15), Fx::from_int(15));
  pose = Pose{p, Angle::quarter_turn() + Angle::from_degrees(deg)};
  return WorldError::None;
}

} // namespace antkit::buffon
