// --decide's error by simulation (experiments/sequential.hpp, issue 44): claims whose truth is set
// by construction, decided look after look as reproduce --decide decides a part. The figures are
// keyed (the same on every run), so these checks are deterministic.
#include <antkit/experiments/sequential.hpp>
#include <catch2/catch.hpp>

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
