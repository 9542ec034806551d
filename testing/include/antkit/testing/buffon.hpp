#pragma once
// Rich checks of a Buffon trial (paper 000's measurement, algorithms/buffon): run it with
// TrialParams::keep_trails and hold the result to what the kernel promises.
//   1 crossings: crossings_exact equals the plain loop over every pair of segments of the two
//     trails (kernel::properly_cross), the count the closed form divides by;
//   2 body: every point of both trails keeps the body's disk clear of the walls (World::clear)
//     and lies inside the arena (even-odd rule over the walls, exact integer arithmetic);
//   3 budget: each visit took at most its cap of steps (or both together at most the budget).
#include <antkit/buffon/measurement.hpp>
#include <antkit/buffon/world.hpp>
#include <cstdint>
#include <span>
#include <string>

namespace antkit::testing {

struct BuffonTrialCheck {
  bool ok = true;
  std::string rule;        // "1 crossings", "2 body" or "3 budget"
  int visit = 0;           // 1 or 2 when the rule is about one visit's trail
  std::int64_t point = -1; // the trail point, when the rule is about one
  std::string detail;

  explicit operator bool() const noexcept { return ok; }
  [[nodiscard]] std::string describe() const;
};

// Caps: steps1 / steps2 per visit, or (when total > 0) both visits together.
struct BuffonBudget {
  std::int64_t steps1 = 0, steps2 = 0, total = 0;
};

[[nodiscard]] BuffonTrialCheck check_buffon_trial(const buffon::World& world,
                                                  const buffon::TrialResult& trial,
                                                  const BuffonBudget& budget);

// Strictly inside the closed polygon(s) the walls bound, by the even-odd rule along a ray to +x
// (a wall counts when it straddles the point's height, half-open, and crosses right of it).
[[nodiscard]] bool inside_walls(std::span<const kernel::FxSegment> walls, kernel::FxPoint p);

} // namespace antkit::testing
