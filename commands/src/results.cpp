// The JSON of `antkit stc`, `antkit replay` and `antkit buffon-from-logs` (json.hpp), and the
// choices `antkit stc` and `antkit buffon-from-logs` make from their options (options.hpp).
#include <antkit/algorithms/options.hpp>
#include <antkit/commands/json.hpp>
#include <antkit/commands/options.hpp>
#include <antkit/geometry/fixed_convert.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/stc/start.hpp>

namespace antkit::commands {

stc::Variant stc_variant(const std::string& name, const std::string& where) {
  if (const auto v = stc::parse_variant(name)) return *v;
  throw kernel::InputError(where, "'" + name +
                                      "' is not a variant: expected offline, online, ant, "
                                      "ant-edge or full");
}

stc::NoiseModel stc_noise(stc::Variant variant, const std::string& probability, std::uint64_t seed,
                          const std::string& where) {
  if (variant != stc::Variant::Ant && variant != stc::Variant::AntEdge)
    throw kernel::InputError(where, "marker noise applies to the variants that read marks, ant "
                                    "and ant-edge, not " +
                                        std::string(stc::variant_name(variant)));
  return {algorithms::parse_probability_ppm(where, probability), seed, 0};
}

kernel::Cell choose_stc_start(const maps::GridMap& map, stc::Variant variant,
                              std::optional<kernel::Cell> given, const std::string& map_name) {
  return stc::choose_start(map.cells, variant, given, map.start, map_name);
}

nlohmann::json stc_json(const stc::RunResult& r, std::int32_t width, std::int32_t height,
                        kernel::Cell start, std::optional<StcNoiseFields> noise) {
  nlohmann::json j;
  j["variant"] = std::string(stc::variant_name(r.variant));
  j["width"] = width;
  j["height"] = height;
  j["start"] = cell_json(start);
  j["reachable_subcells"] = r.reachable_subcells;
  j["covered"] = r.covered;
  j["repeats"] = r.repeats;
  j["returned_to_start"] = r.returned_to_start;
  j["hash"] = kernel::hash_hex(r.hash);
  if (noise) {
    j["noise_ppm"] = noise->ppm;
    j["seed"] = noise->seed;
  }
  return j;
}

nlohmann::json replay_json(const devices::ReplayResult& r) {
  nlohmann::json j;
  j["steps"] = r.steps;
  j["identical"] = r.identical;
  if (r.first_divergence) {
    const auto& d = *r.first_divergence;
    j["first_divergence"] = {
        {"step", d.step}, {"field", d.field}, {"expected", d.expected}, {"actual", d.actual}};
  } else {
    j["first_divergence"] = nullptr;
  }
  j["truncated"] = r.truncated;
  j["complete"] = r.complete;
  j["hash"] = kernel::hash_hex(r.hash);
  j["robot"] = r.header.robot;
  j["controller"] = r.header.controller;
  j["stopped"] = r.stop ? nlohmann::json(r.stop->reason) : nlohmann::json(nullptr);
  return j;
}

nlohmann::json trail_json(const devices::LoggedTrail& t) {
  return {{"steps", t.steps},
          {"length", static_cast<double>(t.length_raw) / 65536.0},
          {"truncated", t.truncated},
          {"hash", kernel::hash_hex(t.run_hash)}};
}

namespace {
nlohmann::json maybe(const std::optional<double>& v, double scale = 1) {
  return v ? nlohmann::json(*v * scale) : nlohmann::json(nullptr);
}

nlohmann::json interval(const devices::AreaInterval& ci, double scale = 1) {
  return nlohmann::json::array({maybe(ci.lower, scale), maybe(ci.upper, scale)});
}
} // namespace

devices::BuffonFromLogs buffon_from_logs(const std::string& visit1, const std::string& visit2,
                                         double width, const std::string& arena,
                                         const std::string& width_where) {
  if (!(width >= 0.01 && width <= 10))
    throw kernel::InputError(width_where, "the trail width must be in [0.01, 10] units");
  return devices::buffon_from_logs(visit1, visit2,
                                   geometry::fixed_from_double<kernel::Fx>(width, width_where),
                                   {arena, &arena_spec_area, &same_arena});
}

nlohmann::json buffon_from_logs_json(const devices::BuffonFromLogs& r, double width) {
  const double m2 = r.diameter_m * r.diameter_m;
  const auto& e = r.estimate;
  nlohmann::json j;
  j["robot"] = r.visit1.robot;
  j["diameter_m"] = r.diameter_m;
  j["visit1"] = trail_json(r.visit1);
  j["visit2"] = trail_json(r.visit2);
  j["width"] = width;
  j["bc"] = r.bc;
  j["crossings_exact"] = r.crossings_exact;
  j["area"] = maybe(r.area);
  j["area_m2"] = maybe(r.area, m2);
  j["area_bc"] = maybe(r.area_bc);
  j["area_bc_m2"] = maybe(r.area_bc, m2);
  j["area_raw"] = maybe(e.area_raw);
  j["area_raw_ci"] = interval(e.raw_ci);
  j["area_corrected"] = maybe(e.area_corrected);
  j["area_corrected_m2"] = maybe(e.area_corrected, m2);
  j["area_corrected_ci"] = interval(e.corrected_ci);
  j["area_corrected_ci_m2"] = interval(e.corrected_ci, m2);
  j["erosion_factor"] = e.erosion_factor;
  j["wall_encounters"] = r.wall_encounters;
  j["variance_visit1"] = r.variance_visit1;
  j["variance_visit2"] = r.variance_visit2;
  j["arena"] = r.arena.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.arena);
  j["arena_source"] = r.arena.empty() ? nlohmann::json(nullptr)
                                      : nlohmann::json(devices::arena_source_name(r.arena_source));
  j["area_true"] = maybe(r.area_true);
  j["area_true_m2"] = maybe(r.area_true, m2);
  j["relative_error"] = maybe(r.relative_error);
  j["relative_error_raw"] = maybe(r.relative_error_raw);
  return j;
}

} // namespace antkit::commands
