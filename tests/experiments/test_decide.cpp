// `antkit reproduce --decide` as a library (issue 44): paper 000's trials added batch by batch
// give the figure a single run gives; the looks settle claims and say so; the bytes depend on the
// seed and the budget in trials alone (not the threads), and a time budget's report is reproduced
// by the budget in trials it states. The two whole runs are [slow] (20 s each here): the sanitizer
// pass runs the decide path through tests/cli's `reproduce --decide` instead.
#include "scratch_dir.hpp"
#include "test_paths.hpp"

#include <algorithm>
#include <antkit/experiments/buffon_figures.hpp>
#include <antkit/experiments/papers.hpp>
#include <antkit/experiments/reproduce.hpp>
#include <antkit/kernel/input_error.hpp>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <unistd.h>

namespace ex = antkit::experiments;
namespace fs = std::filesystem;

namespace {

std::map<std::string, std::string> tree(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) {
      std::ifstream in(e.path(), std::ios::binary);
      std::ostringstream s;
      s << in.rdbuf();
      files[fs::relative(e.path(), dir).string()] = s.str();
    }
  return files;
}

ex::ReproduceOptions decide_options(const fs::path& out) {
  ex::ReproduceOptions o;
  o.only = {"los"};
  o.out = out;
  o.decide = true;
  o.budget_trials = 80; // --quick: looks at 20, 40, 80 (paper 001: 10, 20, 40 repetitions)
  return o;
}

} // namespace

TEST_CASE("decide: paper 000's trials added in batches give the single run's figure") {
  antkit::algorithms::Runner runner;
  runner.threads = 2;
  ex::BuffonFigureParams p;
  p.figure = 6;
  p.trials = 5;
  p.steps = 2000;
  const auto whole = ex::run_buffon_figure(p, runner);
  ex::BuffonFigureTrials batches(p);
  batches.extend(2, runner);
  batches.extend(2, runner); // no new trials
  CHECK(batches.trials() == 2);
  batches.extend(5, runner);
  const auto added = batches.finish();
  CHECK(added.hash == whole.hash);
  CHECK(added.params.trials == 5);
  REQUIRE(added.rows.size() == whole.rows.size());
  for (std::size_t k = 0; k < whole.rows.size(); ++k) {
    CHECK(added.rows[k].nbc_trials == whole.rows[k].nbc_trials);
    CHECK(added.rows[k].nbc_median == whole.rows[k].nbc_median);
    CHECK(added.rows[k].closed_form_median == whole.rows[k].closed_form_median);
  }
  // The hash is every trial's: a different count gives another.
  p.trials = 4;
  CHECK(ex::run_buffon_figure(p, runner).hash != whole.hash);

  p.figure = 14;
  p.trials = 3;
  const auto fig14 = ex::run_figure14(p, runner);
  ex::Figure14Trials f14(p);
  f14.extend(1, runner);
  f14.extend(3, runner);
  const auto fig14_added = f14.finish();
  CHECK(fig14_added.hash == fig14.hash);
  REQUIRE(fig14_added.rows.size() == fig14.rows.size());
  for (std::size_t k = 0; k < fig14.rows.size(); ++k)
    CHECK(fig14_added.rows[k].buffon_median == fig14.rows[k].buffon_median);
}

TEST_CASE("decide: a look extends only the arenas asked for, each as its own run would") {
  antkit::algorithms::Runner runner;
  runner.threads = 2;
  ex::BuffonFigureParams p;
  p.figure = 8;
  p.steps = 1500;
  p.trials = 2;
  const auto two = ex::run_buffon_figure(p, runner);
  p.trials = 4;
  const auto four = ex::run_buffon_figure(p, runner);
  ex::BuffonFigureTrials t(p);
  REQUIRE(t.arenas() == four.rows.size());
  REQUIRE(t.arenas() >= 3);
  t.extend(2, runner);
  std::vector<bool> asked(t.arenas(), false);
  asked[0] = asked[2] = true;
  t.extend(4, asked, runner);
  CHECK(t.trials() == 4);
  const auto mixed = t.finish();
  CHECK(mixed.params.trials == 4);
  REQUIRE(mixed.rows.size() == four.rows.size());
  for (std::size_t k = 0; k < mixed.rows.size(); ++k) {
    INFO("arena " << k);
    const auto& want = asked[k] ? four.rows[k] : two.rows[k];
    CHECK(mixed.rows[k].trials == (asked[k] ? 4 : 2));
    CHECK(mixed.rows[k].nbc_trials == want.nbc_trials);
    CHECK(mixed.rows[k].nbc_median == want.nbc_median);
  }
  // The CSV says each row's count; a figure at one count says that count on every row.
  const std::string csv = ex::buffon_figure_csv(mixed);
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line); // header
  for (std::size_t k = 0; std::getline(lines, line); ++k) {
    INFO(line);
    // series,x,"spec",width,area,trials,...: the third field after the quoted spec.
    std::istringstream after(line.substr(line.rfind('"') + 2));
    std::string width, area, trials;
    std::getline(after, width, ',');
    std::getline(after, area, ',');
    std::getline(after, trials, ',');
    CHECK(trials == std::to_string(asked[k] ? 4 : 2));
  }
  // Then every arena to 4: the one run's figure, hash included.
  t.extend(4, runner);
  const auto all = t.finish();
  CHECK(all.hash == four.hash);
  CHECK(ex::buffon_figure_csv(all) == ex::buffon_figure_csv(four));
  // One flag per arena.
  CHECK_THROWS_AS(t.extend(6, std::vector<bool>(t.arenas() + 1, true), runner),
                  std::invalid_argument);
}

TEST_CASE("decide: the looks settle claims, say when, and the bytes do not depend on the threads",
          "[slow]") {
  const antkit::test::ScratchDir scratch("decide-threads");
  const fs::path& base = scratch.path();
  std::map<std::string, std::string> first;
  for (const unsigned threads : {1u, 3u}) {
    const fs::path dir = base / std::to_string(threads);
    fs::create_directories(dir);
    antkit::algorithms::Runner runner;
    runner.threads = threads;
    const auto report = ex::reproduce(decide_options(dir), runner);
    CHECK(report.looks >= 1);
    CHECK(report.looks <= 3); // the budget's 80 trials: looks at 20, 40, 80 at most
    CHECK(report.budget_trials == (20 << (report.looks - 1)));
    const auto files = tree(dir);
    if (first.empty()) {
      first = files;
      continue;
    }
    for (const auto& [name, bytes] : files) {
      INFO(name);
      CHECK(bytes == first[name]);
    }
  }
  const auto j = nlohmann::json::parse(first.at("claims.json"));
  const int looks = j["decide"]["looks"];
  REQUIRE(j["decide"]["factors"].size() == static_cast<std::size_t>(looks));
  double alpha = 0;
  for (std::size_t k = 0; k < static_cast<std::size_t>(looks); ++k) {
    CHECK(j["decide"]["factors"][k] == (1 << k));
    alpha += j["decide"]["alpha_per_look"][k].get<double>();
  }
  CHECK(alpha <= 0.05); // the spending never passes 5 %
  CHECK(j["command"].get<std::string>().find(
            "--decide --budget " + std::to_string(20 << (looks - 1))) != std::string::npos);
  // Every claim says at which look it settled (or the last), with that look's trials; a claim
  // settled early keeps the trials of its look.
  std::size_t settled_early = 0, open = 0;
  for (const auto& c : j["claims"]) {
    const int look = c["look"];
    CHECK(look >= 0);
    CHECK(look < looks);
    const std::string reps = std::to_string(10 << look) + " repetitions";
    CHECK(c["trials"].get<std::string>().rfind(reps, 0) == 0);
    const bool undecided = c["verdict"] == "inconclusive at this trial count";
    CHECK(c["needed"].get<std::string>().empty() == !undecided);
    if (undecided)
      ++open;
    else
      settled_early += look < looks - 1;
  }
  CHECK(settled_early > 0);
  const auto& readme = first.at("README.md");
  CHECK(readme.find("### How `--decide` decided") != std::string::npos);
  CHECK(readme.find("#### The error, by simulation") != std::string::npos);
  CHECK(first.count("claims_forest.png") == 1);
  CHECK(first.count("claims_forest.svg") == 1);
  INFO(open << " claims still open");
}

TEST_CASE("decide: a time budget's report is the report of the budget in trials it states",
          "[slow]") {
  const antkit::test::ScratchDir scratch("decide-time");
  const fs::path& base = scratch.path();
  antkit::algorithms::Runner runner;
  runner.threads = 2;
  auto o = decide_options(base / "time");
  o.budget_trials = 0;
  o.budget_seconds = 2;
  fs::create_directories(o.out);
  const auto timed = ex::reproduce(o, runner);
  CHECK(timed.budget_trials >= 20);
  CHECK(timed.budget_trials % 20 == 0);
  auto again = decide_options(base / "trials");
  again.budget_trials = timed.budget_trials;
  again.unit_budget = timed.unit_budget; // the units the time stopped before the last look
  CHECK(timed.rerun.rfind("--budget " + std::to_string(timed.budget_trials), 0) == 0);
  fs::create_directories(again.out);
  const auto counted = ex::reproduce(again, runner);
  CHECK(counted.looks == timed.looks);
  CHECK(tree(base / "time") == tree(base / "trials"));
}

TEST_CASE("decide: a unit's budget stops it at its count, and the report names it for the rerun",
          "[slow]") {
  const antkit::test::ScratchDir scratch("decide-unit");
  const fs::path& base = scratch.path();
  antkit::algorithms::Runner runner;
  runner.threads = 2;
  auto o = decide_options(base / "capped");
  o.only = {"los", "uniform"};
  o.unit_budget = {{"uniform", 20}}; // the first look's count: paper 004 runs once
  fs::create_directories(o.out);
  const auto capped = ex::reproduce(o, runner);
  const auto j = nlohmann::json::parse(tree(o.out).at("claims.json"));
  const std::string command = j["command"];
  std::set<std::string> ids004;
  for (const auto& spec : ex::claims_004()) ids004.insert(spec.id);
  REQUIRE(!ids004.empty());
  // At seed 1 paper 001 looks again and paper 004 leaves claims open at its first look: the cap
  // is then what stops it (were either to change, this test would no longer test the cap).
  REQUIRE(capped.looks > 1);
  std::size_t uniform_open = 0;
  for (const auto& c : capped.claims) {
    if (ids004.count(c.id) == 0) continue;
    INFO(c.id);
    CHECK(c.look == 0); // never past the unit's budget, whatever it asked for
    if (c.verdict == ex::Verdict::Inconclusive) {
      ++uniform_open;
      CHECK(c.needed.find("the budget stopped uniform at the look of 20") != std::string::npos);
    }
  }
  REQUIRE(uniform_open > 0);
  // The rerun's options name the cap.
  CHECK(capped.unit_budget == std::map<std::string, std::int64_t>{{"uniform", 20}});
  CHECK(command.find("--unit-budget uniform=20") != std::string::npos);
  CHECK(capped.rerun ==
        "--budget " + std::to_string(capped.budget_trials) + " --unit-budget uniform=20");
  CHECK(j["decide"]["unit_budget"]["uniform"] == 20);
  // Without the cap paper 004 may look again; the cap's units stay as the first look left them.
  auto free = decide_options(base / "free");
  free.only = o.only;
  fs::create_directories(free.out);
  const auto uncapped = ex::reproduce(free, runner);
  for (std::size_t i = 0; i < capped.claims.size(); ++i)
    if (ids004.count(capped.claims[i].id) > 0 && uncapped.claims[i].look == 0)
      CHECK(capped.claims[i].verdict == uncapped.claims[i].verdict);
}

TEST_CASE("decide: a unit's budget must name a unit the papers run, within the budget's range") {
  auto o = decide_options("unused");
  o.unit_budget = {{"buffon/figure14", 20}}; // paper 000 does not run under --only los
  CHECK_THROWS_WITH(ex::validate(o),
                    Catch::Contains("'buffon/figure14' is not a unit of the papers run (los)"));
  o.unit_budget = {{"los", 10}}; // below the first look's 20
  CHECK_THROWS_AS(ex::validate(o), antkit::kernel::InputError);
  o.unit_budget = {{"los", 100001}};
  CHECK_THROWS_AS(ex::validate(o), antkit::kernel::InputError);
  o.unit_budget = {{"los", 40}};
  o.decide = false;
  o.budget_trials = 0;
  CHECK_THROWS_WITH(ex::validate(o), Catch::Contains("for --decide"));
}

TEST_CASE("decide: budgets out of range are refused") {
  ex::ReproduceOptions o;
  o.budget_trials = 80;
  CHECK_THROWS_AS(ex::validate(o), antkit::kernel::InputError); // without --decide
  o.decide = true;
  CHECK_NOTHROW(ex::validate(o));
  o.budget_trials = 10; // below the first look's 20
  CHECK_THROWS_AS(ex::validate(o), antkit::kernel::InputError);
  o.budget_trials = 100001;
  CHECK_THROWS_AS(ex::validate(o), antkit::kernel::InputError);
  o.budget_trials = 80;
  o.budget_seconds = 60;
  CHECK_THROWS_AS(ex::validate(o), antkit::kernel::InputError); // both
}

TEST_CASE("the papers are registered entries, and the README counts their claims") {
  const auto& entries = ex::papers();
  REQUIRE_FALSE(entries.empty());
  std::size_t claims = 0;
  std::string last_id;
  for (const auto& e : entries) {
    CHECK(e.id > last_id); // in id order
    last_id = e.id;
    claims += e.claims().size();
    for (const auto& spec : e.claims()) CHECK(std::string(spec.id).rfind(e.id + "-", 0) == 0);
    // Every claim reads a unit its paper runs.
    ex::ReproduceOptions o;
    const auto run = e.make(o);
    const auto units = run->units();
    for (const auto& spec : e.claims()) {
      INFO(spec.id);
      CHECK(std::find(units.begin(), units.end(), run->unit_of(spec)) != units.end());
    }
  }
  std::ifstream in(antkit::test::source_path("README.md"));
  std::ostringstream raw;
  raw << in.rdbuf();
  std::string text; // the README with its line breaks as spaces
  for (const char c : raw.str()) text += c == '\n' ? ' ' : c;
  const std::string said = "that a run can decide (" + std::to_string(claims) + " today";
  INFO("README.md should say: " << said);
  CHECK(text.find(said) != std::string::npos);
}
