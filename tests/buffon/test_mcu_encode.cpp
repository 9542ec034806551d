// The host's writers of the chip's Buffon and RS inputs (buffon/mcu_encode.hpp) against the chip's
// readers (mcu_input.hpp, rs_mcu_input.hpp): what the host writes, the chip reads back field for
// field and wall for wall, and the trial the chip runs from those bytes (run_fixed_trial, as
// mcu/src/buffon_run.cpp runs it) is the host's run_trial. Refusals come in the library's words.
#include <antkit/buffon/fixed_trial.hpp>
#include <antkit/buffon/mcu_digest_input.hpp>
#include <antkit/buffon/mcu_encode.hpp>
#include <antkit/buffon/mcu_input.hpp>
#include <antkit/buffon/measurement.hpp>
#include <antkit/buffon/rs_mcu_input.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <cstdint>
#include <rapidcheck/catch.h>
#include <string>
#include <vector>

namespace buffon = antkit::buffon;
using antkit::kernel::Fx;
using antkit::kernel::FxSegment;

namespace {

buffon::World world_of(const std::string& spec, buffon::BodyParams body = {}) {
  return buffon::World(antkit::geometry::build_arena_spec(spec).arena.walls_fx(), body);
}

// The walls as the chip reads them from an input's bytes after a header of `header` bytes.
std::vector<FxSegment> walls_read(const std::vector<std::uint8_t>& bytes, std::size_t header,
                                  std::uint32_t walls) {
  std::vector<FxSegment> out;
  for (std::uint32_t i = 0; i < walls; ++i) out.push_back(buffon::read_mcu_wall(&bytes[header], i));
  return out;
}

// A d x d square, with a unit pillar at (1, 1) when `pillar` (the chip's arena holds arenas of a
// few walls: the named circles' 256 walls and their buckets do not fit).
std::vector<FxSegment> room(int d, bool pillar) {
  std::vector<FxSegment> walls;
  const auto box = [&walls](int x0, int y0, int x1, int y1) {
    const antkit::kernel::FxPoint a{Fx::from_int(x0), Fx::from_int(y0)},
        b{Fx::from_int(x1), Fx::from_int(y0)}, c{Fx::from_int(x1), Fx::from_int(y1)},
        e{Fx::from_int(x0), Fx::from_int(y1)};
    walls.insert(walls.end(), {{a, b}, {b, c}, {c, e}, {e, a}});
  };
  box(0, 0, d, d);
  if (pillar) box(1, 1, 2, 2);
  return walls;
}

bool same(const std::vector<FxSegment>& a, std::span<const FxSegment> b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].a.x != b[i].a.x || a[i].a.y != b[i].a.y || a[i].b.x != b[i].b.x ||
        a[i].b.y != b[i].b.y)
      return false;
  return true;
}

} // namespace

TEST_CASE("the chip reads back what mcu_buffon_input writes, and runs the host's trial",
          "[property][mcu]") {
  rc::prop("random rooms, noise, widths, seeds and steps", [] {
    const int d = *rc::gen::inRange(5, 14);
    buffon::BodyParams body;
    body.noise = Fx::from_raw(*rc::gen::element(0, 3277, 13107));
    const buffon::World world(room(d, *rc::gen::arbitrary<bool>()), body);
    const Fx width = Fx::from_raw(*rc::gen::element(6554, 13107, 19661));
    const auto seed = *rc::gen::inRange<std::uint64_t>(0, 1u << 30);
    const auto steps = *rc::gen::inRange<std::int64_t>(1, 1200);
    const buffon::McuInput in = buffon::mcu_buffon_input(world, width, seed, steps);
    buffon::McuBuffonRun run;
    RC_ASSERT(buffon::read_mcu_buffon_header(in.bytes.data(), in.bytes.size(), run) ==
              buffon::McuBuffonError::None);
    RC_ASSERT(run.seed == seed);
    RC_ASSERT(run.steps == steps);
    RC_ASSERT(run.width == width);
    RC_ASSERT(run.body.noise == body.noise);
    RC_ASSERT(run.body.speed == world.body().speed);
    RC_ASSERT(run.walls == world.walls().size());
    RC_ASSERT(in.walls == run.walls);
    RC_ASSERT(in.bytes.size() == buffon::kMcuBuffonHeaderBytes + run.walls * buffon::kMcuWallBytes);
    const auto walls = walls_read(in.bytes, buffon::kMcuBuffonHeaderBytes, run.walls);
    RC_ASSERT(same(walls, world.walls()));
    RC_ASSERT(in.plan <= buffon::kMcuArenaBytes);

    // The chip's run from the bytes read back: the walls at the arena's start, the plan after.
    std::vector<std::uint64_t> words(buffon::kMcuArenaBytes / 8);
    const std::uint64_t at = buffon::mcu_walls_bytes(run.walls);
    buffon::FixedTrialResult r;
    RC_ASSERT(buffon::run_fixed_trial(
                  walls, run.body, run.width, run.seed, 0, run.steps,
                  {reinterpret_cast<std::uint8_t*>(words.data()) + at, buffon::kMcuArenaBytes - at},
                  r) == nullptr);
    RC_ASSERT(at + r.bytes <= in.plan);
    buffon::TrialParams p;
    p.seed = seed;
    p.steps = steps;
    p.width = width;
    const buffon::TrialResult host = buffon::run_trial(world, p, 0);
    RC_ASSERT(r.hash == host.hash);
    RC_ASSERT(r.bc == host.bc);
    RC_ASSERT(r.crossings_exact == host.crossings_exact);

    // The digest program's input differs in the magic only.
    const auto digest =
        buffon::mcu_buffon_input(world, width, seed, steps, buffon::McuBuffonProgram::Digest);
    RC_ASSERT(digest.bytes.size() == in.bytes.size());
    RC_ASSERT(std::equal(digest.bytes.begin() + 8, digest.bytes.end(), in.bytes.begin() + 8));
    RC_ASSERT(std::equal(digest.bytes.begin(), digest.bytes.begin() + 8,
                         std::begin(buffon::kMcuBuffonDigestMagic)));
  });
}

TEST_CASE("the chip reads back what mcu_rs_input writes", "[property][mcu]") {
  rc::prop("random squares, noise, seeds and steps", [] {
    const int d = *rc::gen::inRange(2, 10);
    buffon::BodyParams body;
    body.noise = Fx::from_raw(*rc::gen::element(0, 3277, 13107));
    const buffon::World world = world_of("square:area=" + std::to_string(d * d), body);
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto steps = *rc::gen::inRange<std::int64_t>(1, buffon::kMcuMaxSteps + 1);
    const buffon::McuInput in = buffon::mcu_rs_input(world, seed, steps);
    buffon::McuRsRun run;
    RC_ASSERT(buffon::read_mcu_rs_header(in.bytes.data(), in.bytes.size(), run) ==
              buffon::McuBuffonError::None);
    RC_ASSERT(run.seed == seed);
    RC_ASSERT(run.steps == steps);
    RC_ASSERT(run.body.noise == body.noise);
    RC_ASSERT(run.body.speed == world.body().speed);
    RC_ASSERT(run.walls == world.walls().size());
    RC_ASSERT(in.bytes.size() == buffon::kMcuRsHeaderBytes + run.walls * buffon::kMcuWallBytes);
    RC_ASSERT(same(walls_read(in.bytes, buffon::kMcuRsHeaderBytes, run.walls), world.walls()));
    RC_ASSERT(in.plan <= buffon::kMcuArenaBytes);
  });
}

TEST_CASE("the writers refuse what the chip would refuse, in the library's words", "[unit][mcu]") {
  const auto where = [](auto&& f) {
    try {
      f();
    } catch (const antkit::kernel::InputError& e) {
      return e.where() + ": " + e.message();
    }
    return std::string("no error");
  };
  const buffon::World square = world_of("square:area=25");
  const Fx width = Fx::from_raw(6554);
  CHECK(where([&] { (void)buffon::mcu_buffon_input(square, width, 1, 0); }) ==
        "steps per visit: the steps per visit must be in [1, 10000000]");
  CHECK(where([&] { (void)buffon::mcu_rs_input(square, 1, 10000001); }) ==
        "steps: the steps must be in [1, 10000000]");
  // Steps whose trail and crossing index do not fit, on an arena that does: say how many fit.
  const std::string steps =
      where([&] { (void)buffon::mcu_buffon_input(square, width, 1, 900000); });
  CHECK(steps.rfind("steps per visit: too many steps for the chip", 0) == 0);
  CHECK(steps.find("steps per visit fit this arena") != std::string::npos);
  // A circle of 256 walls: its buckets alone exceed the arena.
  const std::string circle =
      where([&] { (void)buffon::mcu_buffon_input(world_of("circle:d=10"), width, 1, 500); });
  CHECK(circle.rfind("arena: too large for the chip", 0) == 0);
  CHECK(circle.find("holds 114688 bytes") != std::string::npos);
  CHECK(where([&] {
          (void)buffon::mcu_rs_input(world_of("square:area=1600"), 1, 100);
        }).rfind("arena: too large for the chip: the walk needs", 0) == 0);
}
