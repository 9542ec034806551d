// `antkit stc-noise`: the marker-noise experiment of ant-like STC (issue 3): coverage and repeats
// against the probability that a mark is misread, missed or phantom, averaged over keyed trials.
//
//   antkit stc-noise --map FILE [--variant ant|ant-edge] [--start X,Y] [--levels P,P,...]
//                    [--trials N] [--seed S] [--format table|json]
//
// JSON: variant, map, start, reachable_subcells, trials, seed, curve (one {"noise", "coverage",
// "repeats_per_subcell", "complete_tours", "mean_positions"} per level, in the order given).
// Coordinates are sub-cells, as for `antkit stc` (stc.cpp). Exit status: 0, 2 for bad input.
#include "commands.hpp"
#include "output.hpp"
#include "stc_options.hpp"

#include <algorithm>
#include <antkit/algorithms/options.hpp>
#include <antkit/experiments/stc_tours.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/map_io.hpp>
#include <cstdint>
#include <iostream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace {

using antkit::cli::Format;
using antkit::kernel::InputError;
using namespace antkit::stc;

struct NoiseOptions {
  std::string map;
  std::string variant = "ant";
  std::string start;
  std::string levels = "0,0.0001,0.001,0.005,0.01,0.02,0.05,0.1,0.2";
  std::int32_t trials = 20;
  std::uint64_t seed = 1;
  Format format = Format::Table;
};

void run_noise_command(const NoiseOptions& o) {
  const Variant variant = antkit::commands::stc_variant(o.variant, "--variant");
  if (variant != Variant::Ant && variant != Variant::AntEdge)
    throw InputError("--variant", "marker noise applies to ant and ant-edge only");
  if (o.trials < 1 || o.trials > 100000)
    throw InputError("--trials", std::to_string(o.trials) + " is outside [1, 100000]");
  std::vector<std::pair<std::string, std::uint32_t>> levels;
  std::size_t from = 0;
  while (from <= o.levels.size()) {
    const auto comma = std::min(o.levels.find(',', from), o.levels.size());
    const std::string item = o.levels.substr(from, comma - from);
    levels.emplace_back(item, antkit::algorithms::parse_probability_ppm("--levels", item));
    from = comma + 1;
  }
  const auto map = antkit::maps::load_map(o.map);
  const antkit::kernel::Cell start = antkit::cli::read_stc_start(map, variant, o.start, o.map);
  std::vector<std::uint32_t> ppm;
  for (const auto& level : levels) ppm.push_back(level.second);
  std::int64_t reachable = 0;
  std::vector<antkit::experiments::StcNoisePoint> points;
  try {
    // Trials run in order, each with its own keyed stream (trial = its index): the curve does
    // not depend on anything but the seed (experiments/stc_tours.hpp).
    points = antkit::experiments::run_stc_noise(map.cells, start, {o.variant}, ppm, o.trials,
                                                o.seed, antkit::algorithms::Runner{}, &reachable);
  } catch (const InputError& e) {
    throw InputError(o.start.empty() ? o.map : "--start", e.message());
  }
  nlohmann::json curve = nlohmann::json::array();
  for (std::size_t k = 0; k < points.size(); ++k)
    curve.push_back({{"noise", levels[k].first},
                     {"coverage", points[k].coverage},
                     {"repeats_per_subcell", points[k].repeats_per_subcell},
                     {"complete_tours", points[k].complete},
                     {"mean_positions", points[k].mean_positions}});
  nlohmann::json j;
  j["variant"] = std::string(variant_name(variant));
  j["map"] = o.map;
  j["start"] = {start.x, start.y};
  j["reachable_subcells"] = reachable;
  j["trials"] = o.trials;
  j["seed"] = o.seed;
  j["curve"] = std::move(curve);
  antkit::cli::emit(j, o.format, std::cout);
}

void register_stc_noise(CLI::App& app) {
  auto n = std::make_shared<NoiseOptions>();
  auto* noise = app.add_subcommand(
      "stc-noise", "Marker noise experiment: coverage and repeats of ant-like STC against the "
                   "probability that a mark is misread, averaged over keyed trials");
  noise->add_option("--map", n->map, "The map (.map, .yaml or .txt)")->required();
  noise->add_option("--variant", n->variant, "ant (default) or ant-edge");
  noise->add_option("--start", n->start, "Start sub-cell X,Y (default as for `antkit stc`)");
  noise->add_option("--levels", n->levels, "Comma-separated misread probabilities")
      ->default_str(n->levels);
  noise->add_option("--trials", n->trials, "Trials per level (default 20)");
  noise->add_option("--seed", n->seed, "Seed of the keyed noise streams (default 1)");
  antkit::cli::add_format_option(*noise, n->format);
  noise->callback([n] { run_noise_command(*n); });
}

const antkit::cli::Registration stc_noise_registration{"stc-noise", &register_stc_noise};

} // namespace
