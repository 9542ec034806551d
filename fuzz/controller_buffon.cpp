// Fuzz target: paper 000's exploration behaviour (buffon::ExplorationBehaviour) and the three
// controllers a robot runs under antkit (devices::make_controller: buffon visit 1 and 2, rs,
// wander), fed a sequence of observations read from the fuzzer's bytes, including ones no
// simulator produces: every sensor at full scale (walls all round), every sensor at zero, readings
// at the limits of the robot's range and far outside it (a decoder never passes those, but a
// reading is clamped, not trusted), alternating extremes, and raw observation values of a
// hand-edited log (any int64: the controller must reject them with kernel::InputError or accept
// them, never misbehave).
//
// Every step checks the command is valid for the body: m_l, m_r in [-1, 1] and the behaviour's
// state in its documented ranges (r in [-1, 1], w in [0, 1]); the robot's wheel commands inside the
// robot's D range; the wanderer's action one of Wait / TurnLeft / TurnRight / Forward, and Forward
// only when the cell ahead was reported free. A twin controller built alike and fed the same
// observations must answer the same commands and state hash (the contract's determinism).
#include "fuzz_bytes.hpp"

#include <antkit/buffon/exploration.hpp>
#include <antkit/devices/controllers.hpp>
#include <antkit/devices/protocol.hpp>
#include <antkit/devices/robot.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/kernel/random.hpp>
#include <antkit/uniform/controllers.hpp>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace {

using namespace antkit;
using devices::RobotKind;
using kernel::Fx;

constexpr std::size_t kMaxSteps = 4096;

// One set of raw proximity readings for `robot`, the way the step byte says.
devices::Proximity readings(fuzzing::Bytes& in, const devices::RobotDescription& robot) {
  devices::Proximity p;
  const unsigned mode = in.below(6);
  for (std::size_t i = 0; i < p.raw.size(); ++i) {
    switch (mode) {
    case 0:
      p.raw[i] = robot.proximity_max;
      break; // walls all round
    case 1:
      p.raw[i] = robot.proximity_min;
      break; // nothing anywhere
    case 2:
      p.raw[i] = (i % 2 == 0) ? robot.proximity_max : robot.proximity_min;
      break;
    case 3:
      p.raw[i] = static_cast<std::int32_t>(in.u32());
      break; // outside the range too
    default: // inside the range, biased to its ends
      p.raw[i] =
          robot.proximity_min +
          static_cast<std::int32_t>(
              in.u16() % static_cast<std::uint32_t>(robot.proximity_max - robot.proximity_min + 1));
      break;
    }
  }
  return p;
}

void check_behaviour(fuzzing::Bytes& in, std::uint64_t seed) {
  buffon::ExplorationBehaviour a(kernel::Stream(seed, 4, 0, 1, 0));
  buffon::ExplorationBehaviour b(kernel::Stream(seed, 4, 0, 1, 0));
  const Fx one = Fx::one(), zero{};
  for (std::size_t step = 0; step < kMaxSteps && !in.empty(); ++step) {
    buffon::Observation o;
    const unsigned mode = in.below(4);
    for (auto& v : o.ir) {
      switch (mode) {
      case 0:
        v = one;
        break;
      case 1:
        v = zero;
        break;
      case 2:
        v = in.u8() & 1 ? one : zero;
        break;
      default:
        v = Fx::from_raw(static_cast<std::int32_t>(in.u32() % (Fx::one_raw + 1)));
        break;
      }
    }
    const buffon::Command c = a.step(o);
    const buffon::Command d = b.step(o);
    ANTKIT_FUZZ_REQUIRE(c.left == d.left && c.right == d.right);
    ANTKIT_FUZZ_REQUIRE(-one <= c.left && c.left <= one && -one <= c.right && c.right <= one);
    ANTKIT_FUZZ_REQUIRE(-one <= a.r() && a.r() <= one && -one <= a.r_bar() && a.r_bar() <= one);
    ANTKIT_FUZZ_REQUIRE(zero <= a.w_left() && a.w_left() <= one);
    ANTKIT_FUZZ_REQUIRE(zero <= a.w_right() && a.w_right() <= one);
  }
}

void check_logged(fuzzing::Bytes& in, std::uint64_t seed) {
  static const char* const kNames[] = {"buffon", "buffon", "rs", "wander"};
  const unsigned which = in.below(4);
  const auto& robot = devices::describe(
      devices::serial_robots()[in.below(static_cast<unsigned>(devices::serial_robots().size()))]);
  devices::Params params;
  if (which == 1) params.push_back({"visit", 2});
  if (which == 3) params.push_back({"robot", in.below(4)});
  const auto spec = devices::make_spec(kNames[which], seed, params, "fuzz");
  auto a = devices::make_controller(spec);
  auto b = devices::make_controller(spec);
  std::vector<std::int64_t> obs, cmd_a, cmd_b;
  for (std::size_t step = 0; step < kMaxSteps && !in.empty(); ++step) {
    if (in.below(8) == 0) {
      // A hand-edited log: any values, any count.
      obs.assign(in.below(8), 0);
      for (auto& v : obs) {
        const unsigned kind = in.below(4);
        v = kind == 0   ? static_cast<std::int64_t>(in.u32()) << 32 | in.u32()
            : kind == 1 ? Fx::one_raw + static_cast<std::int64_t>(in.below(3)) - 1
                        : static_cast<std::int64_t>(in.u32() % (Fx::one_raw + 1));
      }
    } else {
      a->observe(robot, readings(in, robot), obs);
    }
    bool threw_a = false, threw_b = false;
    try {
      a->step(robot, obs, cmd_a);
    } catch (const kernel::InputError&) {
      threw_a = true;
    }
    try {
      b->step(robot, obs, cmd_b);
    } catch (const kernel::InputError&) {
      threw_b = true;
    }
    ANTKIT_FUZZ_REQUIRE(threw_a == threw_b);
    if (threw_a) continue;
    ANTKIT_FUZZ_REQUIRE(cmd_a == cmd_b && a->state_hash() == b->state_hash());
    if (which == 3) {
      ANTKIT_FUZZ_REQUIRE(cmd_a.size() == 1);
      const auto action = static_cast<uniform::Action>(cmd_a[0]);
      ANTKIT_FUZZ_REQUIRE(action == uniform::Action::Wait || action == uniform::Action::TurnLeft ||
                          action == uniform::Action::TurnRight ||
                          action == uniform::Action::Forward);
      ANTKIT_FUZZ_REQUIRE(action != uniform::Action::Forward || obs[0] == 1);
    } else {
      ANTKIT_FUZZ_REQUIRE(cmd_a.size() == 4);
      for (std::size_t k = 0; k < 2; ++k)
        ANTKIT_FUZZ_REQUIRE(-Fx::one_raw <= cmd_a[k] && cmd_a[k] <= Fx::one_raw);
      for (std::size_t k = 2; k < 4; ++k)
        ANTKIT_FUZZ_REQUIRE(robot.speed_min <= cmd_a[k] && cmd_a[k] <= robot.speed_max);
    }
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzzing::Bytes in(data, size);
  const std::uint64_t seed = in.u32();
  if (in.u8() & 1)
    check_behaviour(in, seed);
  else
    check_logged(in, seed);
  return 0;
}
