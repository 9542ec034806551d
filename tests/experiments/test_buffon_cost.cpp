// The cost of precision's sweep and files (experiments/buffon_cost.hpp): its arenas, its tables
// and figure on a quick run, the same bytes for any number of threads, and its refusals.
#include "scratch_dir.hpp"

#include <algorithm>
#include <antkit/experiments/buffon_cost.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

namespace ex = antkit::experiments;

namespace {

std::size_t lines(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

std::string refusal(const ex::BuffonCostParams& p) {
  try {
    (void)ex::run_buffon_cost(p);
  } catch (const antkit::kernel::InputError& e) {
    return e.what();
  }
  return "(no error)";
}

} // namespace

TEST_CASE("buffon_cost_arenas: circles and squares of the same areas, then Figure 3's shapes",
          "[experiments]") {
  const auto quick = ex::buffon_cost_arenas(true);
  REQUIRE(quick.size() == 6);
  CHECK(quick[0].spec == "circle:d=20");
  CHECK(quick[0].family == "circle");
  CHECK(quick[1].spec == "square:area=314");
  CHECK(quick[1].family == "square");
  CHECK(quick[3].spec == "square:area=1257");
  CHECK(quick[5].spec == "square:area=5027");
  const auto full = ex::buffon_cost_arenas(false);
  REQUIRE(full.size() == 16);
  CHECK(full[9].spec == "square:area=31416");
  CHECK(full[10].spec == "ellipse:area=7854,e=0.968");
  CHECK(full[15].spec == "obstacles");
  for (std::size_t i = 10; i < full.size(); ++i) CHECK(full[i].family == "figure 3 shape");
}

TEST_CASE("run_buffon_cost --quick: every arena, P and method, its fits, its figure and files",
          "[experiments]") {
  ex::BuffonCostParams p;
  p.quick = true;
  p.trials = 1;
  antkit::algorithms::Runner runner;
  runner.threads = 2;
  std::size_t calls = 0;
  std::uint64_t last_total = 0;
  runner.progress = [&](std::string_view, std::uint64_t done, std::uint64_t total) {
    ++calls;
    CHECK(done == calls);
    last_total = total;
  };
  const auto cost = ex::run_buffon_cost(p, runner);
  CHECK(calls == 36); // 6 arenas, P = 0.2 and 0.1, 3 methods, 1 trial: 36 units
  CHECK(last_total == 36);
  CHECK(cost.run.trials == 1);
  CHECK(cost.run.precisions == std::vector<std::uint32_t>{200000, 100000});
  const std::string csv = ex::buffon_cost_csv(cost);
  CHECK(csv.rfind("arena,family,area,precision,method,trials,reached,median,q1,q3\n", 0) == 0);
  CHECK(lines(csv) == 1 + 36);
  CHECK(csv.find("\n\"circle:d=20\",circle,314.1592") != std::string::npos);
  const std::string fits = ex::buffon_cost_fits_csv(cost);
  CHECK(fits.rfind("method,precision,exponent,coefficient,points\n", 0) == 0);
  CHECK(lines(fits) == 1 + cost.table.fits.size());
  const auto figure = ex::buffon_cost_plot(cost);
  REQUIRE(figure.panels.size() == 2);
  CHECK(figure.panels[0].title == "P = 0.2");
  CHECK(figure.panels[1].title == "P = 0.1");
  CHECK(figure.caption.rfind("1 trials per point", 0) == 0);

  // Threads do not change a byte (precision_cost reduces in trial order).
  p.trials = 2;
  const auto one = ex::run_buffon_cost(p);
  antkit::algorithms::Runner three_threads;
  three_threads.threads = 3;
  const auto three = ex::run_buffon_cost(p, three_threads);
  CHECK(ex::buffon_cost_csv(one) == ex::buffon_cost_csv(three));
  CHECK(ex::buffon_cost_fits_csv(one) == ex::buffon_cost_fits_csv(three));

  const antkit::test::ScratchDir scratch("test-buffon-cost");
  const auto& dir = scratch.path();
  const auto files = ex::write_buffon_cost(cost, dir);
  CHECK(files[0] == dir / "precision_cost.csv");
  CHECK(files[3] == dir / "precision_cost.png");
  std::ifstream in(files[0]);
  std::stringstream written;
  written << in.rdbuf();
  CHECK(written.str() == csv);
  for (const auto& f : files) CHECK(std::filesystem::file_size(f) > 0);
  ex::release_drawing_caches();
}

TEST_CASE("run_buffon_cost refuses trials and budgets out of range, in its own words",
          "[experiments]") {
  ex::BuffonCostParams p;
  p.quick = true;
  p.trials = 0;
  CHECK(refusal(p) == "trials: the number of trials must be in [1, 100000]");
  p.trials = 100001;
  CHECK(refusal(p) == "trials: the number of trials must be in [1, 100000]");
  p.trials = 1;
  p.budget = 1;
  CHECK(refusal(p) == "step budget: the budget per trial must be in [2, 100000000]");
  CHECK_THROWS_AS(ex::validate(p), antkit::kernel::InputError);
}
