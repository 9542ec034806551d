// `antkit buffon-from-logs`: paper 000's measurement from two recorded visits (issue 13): what
// section 7 counted by hand on the floor, from the robots' odometry (devices/odometry.hpp).
//   antkit buffon-from-logs VISIT1 VISIT2 [--width W] [--format table|json]
// JSON: {"robot", "diameter_m", "visit1": {"steps", "length"}, "visit2": {...}, "bc",
// "crossings_exact", "area", "area_m2", "area_bc", "area_bc_m2"} (lengths in body diameters,
// areas in body diameters squared and in square metres; an area is null when its count is 0).
#include "commands.hpp"
#include "output.hpp"

#include <antkit/devices/odometry.hpp>
#include <antkit/geometry/fixed_convert.hpp>
#include <antkit/kernel/input_error.hpp>
#include <iostream>
#include <memory>

namespace {

namespace devices = antkit::devices;
using antkit::cli::Format;

struct FromLogsCommand {
  std::string visit1, visit2;
  double width = 0.1;
  Format format = Format::Table;
};

nlohmann::json visit_json(const devices::LoggedTrail& t) {
  return {{"steps", t.steps},
          {"length", static_cast<double>(t.length_raw) / 65536.0},
          {"truncated", t.truncated}};
}

void run(const FromLogsCommand& c) {
  if (!(c.width >= 0.01 && c.width <= 10))
    throw antkit::kernel::InputError("--width", "the trail width must be in [0.01, 10] units");
  const auto width = antkit::geometry::fixed_from_double<antkit::kernel::Fx>(c.width, "--width");
  const auto r = devices::buffon_from_logs(c.visit1, c.visit2, width);
  const double m2 = r.diameter_m * r.diameter_m;
  const auto area = [m2](const std::optional<double>& a, double scale) {
    return a ? nlohmann::json(*a * scale) : nlohmann::json(nullptr);
  };
  nlohmann::json j;
  j["robot"] = r.visit1.robot;
  j["diameter_m"] = r.diameter_m;
  j["visit1"] = visit_json(r.visit1);
  j["visit2"] = visit_json(r.visit2);
  j["width"] = c.width;
  j["bc"] = r.bc;
  j["crossings_exact"] = r.crossings_exact;
  j["area"] = area(r.area, 1);
  j["area_m2"] = area(r.area, m2);
  j["area_bc"] = area(r.area_bc, 1);
  j["area_bc_m2"] = area(r.area_bc, m2);
  antkit::cli::emit(j, c.format, std::cout);
}

void register_from_logs(CLI::App& app) {
  auto c = std::make_shared<FromLogsCommand>();
  auto* sub = app.add_subcommand(
      "buffon-from-logs", "Buffon's measurement (paper 000) from two recorded visits' odometry: "
                          "BC, the exact crossing count and the area estimate");
  sub->add_option("visit1", c->visit1, "The log of visit 1 (antkit record ... --visit 1)")
      ->required();
  sub->add_option("visit2", c->visit2, "The log of visit 2")->required();
  sub->add_option("--width", c->width, "Pheromone band width in body diameters (default 0.1)");
  antkit::cli::add_format_option(*sub, c->format);
  sub->callback([c] { run(*c); });
}

const antkit::cli::Registration reg{"buffon-from-logs", &register_from_logs};

// `antkit rs-from-log LOG`: the Randomized Search baseline (paper 000 section 8.1) from one logged
// walk: the area the body covered along its dead-reckoned trail.
struct RsCommand {
  std::string log;
  Format format = Format::Table;
};

void register_rs(CLI::App& app) {
  auto c = std::make_shared<RsCommand>();
  auto* sub = app.add_subcommand(
      "rs-from-log", "The Randomized Search area estimate (paper 000, section 8.1) from one logged "
                     "walk's odometry: the area the body covered");
  sub->add_option("log", c->log, "The log (antkit record ... --controller rs)")->required();
  antkit::cli::add_format_option(*sub, c->format);
  sub->callback([c] {
    const auto r = devices::rs_from_log(c->log);
    nlohmann::json j;
    j["robot"] = r.walk.robot;
    j["diameter_m"] = r.diameter_m;
    j["walk"] = visit_json(r.walk);
    j["cells"] = r.cells;
    j["area"] = r.area;
    j["area_m2"] = r.area * r.diameter_m * r.diameter_m;
    antkit::cli::emit(j, c->format, std::cout);
  });
}

const antkit::cli::Registration reg_rs{"rs-from-log", &register_rs};

} // namespace
