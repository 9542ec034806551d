#pragma once
// The simulated Khepera and its world: a disk of diameter 1 (the Khepera's 5.34 cm is the unit of
// length) driven by two wheels, eight IR sensors of which the six front ones are read, and walls
// given as fixed-point segments (the arena's boundary and holes, from the geometry layer).
//
// Model (choices where the paper is silent; it used Webots' Khepera model, sampled from a real
// robot):
//  * Sensors at the Khepera's angles from the heading, counter-clockwise positive: I_0 +90,
//    I_1 +45, I_2 +10, I_3 -10, I_4 -45, I_5 -90 (the rear pair at +/-165 is not used). Each sits
//    on the body's edge and looks outward along its angle.
//  * Reading versus distance: I = 1 - d / kSensorRange for the distance d from the sensor to the
//    nearest wall along its ray, 0 beyond kSensorRange = 0.75 (4 cm, the Khepera's useful IR
//    range). Linear, so "I_0 > 0.95" means a side wall within 0.0375 units (2 mm) and the front
//    sum 2.7 is reached about 0.25 units from a wall met head on. Optional noise: a uniform
//    offset in [-noise, noise] from the trial's keyed stream, clamped to [0, 1].
//  * Differential drive, wheel base 1: per step the robot turns by speed * (m_r - m_l) radians
//    and moves speed * (m_l + m_r) / 2 along the mean of the old and new headings. speed is the
//    distance per step at wheel speed 1; kDefaultSpeed = 0.1683 makes a 50 000-step visit about
//    1680 units long, the paper's mean (measured: see the tests and the report).
//  * Collisions: a step whose end position would bring the body's disk within 0.5 of a wall
//    (closed distance < 0.5) is not taken: the robot turns in place but does not move, and the
//    step is counted as blocked. Steps are at most 0.043 units (0.25 x speed), far shorter than any
//    wall is thick, so checking the end position is enough: no step ever overlaps a wall.
//
// Everything that feeds a decision is integer or Q15.16; the world is immutable after
// construction and safe to share between threads.
//
// Storage (issue 27): WorldCore is the world over spans the caller provides, freestanding (it
// builds for the Cortex-M image, mcu/, from world.cpp); World owns that storage in vectors and
// throws where WorldCore returns a WorldError (world_host.cpp). Same source, same answers.
#include <antkit/buffon/exploration.hpp>
#include <antkit/kernel/angle.hpp>
#include <antkit/kernel/fixed.hpp>
#include <antkit/kernel/random.hpp>
#include <antkit/kernel/segment.hpp>
#include <cstdint>
#include <span>
#include <vector>

namespace antkit::buffon {

using kernel::Angle;
using kernel::FxPoint;
using kernel::FxSegment;

inline constexpr Fx kBodyRadius = Fx::from_raw(32768);   // 0.5: the body is the unit diameter
inline constexpr Fx kSensorRange = Fx::from_raw(49152);  // 0.75
inline constexpr Fx kDefaultSpeed = Fx::from_raw(11031); // 0.1683 (11031 / 65536)
// Start (Section 4.1): the centre 0.83 units above the wall below the arena's central bottom.
inline constexpr Fx kStartClearance = Fx::from_raw(54395); // 0.83

struct Pose {
  FxPoint position;
  Angle heading; // counter-clockwise from +x, y up
};

struct BodyParams {
  Fx speed = kDefaultSpeed; // distance per step at wheel speed 1
  Fx noise{};               // IR noise amplitude (0: none)
};

// Why a world cannot be built or started (WorldCore::plan, WorldCore::place_start); the host's
// World throws kernel::InputError(error_where(e), describe(e)) for them.
enum class WorldError : std::uint8_t {
  None,
  NoWalls,      // no wall at all
  TooManyWalls, // 2^31 walls or more
  Speed,        // speed per step outside (0, 0.25]
  Noise,        // noise outside [0, 1]
  Coordinates,  // a wall end beyond +/-16000 units
  TooLarge,     // the walls' box larger than 4096 x 4096 units
  NoStartWall,  // no wall below the arena's centre to start at
  StartBlocked, // the start position is not clear of the walls
};
[[nodiscard]] const char* describe(WorldError e) noexcept;
// The option or input a world error is about: "arena", "speed" or "noise".
[[nodiscard]] const char* error_where(WorldError e) noexcept;

// A wall as a bucket stores it: its ends and its bounding box in raw units, so that the queries
// can reject it with four comparisons before any product (a wall whose box is out of reach
// cannot change a reading or a collision, so the answers are those of the full loop).
struct BucketWall {
  std::int32_t ax, ay, bx, by;
  std::int32_t x0, y0, x1, y1; // bounding box
};

// The storage a world's buckets need (WorldCore::plan): `buckets` + 1 bucket starts and `members`
// bucket entries. 64-bit so that a 32-bit target can refuse a layout it could not address.
struct WorldLayout {
  std::uint64_t buckets = 0;
  std::uint64_t members = 0;
  FxPoint lower{}, upper{}; // the walls' bounding box (WorldCore::lower, upper once built)
  [[nodiscard]] std::uint64_t bytes() const noexcept {
    return (buckets + 1) * sizeof(std::uint32_t) + members * sizeof(BucketWall);
  }
};

// The world over storage the caller provides (issue 27): the walls, the bucket starts and the
// bucket entries are spans, so that the same code runs on the host, where World (below) owns them
// in vectors, and on a microcontroller, where they live in a buffer the firmware gives
// (mcu/src/main.cpp). Freestanding: no allocation, no exception; errors are returned. A
// WorldCore built by build() answers exactly as a World over the same walls and body.
class WorldCore {
public:
  // Checks the walls and the body and computes the storage build() needs (None: ok).
  [[nodiscard]] static WorldError plan(std::span<const FxSegment> walls, BodyParams body,
                                       WorldLayout& layout) noexcept;
  // Builds the buckets into `start` (layout.buckets + 1 entries) and `members` (layout.members),
  // after plan() gave `layout` and None. The spans must outlive the world (they are not copied).
  void build(std::span<const FxSegment> walls, BodyParams body, const WorldLayout& layout,
             std::span<std::uint32_t> start, std::span<BucketWall> members) noexcept;

  [[nodiscard]] std::span<const FxSegment> walls() const noexcept { return walls_; }
  [[nodiscard]] const BodyParams& body() const noexcept { return body_; }
  // Bounding box of the walls, raw Q15.16.
  [[nodiscard]] FxPoint lower() const noexcept { return lo_; }
  [[nodiscard]] FxPoint upper() const noexcept { return hi_; }

  // The six front readings at `pose`; `noise` may be null when body().noise is 0.
  //
  // sense(), clear() and move() are inline so that the step loop (run_visit) sees through them:
  // far from the walls, where a visit spends most of its steps, the bucket is empty, every reading
  // is 0 and every position is clear, and that is decided here without a call; only steps near a
  // wall take the out-of-line paths (sense_walls, clear_walls), which test the bucket's walls.
  [[nodiscard]] Observation sense(const Pose& pose, kernel::Stream* noise) const {
    if (nearby(pose.position).empty() && !(noise != nullptr && body_.noise > Fx{}))
      return Observation{}; // no wall within 1.5 of the centre: every ray misses (see sense_walls)
    return sense_walls(pose, noise);
  }
  // Does the body's disk centred at p keep at least 0.5 from every wall (exact)?
  [[nodiscard]] bool clear(FxPoint p) const {
    const auto bucket = nearby(p);
    return bucket.empty() || clear_walls(p, bucket);
  }
  // Carries out one command; returns false when the translation was blocked (pose turned only).
  bool move(Pose& pose, const Command& cmd) const {
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

  // Section 4.1: the bottom-most wall point on the vertical line through the walls' horizontal
  // centre, the robot's centre 0.83 above it, heading up (into the arena) +/- 15 degrees drawn
  // from `stream`. Reading of "within +/-15 degrees of the wall": the heading is perpendicular to
  // the wall it starts at, give or take 15 degrees. NoStartWall or StartBlocked when there is no
  // such point or it is not clear (then `pose` is unchanged).
  [[nodiscard]] WorldError place_start(kernel::Stream& stream, Pose& pose) const noexcept;

protected:
  // The walls registered in the bucket holding p (empty when p is far from every wall).
  [[nodiscard]] std::span<const BucketWall> nearby(FxPoint p) const noexcept {
    // Buckets are 2^16 raw wide: an arithmetic shift is the floor division (C++20 defines >> on
    // negatives).
    const std::int64_t bx = (std::int64_t{p.x.raw()} >> 16) - grid_x0_;
    const std::int64_t by = (std::int64_t{p.y.raw()} >> 16) - grid_y0_;
    if (bx < 0 || by < 0 || bx >= grid_w_ || by >= grid_h_) return {}; // far from every wall
    const auto k = static_cast<std::size_t>(by * grid_w_ + bx);
    return {members_.data() + start_[k], members_.data() + start_[k + 1]};
  }
  // sense() and clear() over the bucket's walls.
  [[nodiscard]] Observation sense_walls(const Pose& pose, kernel::Stream* noise) const;
  [[nodiscard]] bool clear_walls(FxPoint p, std::span<const BucketWall> bucket) const;
  // World::ray_reading for a range already checked to be in (0, kSensorRange].
  [[nodiscard]] Fx ray_reading_in_range(const Pose& pose, Angle offset, Fx range) const noexcept;
  // Points the spans at other storage holding the same contents (World's copies and moves).
  void rebind(std::span<const FxSegment> walls, std::span<const std::uint32_t> start,
              std::span<const BucketWall> members) noexcept {
    walls_ = walls, start_ = start, members_ = members;
  }

private:
  std::span<const FxSegment> walls_;
  BodyParams body_;
  FxPoint lo_{}, hi_{};
  // Uniform grid of 1-unit buckets; bucket k lists the walls within kMargin of any point in it,
  // copied into the bucket (members_[start_[k] .. start_[k + 1])) so that a query reads one
  // contiguous run.
  std::int64_t grid_x0_ = 0, grid_y0_ = 0, grid_w_ = 0, grid_h_ = 0;
  std::span<const std::uint32_t> start_;
  std::span<const BucketWall> members_;
};

// The host's world: a WorldCore whose walls and buckets it owns in vectors, errors thrown as
// kernel::InputError. Immutable after construction and safe to share between threads.
class World : public WorldCore {
public:
  using BucketWall = buffon::BucketWall;
  // Throws kernel::InputError (where = "arena", "speed" or "noise"; WorldError) when there are no
  // walls, the arena is too large for the fixed-point format (coordinates beyond +/-16000 units)
  // or the body is out of range.
  World(std::vector<FxSegment> walls, BodyParams body = {});
  World(const World& other);
  World(World&& other) noexcept;
  World& operator=(const World& other);
  World& operator=(World&& other) noexcept;
  ~World() = default;

  // One IR reading along a ray at `offset` from the heading, from the body's edge, for a sensor of
  // range `range` in (0, kSensorRange]: 1 - d / range for the distance d to the nearest wall along
  // the ray, 0 when none is within range (the model of sense(), for any sensor angle and a shorter
  // range; no noise). For bodies other than the simulated Khepera: the firmware emulators place
  // each robot's sensors at its own angles (devices/emulator.hpp). Throws std::invalid_argument
  // for a range outside (0, kSensorRange]: the walls' buckets only reach that far.
  [[nodiscard]] Fx ray_reading(const Pose& pose, Angle offset, Fx range) const;

  // place_start (WorldCore), its errors thrown as InputError("arena", ...).
  [[nodiscard]] Pose start_pose(kernel::Stream& stream) const;

private:
  void rebind_owned() noexcept { rebind(owned_walls_, owned_start_, owned_members_); }
  std::vector<FxSegment> owned_walls_;
  std::vector<std::uint32_t> owned_start_;
  std::vector<BucketWall> owned_members_;
};

} // namespace antkit::buffon
