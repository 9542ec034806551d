#pragma once
// The controllers a robot runs under antkit, as a log sees them: built from a name, integer
// parameters and a seed (the log header), fed integer observations, answering integer commands and
// a state hash (the log records). record() (record_loop.hpp) and replay() (replay.hpp) build them
// the same way, so a replay is the recorded run's controller fed the recorded observations.
//
//   buffon   paper 000's exploration behaviour (algorithms/buffon/exploration.hpp), one visit of a
//            Buffon measurement: params trial, visit (1 lays the trail, 2 counts crossings; the
//            visit picks the behaviour's keyed stream, as in the simulator: Stream(seed, 4, trial,
//            visit, 0)). Observation: the six front readings I_0..I_5 as raw Q15.16, normalised
//            from the robot's proximity readings (protocol.hpp, normalise_reading). Command: the
//            wheel speeds m_l, m_r as raw Q15.16, then the robot's wheel commands for them
//            (to_wheel_command), so a change of the speed scaling shows in a replay.
//   rs       the Randomized Search baseline of paper 000 section 8.1: the same behaviour on the
//            trial's visit-3 stream (as algorithms/buffon/checkpoints.hpp), walked for as long as
//            both Buffon visits together; the area estimate is the body's footprint along the
//            odometry trail (odometry.hpp).
//   wander   paper 004's Random Wanderer for a robot that only steps and turns
//            (uniform::StepTurnWanderer): params trial, robot. Observation: 1 when the cell ahead
//            is free (no proximity reading within +/-50 degrees of the heading at or above 1/4 of
//            full scale, a choice: about half the sensor range), else 0. Command: the action
//            (uniform::Action as an integer).
//
// The state hash after a step is the kernel trace hash (kernel/hash.hpp) of the controller's whole
// state: buffon/rs: the step count and r, w_l, w_r, r_bar (raw Q15.16); wander: the step count and
// the last action.
#include <antkit/devices/protocol.hpp>
#include <antkit/devices/robot.hpp>
#include <antkit/devices/run_hash.hpp>
#include <antkit/kernel/hash.hpp>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace antkit::devices {

using Params = std::vector<std::pair<std::string, std::int64_t>>;

struct ControllerSpec {
  std::string name;
  Params params; // canonical: every parameter of the controller, in its order
  std::uint64_t seed = 1;
};

// The canonical spec of controller `name` with `given` parameters (any order, each at most once;
// the others take their defaults). Throws kernel::InputError(where, ...) for an unknown controller
// or parameter, or a value out of range (visit in 1..2, trial and robot >= 0).
ControllerSpec make_spec(const std::string& name, std::uint64_t seed, const Params& given,
                         const std::string& where);

// The controllers' names, for messages and --help.
std::string_view controller_names() noexcept; // "buffon, rs, wander"

class LoggedController {
public:
  virtual ~LoggedController() = default;
  // The observation this controller takes from the robot's proximity readings.
  virtual void observe(const RobotDescription& robot, const Proximity& readings,
                       std::vector<std::int64_t>& obs) const = 0;
  // One step. `obs` is as observe() writes it (a replay passes the recorded one; a wrong length is
  // kernel::InputError("obs")); `cmd` is overwritten.
  virtual void step(const RobotDescription& robot, std::span<const std::int64_t> obs,
                    std::vector<std::int64_t>& cmd) = 0;
  [[nodiscard]] virtual std::uint64_t state_hash() const = 0;
};

// Throws kernel::InputError("controller", ...) when the spec is not canonical (make_spec's output).
std::unique_ptr<LoggedController> make_controller(const ControllerSpec& spec);

} // namespace antkit::devices
