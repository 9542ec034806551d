// Issue 8 item 1: pure geometry, no robot. The exact crossing count of two random isotropic
// segment families inside a polygon with a hole gives the Buffon-Crofton estimate
// A_hat = 2 L1 L2 / (pi N) without bias, with relative error falling as 1/sqrt(N); and the
// Buffon-Laplace needle on a rectangular grid is a golden check of count_proper_crossings.
// Random polygons with holes (CGAL-generated, exact area) are in test_crofton_polygons.cpp; the
// families, the crossing count and the pooled z shared by both files are in crofton_common.hpp.
//
// Randomness: keyed kernel::Stream with fixed seeds (printed on failure). The bounds are normal
// tails at z = 5.3 (two-sided false-failure rate 1.2e-7 per check, below 1e-6).
#include "crofton_common.hpp"
#include "random_polygon.hpp"

#include <antkit/buffon/estimate.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <rapidcheck/catch.h>
#include <vector>

namespace {

using namespace antkit::test::crofton;

// ---------------------------------------------------------------- Buffon-Laplace needle on a grid
// Grid lines x = k a and y = j b; the needle's centre is uniform in one cell (by periodicity this
// is the same as uniform over the plane) and its direction uniform. The vertical lines are joined
// into one serpentine polyline whose connectors lie far outside the needle's reach, likewise the
// horizontal ones, so one count_proper_crossings call per family counts the needle's crossings.
struct NeedleResult {
  std::uint64_t hits = 0, n = 0;
};

NeedleResult drop_needles(double a, double b, double l, std::uint64_t n, std::uint64_t seed) {
  std::vector<FxPoint> vert, horiz;
  const double far = 10.0 * (a + b);
  for (int k = 0; k <= 3; ++k) { // cell [a, 2a) x [b, 2b) plus reach l/2 < a, b
    const double lo = (k % 2 == 0) ? -far : far, hi = -lo;
    vert.push_back(to_fx(k * a, lo));
    vert.push_back(to_fx(k * a, hi));
    horiz.push_back(to_fx(lo, k * b));
    horiz.push_back(to_fx(hi, k * b));
  }
  Stream s(seed, /*experiment=*/8, /*trial=*/0, 0, /*purpose=*/1);
  NeedleResult r;
  for (std::uint64_t i = 0; i < n; ++i) {
    const double cx = a + a * unit(s), cy = b + b * unit(s), th = kPi * unit(s);
    const double dx = 0.5 * l * std::cos(th), dy = 0.5 * l * std::sin(th);
    const FxPoint needle[2] = {to_fx(cx - dx, cy - dy), to_fx(cx + dx, cy + dy)};
    const std::uint64_t c = antkit::kernel::count_proper_crossings(needle, vert) +
                            antkit::kernel::count_proper_crossings(needle, horiz);
    r.hits += c > 0 ? 1 : 0;
    ++r.n;
  }
  return r;
}

// |hits - n p| <= z sqrt(n p (1 - p)) (normal approximation to the binomial; n p (1-p) > 1e4 here).
bool binomial_accepts(const NeedleResult& r, double p) {
  const double n = static_cast<double>(r.n);
  return std::abs(static_cast<double>(r.hits) - n * p) <= kZ * std::sqrt(n * p * (1 - p));
}

// ------------------------------------------------ polygon with a hole, isotropic segments
// Region: a rectangle minus a rectangular hole (integer corners, so the area is exact). The two
// families are dropped over it by crofton_common.hpp's drop_family / drop_walks (see there why
// clipping, not keep-or-drop, is unbiased).
struct Region {
  double W = 20, H = 20;                       // outer rectangle [0, W] x [0, H]
  double hx0 = 7, hy0 = 7, hx1 = 13, hy1 = 13; // hole [hx0, hx1] x [hy0, hy1], inside
  double area() const { return W * H - (hx1 - hx0) * (hy1 - hy0); }
  Box box() const { return {0, 0, W, H}; }
};

// A random rectangle with a random rectangular hole, integer corners: W, H in [8, 40], the hole at
// least one unit from every outer edge (so the region stays connected around it).
Region random_region(Stream& s) {
  Region g;
  g.W = s.between(8, 40);
  g.H = s.between(8, 40);
  g.hx0 = s.between(1, static_cast<std::int32_t>(g.W) - 3);
  g.hx1 = s.between(static_cast<std::int32_t>(g.hx0) + 1, static_cast<std::int32_t>(g.W) - 1);
  g.hy0 = s.between(1, static_cast<std::int32_t>(g.H) - 3);
  g.hy1 = s.between(static_cast<std::int32_t>(g.hy0) + 1, static_cast<std::int32_t>(g.H) - 1);
  return g;
}

// Parameter interval [t0, t1] of p + t d inside the box [x0, x1] x [y0, y1] (Liang-Barsky).
bool clip_box(double px, double py, double dx, double dy, double x0, double y0, double x1,
              double y1, double& t0, double& t1) {
  auto edge = [&](double p, double q) {
    if (p == 0) return q >= 0;
    const double r = q / p;
    if (p < 0)
      t0 = std::max(t0, r);
    else
      t1 = std::min(t1, r);
    return true;
  };
  return edge(-dx, px - x0) && edge(dx, x1 - px) && edge(-dy, py - y0) && edge(dy, y1 - py) &&
         t0 < t1;
}

// Appends the parts of the segment p + t (dx, dy), t in [0, 1], that lie in the region (its box
// minus its hole) and adds their lengths, measured from the rounded ends that are counted.
void add_clipped(const Region& g, double px, double py, double dx, double dy,
                 std::vector<FxSegment>& out, double& length_inside) {
  double t0 = 0, t1 = 1;
  if (!clip_box(px, py, dx, dy, 0, 0, g.W, g.H, t0, t1)) return;
  double h0 = t0, h1 = t1; // remove the part inside the hole
  std::vector<std::pair<double, double>> pieces;
  if (clip_box(px, py, dx, dy, g.hx0, g.hy0, g.hx1, g.hy1, h0, h1)) {
    if (h0 > t0) pieces.emplace_back(t0, h0);
    if (t1 > h1) pieces.emplace_back(h1, t1);
  } else {
    pieces.emplace_back(t0, t1);
  }
  for (auto [u, v] : pieces) {
    const FxSegment seg{to_fx(px + u * dx, py + u * dy), to_fx(px + v * dx, py + v * dy)};
    out.push_back(seg);
    length_inside += len(seg);
  }
}

Trial crofton_trial(const Region& g, double l, double total, std::uint64_t seed, std::uint64_t t) {
  Stream s1(seed, 8, t, 0, 2), s2(seed, 8, t, 0, 3);
  std::vector<FxSegment> f1, f2;
  Trial r{};
  drop_family(g, l, total, s1, f1, r.l1);
  drop_family(g, l, total, s2, f2, r.l2);
  r.n = crossings(f1, f2);
  return r;
}

} // namespace

TEST_CASE("Buffon-Laplace needle on a rectangular grid: P(cross) = (2l(a+b) - l^2)/(pi a b)",
          "[crofton][property]") {
  const double a = 3, b = 2, l = 1.5; // l < min(a, b)
  const std::uint64_t seed = 20261121, n = 200000;
  const NeedleResult r = drop_needles(a, b, l, n, seed);
  const double p = (2 * l * (a + b) - l * l) / (kPi * a * b);
  INFO("seed " << seed << " needles " << n << " hits " << r.hits << " expected " << n * p);
  CHECK(binomial_accepts(r, p));
  // Teeth: pi replaced by 3, and the formula without the - l^2 term, are rejected.
  CHECK_FALSE(binomial_accepts(r, (2 * l * (a + b) - l * l) / (3.0 * a * b)));
  CHECK_FALSE(binomial_accepts(r, 2 * l * (a + b) / (kPi * a * b)));
}

TEST_CASE("Crofton: two clipped isotropic segment families in a polygon with a hole give "
          "A_hat without bias, its CI covers, and the spread falls as 1/sqrt(N)",
          "[crofton][property]") {
  const Region g;
  const double l = 2.0;
  const std::uint64_t seed = 20261121;
  const int trials = 40;
  // Lengths chosen so E[N] = L^2 2 / (pi A) is about 100, 400, 1600, 6400 (x4 each).
  std::vector<double> log_n, log_spread;
  std::vector<Trial> all;
  for (int k = 0; k < 4; ++k) {
    const double target_n = 100.0 * std::pow(4.0, k);
    const double total = std::sqrt(target_n * kPi * g.area() / 2);
    std::vector<Trial> ts;
    double mean = 0, sq = 0;
    int covered = 0;
    for (int t = 0; t < trials; ++t) {
      const Trial tr = crofton_trial(
          g, l, total, seed, static_cast<std::uint64_t>(k) * 1000 + static_cast<std::uint64_t>(t));
      ts.push_back(tr);
      const auto cf = antkit::buffon::closed_form_area(tr.l1, tr.l2, tr.n);
      REQUIRE(cf.area.has_value());
      const double rel = *cf.area / g.area() - 1;
      mean += rel;
      sq += rel * rel;
      covered += (cf.lower <= g.area() && cf.upper && g.area() <= *cf.upper) ? 1 : 0;
    }
    mean /= trials;
    const double sd = std::sqrt((sq - trials * mean * mean) / (trials - 1));
    const double cov = static_cast<double>(covered) / trials;
    const double z = crofton_z(ts, g.area(), kPi);
    INFO("seed " << seed << " length index " << k << " target N " << target_n << " rel.sd " << sd
                 << " coverage " << cov << " z " << z);
    // The CI of estimate.hpp is a 95 % interval; coverage over 40 trials is Binomial(40, 0.95) if
    // crossings are Poisson-like: below 0.95 - 5.3 sqrt(0.95 0.05 / 40) = 0.77 fails.
    CHECK(cov >= 0.95 - kZ * std::sqrt(0.95 * 0.05 / trials));
    CHECK(std::abs(z) <= kZ);
    log_n.push_back(std::log(target_n));
    log_spread.push_back(std::log(sd));
    all.insert(all.end(), ts.begin(), ts.end());
    std::printf("crofton k=%d targetN=%.0f rel_sd=%.4f coverage=%.3f z=%.2f\n", k, target_n, sd,
                cov, z);
  }
  // Slope of log(sd) on log(N) by least squares. The sample sd of T normal-ish values has
  // var(ln sd) ~ 1/(2 (T - 1)); the slope's standard error is sqrt of that over sum (x - xbar)^2.
  // (The fit's own residual SE has only 2 degrees of freedom, so its 1e-6 t quantile is useless.)
  double xb = 0, yb = 0;
  for (std::size_t i = 0; i < 4; ++i) xb += log_n[i] / 4, yb += log_spread[i] / 4;
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    sxx += (log_n[i] - xb) * (log_n[i] - xb);
    sxy += (log_n[i] - xb) * (log_spread[i] - yb);
  }
  const double slope = sxy / sxx;
  const double se = std::sqrt(1.0 / (2.0 * (trials - 1)) / sxx);
  std::printf("crofton slope=%.4f se=%.4f\n", slope, se);
  INFO("seed " << seed << " slope " << slope << " se " << se);
  CHECK(std::abs(slope + 0.5) <= kZ * se);
  // Teeth: pi replaced by 3, or the area off by 10 %, is rejected over all trials pooled.
  CHECK(std::abs(crofton_z(all, g.area(), kPi)) <= kZ);
  CHECK(std::abs(crofton_z(all, g.area(), 3.0)) > kZ);
  CHECK(std::abs(crofton_z(all, 1.1 * g.area(), kPi)) > kZ);
}

TEST_CASE("Crofton with random-walk polylines against segments in a polygon with a hole",
          "[crofton][property]") {
  const std::uint64_t seed = 20261123;
  const Region g;
  std::vector<Trial> ts;
  for (std::uint64_t t = 0; t < 80; ++t) { // 80: the pi->3 teeth expect |z| ~ 8
    Stream s1(seed, 8, t, 0, 5), s2(seed, 8, t, 0, 6);
    std::vector<FxSegment> f1, f2;
    Trial r{};
    const double total =
        std::sqrt(6400.0 * kPi * g.area() / 2); // E[N] ~ 6400: enough for the teeth
    drop_walks(g, 0.5, 8, total, s1, f1, r.l1);
    drop_family(g, 2.0, total, s2, f2, r.l2);
    r.n = crossings(f1, f2);
    ts.push_back(r);
  }
  const double z = crofton_z(ts, g.area(), kPi);
  std::printf("crofton walks z=%.2f (pi->3: %.1f, area+10%%: %.1f)\n", z,
              crofton_z(ts, g.area(), 3.0), crofton_z(ts, 1.1 * g.area(), kPi));
  INFO("seed " << seed << " z " << z);
  CHECK(std::abs(z) <= kZ);
  CHECK(std::abs(crofton_z(ts, g.area(), 3.0)) > kZ);
  CHECK(std::abs(crofton_z(ts, 1.1 * g.area(), kPi)) > kZ);
}

TEST_CASE("Crofton on random rectangles with random holes: A_hat unbiased over 20 regions",
          "[crofton][property]") {
  const std::uint64_t seed = 20261122;
  Stream gs(seed, 8, 0, 0, 4);
  const double l = 1.5;
  std::vector<Trial> all;
  std::vector<double> areas;
  for (int r = 0; r < 20; ++r) {
    const Region g = random_region(gs);
    const double total = std::sqrt(800.0 * kPi * g.area() / 2); // E[N] about 800
    for (int t = 0; t < 10; ++t) {
      all.push_back(crofton_trial(g, l, total, seed, static_cast<std::uint64_t>(r * 100 + t)));
      areas.push_back(g.area());
    }
  }
  // Pooled z with each trial's own area: sum (N - E) / sqrt(sum (N - E)^2).
  auto z_of = [&](double pi, double scale) {
    double num = 0, var = 0;
    for (std::size_t i = 0; i < all.size(); ++i) {
      const double e = 2 * all[i].l1 * all[i].l2 / (pi * scale * areas[i]);
      const double d = static_cast<double>(all[i].n) - e;
      num += d;
      var += d * d;
    }
    return num / std::sqrt(var);
  };
  const double z = z_of(kPi, 1.0);
  std::printf("crofton random regions z=%.2f (pi->3: %.1f, area+10%%: %.1f)\n", z, z_of(3.0, 1.0),
              z_of(kPi, 1.1));
  INFO("seed " << seed << " z " << z);
  CHECK(std::abs(z) <= kZ);
  CHECK(std::abs(z_of(3.0, 1.0)) > kZ);
  CHECK(std::abs(z_of(kPi, 1.1)) > kZ);
}

// The general polygon clipper of random_polygon.hpp, held against the Liang-Barsky clipping above
// on the same rectangles with rectangular holes: same pieces, ends within one fixed-point unit
// (the two compute the same crossing parameters by different binary64 formulas, so a rounding to
// Q15.16 may land on either side of a half).
TEST_CASE("the polygon clipper cuts the same pieces as the rectangle-minus-hole clipper",
          "[crofton][property]") {
  rc::prop("pieces agree on a random rectangle with a hole", [] {
    Region g;
    g.W = uniform_in(8, 41);
    g.H = uniform_in(8, 41);
    g.hx0 = uniform_in(1, static_cast<int>(g.W) - 2);
    g.hx1 = uniform_in(static_cast<int>(g.hx0) + 1, static_cast<int>(g.W));
    g.hy0 = uniform_in(1, static_cast<int>(g.H) - 2);
    g.hy1 = uniform_in(static_cast<int>(g.hy0) + 1, static_cast<int>(g.H));
    auto grid = [](double v) { return static_cast<std::int64_t>(v) * kGrid; };
    const RandomPolygon p =
        make_polygon({{{0, 0}, {grid(g.W), 0}, {grid(g.W), grid(g.H)}, {0, grid(g.H)}},
                      {{grid(g.hx0), grid(g.hy0)},
                       {grid(g.hx0), grid(g.hy1)},
                       {grid(g.hx1), grid(g.hy1)},
                       {grid(g.hx1), grid(g.hy0)}}});
    RC_ASSERT(valid_rings(p.rings));
    RC_ASSERT(p.exact_area == antkit::geometry::ExactNumber(static_cast<long>(g.area())));
    for (int k = 0; k < 50; ++k) {
      const double l = uniform_in(1, 200) / 10.0;
      const double th = uniform_in(0, 1 << 20) * (2 * kPi / (1 << 20));
      const double mx = -2 + (g.W + 4) * uniform_in(0, 1 << 16) / 65536.0;
      const double my = -2 + (g.H + 4) * uniform_in(0, 1 << 16) / 65536.0;
      const double dx = l * std::cos(th), dy = l * std::sin(th);
      std::vector<FxSegment> box_pieces, poly_pieces;
      double box_len = 0, poly_len = 0;
      add_clipped(g, mx - dx / 2, my - dy / 2, dx, dy, box_pieces, box_len);
      add_clipped(p, mx - dx / 2, my - dy / 2, dx, dy, poly_pieces, poly_len);
      RC_ASSERT(box_pieces.size() == poly_pieces.size());
      auto near = [](FxPoint a, FxPoint b) {
        return std::abs(a.x.raw() - b.x.raw()) <= 1 && std::abs(a.y.raw() - b.y.raw()) <= 1;
      };
      for (std::size_t i = 0; i < box_pieces.size(); ++i) {
        RC_ASSERT(near(box_pieces[i].a, poly_pieces[i].a));
        RC_ASSERT(near(box_pieces[i].b, poly_pieces[i].b));
      }
    }
  });
}

// The swept crossing count of crofton_common.hpp equals the plain count over all pairs.
TEST_CASE("the swept crossing count equals the all-pairs count", "[crofton][property]") {
  rc::prop("random segment and walk families in the square with a hole", [] {
    const Region g;
    Stream s1(uniform_in<std::uint64_t>(0, 1u << 30), 8, 0, 0, 11),
        s2(uniform_in<std::uint64_t>(0, 1u << 30), 8, 0, 0, 12);
    const double l = uniform_in(1, 100) / 10.0, total = uniform_in(10, 400);
    std::vector<FxSegment> f1, f2;
    std::vector<std::uint32_t> drop;
    double l1 = 0, l2 = 0;
    drop_walks(g, l / 4, 8, total, s1, f1, l1, &drop);
    drop_family(g, l, total, s2, f2, l2);
    std::uint64_t all_pairs = 0;
    for (const auto& a : f1)
      for (const auto& b : f2) all_pairs += antkit::kernel::properly_cross(a, b) ? 1u : 0u;
    RC_ASSERT(crossings(f1, f2) == all_pairs);
    RC_ASSERT(crossings(f2, f1) == all_pairs);
    // The drop-by-drop trial adds up to the same count and length.
    const ClusterTrial c = cluster_trial(f1, drop, f2, l2);
    double m = 0, lambda = 0;
    for (auto [mw, lw] : c.drops) m += mw, lambda += lw;
    RC_ASSERT(m == static_cast<double>(all_pairs));
    RC_ASSERT(std::abs(lambda - l1) <= 1e-9 * (1 + l1));
  });
}
