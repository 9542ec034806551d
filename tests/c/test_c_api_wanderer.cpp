// The C API's step-turn wanderer and the Buffon behaviour's state words (issue 27): the C functions
// must take the C++ cores' decisions and report their state, step for step.
#include <antkit/buffon/exploration.hpp>
#include <antkit/c/antkit.h>
#include <antkit/kernel/random.hpp>
#include <antkit/uniform/step_turn.hpp>
#include <catch2/catch.hpp>
#include <cstdint>
#include <rapidcheck/catch.h>

using namespace antkit;

TEST_CASE("C API: the step-turn wanderer is StepTurnCore, step for step", "[c][property]") {
  rc::prop("random keys and cells ahead", [] {
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto trial = *rc::gen::inRange<std::uint64_t>(0, 100);
    const auto robot = *rc::gen::inRange<std::uint64_t>(0, 8);
    uniform::StepTurnCore cpp(seed, trial, robot);
    // The draws themselves, straight from the wanderer's keyed stream (step_turn.hpp's keys).
    kernel::Stream stream(seed, uniform::kWandererExperiment, trial, robot,
                          uniform::kWandererPurpose);
    antkit_step_turn_wanderer c;
    antkit_step_turn_wanderer_init(&c, seed, trial, robot);
    RC_ASSERT(antkit_step_turn_wanderer_steps(&c) == 0u);
    const auto steps = *rc::gen::inRange(1, 200);
    for (int i = 0; i < steps; ++i) {
      const bool front_free = *rc::gen::arbitrary<bool>();
      const uniform::Command want = cpp.step(front_free);
      const uniform::Command direct =
          uniform::wander_decide(stream, [front_free] { return front_free; });
      const int got = antkit_step_turn_wanderer_step(&c, front_free ? 1 : 0);
      RC_ASSERT(got == static_cast<int>(want.action));
      RC_ASSERT(want == direct);
      RC_ASSERT(got >= ANTKIT_WANDER_WAIT && got <= ANTKIT_WANDER_FORWARD);
      if (!front_free) RC_ASSERT(got != ANTKIT_WANDER_FORWARD);
      RC_ASSERT(antkit_step_turn_wanderer_steps(&c) == cpp.steps());
    }
  });
}

TEST_CASE("C API: a copied wanderer state goes on as the original", "[c]") {
  antkit_step_turn_wanderer a;
  antkit_step_turn_wanderer_init(&a, 1, 0, 0);
  for (int i = 0; i < 17; ++i) (void)antkit_step_turn_wanderer_step(&a, i % 3 != 0);
  antkit_step_turn_wanderer b = a;
  for (int i = 0; i < 100; ++i)
    REQUIRE(antkit_step_turn_wanderer_step(&a, i % 2) == antkit_step_turn_wanderer_step(&b, i % 2));
  CHECK(antkit_step_turn_wanderer_steps(&a) == 117u);
  CHECK(antkit_step_turn_wanderer_steps(&b) == 117u);
}

TEST_CASE("C API: the Buffon behaviour's state words are the C++ behaviour's, step for step",
          "[c][property]") {
  rc::prop("random readings", [] {
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto trial = *rc::gen::inRange<std::uint64_t>(0, 100);
    const auto visit = *rc::gen::inRange<std::uint64_t>(1, 4); // 3: Randomized Search
    buffon::ExplorationBehaviour cpp(kernel::Stream(seed, 4, trial, visit, 0));
    antkit_buffon_behaviour c;
    antkit_buffon_behaviour_init(&c, seed, 4, trial, visit);
    const auto check_state = [&] {
      std::int32_t r = -1, wl = -1, wr = -1;
      antkit_buffon_behaviour_state(&c, &r, &wl, &wr);
      RC_ASSERT(r == cpp.r().raw());
      RC_ASSERT(wl == cpp.w_left().raw());
      RC_ASSERT(wr == cpp.w_right().raw());
      // Any pointer may be null; the others are still written.
      std::int32_t only_wr = -1;
      antkit_buffon_behaviour_state(&c, nullptr, nullptr, &only_wr);
      RC_ASSERT(only_wr == cpp.w_right().raw());
    };
    check_state();
    const auto steps = *rc::gen::inRange(1, 60);
    for (int i = 0; i < steps; ++i) {
      buffon::Observation obs;
      antkit_ir_reading reading;
      for (std::size_t k = 0; k < 6; ++k) {
        const std::int32_t v = *rc::gen::weightedOneOf<std::int32_t>(
            {{3, rc::gen::just(0)}, {2, rc::gen::inRange(0, 65537)}});
        obs.ir[k] = kernel::Fx::from_raw(v);
        reading.ir[k] = v;
      }
      const buffon::Command want = cpp.step(obs);
      const antkit_wheel_command got = antkit_buffon_behaviour_step(&c, &reading);
      RC_ASSERT(got.left == want.left.raw());
      RC_ASSERT(got.right == want.right.raw());
      check_state();
    }
  });
}
