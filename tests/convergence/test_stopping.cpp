// The online stopping rule (stopping.hpp): the exact test equals the real-valued inequality away
// from ties, the worked example, the monitor's schedule, and the online crossing counter
// (crossing_counter.hpp) against the kernel's batch count.
#include <antkit/buffon/crossing_counter.hpp>
#include <antkit/buffon/measurement.hpp>
#include <antkit/buffon/stopping.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/kernel/segment.hpp>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <numeric>
#include <rapidcheck/catch.h>
#include <vector>

namespace buffon = antkit::buffon;
using antkit::kernel::Fx;
using antkit::kernel::FxPoint;

namespace {
using Sums = std::array<std::uint64_t, buffon::PrecisionMonitor::kBatches>;

// z^2 (1 + P)^2 max(V, N) - P^2 N^2 in long double (64-bit mantissa), with V the two-way
// batch-means variance of stopping.hpp and the rule's z^2 = 5.118 (or `z2`).
long double margin(const Sums& rows, const Sums& cols, std::uint32_t p, long double z2 = 5.118L) {
  const long double n = static_cast<long double>(std::accumulate(rows.begin(), rows.end(), 0ull));
  auto share = [n](const Sums& x) {
    long double sq = 0;
    for (auto v : x) sq += static_cast<long double>(v) * static_cast<long double>(v);
    return (10 * sq - n * n) / 9;
  };
  const long double v = std::max(share(rows) + share(cols), n);
  const long double P = static_cast<long double>(p) / 1e6L;
  return z2 * (1 + P) * (1 + P) * v - P * P * n * n;
}

// Splits n into 10 parts at random (rapidcheck), some of them zero.
Sums split(std::uint64_t n) {
  Sums out{};
  std::uint64_t left = n;
  for (std::size_t i = 0; i + 1 < out.size(); ++i) {
    const auto share = *rc::gen::inRange<std::uint64_t>(0, left + 1);
    out[i] = share;
    left -= share;
  }
  out.back() = left;
  return out;
}
} // namespace

TEST_CASE("precision_met is the real inequality wherever that is not a near tie", "[property]") {
  rc::prop("exact test == sign of the long double margin", [] {
    const auto p = *rc::gen::inRange<std::uint32_t>(1, 1000000);
    const auto n = *rc::gen::oneOf(rc::gen::inRange<std::uint64_t>(1, 2000),
                                   rc::gen::inRange<std::uint64_t>(1, std::uint64_t{1} << 40));
    const Sums rows = split(n), cols = split(n);
    const long double m = margin(rows, cols, p);
    const long double scale = static_cast<long double>(n) * static_cast<long double>(n);
    RC_LOG() << "p = " << p << ", N = " << n << ", margin = " << static_cast<double>(m);
    if (std::fabs(m) > 1e-12L * scale) RC_ASSERT(buffon::precision_met(rows, cols, p) == (m <= 0));
  });
}

TEST_CASE("worked example: equal sums, P = 0.1, the Poisson floor decides at N = 620", "[unit]") {
  // Floor V = N: N >= 5.118 * 1.21 / 0.01 = 619.28. Rows and columns 62 x 9 + 61 (N = 619) have
  // spread 9 each, below the floor 9 N.
  Sums r619{}, r620{};
  r619.fill(62);
  r619.back() = 61;
  r620.fill(62);
  CHECK_FALSE(buffon::precision_met(r619, r619, 100000));
  CHECK(buffon::precision_met(r620, r620, 100000));
  // All crossings on one segment run of visit 1: visit 1's share is 9 N^2 / 9 = N^2, far over.
  Sums lumped{};
  lumped[3] = 100000;
  Sums even{};
  even.fill(10000);
  CHECK_FALSE(buffon::precision_met(lumped, even, 100000));
  CHECK(buffon::precision_met(even, even, 100000));
  CHECK_THROWS_AS(buffon::precision_met(even, even, 0), antkit::kernel::InputError);
  CHECK_THROWS_AS(buffon::precision_met(even, even, 1000000), antkit::kernel::InputError);
}

TEST_CASE("teeth: the one-way variance or a smaller z would pass tables the rule rejects",
          "[property]") {
  rc::prop("some table is rejected by the rule but passes without visit 1's share", [] {
    const auto p = *rc::gen::inRange<std::uint32_t>(10000, 500000);
    // Visit 1's crossings all in two runs, visit 2's spread evenly: the two-way rule must see the
    // clustering that the one-way (columns-only) variance misses.
    const auto n = *rc::gen::inRange<std::uint64_t>(100000, 1000000) * 10;
    Sums rows{}, cols{};
    rows[0] = n / 2;
    rows[7] = n - n / 2;
    cols.fill(n / 10);
    RC_ASSERT(!buffon::precision_met(rows, cols, p));
    RC_ASSERT(margin(cols, cols, p) <= 0); // the one-way form would have stopped
  });
}

TEST_CASE("PrecisionMonitor checks every 10 000 steps on the table it accumulates", "[property]") {
  rc::prop("the monitor's decision = precision_met on the table built independently", [] {
    const auto p = *rc::gen::inRange<std::uint32_t>(20000, 400000);
    const auto segments = *rc::gen::inRange<std::uint64_t>(10, 100000);
    const auto steps = *rc::gen::inRange<int>(1, 60001);
    buffon::PrecisionMonitor monitor(p, segments);
    Sums rows{};
    std::vector<std::uint64_t> per_block;
    std::uint64_t in_block = 0;
    bool stopped = false;
    int stop_step = 0;
    for (int s = 1; s <= steps && !stopped; ++s) {
      const auto k = *rc::gen::inRange<int>(0, 4);
      for (int i = 0; i < k; ++i) {
        const auto seg = *rc::gen::inRange<std::uint64_t>(0, segments);
        monitor.crossing(seg);
        ++rows[seg * 10 / segments];
        ++in_block;
      }
      stopped = monitor.end_step();
      if (s % 1000 == 0) per_block.push_back(std::exchange(in_block, 0));
      if (stopped) stop_step = s;
      if (s % 10000 == 0) {
        const std::size_t m = per_block.size() / 10;
        Sums cols{};
        for (std::size_t b = 0; b < per_block.size(); ++b) cols[b / m] += per_block[b];
        RC_ASSERT(stopped == buffon::precision_met(rows, cols, p));
      } else {
        RC_ASSERT(!stopped); // decisions only at whole numbers of 10 blocks
      }
    }
    RC_ASSERT(monitor.reached() == stopped);
    RC_ASSERT(!stopped || stop_step % 10000 == 0);
  });
}

namespace {
// A random polyline: a walk of short steps with an occasional long jump, anywhere in Fx's range
// near a random origin (negative coordinates included).
std::vector<FxPoint> random_polyline(std::int32_t ox, std::int32_t oy, int n) {
  std::vector<FxPoint> out;
  std::int64_t x = ox, y = oy;
  for (int i = 0; i < n; ++i) {
    const bool jump = *rc::gen::inRange(0, 20) == 0;
    const std::int32_t r = jump ? 400000 : 3000;
    x += *rc::gen::inRange(-r, r + 1);
    y += *rc::gen::inRange(-r, r + 1);
    x = std::clamp<std::int64_t>(x, INT32_MIN, INT32_MAX);
    y = std::clamp<std::int64_t>(y, INT32_MIN, INT32_MAX);
    out.push_back(
        {Fx::from_raw(static_cast<std::int32_t>(x)), Fx::from_raw(static_cast<std::int32_t>(y))});
  }
  return out;
}
} // namespace

TEST_CASE("CrossingCounter's online total equals count_proper_crossings", "[property]") {
  rc::prop("sum over the segments of b of add() == count_proper_crossings(a, b)", [] {
    const auto o = *rc::gen::element(std::int32_t{0}, std::int32_t{-3000000}, std::int32_t{1} << 30,
                                     INT32_MIN + 1000000);
    const auto a = random_polyline(o, o, *rc::gen::inRange(0, 300));
    const auto b = random_polyline(o, o, *rc::gen::inRange(0, 300));
    buffon::CrossingCounter counter(a);
    std::uint64_t total = 0;
    std::vector<std::uint32_t> ids;
    for (std::size_t i = 1; i < b.size(); ++i) {
      ids.clear();
      const auto k = counter.add(b[i - 1], b[i], &ids);
      RC_ASSERT(ids.size() == k);
      for (auto id : ids) // each reported segment really crosses, and only once
        RC_ASSERT(antkit::kernel::properly_cross({a[id], a[id + 1]}, {b[i - 1], b[i]}));
      std::sort(ids.begin(), ids.end());
      RC_ASSERT(std::adjacent_find(ids.begin(), ids.end()) == ids.end());
      total += k;
    }
    RC_ASSERT(total == antkit::kernel::count_proper_crossings(a, b));
  });
}

TEST_CASE("parse_precision reads decimals in (0, 1) exactly", "[unit]") {
  CHECK(buffon::parse_precision("0.05") == 50000);
  CHECK(buffon::parse_precision(".1") == 100000);
  CHECK(buffon::parse_precision("0.000001") == 1);
  CHECK(buffon::parse_precision("0.999999") == 999999);
  for (const char* bad : {"", "0", "0.0", "1", "1.0", "-0.1", "+0.1", "1e-2", "0.0000001", "0.1x",
                          ".", "abc", " 0.1", "00.5.", "2.5"}) {
    INFO("'" << bad << "'");
    CHECK_THROWS_AS(buffon::parse_precision(bad), antkit::kernel::InputError);
  }
}
