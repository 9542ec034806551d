#include <antkit/kernel/segment.hpp>
#include <antkit/testing/buffon.hpp>
#include <sstream>

namespace antkit::testing {

std::string BuffonTrialCheck::describe() const {
  if (ok) return "ok";
  std::ostringstream s;
  s << "rule " << rule;
  if (visit > 0) s << ", visit " << visit;
  if (point >= 0) s << ", point " << point;
  s << ": " << detail;
  return s.str();
}

bool inside_walls(std::span<const kernel::FxSegment> walls, kernel::FxPoint p) {
  using wide = kernel::detail::segment_wide;
  bool in = false;
  const std::int64_t px = p.x.raw(), py = p.y.raw();
  for (const auto& w : walls) {
    const std::int64_t ax = w.a.x.raw(), ay = w.a.y.raw(), bx = w.b.x.raw(), by = w.b.y.raw();
    if ((ay > py) == (by > py)) continue;
    // The wall's x at height py is right of px when (ax - px)(by - ay) + (py - ay)(bx - ax) has
    // the sign of by - ay.
    const wide lhs =
        static_cast<wide>(ax - px) * (by - ay) + static_cast<wide>(py - ay) * (bx - ax);
    if ((by > ay) ? lhs > 0 : lhs < 0) in = !in;
  }
  return in;
}

BuffonTrialCheck check_buffon_trial(const buffon::World& world, const buffon::TrialResult& r,
                                    const BuffonBudget& budget) {
  auto fail = [](std::string rule, int visit, std::int64_t point, std::string detail) {
    return BuffonTrialCheck{false, std::move(rule), visit, point, std::move(detail)};
  };
  std::uint64_t pairs = 0;
  for (std::size_t i = 1; i < r.trail1.size(); ++i)
    for (std::size_t j = 1; j < r.trail2.size(); ++j)
      pairs +=
          kernel::properly_cross({r.trail1[i - 1], r.trail1[i]}, {r.trail2[j - 1], r.trail2[j]});
  if (pairs != r.crossings_exact)
    return fail("1 crossings", 0, -1,
                "crossings_exact is " + std::to_string(r.crossings_exact) +
                    ", the loop over every pair of segments counts " + std::to_string(pairs));
  for (int visit = 1; visit <= 2; ++visit) {
    const auto& trail = visit == 1 ? r.trail1 : r.trail2;
    for (std::size_t i = 0; i < trail.size(); ++i) {
      if (!world.clear(trail[i]))
        return fail("2 body", visit, static_cast<std::int64_t>(i),
                    "the body's disk is not clear of the walls");
      if (!inside_walls(world.walls(), trail[i]))
        return fail("2 body", visit, static_cast<std::int64_t>(i), "outside the arena");
    }
  }
  if (r.steps1 < 0 || r.steps2 < 0 || r.length1_raw < 0 || r.length2_raw < 0)
    return fail("3 budget", 0, -1, "a negative step count or length");
  if (budget.total > 0 ? r.steps1 + r.steps2 > budget.total
                       : r.steps1 > budget.steps1 || r.steps2 > budget.steps2)
    return fail("3 budget", 0, -1,
                "the visits took " + std::to_string(r.steps1) + " and " + std::to_string(r.steps2) +
                    " steps, beyond their budget");
  return {};
}

} // namespace antkit::testing
