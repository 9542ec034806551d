// What the online first visit delivers (issue 17), measured on random polygons with holes of
// 1 000 to 20 000 unit^2, one trial each, with the erosion-corrected estimate (estimate.hpp); and
// the two-marker alternative on the same polygons. Fixed seeds (20261125); every line printed
// names the polygon and its trial, so a failure reproduces from the log. Slow: about a minute.
#include <algorithm>
#include <antkit/algorithms/units.hpp>
#include <antkit/buffon/estimate.hpp>
#include <antkit/buffon/measurement.hpp>
#include <antkit/buffon/stopping.hpp>
#include <antkit/buffon/two_markers.hpp>
#include <antkit/geometry/wkt.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/kernel/random.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace buffon = antkit::buffon;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::uint64_t kSeed = 20261125;

struct Polygon {
  std::string wkt;
  double area = 0;
};

// Polygon k: an outer star of 8..16 vertices at 70..100 % of a radius R (so the disc of radius
// 0.64 R is inside it), R drawn so that the area is log-uniform in about [1 000, 20 000], and 0..3
// square holes of half-side 4..10 % of R, centred within 0.5 R, at least 2 units apart (room for
// the robot's unit body between them). Coordinates on the 1/16 grid (exact in Q15.16).
std::optional<Polygon> make_polygon(std::uint64_t k) {
  antkit::kernel::Stream st(kSeed, 17, k);
  const double target = 1250.0 * std::pow(20.0, st.below(1001) / 1000.0);
  const int n = st.between(8, 16);
  const double radius = std::sqrt(target / kPi) / 0.85;
  auto grid = [](double v) { return std::round(v * 16) / 16; };
  std::ostringstream out;
  out.precision(17);
  out << "POLYGON((";
  std::vector<std::pair<double, double>> outer;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * kPi * (i + st.between(10, 90) / 100.0) / n;
    const double r = radius * st.between(70, 100) / 100.0;
    outer.emplace_back(grid(r * std::cos(a)), grid(r * std::sin(a)));
  }
  outer.push_back(outer.front());
  for (std::size_t i = 0; i < outer.size(); ++i)
    out << (i ? ", " : "") << outer[i].first << ' ' << outer[i].second;
  out << ')';
  struct Hole {
    double x, y, h;
  };
  std::vector<Hole> holes;
  const int wanted = st.between(0, 3);
  for (int attempt = 0; attempt < 50 && static_cast<int>(holes.size()) < wanted; ++attempt) {
    const double h = grid(radius * st.between(4, 10) / 100.0);
    const double a = 2 * kPi * st.below(3600) / 3600.0, r = 0.5 * radius * st.below(1001) / 1000.0;
    const Hole c{grid(r * std::cos(a)), grid(r * std::sin(a)), h};
    bool apart = true;
    for (const Hole& o : holes)
      apart = apart && std::max(std::abs(c.x - o.x), std::abs(c.y - o.y)) > c.h + o.h + 2;
    if (apart) holes.push_back(c);
  }
  for (const Hole& c : holes) // clockwise
    out << ", (" << c.x - c.h << ' ' << c.y - c.h << ", " << c.x - c.h << ' ' << c.y + c.h << ", "
        << c.x + c.h << ' ' << c.y + c.h << ", " << c.x + c.h << ' ' << c.y - c.h << ", "
        << c.x - c.h << ' ' << c.y - c.h << ')';
  out << ')';
  try {
    const auto arena = antkit::geometry::read_wkt(out.str(), "polygon " + std::to_string(k));
    return Polygon{out.str(), arena.area()};
  } catch (const antkit::kernel::InputError&) {
    return std::nullopt; // rounding made it invalid: the caller draws the next one
  }
}

struct Outcome {
  double area = 0, raw = 0, corrected = 0, total_length = 0, ratio21 = 0; // ratio21: L2 / L1
  bool reached = false;
  [[nodiscard]] double error() const { return std::abs(corrected / area - 1); }
};

// One trial (trial index k) of `rule` on polygon k at precision p (millionths).
Outcome run(const Polygon& g, std::uint64_t k, std::uint32_t p, bool markers) {
  const auto arena = antkit::geometry::read_wkt(g.wkt);
  const buffon::World world(arena.walls_fx());
  buffon::TrialParams params;
  params.seed = kSeed;
  params.precision_millionths = p;
  params.online_first_visit = !markers;
  params.total_steps = 40000000;
  const auto t = markers ? buffon::run_two_marker_trial(world, params, k)
                         : buffon::run_trial(world, params, k);
  const double l1 = static_cast<double>(t.length1_raw) / 65536,
               l2 = static_cast<double>(t.length2_raw) / 65536;
  const auto cf = buffon::closed_form_area(l1 * t.pair_share, l2, t.crossings_exact);
  Outcome o;
  o.area = g.area;
  o.raw = cf.area ? *cf.area : 0.0;
  o.corrected = o.raw * buffon::erosion_factor(t.wall_encounters, l1 + l2);
  o.total_length = l1 + l2;
  o.ratio21 = l1 > 0 ? l2 / l1 : 0.0;
  o.reached = t.reached_precision;
  return o;
}

std::vector<Polygon> polygons(std::size_t count) {
  std::vector<Polygon> out;
  for (std::uint64_t k = 0; out.size() < count; ++k)
    if (auto g = make_polygon(k)) out.push_back(*g);
  return out;
}

std::vector<Outcome> run_all(const std::vector<Polygon>& gs, std::uint32_t p, bool markers) {
  std::vector<Outcome> out(gs.size());
  antkit::algorithms::for_each_unit(
      gs.size(), 2, [&](std::uint64_t k, unsigned) { out[k] = run(gs[k], k, p, markers); });
  for (std::size_t k = 0; k < out.size(); ++k)
    std::cout << (markers ? "markers" : "online") << " P " << p / 1e6 << " polygon " << k
              << " area " << out[k].area << " corrected " << out[k].corrected << " error "
              << out[k].error() << " trail " << out[k].total_length << " reached " << out[k].reached
              << '\n';
  return out;
}

double share_within(const std::vector<Outcome>& v, double bound) {
  return static_cast<double>(std::count_if(v.begin(), v.end(),
                                           [&](const Outcome& o) { return o.error() <= bound; })) /
         static_cast<double>(v.size());
}

double median_trail(const std::vector<Outcome>& v) {
  std::vector<double> t;
  for (const auto& o : v) t.push_back(o.total_length);
  return buffon::quantile(t, 0.5);
}

// The targets, for both rules: with P = 0.1 the corrected estimate within 10 % of the
// true area in >= 90 % of the trials and within 15 % in >= 97 %; with P = 0.2 within 20 % in
// >= 90 %; no trial that reached P misses by more than 2 P.
void check_targets(const std::vector<Outcome>& v, std::uint32_t p, const char* rule) {
  const double P = p / 1e6;
  const double within = share_within(v, P), within15 = share_within(v, 0.15);
  INFO(rule << " P " << P << ", " << v.size() << " polygons, seed " << kSeed << ": within P "
            << within << ", within 15 % " << within15 << ", median trail " << median_trail(v));
  CHECK(within >= 0.90);
  if (p == 100000) CHECK(within15 >= 0.97);
  for (std::size_t k = 0; k < v.size(); ++k) {
    INFO("polygon " << k << ": error " << v[k].error());
    CHECK(v[k].reached); // the budget (40 M steps) is never what stops a trial here
    CHECK(v[k].error() <= 2 * P);
  }
}

} // namespace

TEST_CASE("random polygons with holes: the corrected estimate meets P with either rule", "[slow]") {
  const auto gs = polygons(60);
  for (const std::uint32_t p : {100000u, 200000u}) {
    const auto online = run_all(gs, p, false);
    check_targets(online, p, "online");
    // The online rule aims at equal visits (stopping.hpp): the median of visit 2 / visit 1.
    std::vector<double> ratios;
    for (const auto& o : online) ratios.push_back(o.ratio21);
    const double median = buffon::quantile(ratios, 0.5);
    INFO("online P " << p / 1e6 << ": median visit 2 / visit 1 " << median);
    CHECK(median > 0.5);
    CHECK(median < 2.0);
    check_targets(run_all(gs, p, true), p, "markers");
  }
}

TEST_CASE("the erosion correction removes the closed form's bias on held-out polygons", "[slow]") {
  // kappa was fitted on a circle and a square (estimate.hpp); these polygons (holes, concave
  // outer rings) were not used. Mean signed error over the 60, online rule at P = 0.1: the
  // uncorrected closed form is low (the centre explores less than the arena), the corrected one
  // centred on the truth.
  const auto v = run_all(polygons(60), 100000, false);
  double raw = 0, corrected = 0;
  for (const auto& o : v) {
    raw += o.raw / o.area - 1;
    corrected += o.corrected / o.area - 1;
  }
  raw /= static_cast<double>(v.size());
  corrected /= static_cast<double>(v.size());
  INFO("mean signed error: uncorrected " << raw << ", corrected " << corrected);
  CHECK(raw < -0.03);
  CHECK(std::abs(corrected) < 0.015);
}

TEST_CASE("two markers reach P = 0.1 with less total trail than the online first visit", "[slow]") {
  // The comparison the default of --rule rests on (two_markers.hpp): the same 60 polygons, the
  // same precision, the median total trail of each rule. Measured: online 12 755, markers 9 740
  // (0.76 of it). The bound leaves room for noise (the medians of 60 have a relative spread of a
  // few per cent) but not for a reversal.
  const auto gs = polygons(60);
  const double online = median_trail(run_all(gs, 100000, false));
  const double markers = median_trail(run_all(gs, 100000, true));
  std::cout << "P 0.1, 60 polygons: median total trail online " << online << ", markers " << markers
            << " (ratio " << markers / online << ")\n";
  CHECK(markers < 0.9 * online);
}
