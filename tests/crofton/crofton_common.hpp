#pragma once
// What the Crofton tests share: uniform draws from a kernel::Stream, conversion to the kernel's
// fixed-point segments, the two dropped families (isotropic segments and random-walk polylines)
// for any region, their exact crossing count, and the pooled z of E[N] = 2 L1 L2 / (pi A).
//
// A region is anything with `Box box() const` (its bounding box), `double area() const` and a
// free function add_clipped(region, px, py, dx, dy, out, length_inside) found by argument-dependent
// lookup that appends the parts of the segment p + t d, t in [0, 1], lying in the region. The
// rectangle-with-a-rectangular-hole of test_crofton.cpp and the random polygons with holes of
// random_polygon.hpp are both regions; the families are dropped the same way over both.
#include <algorithm>
#include <antkit/kernel/random.hpp>
#include <antkit/kernel/segment.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace antkit::test::crofton {

using antkit::kernel::Fx;
using antkit::kernel::FxPoint;
using antkit::kernel::FxSegment;
using antkit::kernel::Stream;

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kZ = 5.3; // two-sided normal tail 1.16e-7

inline double unit(Stream& s) { // uniform in [0, 1) with 53 bits
  return static_cast<double>(s.next_u64() >> 11) * 0x1.0p-53;
}

inline FxPoint to_fx(double x, double y) {
  return {Fx::from_raw(static_cast<std::int32_t>(std::llround(x * 65536.0))),
          Fx::from_raw(static_cast<std::int32_t>(std::llround(y * 65536.0)))};
}
inline double to_d(Fx v) {
  return static_cast<double>(v.raw()) / 65536.0;
}
inline double len(const FxSegment& s) {
  return std::hypot(to_d(s.b.x) - to_d(s.a.x), to_d(s.b.y) - to_d(s.a.y));
}

struct Box {
  double x0, y0, x1, y1;
};

// Segments of length l: direction uniform, midpoint uniform in the bounding box dilated by l/2,
// then CLIPPED to the region (not kept-or-dropped). Why this is unbiased for Crofton: the
// (midpoint, direction) measure is invariant under rigid motions, and every point of the region at
// every direction is reached by the same measure of segments because the midpoint box contains the
// region dilated by l/2; so the clipped length is spread uniformly and isotropically over the
// region. Keeping only segments wholly inside would thin the length within l/2 of every edge and
// bias A_hat. The classical formula E[N] = 2 L1 L2 / (pi A) then holds for the two independent
// families of clipped pieces, conditionally on their lengths. A drop whose clipped part is empty
// is the rejection step: it costs its length l in `dropped` and adds nothing. The dropped length
// is total_length * box / area, so that about total_length lands inside.
//
// `drop`, when given, receives for every piece the index of the drop it came from (the drops are
// independent and identically distributed given the other family: the unit of a cluster-robust
// variance, see crofton_common's cluster_z).
template <class Region>
void drop_family(const Region& g, double l, double total_length, Stream& s,
                 std::vector<FxSegment>& out, double& length_inside,
                 std::vector<std::uint32_t>* drop = nullptr) {
  out.clear();
  length_inside = 0;
  if (drop) drop->clear();
  std::uint32_t index = 0;
  const Box b = g.box();
  const double sx = b.x1 - b.x0 + l, sy = b.y1 - b.y0 + l;
  double dropped = 0;
  while (dropped < total_length * (sx * sy) / g.area()) {
    const double mx = b.x0 - 0.5 * l + sx * unit(s), my = b.y0 - 0.5 * l + sy * unit(s);
    const double th = kPi * unit(s);
    const double dx = l * std::cos(th), dy = l * std::sin(th);
    const double px = mx - 0.5 * dx, py = my - 0.5 * dy;
    dropped += l;
    add_clipped(g, px, py, dx, dy, out, length_inside);
    if (drop) drop->resize(out.size(), index);
    ++index;
  }
}

// Random-walk polylines: a walk of m steps of length l, each step's direction uniform and
// independent, starting uniformly in the box enlarged by the walk's reach m l; each step is clipped
// to the region like a segment. Unbiased for Crofton: for any fixed sequence of step
// displacements, the start is uniform over a box that contains the region shifted by every partial
// displacement, so every step's length density is uniform over the region, and its direction is
// uniform.
// `drop` as for drop_family: one index per walk (its steps are not independent of each other).
template <class Region>
void drop_walks(const Region& g, double l, int m, double total_length, Stream& s,
                std::vector<FxSegment>& out, double& length_inside,
                std::vector<std::uint32_t>* drop = nullptr) {
  out.clear();
  length_inside = 0;
  if (drop) drop->clear();
  std::uint32_t index = 0;
  const Box b = g.box();
  const double reach = l * m, sx = b.x1 - b.x0 + 2 * reach, sy = b.y1 - b.y0 + 2 * reach;
  double dropped = 0;
  while (dropped < total_length * (sx * sy) / g.area()) {
    double px = b.x0 - reach + sx * unit(s), py = b.y0 - reach + sy * unit(s);
    for (int j = 0; j < m; ++j) {
      const double th = 2 * kPi * unit(s), dx = l * std::cos(th), dy = l * std::sin(th);
      dropped += l;
      add_clipped(g, px, py, dx, dy, out, length_inside);
      px += dx;
      py += dy;
    }
    if (drop) drop->resize(out.size(), index);
    ++index;
  }
}

// The exact number of proper crossings of each piece of f with the family g (kernel predicate on
// the fixed-point pieces). Sorting g by its left end lets each piece of f stop scanning once g's
// pieces start right of it: the same pairs are tested that can cross, so every count is the
// all-pairs count.
inline std::vector<std::uint32_t> crossings_per_piece(const std::vector<FxSegment>& f,
                                                      std::vector<FxSegment> g) {
  auto left = [](const FxSegment& s) { return std::min(s.a.x.raw(), s.b.x.raw()); };
  auto right = [](const FxSegment& s) { return std::max(s.a.x.raw(), s.b.x.raw()); };
  std::sort(g.begin(), g.end(),
            [&](const FxSegment& u, const FxSegment& v) { return left(u) < left(v); });
  std::int64_t widest = 0; // the longest x-extent in g bounds how far left a crossing g can start
  for (const auto& t : g) widest = std::max<std::int64_t>(widest, std::int64_t{right(t)} - left(t));
  std::vector<std::uint32_t> out;
  out.reserve(f.size());
  for (const auto& s : f) {
    const std::int64_t lo = left(s), hi = right(s);
    // g's pieces with left end < lo - widest end before lo: they cannot meet s.
    auto it = std::lower_bound(g.begin(), g.end(), lo - widest,
                               [&](const FxSegment& u, std::int64_t v) { return left(u) < v; });
    std::uint32_t n = 0;
    for (; it != g.end() && left(*it) <= hi; ++it)
      n += antkit::kernel::properly_cross(s, *it) ? 1u : 0u;
    out.push_back(n);
  }
  return out;
}

inline std::uint64_t crossings(const std::vector<FxSegment>& f, const std::vector<FxSegment>& g) {
  std::uint64_t n = 0;
  for (const std::uint32_t c : crossings_per_piece(f, g)) n += c;
  return n;
}

struct Trial {
  double l1, l2;
  std::uint64_t n;
};

// Self-normalised check of E[N] = 2 L1 L2 / (pi A) over trials: z = (sum N - sum E) / sqrt(sum
// (N - E)^2); under the formula z is approximately standard normal (independent trials).
inline double crofton_z(const std::vector<Trial>& trials, double area, double pi) {
  double num = 0, var = 0;
  for (const auto& t : trials) {
    const double e = 2 * t.l1 * t.l2 / (pi * area);
    num += static_cast<double>(t.n) - e;
    var += (static_cast<double>(t.n) - e) * (static_cast<double>(t.n) - e);
  }
  return num / std::sqrt(var);
}

// A trial kept drop by drop, for a variance that does not assume N Poisson. Given the second
// family, the drops of the first are independent and identically distributed, and for each drop w
// (a segment, or a whole walk) with clipped length lambda_w and M_w crossings with the second
// family, D_w = M_w - 2 lambda_w L2 / (pi A) has mean zero (Crofton for a fixed piece of the
// second family against one random drop). So N - E = sum_w D_w is a sum of many independent
// centred terms, and sum_w D_w^2 estimates its variance whatever the clustering of crossings
// within a drop (a walk folding back crosses one segment several times: N is over-dispersed).
struct ClusterTrial {
  double l2 = 0;
  std::vector<std::pair<double, double>> drops; // (M_w, lambda_w) for every drop with a piece
};

// Groups the pieces of f (with their drop indices) into drops and counts their crossings with g.
inline ClusterTrial cluster_trial(const std::vector<FxSegment>& f,
                                  const std::vector<std::uint32_t>& drop,
                                  const std::vector<FxSegment>& g, double l2) {
  ClusterTrial t;
  t.l2 = l2;
  const std::vector<std::uint32_t> per_piece = crossings_per_piece(f, g);
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (i == 0 || drop[i] != drop[i - 1]) t.drops.emplace_back(0.0, 0.0);
    t.drops.back().first += per_piece[i];
    t.drops.back().second += len(f[i]);
  }
  return t;
}

// z = sum D_w / sqrt(sum D_w^2) over every drop of every trial, trial i in a region of area
// areas[i]; approximately standard normal when E[N] = 2 L1 L2 / (pi A) holds (thousands of terms).
inline double cluster_z(const std::vector<ClusterTrial>& trials, const std::vector<double>& areas,
                        double pi) {
  double num = 0, var = 0;
  for (std::size_t i = 0; i < trials.size(); ++i)
    for (auto [m, lambda] : trials[i].drops) {
      const double d = m - 2 * lambda * trials[i].l2 / (pi * areas[i]);
      num += d;
      var += d * d;
    }
  return num / std::sqrt(var);
}

// The confidence interval for A that goes with cluster_z, over trials in one region: with
// b = 2 / (pi A), D_w = M_w - b L2 lambda_w, and |sum D_w| <= z sqrt(sum D_w^2) is the quadratic
// inequality in b
//     (K^2 - z^2 S_ll) b^2 - 2 (N K - z^2 S_ml) b + (N^2 - z^2 S_mm) <= 0,
// K = sum L2 lambda_w (= sum of L1 L2 over the trials), S_ll = sum (L2 lambda_w)^2,
// S_ml = sum M_w L2 lambda_w, S_mm = sum M_w^2, N = sum M_w. With thousands of drops the leading
// coefficient is positive and the b that pass lie between the two roots; A = 2 / (pi b) maps
// them to [lower, upper] (upper infinite when the lower root is not positive). Empty (lower >
// upper) when no b passes. The point estimate 2 sum L1 L2 / (pi N) (b = N / K) is always inside.
struct AreaInterval {
  double lower, upper;
  bool covers(double a) const { return lower <= a && a <= upper; }
};

inline AreaInterval cluster_interval(const std::vector<ClusterTrial>& trials, double pi, double z) {
  double k = 0, s_ll = 0, s_ml = 0, s_mm = 0, n = 0;
  for (const auto& t : trials)
    for (auto [m, lambda] : t.drops) {
      const double x = t.l2 * lambda;
      k += x;
      s_ll += x * x;
      s_ml += m * x;
      s_mm += m * m;
      n += m;
    }
  const double z2 = z * z, qa = k * k - z2 * s_ll, qb = n * k - z2 * s_ml, qc = n * n - z2 * s_mm;
  const double disc = qb * qb - qa * qc;
  if (qa <= 0 || disc < 0) return {1, 0}; // too few drops for a bounded interval: empty
  const double b_lo = (qb - std::sqrt(disc)) / qa, b_hi = (qb + std::sqrt(disc)) / qa;
  return {2 / (pi * b_hi), b_lo > 0 ? 2 / (pi * b_lo) : std::numeric_limits<double>::infinity()};
}

} // namespace antkit::test::crofton
