// The exploration behaviour of Section 4.2 (see exploration.hpp for the equations, the choices and
// the step itself, exploration_step, which is a template so that the Z3 proof runs the same
// source).
#include <antkit/buffon/exploration.hpp>

namespace antkit::buffon {

// flatten: exploration_step is inlined into both calls below, which the zero-reading fold needs.
[[gnu::flatten]] Command ExplorationBehaviour::step(const Observation& obs) {
  // Both random numbers are drawn every step, in this order, so that the stream's position does
  // not depend on which case applies (a replay that diverges in one case stays aligned).
  const Fx n = stream_.uniform(-detail::kNLimit, detail::kNLimit);
  const Fx n_bar = stream_.uniform(detail::kNBarLow, detail::kOne);
  // Far from the walls (most steps) every reading is 0. The same step is then called with a
  // constant zero array, so that the compiler folds the products with a reading to 0 and the sums
  // of them away (integer arithmetic: x * 0 rounds to exactly 0, x + 0 is x): the same operations
  // on the same values, without the dozen multiplications whose result is known to be 0.
  constexpr std::array<Fx, 6> kDark{};
  std::int32_t any = 0; // nonzero iff some reading is (one OR instead of six compares)
  for (const Fx v : obs.ir) any |= v.raw();
  const ExplorationStep<Fx> s = any == 0
                                    ? exploration_step<FxPolicy>(r_, w_l_, w_r_, kDark, n, n_bar)
                                    : exploration_step<FxPolicy>(r_, w_l_, w_r_, obs.ir, n, n_bar);
  r_bar_ = s.r_bar;
  r_ = s.r;
  w_l_ = s.w_l;
  w_r_ = s.w_r;
  return Command{s.m_l, s.m_r};
}

} // namespace antkit::buffon
