#pragma once
// The step-turn wanderer's core (issue 27): paper 004's Random Wanderer for one robot that only
// steps and turns, as a fixed-size state (a keyed stream and a step count) with a noexcept step.
// Freestanding: the Cortex-M image (mcu/src/wanderer_run.cpp) and the C API (antkit/c/antkit.h)
// run it, and the host's RandomWanderer (every robot of a team) and StepTurnWanderer
// (controllers.hpp) take the same decision through wander_decide, so that the chip's commands are
// the host's by construction.
#include <antkit/kernel/random.hpp>
#include <cstdint>

namespace antkit::uniform {

enum class Action : std::uint8_t {
  Wait = 0,      // stays put this tick
  TurnLeft = 1,  // bearing + 1 (45 degrees counter-clockwise)
  TurnRight = 2, // bearing - 1
  Forward = 3,   // one cell along the bearing
  Step = 4,      // face `bearing`, then one cell along it (A*)
  Stop = 5,      // has no acceptable move (ceased, or nothing left to do)
};

struct Command {
  Action action = Action::Wait;
  std::uint8_t bearing = 0; // for Step
  friend constexpr bool operator==(Command, Command) = default;
};

// The keys of the wanderer's stream: (seed, kWandererExperiment, trial, robot, kWandererPurpose),
// scenario.hpp's kStreamExperiment and StreamPurpose::RandomWanderer (controllers.cpp checks that
// they agree; this header stays free of scenario.hpp's containers).
inline constexpr std::uint64_t kWandererExperiment = 6;
inline constexpr std::uint64_t kWandererPurpose = 3;

// The Random Wanderer's decision: a draw of 0, 1 or 2 from the robot's stream; 0 turns left, 2
// turns right, 1 moves forward when front_free() says the cell ahead can be entered (asked only
// then) and waits otherwise.
template <class FrontFree>
constexpr Command wander_decide(kernel::Stream& stream, FrontFree&& front_free) noexcept {
  switch (stream.below(3)) {
  case 0:
    return {Action::TurnLeft};
  case 2:
    return {Action::TurnRight};
  default:
    return front_free() ? Command{Action::Forward} : Command{Action::Wait};
  }
}

// One robot's wanderer: its stream and the draws taken so far (with the last command, the whole
// state). sizeof is fixed (the stream's block and key, and a counter).
class StepTurnCore {
public:
  constexpr StepTurnCore(std::uint64_t seed, std::uint64_t trial, std::uint64_t robot) noexcept
      : stream_(seed, kWandererExperiment, trial, robot, kWandererPurpose) {}
  constexpr Command step(bool front_free) noexcept {
    ++steps_;
    return wander_decide(stream_, [front_free] { return front_free; });
  }
  [[nodiscard]] constexpr std::uint64_t steps() const noexcept { return steps_; }

private:
  kernel::Stream stream_;
  std::uint64_t steps_ = 0;
};

} // namespace antkit::uniform
