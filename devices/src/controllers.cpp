// The controllers of a device run, from a log's point of view (controllers.hpp).
#include <algorithm>
#include <antkit/buffon/exploration.hpp>
#include <antkit/buffon/measurement.hpp>
#include <antkit/devices/controllers.hpp>
#include <antkit/kernel/angle.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/uniform/controllers.hpp>
#include <cstdlib>
#include <optional>

namespace antkit::devices {

namespace {

using kernel::Fx;
using kernel::InputError;

struct ParamDef {
  std::string_view name;
  std::int64_t fallback, lo, hi;
};

std::span<const ParamDef> definitions(const std::string& name) {
  static constexpr ParamDef buffon[] = {{"trial", 0, 0, INT64_MAX}, {"visit", 1, 1, 2}};
  static constexpr ParamDef rs[] = {{"trial", 0, 0, INT64_MAX}};
  static constexpr ParamDef wander[] = {{"trial", 0, 0, INT64_MAX}, {"robot", 0, 0, 1023}};
  if (name == "buffon") return buffon;
  if (name == "rs") return rs;
  if (name == "wander") return wander;
  return {};
}

void check_obs(std::span<const std::int64_t> obs, std::size_t n) {
  if (obs.size() != n)
    throw InputError("obs", "expected " + std::to_string(n) + " values, got " +
                                std::to_string(obs.size()));
}

// normalise_reading() by table (ReadingNormaliser), built for the robot observe() is given and
// rebuilt only when it is given another. A controller is stepped on one thread (its step() is not
// const), so observe()'s cache needs no lock.
class CachedNormaliser {
public:
  const ReadingNormaliser& operator()(const RobotDescription& robot) const {
    if (!table_ || &table_->robot() != &robot) table_.emplace(robot);
    return *table_;
  }

private:
  mutable std::optional<ReadingNormaliser> table_;
};

class BuffonController final : public LoggedController {
public:
  BuffonController(std::uint64_t seed, std::uint64_t trial, std::uint64_t visit)
      : behaviour_(kernel::Stream(seed, buffon::kExperiment, trial, visit, 0)) {}

  void observe(const RobotDescription& robot, const Proximity& readings,
               std::vector<std::int64_t>& obs) const override {
    const ReadingNormaliser& normalise = normaliser_(robot);
    obs.resize(6);
    for (std::size_t i = 0; i < 6; ++i) obs[i] = normalise(readings.raw[robot.front_six[i]]).raw();
  }
  void step(const RobotDescription& robot, std::span<const std::int64_t> obs,
            std::vector<std::int64_t>& cmd) override {
    check_obs(obs, 6);
    buffon::Observation o;
    for (std::size_t i = 0; i < 6; ++i) {
      if (obs[i] < 0 || obs[i] > Fx::one_raw)
        throw InputError("obs", "a reading must be in [0, 65536] (raw Q15.16 of [0, 1])");
      o.ir[i] = Fx::from_raw(static_cast<std::int32_t>(obs[i]));
    }
    const buffon::Command c = behaviour_.step(o);
    ++steps_;
    cmd.assign({c.left.raw(), c.right.raw(), to_wheel_command(robot, c.left),
                to_wheel_command(robot, c.right)});
  }
  [[nodiscard]] std::uint64_t state_hash() const override {
    kernel::TraceHash h;
    h.add_u64(steps_)
        .add_i32(behaviour_.r().raw())
        .add_i32(behaviour_.w_left().raw())
        .add_i32(behaviour_.w_right().raw())
        .add_i32(behaviour_.r_bar().raw());
    return h.finish();
  }

private:
  buffon::ExplorationBehaviour behaviour_;
  std::uint64_t steps_ = 0;
  CachedNormaliser normaliser_;
};

// Normalised reading at or above which a front sensor says the cell ahead is taken (1/4).
constexpr Fx kWanderObstacle = Fx::from_raw(Fx::one_raw / 4);
constexpr int kWanderFrontDegrees = 50;

class WanderController final : public LoggedController {
public:
  WanderController(std::uint64_t seed, std::uint64_t trial, std::uint64_t robot)
      : wanderer_(seed, trial, robot) {}

  void observe(const RobotDescription& robot, const Proximity& readings,
               std::vector<std::int64_t>& obs) const override {
    const ReadingNormaliser& normalise = normaliser_(robot);
    bool free = true;
    for (std::size_t i = 0; i < robot.proximity_count && i < readings.raw.size(); ++i) {
      if (robot.ground[i] || std::abs(robot.proximity_angle_deg[i]) > kWanderFrontDegrees) continue;
      if (normalise(readings.raw[i]) >= kWanderObstacle) free = false;
    }
    obs.assign({free ? 1 : 0});
  }
  void step(const RobotDescription&, std::span<const std::int64_t> obs,
            std::vector<std::int64_t>& cmd) override {
    check_obs(obs, 1);
    if (obs[0] != 0 && obs[0] != 1) throw InputError("obs", "front_free must be 0 or 1");
    last_ = wanderer_.step({obs[0] == 1});
    cmd.assign({static_cast<std::int64_t>(last_.action)});
  }
  [[nodiscard]] std::uint64_t state_hash() const override {
    kernel::TraceHash h;
    h.add_u64(wanderer_.steps()).add_u8(static_cast<std::uint8_t>(last_.action));
    return h.finish();
  }

private:
  uniform::StepTurnWanderer wanderer_;
  uniform::Command last_{};
  CachedNormaliser normaliser_;
};

} // namespace

std::string_view controller_names() noexcept {
  return "buffon, rs, wander";
}

ControllerSpec make_spec(const std::string& name, std::uint64_t seed, const Params& given,
                         const std::string& where) {
  const auto defs = definitions(name);
  if (defs.empty())
    throw InputError(where, "unknown controller '" + name + "': expected one of " +
                                std::string(controller_names()));
  ControllerSpec spec{name, {}, seed};
  for (const auto& [key, value] : given) {
    const auto known = std::find_if(defs.begin(), defs.end(),
                                    [&key = key](const ParamDef& d) { return d.name == key; });
    if (known == defs.end()) {
      std::string names;
      for (const auto& d : defs) names += (names.empty() ? "" : ", ") + std::string(d.name);
      throw InputError(where,
                       "controller " + name + " has no parameter '" + key + "': expected " + names);
    }
    if (std::count_if(given.begin(), given.end(),
                      [&key = key](const auto& p) { return p.first == key; }) > 1)
      throw InputError(where, "parameter '" + key + "' given twice");
    if (value < known->lo || value > known->hi)
      throw InputError(where, "parameter " + key + "=" + std::to_string(value) +
                                  " is out of range [" + std::to_string(known->lo) + ", " +
                                  std::to_string(known->hi) + "]");
  }
  for (const auto& d : defs) {
    const auto it =
        std::find_if(given.begin(), given.end(), [&d](const auto& p) { return p.first == d.name; });
    spec.params.emplace_back(std::string(d.name), it == given.end() ? d.fallback : it->second);
  }
  return spec;
}

std::unique_ptr<LoggedController> make_controller(const ControllerSpec& spec) {
  const auto canonical = make_spec(spec.name, spec.seed, spec.params, "controller");
  if (canonical.params != spec.params)
    throw InputError("controller",
                     "the parameters of " + spec.name + " must be given in full and in order");
  const auto p = [&](std::size_t i) { return static_cast<std::uint64_t>(spec.params[i].second); };
  if (spec.name == "buffon") return std::make_unique<BuffonController>(spec.seed, p(0), p(1));
  if (spec.name == "rs") return std::make_unique<BuffonController>(spec.seed, p(0), 3);
  return std::make_unique<WanderController>(spec.seed, p(0), p(1));
}

} // namespace antkit::devices
