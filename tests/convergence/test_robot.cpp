// The robot's estimates converge (issue 8, items 2 and 3). Fixed seeds; every check prints what
// reproduces it (arena, steps, trials, seed 1). Slow parts under [slow].
//
// Item 2, bias model: the closed form on the exact crossing count of the two centre lines
// estimates the area the centre line explores, which is the arena eroded by an effective distance
// delta (the body radius 0.5 plus the margin the wall avoidance keeps). For a convex arena whose
// boundary curvature radius exceeds delta the eroded area is A - perimeter delta + k delta^2, k =
// pi for a smooth boundary and k = 4 for a rectangle (its inner parallel body is a rectangle).
// delta is fitted once on circle:d=20 and square:area=314 and checked on the held-out ellipse.
#include <antkit/buffon/estimate.hpp>
#include <antkit/buffon/measurement.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

namespace buffon = antkit::buffon;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Sample {
  std::vector<double> area_exact; // closed form on crossings_exact (trials with a crossing)
  double ratio_pooled = 0;        // sum BC / sum crossings_exact
};

Sample run(const std::string& spec, std::int64_t steps, std::uint64_t trials, double width = 0.1) {
  const auto arena = antkit::geometry::build_arena_spec(spec).arena;
  const buffon::World world(arena.walls_fx());
  buffon::TrialParams params;
  params.steps = steps;
  params.width =
      antkit::kernel::Fx::from_raw(static_cast<std::int32_t>(std::lround(width * 65536)));
  const auto results = buffon::run_trials(world, params, trials, 2);
  Sample s;
  double bc = 0, exact = 0;
  for (const auto& t : results) {
    const auto cf =
        buffon::closed_form_area(static_cast<double>(t.length1_raw) / 65536,
                                 static_cast<double>(t.length2_raw) / 65536, t.crossings_exact);
    if (cf.area) s.area_exact.push_back(*cf.area);
    bc += static_cast<double>(t.bc);
    exact += static_cast<double>(t.crossings_exact);
  }
  s.ratio_pooled = bc / exact;
  return s;
}

double iqr(const std::vector<double>& v) {
  return buffon::quantile(v, 0.75) - buffon::quantile(v, 0.25);
}

// A - P d + k d^2 = target, the smaller root.
double erosion_delta(double area, double perimeter, double k, double target) {
  return (perimeter - std::sqrt(perimeter * perimeter - 4 * k * (area - target))) / (2 * k);
}

} // namespace

TEST_CASE("robot: A_hat's IQR shrinks with visit length and the median meets the eroded area",
          "[slow]") {
  struct ArenaCase {
    std::string spec;
    double k; // pi smooth, 4 polygonal (square)
  };
  const std::vector<ArenaCase> cases = {
      {"circle:d=20", kPi}, {"square:area=314", 4}, {"ellipse:area=314,e=0.968", kPi}};
  const std::uint64_t trials = 40;
  std::vector<double> medians, deltas;
  for (const auto& c : cases) {
    std::vector<double> iqrs;
    Sample full;
    for (const std::int64_t steps : {6250, 12500, 25000, 50000}) {
      full = run(c.spec, steps, trials);
      iqrs.push_back(iqr(full.area_exact));
      INFO(c.spec << " steps " << steps << " trials " << trials << " seed 1: IQR " << iqrs.back()
                  << " median " << buffon::quantile(full.area_exact, 0.5));
      CHECK(full.area_exact.size() == trials);
    }
    // Poisson counts give IQR ~ 1 / sqrt(N) ~ 1 / length (N ~ L1 L2): 8x from 1/8 to 1 of the
    // steps (measured 6.3, 9.8, 6.5). The IQR of 40 draws has a relative spread of about 0.2 per
    // length, so the ratio of two has a log-spread of about 0.3; a bound of 1.3 is 5.3 of those
    // below the smallest measured ratio's log (ln 6.3 - ln 1.3 = 1.58): a false-failure rate
    // below 1e-7 per arena under a normal approximation of the log ratio. (Neighbouring lengths
    // differ by only ln 2 = 0.69, 2.3 spreads, so they are printed, not compared.)
    INFO(c.spec << " IQR ratio 1/8 : 1 = " << iqrs.front() / iqrs.back());
    CHECK(iqrs.front() / iqrs.back() > 1.3);
    const auto a = antkit::geometry::build_arena_spec(c.spec).arena;
    const double median = buffon::quantile(full.area_exact, 0.5);
    medians.push_back(median);
    deltas.push_back(erosion_delta(a.area(), a.perimeter(), c.k, median));
    INFO(c.spec << " median " << median << " delta " << deltas.back());
    // Raw bias: the centre cannot reach the band of 0.5 along the walls, so the median is
    // below the arena's area by at least perimeter * 0.5 - pi 0.25.
    CHECK(median < a.area() - 0.5 * a.perimeter() + 4 * 0.25);
  }
  // Fit on circle and square, check on the ellipse (held out).
  const double delta = (deltas[0] + deltas[1]) / 2;
  INFO("fitted delta " << delta << " (circle " << deltas[0] << ", square " << deltas[1] << ")");
  CHECK(delta > 0.5);  // at least the body radius
  CHECK(delta < 0.95); // the avoidance margin is a fraction of the sensing range
  const auto ellipse = antkit::geometry::build_arena_spec(cases[2].spec).arena;
  auto predicted = [&](double d) { return ellipse.area() - ellipse.perimeter() * d + kPi * d * d; };
  // The median of 40 draws has a relative spread of about 0.5 % at 50 000 steps (IQR 8 of 257):
  // 3 % is 6 of them. Teeth: delta = 0 (no model) is 18 % off and delta = 0.5 (the body radius
  // alone) 6 % off, both fail this bound.
  INFO("ellipse median " << medians[2] << " predicted " << predicted(delta));
  CHECK(std::abs(medians[2] / predicted(delta) - 1) < 0.03);
  CHECK(std::abs(medians[2] / predicted(0.0) - 1) > 0.03);
  CHECK(std::abs(medians[2] / predicted(0.5) - 1) > 0.03);
}

TEST_CASE(
    "pheromone count: BC / exact grows as the trail narrows (to the step) and the arena grows",
    "[slow]") {
  // 10 trials of 50 000 steps per point; the per-trial ratio's spread is at most 0.023 (measured
  // over 30 trials), so the pooled ratio's is below 0.008; the steps asserted below are at least
  // 0.06 (7.5 of those spreads).
  const std::vector<double> widths = {0.4, 0.2, 0.1, 0.05};
  std::vector<double> small, large;
  for (const double w : widths) {
    small.push_back(run("circle:d=20", 50000, 10, w).ratio_pooled);
    large.push_back(run("circle:d=40", 50000, 10, w).ratio_pooled);
    INFO("w " << w << ": BC/exact d=20 " << small.back() << ", d=40 " << large.back());
    CHECK(large.back() > small.back() + 0.06); // blending falls with the trail density
    CHECK(large.back() < 1.0);
  }
  for (std::size_t i = 1; i < widths.size(); ++i) {
    INFO("w " << widths[i - 1] << " -> " << widths[i]);
    CHECK(large[i] > large[i - 1] + 0.04);
    CHECK(small[i] > small[i - 1] + 0.06);
  }
}
