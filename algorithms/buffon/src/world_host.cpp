// The host's World (world.hpp): WorldCore over vectors it owns, errors thrown as InputError.
#include <antkit/buffon/world.hpp>
#include <antkit/kernel/input_error.hpp>
#include <stdexcept>

namespace antkit::buffon {

World::World(std::vector<FxSegment> walls, BodyParams body) : owned_walls_(std::move(walls)) {
  WorldLayout layout;
  if (const WorldError e = plan(owned_walls_, body, layout); e != WorldError::None)
    throw kernel::InputError(error_where(e), describe(e));
  owned_start_.assign(static_cast<std::size_t>(layout.buckets) + 1, 0);
  owned_members_.resize(static_cast<std::size_t>(layout.members));
  build(owned_walls_, body, layout, owned_start_, owned_members_);
}

// The spans of WorldCore point into the vectors: a copy points them at its own; a move keeps the
// vectors' buffers, and points them again all the same.
World::World(const World& other)
    : WorldCore(other), owned_walls_(other.owned_walls_), owned_start_(other.owned_start_),
      owned_members_(other.owned_members_) {
  rebind_owned();
}

World::World(World&& other) noexcept
    : WorldCore(other), owned_walls_(std::move(other.owned_walls_)),
      owned_start_(std::move(other.owned_start_)), owned_members_(std::move(other.owned_members_)) {
  rebind_owned();
  other.rebind_owned();
}

World& World::operator=(const World& other) {
  if (this != &other) {
    WorldCore::operator=(other);
    owned_walls_ = other.owned_walls_;
    owned_start_ = other.owned_start_;
    owned_members_ = other.owned_members_;
    rebind_owned();
  }
  return *this;
}

World& World::operator=(World&& other) noexcept {
  if (this != &other) {
    WorldCore::operator=(other);
    owned_walls_ = std::move(other.owned_walls_);
    owned_start_ = std::move(other.owned_start_);
    owned_members_ = std::move(other.owned_members_);
    rebind_owned();
    other.rebind_owned();
  }
  return *this;
}

Fx World::ray_reading(const Pose& pose, Angle offset, Fx range) const {
  if (range <= Fx{} || range > kSensorRange)
    throw std::invalid_argument("ray_reading: the range must be in (0, 0.75] units");
  return ray_reading_in_range(pose, offset, range);
}

Pose World::start_pose(kernel::Stream& stream) const {
  Pose pose{};
  if (const WorldError e = place_start(stream, pose); e != WorldError::None)
    throw kernel::InputError("arena", describe(e));
  return pose;
}

} // namespace antkit::buffon
