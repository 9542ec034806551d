// The online stopping rule keeps its promise (issue 8, item 5): on every standard arena, among the
// trials where visit 2 stopped on the rule, the achieved error |A_hat / A_eff - 1| is within the
// requested P in at least 95 % of them (the rule's nominal level), checked against a binomial
// bound with a false-failure rate below 1e-6. Also prints the trail length the rule needed
// against the area, and the coverage against the true area.
//
// The reference A_eff: the closed form estimates the area the robot's centre explores, the arena
// eroded by delta = 0.708 (body radius 0.5 plus the wall-avoidance margin; fitted on circle and
// square and held out on the ellipse in test_robot.cpp). A_eff is that eroded area, measured by
// sampling the arena on a 0.1-unit grid (the distance to the nearest wall >= delta); pooled over
// 40 long trials the estimates meet it within 0.3 % on every standard arena but the plus (+1.4 %).
//
// Two regimes: the small arenas of Figure 5 with the default visit 1 (50 000 steps) at P = 0.1;
// the 7854-area standard arenas at P = 0.2 with visit 1 of 300 000 steps (a default visit 1 leaves
// most of a large arena unvisited, and its share of the variance alone exceeds the budget: the
// rule then rightly never stops). Fixed seed 1, trials 0..39; a failure prints the arena.
#include <algorithm>
#include <antkit/buffon/estimate.hpp>
#include <antkit/buffon/measurement.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace buffon = antkit::buffon;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDelta = 0.708; // tests/convergence/test_robot.cpp

// |{x in the free region : dist(x, walls) >= delta}| by sampling cell centres of an h-grid
// (even-odd over the rings for inside). Reporting-side reference, double precision.
double eroded_area(const antkit::geometry::Arena& arena, double delta, double h) {
  struct Seg {
    double x0, y0, x1, y1;
  };
  std::vector<Seg> segs;
  for (const auto& ring : arena.rings())
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const auto& p = ring[i];
      const auto& q = ring[(i + 1) % ring.size()];
      segs.push_back({p[0], p[1], q[0], q[1]});
    }
  const auto bb = arena.bbox();
  double count = 0;
  for (double y = bb.ymin + h / 2; y < bb.ymax; y += h)
    for (double x = bb.xmin + h / 2; x < bb.xmax; x += h) {
      bool inside = false, clear = true;
      for (const Seg& s : segs) {
        if ((s.y0 > y) != (s.y1 > y) && s.x0 + (y - s.y0) * (s.x1 - s.x0) / (s.y1 - s.y0) > x)
          inside = !inside;
        const double vx = s.x1 - s.x0, vy = s.y1 - s.y0;
        const double t =
            std::clamp(((x - s.x0) * vx + (y - s.y0) * vy) / (vx * vx + vy * vy), 0.0, 1.0);
        const double ex = s.x0 + t * vx - x, ey = s.y0 + t * vy - y;
        if (ex * ex + ey * ey < delta * delta) clear = false;
      }
      if (inside && clear) count += 1;
    }
  return count * h * h;
}

// The least k with P(Bin(n, q) < k) <= rate: a coverage of q or more shows at least k successes
// except with probability at most `rate`.
int binomial_floor(int n, double q, double rate) {
  double below = 0; // P(X < k)
  int k = 0;
  for (; k <= n; ++k) {
    const double pk =
        std::exp(std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0) +
                 k * std::log(q) + (n - k) * std::log1p(-q));
    if (below + pk > rate) break;
    below += pk;
  }
  return k;
}

struct Regime {
  const char* spec;
  std::uint32_t precision; // millionths
  std::int64_t steps1, cap2;
  // The stopping rate claimed within the cap (measured: 1.0 on the small arenas, 0.55-1.0 on the
  // large ones); asserted through the same binomial floor at 1e-6.
  double stop_rate;
};

} // namespace

TEST_CASE("binomial_floor: the false-failure bound", "[unit]") {
  // Bin(40, 0.95): P(X <= 28) = 3.65e-7 <= 1e-6 < P(X <= 29) = 2.9e-6, so at least 29 of 40.
  // Bin(10, 0.95): P(X <= 3) = 8.2e-8, P(X <= 4) = 2.8e-6: at least 4 of 10.
  CHECK(binomial_floor(40, 0.95, 1e-6) == 29);
  CHECK(binomial_floor(10, 0.95, 1e-6) == 4);
}

TEST_CASE("online stopping: the achieved error meets P in >= 95 % of the stopped trials",
          "[slow]") {
  constexpr int kTrials = 40;
  const Regime regimes[] = {
      {"circle:d=20", 100000, 50000, 400000, 0.95},
      {"square:area=314", 100000, 50000, 400000, 0.95},
      {"ellipse:area=314,e=0.968", 100000, 50000, 400000, 0.95},
      {"circle:d=40", 100000, 50000, 400000, 0.95},
      {"standard", 200000, 300000, 600000, 0.5},
      {"square", 200000, 300000, 600000, 0.5},
      {"ellipse:e=0.968", 200000, 300000, 600000, 0.5},
      {"ring", 200000, 300000, 600000, 0.5},
      {"plus", 200000, 300000, 600000, 0.5},
      {"obstacles", 200000, 300000, 600000, 0.5},
      {"barrier-i:len=0.5", 200000, 300000, 600000, 0.5},
      {"barrier-plus:len=0.5", 200000, 300000, 600000, 0.5},
  };
  std::printf("online stopping (seed 1, %d trials): arena | area | A_eff | P | L1 | stopped | "
              "met vs A_eff | met vs A | L2 median | L2 q3\n",
              kTrials);
  for (const Regime& r : regimes) {
    const auto named = antkit::geometry::build_arena_spec(r.spec);
    const double a_eff = eroded_area(named.arena, kDelta, 0.1);
    const buffon::World world(named.arena.walls_fx());
    buffon::TrialParams params;
    params.steps = r.steps1;
    params.visit2_steps = r.cap2;
    params.precision_millionths = r.precision;
    const auto results = buffon::run_trials(world, params, kTrials, 2);
    const double P = r.precision / 1e6;
    int stopped = 0, met = 0, met_true = 0;
    std::vector<double> lengths;
    double l1 = 0;
    for (const auto& t : results) {
      l1 += static_cast<double>(t.length1_raw) / 65536 / kTrials;
      if (!t.reached_precision) continue;
      ++stopped;
      const double l2 = static_cast<double>(t.length2_raw) / 65536;
      lengths.push_back(l2);
      const auto cf = buffon::closed_form_area(static_cast<double>(t.length1_raw) / 65536, l2,
                                               t.crossings_exact);
      REQUIRE(cf.area);
      met += std::abs(*cf.area / a_eff - 1) <= P ? 1 : 0;
      met_true += std::abs(*cf.area / named.arena.area() - 1) <= P ? 1 : 0;
    }
    std::printf("%s | %.0f | %.0f | %.2f | %.0f | %d | %d | %d | %.0f | %.0f\n", r.spec,
                named.arena.area(), a_eff, P, l1, stopped, met, met_true,
                buffon::quantile(lengths, 0.5), buffon::quantile(lengths, 0.75));
    std::fflush(stdout);
    INFO(r.spec << ": stopped " << stopped << " of " << kTrials << ", met P against A_eff " << a_eff
                << " in " << met);
    CHECK(stopped >= binomial_floor(kTrials, r.stop_rate, 1e-6));
    CHECK(met >= binomial_floor(stopped, 0.95, 1e-6));
  }
}
