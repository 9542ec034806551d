// `antkit rs-from-log LOG`: the Randomized Search baseline (paper 000 section 8.1) from one logged
// walk: the area the body covered along its dead-reckoned trail (devices/odometry.hpp).
//
// JSON: "robot", "diameter_m" (the unit of length), "walk" (the trail, as buffon-from-logs reports
// a visit), "cells", "area" (body diameters squared), "area_m2".
#include "commands.hpp"
#include "output.hpp"

#include <antkit/commands/json.hpp>
#include <antkit/devices/odometry.hpp>
#include <iostream>
#include <memory>
#include <string>

namespace {

using antkit::cli::Format;

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
    const auto r = antkit::devices::rs_from_log(c->log);
    nlohmann::json j;
    j["robot"] = r.walk.robot;
    j["diameter_m"] = r.diameter_m;
    j["walk"] = antkit::commands::trail_json(r.walk);
    j["cells"] = r.cells;
    j["area"] = r.area;
    j["area_m2"] = r.area * r.diameter_m * r.diameter_m;
    antkit::cli::emit(j, c->format, std::cout);
  });
}

const antkit::cli::Registration rs_from_log_registration{"rs-from-log", &register_rs};

} // namespace
