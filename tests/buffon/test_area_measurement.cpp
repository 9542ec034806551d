// measure_area (area_measurement.hpp), the measurement `antkit buffon` prints: its trials are the
// trial runners' own (run_trial, run_two_marker_trial), its per-trial fields and summary are the
// reductions the command documents, and nothing depends on the thread count.
#include <antkit/buffon/area_measurement.hpp>
#include <antkit/buffon/two_markers.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/kernel/hash.hpp>
#include <catch2/catch.hpp>

namespace buffon = antkit::buffon;

namespace {

buffon::World circle() {
  return buffon::World(antkit::geometry::build_arena_spec("circle:d=20").arena.walls_fx());
}

void check_same(const buffon::AreaMeasurement& a, const buffon::AreaMeasurement& b) {
  REQUIRE(a.trials.size() == b.trials.size());
  for (std::size_t i = 0; i < a.trials.size(); ++i) {
    CHECK(a.trials[i].run.hash == b.trials[i].run.hash);
    CHECK(a.trials[i].nbc == b.trials[i].nbc);
    CHECK(a.trials[i].closed_form.area == b.trials[i].closed_form.area);
  }
  CHECK(a.summary.hash == b.summary.hash);
  CHECK(a.summary.nbc_median == b.summary.nbc_median);
  CHECK(a.summary.area_closed_form_median == b.summary.area_closed_form_median);
}

} // namespace

TEST_CASE("measure_area: two fixed visits, reduced as the command prints them", "[buffon]") {
  const auto world = circle();
  buffon::AreaMeasurementParams p;
  p.trials = 4;
  p.steps = 20000;
  p.seed = 7;
  const auto m = buffon::measure_area(world, p);
  REQUIRE(m.trials.size() == 4);
  buffon::TrialParams tp;
  tp.seed = 7;
  tp.steps = 20000;
  antkit::kernel::TraceHash chain(7);
  std::vector<double> nbcs, areas;
  for (std::uint64_t i = 0; i < 4; ++i) {
    const auto& a = m.trials[i];
    const auto direct = buffon::run_trial(world, tp, i);
    CHECK(a.run.hash == direct.hash);
    CHECK(a.run.trial == i);
    CHECK(a.length1 == static_cast<double>(direct.length1_raw) / 65536.0);
    CHECK(a.length2 == static_cast<double>(direct.length2_raw) / 65536.0);
    CHECK(a.nbc == static_cast<double>(direct.bc) / a.length2);
    const auto cf = buffon::closed_form_area(a.length1, a.length2, direct.crossings_exact);
    CHECK(a.closed_form.area == cf.area);
    CHECK(a.closed_form.lower == cf.lower);
    CHECK_FALSE(a.precision);
    CHECK_FALSE(a.stopped);
    CHECK_FALSE(a.area_pilot);
    CHECK(a.run.trail1.empty());
    chain.add_u64(direct.hash);
    nbcs.push_back(a.nbc);
    if (cf.area) areas.push_back(*cf.area);
  }
  CHECK(m.summary.hash == chain.finish());
  CHECK(m.summary.nbc_median == buffon::quantile(nbcs, 0.5));
  CHECK(m.summary.nbc_q1 == buffon::quantile(nbcs, 0.25));
  CHECK(m.summary.nbc_q3 == buffon::quantile(nbcs, 0.75));
  REQUIRE(m.summary.area_closed_form_median);
  CHECK(*m.summary.area_closed_form_median == buffon::quantile(areas, 0.5));
  CHECK(m.summary.reached_precision == 0);
  CHECK(m.summary.out_of_steps == 0);

  p.threads = 3;
  check_same(m, buffon::measure_area(world, p));
}

TEST_CASE("measure_area: the precision rules' fields and the trails kept for a figure",
          "[buffon]") {
  const auto world = circle();
  buffon::AreaMeasurementParams p;
  p.trials = 3;
  p.precision_millionths = 200000; // P = 0.2
  p.keep_first_trails = true;

  SECTION("markers: the two-marker trial, stopped on the precision or the budget") {
    p.rule = buffon::PrecisionRule::markers;
    const auto m = buffon::measure_area(world, p);
    buffon::TrialParams tp;
    tp.steps = p.steps;
    tp.precision_millionths = 200000;
    tp.total_steps = buffon::kDefaultPrecisionBudget;
    CHECK(m.trials[1].run.hash == buffon::run_two_marker_trial(world, tp, 1).hash);
    CHECK_FALSE(m.trials[0].run.trail1.empty());
    CHECK(m.trials[1].run.trail1.empty());
    for (const auto& a : m.trials) {
      REQUIRE(a.precision);
      REQUIRE(a.stopped);
      CHECK(*a.stopped ==
            (a.run.reached_precision ? buffon::TrialStop::precision : buffon::TrialStop::budget));
      CHECK_FALSE(a.area_pilot);
    }
    CHECK(m.summary.reached_precision + m.summary.out_of_steps == 3);
    p.threads = 2;
    check_same(m, buffon::measure_area(world, p));
  }
  SECTION("online: the pilot area from visit 1's self-crossings; a short budget is counted") {
    p.rule = buffon::PrecisionRule::online;
    p.total_steps = 20000; // too short for P = 0.05 on this circle
    p.precision_millionths = 50000;
    const auto m = buffon::measure_area(world, p);
    CHECK(m.summary.out_of_steps > 0);
    for (const auto& a : m.trials) {
      REQUIRE(a.stopped);
      CHECK(*a.stopped != buffon::TrialStop::budget);
      if (a.run.self_crossings > 0) {
        REQUIRE(a.area_pilot);
        CHECK(*a.area_pilot ==
              a.length1 * a.length1 /
                  (3.14159265358979323846 * static_cast<double>(a.run.self_crossings)));
      }
    }
  }
  SECTION("fixed: the interval without a budget's fields") {
    p.rule = buffon::PrecisionRule::fixed;
    p.steps = 20000;
    const auto m = buffon::measure_area(world, p);
    for (const auto& a : m.trials) {
      REQUIRE(a.precision);
      CHECK_FALSE(a.stopped);
    }
    CHECK(m.summary.length1_median == 0);
  }
}
