// --decide's error by simulation (experiments/sequential.hpp, issue 44): claims whose truth is set
// by construction, decided look after look as reproduce --decide decides a part. The figures are
// keyed (the same on every run), so these checks are deterministic.
#include <algorithm>
#include <antkit/experiments/sequential.hpp>
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>
#include <string>
#include <utility>
#include <vector>

namespace ex = antkit::experiments;

namespace {
ex::SequentialSimulation run(double margin, bool spend) {
  ex::SequentialSimulation s;
  s.margin = margin;
  s.spend = spend;
  s.replications = 400;
  return ex::simulate_sequential(s, 2);
}
} // namespace

TEST_CASE("sequential: spending alpha over the looks keeps false verdicts at 5 % on the "
          "threshold") {
  // The worst case: the truth on the threshold, where any verdict is false.
  const auto s = run(0, true);
  INFO(s.false_verdicts << " false of " << s.replications);
  CHECK(s.false_verdicts == s.decided);
  CHECK(s.false_rate_ci.lo <= 0.05); // not above 5 % at 95 % confidence
  CHECK(s.false_rate() < 0.07);
}

TEST_CASE("sequential: looking four times at 95 % without spending inflates the error") {
  // The teeth of the check above: the same simulation without spending is above 5 %.
  const auto s = run(0, false);
  INFO(s.false_verdicts << " false of " << s.replications);
  CHECK(s.false_rate_ci.lo > 0.05);
}

TEST_CASE("sequential: a clear truth is decided, and rightly") {
  for (const double margin : {0.5, -0.5}) {
    const auto s = run(margin, true);
    INFO("margin " << margin << ": " << s.decided << " decided, " << s.false_verdicts << " false");
    CHECK(s.decided >= 320); // 80 %
    CHECK(s.false_verdicts == 0);
    CHECK(s.mean_trials < 300); // most stop before the last look (20 + 40 + 80 + 160)
  }
}

TEST_CASE("sequential: the results do not depend on the threads") {
  ex::SequentialSimulation s;
  s.replications = 60;
  const auto one = ex::simulate_sequential(s, 1);
  const auto three = ex::simulate_sequential(s, 3);
  CHECK(one.decided == three.decided);
  CHECK(one.false_verdicts == three.false_verdicts);
  CHECK(one.mean_trials == three.mean_trials);
}

// --decide's time budget: which units run the next look (fit_next_look). What it keeps fits the
// time left, each kept unit's need fits it, a unit the look could not take was at least as costly
// as every unit kept, and the answer does not depend on the order the units come in.
TEST_CASE("decide's time budget keeps what fits, stopping the hopeless and then the costliest",
          "[property]") {
  rc::prop("fit", [](std::vector<std::pair<std::uint16_t, std::uint8_t>> raw, std::uint16_t l) {
    RC_PRE(raw.size() <= 12);
    std::vector<ex::UnitForecast> open;
    for (std::size_t i = 0; i < raw.size(); ++i)
      open.push_back({"u" + std::to_string(100 + i), raw[i].first / 8.0, 1 + raw[i].second / 16.0});
    const double left = l / 4.0 - 100; // may be negative: the budget spent
    const auto kept = ex::fit_next_look(open, left);
    RC_ASSERT(std::is_sorted(kept.begin(), kept.end()));
    double total = 0;
    for (const auto& name : kept) {
      const auto& u = *std::find_if(open.begin(), open.end(),
                                    [&](const ex::UnitForecast& f) { return f.unit == name; });
      total += u.next_seconds;
      RC_ASSERT(u.next_seconds * (u.need - 1) <= left);
    }
    RC_ASSERT(kept.empty() || total <= left);
    for (const auto& u : open) {
      if (std::find(kept.begin(), kept.end(), u.unit) != kept.end()) continue;
      if (u.next_seconds * (u.need - 1) > left) continue; // hopeless within the time left
      for (const auto& name : kept) // stopped for the look's time: no kept unit costs more
        RC_ASSERT(std::find_if(open.begin(), open.end(), [&](const ex::UnitForecast& f) {
                    return f.unit == name;
                  })->next_seconds <= u.next_seconds);
    }
    auto shuffled = open;
    std::reverse(shuffled.begin(), shuffled.end());
    RC_ASSERT(ex::fit_next_look(shuffled, left) == kept);
  });
}

TEST_CASE("decide's time budget: a worked example") {
  // 100 s left: c's need (10 s x 19) cannot fit; a (60 s) and b (50 s) together exceed the look,
  // so a, the costlier, stops; b and d (30 s) run.
  const std::vector<ex::UnitForecast> open{
      {"b", 50, 1.5}, {"a", 60, 1}, {"c", 10, 20}, {"d", 30, 2}};
  CHECK(ex::fit_next_look(open, 100) == std::vector<std::string>{"b", "d"});
  CHECK(ex::fit_next_look(open, 1000) == std::vector<std::string>{"a", "b", "c", "d"});
  CHECK(ex::fit_next_look(open, -1).empty());
}
