#pragma once
// The robot body under the controller contract, shared by record() (record_loop.cpp) and replay()
// (replay.cpp): both run exactly this code, the first over a RobotLink to the robot, the second
// over the log's exchanges, so that a replay re-derives every byte a recording sent (internal).
#include <antkit/devices/controllers.hpp>
#include <antkit/devices/link.hpp>
#include <antkit/devices/odometry.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/uniform/controllers.hpp>
#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace antkit::devices::detail {

// The longest run a robot without encoders reckons (2^55 ns, about 13 months): its sums of travel
// x time stay far inside 128 bits (travel per model step below 2^34, times 2^55, times the speed
// scale below 2^35). A recording stops with an error there; a replay refuses a later time.
inline constexpr std::int64_t kMaxRunNs = std::int64_t{1} << 55;

class Body {
public:
  // `period`: the shortest time between two sensor reads (0: as fast as the link allows; a replay
  // passes 0, it does not wait).
  // `codec`: the text robot's, which encodes its commands and decodes the replies `link` returns.
  Body(CommandLink& link, const Codec& codec, std::chrono::nanoseconds period = {});

  // Before the first step: the wheel counters to zero (robots with encoders), or, where the robot
  // cannot set them (the Webots relay acknowledges G and does nothing, PROTOCOLS.md), their value
  // now, read as the baseline the odometry counts from.
  void start(std::vector<Exchange>& io);
  // At connect (record_loop.hpp, "First, at connect"): the version request, its reply held to the
  // robot's identification rule; WrongRobot when it is another robot's, or when every try got only
  // lines that are not its reply (a robot that answers, but not this protocol's version request).
  // LinkError as transact() when the robot does not answer. Nothing for a robot without a rule.
  void identify(std::vector<Exchange>& io);
  Proximity read_sensors(std::vector<Exchange>& io);
  void set_wheels(std::int32_t left, std::int32_t right, std::vector<Exchange>& io);
  // Odometry after the step: the counters less the baseline, or, for a robot without encoders
  // (the Hemisson), the travel its wheel commands give by the motion model over the times they
  // were in force, in micrometres (reckon_until below).
  WheelTravel odometry(std::vector<Exchange>& io);
  [[nodiscard]] const RobotDescription& robot() const noexcept { return robot_; }

private:
  // A robot without encoders: the wheels turned at the speeds in force from the last send to this
  // one (link.last_send_ns(): the recording's clock, or the logged time in a replay).
  void reckon_until(std::int64_t t_ns);
  // A validated reply to read_proximity() or read_odometry(), decoded (or the link's values).
  Proximity proximity_of(std::string_view reply) const;
  WheelPair odometry_of(std::string_view reply) const;
  CommandLink& link_;
  const Codec& codec_;
  const RobotDescription& robot_;
  std::chrono::nanoseconds period_;
  std::chrono::steady_clock::time_point next_read_{};
  std::int32_t left_ = 0, right_ = 0;
  // The reckoning: sum over intervals of (one model step's travel2 at the interval's speeds) x
  // (the interval in ns), exact; divided only when read (so nothing is lost to rounding).
  std::int64_t reckoned_ns_ = -1; // the time reckoned up to (-1: no send yet)
  Travel2 weighted_;
  WheelTravel baseline_;
};

// One of the wanderer's moves (paper 004's step or 45-degree turn) as wheel commands: both wheels
// at half speed (a turn: opposite), until the right wheel has travelled target_um micrometres by
// the odometry (units of unit_nm nanometres: encoder pulses, or the reckoned micrometres), read
// once per control period, for at most 2 x periods reads (periods: the nominal count, from the
// motion model). Every robot that runs the wanderer moves by this plan.
struct WanderMove {
  std::int32_t left = 0, right = 0;
  std::int64_t target_um = 0;
  std::int64_t periods = 1;
  std::int64_t unit_nm = 1000;
  // Whether `travelled_units` of the right wheel complete the move.
  [[nodiscard]] bool done(std::int64_t travelled_units) const noexcept;
};
WanderMove wander_move_plan(const RobotDescription& robot, uniform::Action action);

// Carries a controller's command out (record_loop.hpp, step 3).
void act(Body& body, bool wander, std::span<const std::int64_t> cmd, std::vector<Exchange>& io);

// The replay of a serial robot's log (replay.hpp): the body above over the log's exchanges.
ReplayResult replay_serial(LogReader& reader, const std::string& path,
                           std::optional<std::int64_t> until, RobotKind kind);

} // namespace antkit::devices::detail
