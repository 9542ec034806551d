// The Buffon family's freestanding cores (issue 27) against the host's classes that own their
// storage: one trial in a caller's buffer (run_fixed_trial, what the Cortex-M image runs) is
// run_trial's, hash for hash; WorldCore, RasterCore and CrossingCounterCore over spans answer as
// World, PheromoneRaster and CrossingCounter; errors are returned where the host throws.
#include <antkit/buffon/crossing_counter.hpp>
#include <antkit/buffon/fixed_trial.hpp>
#include <antkit/buffon/measurement.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>
#include <rapidcheck/catch.h>
#include <string>
#include <vector>

namespace buffon = antkit::buffon;
using antkit::kernel::Fx;
using antkit::kernel::FxPoint;
using antkit::kernel::FxSegment;

namespace {

std::vector<FxSegment> walls_of(const std::string& spec) {
  return antkit::geometry::build_arena_spec(spec).arena.walls_fx();
}

// run_fixed_trial over a buffer of exactly `bytes` bytes (8-byte aligned).
const char* fixed_trial(const std::vector<FxSegment>& walls, buffon::BodyParams body, Fx width,
                        std::uint64_t seed, std::int64_t steps, std::size_t bytes,
                        buffon::FixedTrialResult& r) {
  std::vector<std::uint64_t> words((bytes + 7) / 8);
  return buffon::run_fixed_trial(walls, body, width, seed, 0, steps,
                                 {reinterpret_cast<std::uint8_t*>(words.data()), bytes}, r);
}

std::uint64_t plan_bytes(const std::vector<FxSegment>& walls, buffon::BodyParams body, Fx width,
                         std::int64_t steps) {
  buffon::WorldLayout layout;
  REQUIRE(buffon::WorldCore::plan(walls, body, layout) == buffon::WorldError::None);
  buffon::RasterCore raster;
  REQUIRE(raster.init(layout.lower, layout.upper, width) == buffon::RasterError::None);
  return buffon::plan_fixed_trial(layout, raster, steps).total;
}

} // namespace

TEST_CASE("run_fixed_trial in a caller's buffer is run_trial's trial", "[property]") {
  rc::prop("hash, BC, exact crossings, blocked steps and lengths", [] {
    const int d = *rc::gen::inRange(4, 16);
    const bool square = *rc::gen::arbitrary<bool>();
    const auto walls =
        walls_of(square ? "square:area=" + std::to_string(d * d) : "circle:d=" + std::to_string(d));
    buffon::BodyParams body;
    body.noise = Fx::from_raw(*rc::gen::element(0, 3277, 13107));
    buffon::TrialParams p;
    p.seed = *rc::gen::inRange<std::uint64_t>(0, 1u << 30);
    p.steps = *rc::gen::inRange(0, 1500);
    p.width = Fx::from_raw(*rc::gen::element(6554, 3277, 19661));
    const buffon::World world(walls, body);
    const auto trial = static_cast<std::uint64_t>(*rc::gen::inRange(0, 3));
    const buffon::TrialResult host = buffon::run_trial(world, p, trial);
    buffon::FixedTrialResult r;
    const std::uint64_t bytes = plan_bytes(walls, body, p.width, p.steps);
    std::vector<std::uint64_t> words(bytes / 8 + 1);
    RC_ASSERT(buffon::run_fixed_trial(walls, body, p.width, p.seed, trial, p.steps,
                                      {reinterpret_cast<std::uint8_t*>(words.data()), bytes},
                                      r) == nullptr);
    RC_ASSERT(r.hash == host.hash);
    RC_ASSERT(r.bc == host.bc);
    RC_ASSERT(r.crossings_exact == host.crossings_exact);
    RC_ASSERT(r.blocked == host.blocked);
    RC_ASSERT(r.length1_raw == host.length1_raw);
    RC_ASSERT(r.length2_raw == host.length2_raw);
    RC_ASSERT(r.bytes <= bytes);
  });
}

TEST_CASE("run_fixed_trial refuses what the host refuses, and a buffer below its plan", "[unit]") {
  const auto walls = walls_of("square:area=25");
  const Fx width = Fx::from_raw(6554);
  buffon::FixedTrialResult r;
  const std::uint64_t bytes = plan_bytes(walls, {}, width, 500);
  CHECK(fixed_trial(walls, {}, width, 1, 500, bytes, r) == nullptr);
  CHECK(std::string(fixed_trial(walls, {}, width, 1, 500, bytes - 1, r)) ==
        "the trial's plan is larger than the buffer");
  CHECK(std::string(fixed_trial({}, {}, width, 1, 500, bytes, r)) ==
        "an arena needs at least one wall");
  CHECK(std::string(fixed_trial(walls, {}, Fx{}, 1, 500, bytes, r)) ==
        "the trail width must be in [0.01, 10] units");
  buffon::BodyParams fast;
  fast.speed = Fx::from_int(1);
  CHECK(std::string(fixed_trial(walls, fast, width, 1, 500, bytes, r)) ==
        "the speed per step must be in (0, 0.25] units");
  // The host's World throws the same messages, located.
  try {
    const buffon::World w(walls, fast);
    FAIL("no throw");
  } catch (const antkit::kernel::InputError& e) {
    CHECK(e.where() == "speed");
    CHECK(e.message() == buffon::describe(buffon::WorldError::Speed));
  }
  // A start that is not clear: a 0.8-unit square leaves no room for the body.
  const FxPoint a{}, b{Fx::from_ratio(4, 5), Fx{}}, c{Fx::from_ratio(4, 5), Fx::from_ratio(4, 5)},
      d{Fx{}, Fx::from_ratio(4, 5)};
  const std::vector<FxSegment> tiny{{a, b}, {b, c}, {c, d}, {d, a}};
  CHECK(std::string(fixed_trial(tiny, {}, width, 1, 10, 1 << 20, r)) ==
        buffon::describe(buffon::WorldError::StartBlocked));
}

TEST_CASE("a World's copies and moves answer as the original", "[unit]") {
  const buffon::World original(walls_of("circle:d=8"));
  buffon::World copy = original;
  buffon::World moved_from(original);
  const buffon::World moved(std::move(moved_from));
  buffon::World assigned(walls_of("square:area=4"));
  assigned = copy;
  antkit::kernel::Stream s(1, 2, 3, 4, 5);
  for (int i = 0; i < 2000; ++i) {
    const buffon::Pose pose{
        {Fx::from_raw(static_cast<std::int32_t>(s.next_u32() % 589824) - 294912),
         Fx::from_raw(static_cast<std::int32_t>(s.next_u32() % 589824) - 294912)},
        antkit::kernel::Angle::from_raw(s.next_u32())};
    const auto a = original.sense(pose, nullptr);
    for (const buffon::World* w : std::vector<const buffon::World*>{&copy, &moved, &assigned}) {
      CHECK(w->sense(pose, nullptr).ir == a.ir);
      CHECK(w->clear(pose.position) == original.clear(pose.position));
    }
  }
}

TEST_CASE("RasterCore over a caller's words marks PheromoneRaster's cells", "[property]") {
  rc::prop("the same geometry and bits after the same stamps", [] {
    const FxPoint lower{Fx::from_int(-3), Fx::from_int(-2)},
        upper{Fx::from_int(5), Fx::from_int(4)};
    const Fx width = Fx::from_raw(*rc::gen::inRange(656, 65536));
    buffon::PheromoneRaster host(lower, upper, width);
    buffon::RasterCore core;
    RC_ASSERT(core.init(lower, upper, width) == buffon::RasterError::None);
    std::vector<std::uint64_t> words(static_cast<std::size_t>(core.words()));
    core.bind(words);
    const auto n = *rc::gen::inRange(0, 200);
    for (int i = 0; i < n; ++i) {
      const FxPoint p{Fx::from_raw(*rc::gen::inRange(-3 * 65536, 5 * 65536)),
                      Fx::from_raw(*rc::gen::inRange(-2 * 65536, 4 * 65536))};
      host.lay(p);
      core.lay(p);
      RC_ASSERT(core.at(p) == host.at(p));
    }
    RC_ASSERT(core == host);
    RC_ASSERT(core.marked() == host.marked());
  });
  buffon::RasterCore core;
  CHECK(core.init({}, {Fx::from_int(1), Fx::from_int(1)}, Fx{}) == buffon::RasterError::Width);
}

TEST_CASE("CrossingCounterCore in one caller's buffer counts CrossingCounter's crossings",
          "[property]") {
  rc::prop("the same counts and crossed segments, in the same order", [] {
    const auto walk = [](std::size_t n) {
      std::vector<FxPoint> pts;
      std::int32_t x = 0, y = 0;
      for (std::size_t i = 0; i < n; ++i) {
        x += *rc::gen::inRange(-4000, 4001);
        y += *rc::gen::inRange(-4000, 4001);
        pts.push_back({Fx::from_raw(x), Fx::from_raw(y)});
      }
      return pts;
    };
    const auto a = walk(*rc::gen::inRange<std::size_t>(0, 400));
    const auto b = walk(*rc::gen::inRange<std::size_t>(0, 400));
    buffon::CrossingLayout layout;
    RC_ASSERT(buffon::CrossingCounterCore::plan(a, layout));
    std::vector<std::uint32_t> words(static_cast<std::size_t>(layout.words()));
    const std::span<std::uint32_t> all(words);
    buffon::CrossingCounterCore core;
    const auto starts = static_cast<std::size_t>(layout.buckets + (a.size() >= 2 ? 1 : 0));
    core.build(a, layout, all.subspan(0, starts),
               all.subspan(starts, static_cast<std::size_t>(layout.ids)),
               all.subspan(starts + static_cast<std::size_t>(layout.ids)));
    buffon::CrossingCounter host(a);
    std::uint64_t total = 0;
    for (std::size_t i = 1; i < b.size(); ++i) {
      std::vector<std::uint32_t> host_ids, core_ids;
      const auto k = host.add(b[i - 1], b[i], &host_ids);
      RC_ASSERT(core.add(b[i - 1], b[i], [&](std::uint32_t id) { core_ids.push_back(id); }) == k);
      RC_ASSERT(core_ids == host_ids);
      total += k;
    }
    RC_ASSERT(total == antkit::kernel::count_proper_crossings(a, b));
  });
}
