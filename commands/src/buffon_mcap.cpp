// A Buffon's-needle run as MCAP for Foxglove (buffon_mcap.hpp).
#include "foxglove_json.hpp"

#include <antkit/buffon/crossing_counter.hpp>
#include <antkit/commands/buffon_mcap.hpp>
#include <antkit/io/atomic_file.hpp>
#include <antkit/io/mcap.hpp>
#include <antkit/kernel/input_error.hpp>
#include <sstream>

namespace antkit::commands {

namespace {

using foxglove::log_json, foxglove::pose_json, foxglove::stamp_of;

void check_positions(std::int64_t positions) {
  if (positions > kStcMcapMaxSubcells)
    throw kernel::InputError(
        "--mcap", "two visits of at most " + std::to_string(kStcMcapMaxSubcells) +
                      " positions together (a message each), not " + std::to_string(positions));
}

std::string number(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

} // namespace

void check_buffon_mcap(const buffon::AreaMeasurementParams& params) {
  if (params.precision_millionths != 0 && params.rule == buffon::PrecisionRule::markers)
    throw kernel::InputError("--mcap", "draws two visits one after the other; --rule markers (the "
                                       "default with --precision) lays both markers in one walk: "
                                       "give --rule fixed or online");
  if (params.precision_millionths != 0 && params.rule == buffon::PrecisionRule::online) return;
  const std::int64_t visit2 = params.precision_millionths != 0 && params.visit2_steps != 0
                                  ? params.visit2_steps
                                  : params.steps;
  check_positions(params.steps + 1 + visit2 + 1);
}

McapWritten write_buffon_mcap(const buffon::World& world, const buffon::AreaMeasurement& m,
                              const buffon::AreaMeasurementParams& params, const std::string& arena,
                              double area, const std::filesystem::path& out) {
  check_buffon_mcap(params);
  if (m.trials.empty() || m.trials[0].run.trail1.empty() || m.trials[0].run.trail2.empty())
    throw std::logic_error("write_buffon_mcap: trial 0's trails were not kept");
  const buffon::AreaTrial& trial = m.trials[0];
  const std::array<const std::vector<kernel::FxPoint>*, 2> trails{&trial.run.trail1,
                                                                  &trial.run.trail2};
  check_positions(static_cast<std::int64_t>(trails[0]->size() + trails[1]->size()));
  const auto unit = [](kernel::Fx v) { return static_cast<double>(v.raw()) / 65536.0; };
  std::array<std::vector<foxglove::Point>, 2> at;
  for (std::size_t v = 0; v < 2; ++v)
    for (const auto& p : *trails[v]) at[v].push_back({unit(p.x), unit(p.y)});
  const std::array<std::vector<double>, 2> yaw{foxglove::headings(at[0]),
                                               foxglove::headings(at[1])};
  const std::size_t n1 = at[0].size(), n2 = at[1].size();
  const auto t_of = [](std::size_t k) { return static_cast<std::uint64_t>(k) * kBuffonStepNs; };

  foxglove::JsonMcap mcap(
      {"foxglove.SceneUpdate", "foxglove.PoseInFrame", "foxglove.PosesInFrame", "foxglove.Log"});
  const std::uint16_t arena_ch = mcap.channel("foxglove.SceneUpdate", "/arena");
  const std::uint16_t log_ch = mcap.channel("foxglove.Log", "/log");
  std::array<std::uint16_t, 2> pose_ch{}, trail_ch{};
  for (std::size_t v = 0; v < 2; ++v) {
    const std::string visit = "/visit" + std::to_string(v + 1);
    pose_ch[v] = mcap.channel("foxglove.PoseInFrame", visit + "/pose");
    trail_ch[v] = mcap.channel("foxglove.PosesInFrame", visit + "/trail");
  }
  const auto put = [&](std::uint16_t ch, std::size_t seq, std::uint64_t t,
                       const nlohmann::json& j) { mcap.put(ch, seq, t, j); };

  nlohmann::json walls = nlohmann::json::array();
  for (const auto& s : world.walls())
    for (const auto& p : {s.a, s.b})
      walls.push_back({{"x", unit(p.x)}, {"y", unit(p.y)}, {"z", 0.0}});
  put(arena_ch, 0, 0,
      foxglove::line_list_scene(0, "arena", "arena", std::move(walls),
                                {{"r", 0.2}, {"g", 0.2}, {"b", 0.2}, {"a", 1}}));
  put(log_ch, 0, 0,
      log_json(0, 2,
               "buffon on " + arena + " (area " + number(area) + "): trial 0 of " +
                   std::to_string(m.trials.size()) + ", seed " + std::to_string(params.seed) +
                   ", width " + number(unit(params.width)) + "; visit 1 " + std::to_string(n1 - 1) +
                   " steps from time 0, then visit 2 " + std::to_string(n2 - 1) +
                   " steps from step " + std::to_string(n1) + ", one every " +
                   std::to_string(kBuffonStepNs / 1000000) + " ms"));

  // Visit 1's segments, indexed, for the steps of visit 2 that cross them.
  buffon::GrowingTrailIndex index(world.lower(), world.upper());
  for (std::size_t j = 1; j < n1; ++j) (void)index.insert((*trails[0])[j - 1], (*trails[0])[j]);
  std::uint64_t crossings = 0;
  for (std::size_t v = 0; v < 2; ++v) {
    const std::size_t n = at[v].size(), first = v == 0 ? 0 : n1;
    for (std::size_t j = 0; j < n; ++j) {
      const std::size_t k = first + j;
      const std::uint64_t t = t_of(k);
      put(pose_ch[v], k, t,
          {{"timestamp", stamp_of(t)},
           {"frame_id", "arena"},
           {"pose", pose_json(at[v][j].x, at[v][j].y, yaw[v][j])}});
      if (foxglove::trail_due(j, n))
        put(trail_ch[v], k, t,
            {{"timestamp", stamp_of(t)},
             {"frame_id", "arena"},
             {"poses", foxglove::trail_poses(j, [&](std::size_t i) {
                return pose_json(at[v][i].x, at[v][i].y, yaw[v][i]);
              })}});
      if (v == 0 || j == 0) continue;
      const std::uint64_t c = index.cross((*trails[1])[j - 1], (*trails[1])[j]);
      if (c == 0) continue;
      crossings += c;
      put(log_ch, k, t,
          log_json(t, 2,
                   "visit 2 step " + std::to_string(j) + " crosses visit 1's trail" +
                       (c > 1 ? " " + std::to_string(c) + " times" : "") + " (" +
                       std::to_string(crossings) + " so far)"));
    }
  }
  const std::size_t last = n1 + n2 - 1;
  const std::uint64_t end = t_of(last);
  const auto& cf = trial.closed_form;
  std::string result = "crossings " + std::to_string(trial.run.crossings_exact) + " (exact), BC " +
                       std::to_string(trial.run.bc) + ", nBC " + number(trial.nbc) + ", length1 " +
                       number(trial.length1) + ", length2 " + number(trial.length2) +
                       ", blocked steps " + std::to_string(trial.run.blocked) + "; ";
  result += cf.area ? "closed-form area " + number(*cf.area) + ", 95 % interval [" +
                          number(cf.lower) + ", " + (cf.upper ? number(*cf.upper) : "inf") + "]"
                    : "no crossing: no closed-form area";
  put(log_ch, last, end, log_json(end, 2, result));
  return mcap.write(out);
}

} // namespace antkit::commands
