// The online first visit (issue 17; stopping.hpp, FirstVisitMonitor; crossing_counter.hpp,
// SelfCrossingCounter): the self-crossing count against the brute-force count of the pairs, the
// exact test against the real-valued inequality, the monitor's schedule, and what the rule does on
// whole trials (slow).
#include <algorithm>
#include <antkit/buffon/crossing_counter.hpp>
#include <antkit/buffon/estimate.hpp>
#include <antkit/buffon/measurement.hpp>
#include <antkit/buffon/stopping.hpp>
#include <antkit/buffon/two_markers.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/kernel/segment.hpp>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <numeric>
#include <rapidcheck/catch.h>
#include <string>
#include <vector>

namespace buffon = antkit::buffon;
using antkit::kernel::Fx;
using antkit::kernel::FxPoint;
using antkit::kernel::FxSegment;

namespace {
using Runs = std::array<std::uint64_t, buffon::FirstVisitMonitor::kBatches>;
constexpr std::uint32_t kGap = buffon::SelfCrossingCounter::kGap;

FxPoint raw_point(std::int64_t x, std::int64_t y) {
  return {Fx::from_raw(static_cast<std::int32_t>(x)), Fx::from_raw(static_cast<std::int32_t>(y))};
}

// Every pair (i, j), j - i >= kGap, of the polyline's segments that cross properly, as (j, i),
// sorted: what SelfCrossingCounter must report, by the definition.
std::vector<std::pair<std::uint32_t, std::uint32_t>>
brute_force_pairs(const std::vector<FxPoint>& p) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  for (std::size_t j = 0; j + 1 < p.size(); ++j) {
    const FxSegment s{p[j], p[j + 1]};
    const auto x0 = std::min(p[j].x.raw(), p[j + 1].x.raw()),
               x1 = std::max(p[j].x.raw(), p[j + 1].x.raw());
    const auto y0 = std::min(p[j].y.raw(), p[j + 1].y.raw()),
               y1 = std::max(p[j].y.raw(), p[j + 1].y.raw());
    for (std::size_t i = 0; i + kGap <= j; ++i) {
      // Bounding boxes apart: no crossing (a pre-filter only; the predicate decides).
      if (std::max(p[i].x.raw(), p[i + 1].x.raw()) < x0 ||
          std::min(p[i].x.raw(), p[i + 1].x.raw()) > x1 ||
          std::max(p[i].y.raw(), p[i + 1].y.raw()) < y0 ||
          std::min(p[i].y.raw(), p[i + 1].y.raw()) > y1)
        continue;
      if (antkit::kernel::properly_cross(s, FxSegment{p[i], p[i + 1]}))
        out.emplace_back(static_cast<std::uint32_t>(j), static_cast<std::uint32_t>(i));
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> counter_pairs(const std::vector<FxPoint>& p,
                                                                   FxPoint lower, FxPoint upper) {
  buffon::SelfCrossingCounter counter(lower, upper, p.front());
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  std::vector<std::uint32_t> crossed;
  for (std::size_t j = 1; j < p.size(); ++j) {
    crossed.clear();
    const std::uint64_t n = counter.add(p[j], &crossed);
    if (n != crossed.size()) return {}; // the count and the list disagree: fail the comparison
    for (std::uint32_t i : crossed) out.emplace_back(static_cast<std::uint32_t>(j - 1), i);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// z^2 (1 + P)^2 max(V_S, S) - 2 P^2 S^2 in long double, V_S = 10 s^2(R) = (10 sum R^2 - (2S)^2)/9.
long double margin(const Runs& runs, std::uint32_t p) {
  const long double twice_s =
      static_cast<long double>(std::accumulate(runs.begin(), runs.end(), 0ull));
  const long double s = std::floor(twice_s / 2);
  long double sq = 0;
  for (auto v : runs) sq += static_cast<long double>(v) * static_cast<long double>(v);
  const long double v = std::max((10 * sq - twice_s * twice_s) / 9, s);
  const long double P = static_cast<long double>(p) / 1e6L;
  return 5.118L * (1 + P) * (1 + P) * v - 2 * P * P * s * s;
}
} // namespace

TEST_CASE("SelfCrossingCounter reports exactly the pairs at least kGap apart that cross",
          "[property]") {
  rc::prop("online pairs == brute-force pairs on random walks", [] {
    // Lattice walks in a small box cross themselves often, overlap collinearly and pass through
    // vertices: the cases the proper-crossing predicate must tell apart.
    const auto n = *rc::gen::inRange<int>(2, 400);
    const auto scale = *rc::gen::element<std::int64_t>(1, 4096, 1 << 14, 1 << 16);
    const auto reach = *rc::gen::inRange<std::int64_t>(1, 4);
    std::vector<FxPoint> p{raw_point(0, 0)};
    std::int64_t x = 0, y = 0;
    for (int k = 1; k < n; ++k) {
      x = std::clamp<std::int64_t>(x + *rc::gen::inRange<std::int64_t>(-reach, reach + 1), -6, 6);
      y = std::clamp<std::int64_t>(y + *rc::gen::inRange<std::int64_t>(-reach, reach + 1), -6, 6);
      p.push_back(raw_point(x * scale, y * scale));
    }
    const auto expected = brute_force_pairs(p);
    RC_LOG() << "points " << n << ", scale " << scale << ", crossings " << expected.size();
    // With the walk's true box, and with a box far too small (every point clamped to the border
    // buckets): the same pairs.
    RC_ASSERT(counter_pairs(p, raw_point(-6 * scale, -6 * scale),
                            raw_point(6 * scale, 6 * scale)) == expected);
    RC_ASSERT(counter_pairs(p, raw_point(0, 0), raw_point(1, 1)) == expected);
  });
}

TEST_CASE("SelfCrossingCounter on a robot's visit 1 equals the brute-force count", "[unit]") {
  // A real trail (the Buffon behaviour in a 20-unit circle, 6 000 steps): the counter's total
  // against the brute force, and the worked fact that such a trail does cross itself.
  const auto arena = antkit::geometry::build_arena_spec("circle:d=20").arena;
  const buffon::World world(arena.walls_fx());
  buffon::TrialParams params;
  params.steps = 6000;
  antkit::kernel::TraceHash hash(1);
  const auto log =
      buffon::run_visit(world, params, 0, 1, hash, [](const buffon::Pose&) { return true; });
  const auto pairs = counter_pairs(log.trail, world.lower(), world.upper());
  INFO("6000 steps in circle:d=20, seed 1: " << pairs.size() << " self-crossings");
  CHECK(pairs.size() > 10);
  CHECK(pairs == brute_force_pairs(log.trail));
}

TEST_CASE("first_visit_met is the real inequality wherever that is not a near tie", "[property]") {
  rc::prop("exact test == sign of the long double margin", [] {
    const auto p = *rc::gen::inRange<std::uint32_t>(1, 1000000);
    const auto s = *rc::gen::oneOf(rc::gen::inRange<std::uint64_t>(1, 2000),
                                   rc::gen::inRange<std::uint64_t>(1, std::uint64_t{1} << 40));
    // 2 S crossing ends over 10 runs, some runs empty.
    Runs runs{};
    std::uint64_t left = 2 * s;
    for (std::size_t i = 0; i + 1 < runs.size(); ++i) {
      runs[i] = *rc::gen::inRange<std::uint64_t>(0, left + 1);
      left -= runs[i];
    }
    runs.back() = left;
    const long double m = margin(runs, p);
    const long double scale = static_cast<long double>(s) * static_cast<long double>(s);
    RC_LOG() << "p = " << p << ", S = " << s << ", margin = " << static_cast<double>(m);
    if (std::fabs(m) > 1e-12L * scale) RC_ASSERT(buffon::first_visit_met(runs, p) == (m <= 0));
  });
}

TEST_CASE("worked example: even runs, P = 0.1, the Poisson floor decides at S = 310", "[unit]") {
  // Floor V_S = S: S >= 5.118 * 1.21 / (2 * 0.01) = 309.64. Runs of 62 ends each (2 S = 620) have
  // spread 0, below the floor; 9 x 62 + 60 ends make S = 309.
  Runs r309{}, r310{};
  r309.fill(62);
  r309.back() = 60;
  r310.fill(62);
  CHECK_FALSE(buffon::first_visit_met(r309, 100000));
  CHECK(buffon::first_visit_met(r310, 100000));
  // Half the budget of the visit-2 rule at the same count: the pilot must be twice as sure. The
  // visit-2 rule's floor stops at N = 620, the pilot only at S = 310 (2 S = 620 ends): the same
  // number of crossing ends, as the variance of S is counted from both ends of each crossing.
  std::array<std::uint64_t, 10> even{};
  even.fill(62);
  CHECK(buffon::precision_met(even, even, 100000));
  // Crossings whose ends all lie in two runs: far from met whatever S.
  Runs lumped{};
  lumped[0] = 1000000;
  lumped[9] = 1000000;
  CHECK_FALSE(buffon::first_visit_met(lumped, 100000));
  CHECK_THROWS_AS(buffon::first_visit_met(r310, 0), antkit::kernel::InputError);
  CHECK_THROWS_AS(buffon::first_visit_met(r310, 1000000), antkit::kernel::InputError);
}

TEST_CASE("FirstVisitMonitor checks every 10 000 steps on the runs it accumulates", "[property]") {
  rc::prop("the monitor's decision = first_visit_met on runs built independently", [] {
    const auto p = *rc::gen::inRange<std::uint32_t>(50000, 600000);
    const auto steps = *rc::gen::inRange<int>(1, 45001);
    buffon::FirstVisitMonitor monitor(p);
    std::vector<std::uint64_t> per_block{0};
    bool stopped = false;
    for (int s = 1; s <= steps && !stopped; ++s) {
      // The current step's segment is s - 1; an earlier segment is at most s - 1 - kGap.
      if (s - 1 >= static_cast<int>(kGap)) {
        const auto k = *rc::gen::inRange<int>(0, 3);
        for (int i = 0; i < k; ++i) {
          const auto earlier =
              *rc::gen::inRange<std::uint64_t>(0, static_cast<std::uint64_t>(s) - kGap);
          monitor.crossing(earlier);
          ++per_block[static_cast<std::size_t>(earlier / 1000)];
          ++per_block.back();
        }
      }
      stopped = monitor.end_step();
      if (s % 1000 == 0) per_block.push_back(0);
      if (s % 10000 == 0) {
        const std::size_t blocks = per_block.size() - 1, m = blocks / 10;
        Runs runs{};
        for (std::size_t b = 0; b < blocks; ++b) runs[b / m] += per_block[b];
        RC_ASSERT(stopped == buffon::first_visit_met(runs, p));
        RC_ASSERT(monitor.count() * 2 == std::accumulate(runs.begin(), runs.end(), 0ull));
      } else {
        RC_ASSERT(!stopped); // decisions only at whole numbers of 10 blocks
      }
    }
    RC_ASSERT(monitor.reached() == stopped);
  });
}

TEST_CASE("online first visit: the trial's S is visit 1's self-crossing count and the budget holds",
          "[unit]") {
  const auto arena = antkit::geometry::build_arena_spec("circle:d=20").arena;
  const buffon::World world(arena.walls_fx());
  buffon::TrialParams params;
  params.precision_millionths = 300000; // P = 0.3: a short visit 1 (stops at a 10 000-step check)
  params.online_first_visit = true;
  params.keep_trails = true;
  const auto t = buffon::run_trial(world, params, 0);
  INFO("circle:d=20, seed 1, P = 0.3: steps1 " << t.steps1 << ", S " << t.self_crossings);
  CHECK(t.first_visit_reached);
  CHECK(t.steps1 % 10000 == 0);
  CHECK(t.steps1 < params.steps);
  CHECK(t.self_crossings == brute_force_pairs(t.trail1).size());
  CHECK(t.steps2 == static_cast<std::int64_t>(t.trail2.size()) - 1);
  // The same trial again: bit for bit.
  CHECK(buffon::run_trial(world, params, 0).hash == t.hash);
  // A budget for both visits: visit 1 at most half, the two together at most the budget.
  params.total_steps = 24000;
  params.precision_millionths = 10000; // P = 0.01: out of reach in 24 000 steps
  const auto capped = buffon::run_trial(world, params, 0);
  CHECK(capped.steps1 == 12000);
  CHECK_FALSE(capped.first_visit_reached);
  CHECK(capped.steps1 + capped.steps2 == 24000);
  CHECK_FALSE(capped.reached_precision);
  // Misuse is a located error.
  params.precision_millionths = 0;
  CHECK_THROWS_AS(buffon::run_trial(world, params, 0), antkit::kernel::InputError);
}

TEST_CASE("two markers: N is the brute-force count of the crossings of pieces more than "
          "kNearPieces apart",
          "[unit]") {
  // 12 000 steps at a precision no check meets: 12 pieces of 1000 steps, A the even ones (walk
  // order), B the odd. The trails come back piece by piece (1001 points each).
  const auto arena = antkit::geometry::build_arena_spec("circle:d=20").arena;
  const buffon::World world(arena.walls_fx());
  buffon::TrialParams params;
  params.precision_millionths = 1;
  params.total_steps = 12000;
  params.keep_trails = true;
  const auto t = buffon::run_two_marker_trial(world, params, 0);
  CHECK(t.steps1 == 6000);
  CHECK(t.steps2 == 6000);
  CHECK_FALSE(t.reached_precision);
  REQUIRE(t.trail1.size() == 6 * 1001);
  REQUIRE(t.trail2.size() == 6 * 1001);
  auto piece = [&](const std::vector<FxPoint>& trail, std::size_t q) {
    return std::vector<FxPoint>(trail.begin() + static_cast<std::ptrdiff_t>(q * 1001),
                                trail.begin() + static_cast<std::ptrdiff_t>((q + 1) * 1001));
  };
  std::uint64_t expected = 0, near = 0;
  double all_pairs = 0, counted_pairs = 0;
  auto length = [](const std::vector<FxPoint>& p) {
    double l = 0;
    for (std::size_t i = 1; i < p.size(); ++i)
      l += std::floor(std::sqrt(std::pow(double(p[i].x.raw() - p[i - 1].x.raw()), 2) +
                                std::pow(double(p[i].y.raw() - p[i - 1].y.raw()), 2)));
    return l;
  };
  for (std::size_t qa = 0; qa < 6; ++qa)
    for (std::size_t qb = 0; qb < 6; ++qb) {
      const auto a = piece(t.trail1, qa), b = piece(t.trail2, qb);
      const std::uint64_t n = antkit::kernel::count_proper_crossings(a, b);
      const auto ka = static_cast<std::int64_t>(2 * qa), kb = static_cast<std::int64_t>(2 * qb + 1);
      const double product = length(a) * length(b);
      all_pairs += product;
      if (std::abs(ka - kb) > buffon::kNearPieces) {
        expected += n;
        counted_pairs += product;
      } else {
        near += n;
      }
    }
  INFO("crossings counted " << expected << ", left out (pieces close in time) " << near);
  CHECK(t.crossings_exact == expected);
  CHECK(near > 0); // the exclusion has something to leave out here
  CHECK(t.pair_share == Approx(counted_pairs / all_pairs).epsilon(1e-9));
  // The lengths are the pieces' exact floor roots, summed per marker.
  double l1 = 0, l2 = 0;
  for (std::size_t q = 0; q < 6; ++q)
    l1 += length(piece(t.trail1, q)), l2 += length(piece(t.trail2, q));
  CHECK(static_cast<double>(t.length1_raw) == l1);
  CHECK(static_cast<double>(t.length2_raw) == l2);
}
