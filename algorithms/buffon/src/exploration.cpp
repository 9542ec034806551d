// The exploration behaviour of Section 4.2 (see exploration.hpp for the equations, the choices and
// the step itself, exploration_step, which is a template so that the Z3 proof runs the same
// source).
#include <antkit/buffon/exploration.hpp>

namespace antkit::buffon {

Command ExplorationBehaviour::step(const Observation& obs) {
  // Both random numbers are drawn every step, in this order, so that the stream's position does
  // not depend on which case applies (a replay that diverges in one case stays aligned).
  const Fx n = stream_.uniform(-detail::kNLimit, detail::kNLimit);
  const Fx n_bar = stream_.uniform(detail::kNBarLow, detail::kOne);
  const ExplorationStep<Fx> s = exploration_step<FxPolicy>(r_, w_l_, w_r_, obs.ir, n, n_bar);
  r_bar_ = s.r_bar;
  r_ = s.r;
  w_l_ = s.w_l;
  w_r_ = s.w_r;
  return Command{s.m_l, s.m_r};
}

} // namespace antkit::buffon
