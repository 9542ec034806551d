#pragma once
// One step of a Buffon visit (measurement.hpp, run_visit): sense, decide, move, measure, hash.
// Freestanding (issue 27): the host's run_visit and the Cortex-M image (mcu/src/buffon_run.cpp)
// call these same inline functions, so that the chip's trace hash is the host's by construction.
// The behaviour and the hash are template parameters: the C++ cores (ExplorationBehaviour,
// kernel::TraceHash: VisitParts) on the host, and on the chip also the C API's
// (antkit_buffon_behaviour_*, antkit_trace_hash_*: mcu/src/c_api_parts.hpp), which then run these
// same steps rather than a restatement of them.
#include <antkit/buffon/exploration.hpp>
#include <antkit/buffon/step_root.hpp>
#include <antkit/buffon/world.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/random.hpp>
#include <cstdint>

namespace antkit::buffon {

// The experiment number of this family's streams (issue 4).
inline constexpr std::uint64_t kExperiment = 4;

// Visit v (1, 2) of trial t draws its behaviour from Stream(seed, experiment, t, v, 0), its start
// heading from purpose 1 and its IR noise from purpose 2 (measurement.hpp).
struct VisitStreams {
  kernel::Stream behaviour, start, noise;
  VisitStreams(std::uint64_t seed, std::uint64_t experiment, std::uint64_t trial,
               int visit) noexcept
      : behaviour(seed, experiment, trial, static_cast<std::uint64_t>(visit), 0),
        start(seed, experiment, trial, static_cast<std::uint64_t>(visit), 1),
        noise(seed, experiment, trial, static_cast<std::uint64_t>(visit), 2) {}
};

namespace detail {
// The exact floor square root of a step's squared length n2 (step_root.hpp), guessed from the
// commanded forward distance f (the step's length is within a few raw units of it) as
// f - 2 + the number of k in {f - 1, f, f + 1} with k^2 <= n2, branch-free (data-dependent loop
// branches were mispredicted on a good share of the steps); step_root takes the guess only when it
// is the root, else runs the proved loop.
inline std::uint64_t step_length_raw(std::uint64_t n2, Fx forward) noexcept {
  const auto f = static_cast<std::uint64_t>(kernel::abs(forward).raw());
  const std::uint64_t guess = f < 2 || n2 == 0 ? 0 // a blocked step: 0 is its root
                                               : f - 2 + std::uint64_t{(f - 1) * (f - 1) <= n2} +
                                                     std::uint64_t{f * f <= n2} +
                                                     std::uint64_t{(f + 1) * (f + 1) <= n2};
  return step_root(n2, guess);
}

inline std::uint64_t hash_word(std::int32_t lo, std::int32_t hi) noexcept {
  return static_cast<std::uint64_t>(static_cast<std::uint32_t>(lo)) |
         (static_cast<std::uint64_t>(static_cast<std::uint32_t>(hi)) << 32);
}
} // namespace detail

// What a visit's steps are made of: a behaviour (Command step(const Observation&); r(), w_left(),
// w_right() as Fx) made for visit `visit` of trial `trial`, and a trace hash (add_u64) started
// from the seed. These are the C++ cores; the chip's C API parts have the same shape.
struct VisitParts {
  using Behaviour = ExplorationBehaviour;
  using Hash = kernel::TraceHash;
  static Behaviour behaviour(std::uint64_t seed, std::uint64_t trial, int visit) noexcept {
    return Behaviour(VisitStreams(seed, kExperiment, trial, visit).behaviour);
  }
  static Hash hash(std::uint64_t seed) noexcept { return Hash(seed); }
};

// One step: the readings at `pose` (with the body's noise from `noise`), the behaviour's command,
// the move (a blocked translation counts in `blocked`) and the step's exact length added to
// `length_raw`. Returns the readings the behaviour acted on.
template <class Behaviour>
inline Observation visit_step(const WorldCore& world, Behaviour& behaviour, Pose& pose,
                              kernel::Stream& noise, std::int64_t& length_raw,
                              std::uint64_t& blocked) {
  const Observation obs = world.sense(pose, &noise);
  const Command cmd = behaviour.step(obs);
  const FxPoint before = pose.position;
  if (!world.move(pose, cmd)) ++blocked;
  const std::int64_t dx = std::int64_t{pose.position.x.raw()} - before.x.raw();
  const std::int64_t dy = std::int64_t{pose.position.y.raw()} - before.y.raw();
  const Fx forward = world.body().speed * (cmd.left + cmd.right) * Fx::from_ratio(1, 2);
  length_raw += static_cast<std::int64_t>(
      detail::step_length_raw(static_cast<std::uint64_t>(dx * dx + dy * dy), forward));
  return obs;
}

// The step's share of the trace hash: (x, y), (heading, r), (w_l, w_r) as 64-bit words.
template <class Hash, class Behaviour>
inline void hash_visit_step(Hash& hash, const Pose& pose, const Behaviour& behaviour) {
  hash.add_u64(detail::hash_word(pose.position.x.raw(), pose.position.y.raw()));
  hash.add_u64(
      detail::hash_word(static_cast<std::int32_t>(pose.heading.raw()), behaviour.r().raw()));
  hash.add_u64(detail::hash_word(behaviour.w_left().raw(), behaviour.w_right().raw()));
}

struct VisitEnd {
  std::int64_t length_raw = 0;
  std::uint64_t blocked = 0;
};

// A visit's steps from `pose` (run_visit's loop, measurement.hpp): `steps` times visit_step, then
// on_step(position), then hash_visit_step; on_step(position) first at the start.
template <class OnStep, class Behaviour, class Hash>
VisitEnd run_visit_steps(const WorldCore& world, Behaviour& behaviour, kernel::Stream& noise,
                         Pose pose, std::int64_t steps, Hash& hash, OnStep&& on_step) {
  VisitEnd end;
  on_step(pose.position);
  for (std::int64_t s = 0; s < steps; ++s) {
    (void)visit_step(world, behaviour, pose, noise, end.length_raw, end.blocked);
    on_step(pose.position);
    hash_visit_step(hash, pose, behaviour);
  }
  return end;
}

} // namespace antkit::buffon
