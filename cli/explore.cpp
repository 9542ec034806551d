// `antkit explore`: two-robot line-of-sight exploration (issue 5, paper 001).
//
//   antkit explore (--map FILE | --size WxH [--obstacles K | --blocks K] [--seed S] [--trial T])
//                  [--start X,Y] --algo fast-wall-follow|frontier [--los on|off]
//                  [--w1 N --w2 N --w3 N] [--format table|json] [--svg FILE] [--png FILE]
//                  [--mcap FILE.mcap]
//
// x to the right, y downward from the first row. The robots start on the start cell (default: the
// free cell nearest the lower-left corner, or the map's 'S') and its nearest free neighbour.
// JSON: {"algo", "steps", "eme", "moves": [a, b], "explored", "unobservable",
//        "cells": [one string per row of F S L B N O, B for S+LOS], "hash"}.
//
// Choices: a map or room may have at most 2048 x 2048 cells (memory, see kMaxCells); --size
// without --obstacles or --blocks is an empty room; the environments are drawn
// from the keyed stream (seed, experiment 5, trial, 0, purpose) so that `--trial` reproduces one
// row of the tables driver (`antkit explore-tables`); fast wall-follow always sweeps the line of
// sight, so `--algo fast-wall-follow --los off` is rejected as bad input.
// --mcap writes the run for Foxglove (commands/explore_mcap.hpp: the map, both robots each tick at
// 100 ms a tick, their trails, the line of sight lost and regained, the explored map at the end).
#include "commands.hpp"
#include "output.hpp"

#include <algorithm>
#include <antkit/algorithms/options.hpp>
#include <antkit/commands/explore_mcap.hpp>
#include <antkit/experiments/explore_tables.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/los/explore.hpp>
#include <antkit/maps/map_io.hpp>
#include <iostream>
#include <memory>
#include <string>

namespace {

using antkit::cli::Format;
using antkit::kernel::Cell;
using antkit::kernel::InputError;
using antkit::kernel::OccupancyGrid;
namespace los = antkit::los;

struct ExploreCommand {
  std::string map;
  std::string size;
  std::int64_t obstacles = -1;
  std::int64_t blocks = -1;
  std::uint64_t seed = 1;
  std::uint64_t trial = 1;
  std::string start;
  std::string algo;
  std::string los = "on";
  std::int64_t w1 = 1, w2 = 1, w3 = 0;
  std::string svg, png, mcap;
  Format format = Format::Table;
};

// The exploration keeps about 30 bytes per cell (states, frontier set, planner and tracing
// scratch), so the command caps a map at 2048 x 2048 cells (about 120 MiB); the maps are
// at most about 1000 x 1000.
constexpr std::size_t kMaxCells = std::size_t{2048} * 2048;

struct Environment {
  OccupancyGrid grid;
  Cell start{};
};

Environment build_environment(const ExploreCommand& c) {
  Environment env;
  std::optional<Cell> start;
  if (!c.start.empty()) {
    const auto [x, y] =
        antkit::algorithms::parse_pair("--start", c.start, ',', "X,Y (two integers)");
    if (x < 0 || y < 0 || x >= antkit::kernel::kMaxGridSide || y >= antkit::kernel::kMaxGridSide)
      throw InputError("--start", "cell (" + c.start + ") is outside any map");
    start = Cell{static_cast<std::int32_t>(x), static_cast<std::int32_t>(y)};
  }
  if (!c.map.empty()) {
    if (!c.size.empty() || c.obstacles >= 0 || c.blocks >= 0)
      throw InputError("--map", "give either --map or --size with --obstacles/--blocks, not both");
    auto map = antkit::maps::load_map(c.map);
    if (map.cells.size() > kMaxCells)
      throw InputError(c.map, std::to_string(map.cells.width()) + "x" +
                                  std::to_string(map.cells.height()) +
                                  " cells is more than this command explores (2048 x 2048)");
    env.grid = std::move(map.cells);
    if (!start && map.start) start = map.start;
  } else {
    if (c.size.empty()) throw InputError("explore", "give --map FILE or --size WxH");
    const auto [w, h] = antkit::algorithms::parse_pair("--size", c.size, 'x', "WxH (two integers)");
    if (w < 2 || h < 2 || w > 2048 || h > 2048)
      throw InputError("--size", "'" + c.size + "': each side must be in [2, 2048]");
    if (c.obstacles >= 0 && c.blocks >= 0)
      throw InputError("--blocks", "give --obstacles or --blocks, not both");
    const auto width = static_cast<std::int32_t>(w), height = static_cast<std::int32_t>(h);
    const Cell keep = start.value_or(Cell{0, height - 1});
    if (!(keep.x < width && keep.y < height))
      throw InputError("--start", "cell (" + c.start + ") is outside the " + c.size + " grid");
    try {
      if (c.blocks >= 0) {
        if (c.blocks > 100000) throw InputError("--blocks", "at most 100000 blocks");
        env.grid = los::obstacle_blocks(width, height, static_cast<std::int32_t>(c.blocks), c.seed,
                                        c.trial, keep);
      } else {
        if (c.obstacles > static_cast<std::int64_t>(w) * h)
          throw InputError("--obstacles", "more obstacles than cells");
        env.grid = los::scattered_obstacles(
            width, height, static_cast<std::int32_t>(std::max<std::int64_t>(c.obstacles, 0)),
            c.seed, c.trial, keep);
      }
    } catch (const std::invalid_argument& e) {
      throw InputError(c.blocks >= 0 ? "--blocks" : "--obstacles", e.what());
    }
  }
  try {
    env.start = start ? *start : los::default_start(env.grid);
  } catch (const std::invalid_argument& e) {
    throw InputError(c.map.empty() ? "--size" : c.map, e.what());
  }
  return env;
}

nlohmann::json run(const ExploreCommand& c) {
  los::ExploreOptions options;
  if (c.algo == "fast-wall-follow") {
    options.algorithm = los::Algorithm::FastWallFollow;
    if (c.los == "off")
      throw InputError("--los", "fast-wall-follow always sweeps the line of sight; expected on "
                                "(or --algo frontier)");
  } else {
    options.algorithm = los::Algorithm::Frontier;
  }
  options.line_of_sight = c.los == "on";
  for (const auto& [name, v] : {std::pair{"--w1", c.w1}, {"--w2", c.w2}, {"--w3", c.w3}})
    if (v < -1000000 || v > 1000000)
      throw InputError(name, "weight " + std::to_string(v) + " is outside [-1000000, 1000000]");
  options.weights = {c.w1, c.w2, c.w3};

  const Environment env = build_environment(c);
  std::array<Cell, 2> pair{};
  try {
    pair = los::start_pair(env.grid, env.start);
  } catch (const std::invalid_argument& e) {
    throw InputError("--start", "(" + std::to_string(env.start.x) + "," +
                                    std::to_string(env.start.y) + "): " + e.what());
  }
  const std::string what = "explore --algo " + c.algo + " on " +
                           (c.map.empty() ? c.size + " (seed " + std::to_string(c.seed) +
                                                ", trial " + std::to_string(c.trial) + ")"
                                          : c.map);
  const los::ExploreResult r =
      c.mcap.empty() ? los::explore(env.grid, pair[0], pair[1], options)
                     : antkit::commands::explore_mcap(env.grid, pair, options, what, c.mcap);
  if (!r.completed)
    throw antkit::cli::CheckFailed("the exploration did not finish within its tick budget");
  if (!c.svg.empty() || !c.png.empty())
    antkit::experiments::save_exploration_figure(c.algo, r, c.svg, c.png);

  nlohmann::json j;
  j["algo"] = c.algo;
  j["steps"] = r.steps;
  j["eme"] = r.eme;
  j["moves"] = {r.moves[0], r.moves[1]};
  j["explored"] = r.explored;
  j["unobservable"] = r.unobservable;
  nlohmann::json rows = nlohmann::json::array();
  for (std::int32_t y = 0; y < r.cells.height(); ++y) {
    std::string row(static_cast<std::size_t>(r.cells.width()), 'F');
    for (std::int32_t x = 0; x < r.cells.width(); ++x)
      row[static_cast<std::size_t>(x)] = los::code(r.cells[{x, y}]);
    rows.push_back(std::move(row));
  }
  j["cells"] = std::move(rows);
  j["hash"] = antkit::kernel::hash_hex(r.hash);
  return j;
}

void register_explore(CLI::App& app) {
  auto opts = std::make_shared<ExploreCommand>();
  auto* sub = app.add_subcommand(
      "explore", "Two-robot line-of-sight exploration: fast wall-follow or the frontier baseline");
  sub->add_option("--map", opts->map, "A map file (.map, .yaml, .txt)");
  sub->add_option("--size", opts->size, "A generated WxH room (instead of --map)");
  sub->add_option("--obstacles", opts->obstacles, "Scattered single-cell obstacles (with --size)")
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--blocks", opts->blocks, "Blocks of six obstacles (with --size)")
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--seed", opts->seed, "Seed of the obstacle positions")->default_val(1);
  sub->add_option("--trial", opts->trial, "Trial number of the obstacle positions")->default_val(1);
  sub->add_option("--start", opts->start, "Start cell X,Y (x right, y down from the first row)");
  sub->add_option("--algo", opts->algo, "fast-wall-follow or frontier")
      ->required()
      ->check(CLI::IsMember({"fast-wall-follow", "frontier"}));
  sub->add_option("--los", opts->los, "Sweep the line of sight (frontier only): on or off")
      ->check(CLI::IsMember({"on", "off"}))
      ->default_val("on");
  sub->add_option("--w1", opts->w1, "Frontier weight of the information gain I")->default_val(1);
  sub->add_option("--w2", opts->w2, "Frontier weight of the distance D")->default_val(1);
  sub->add_option("--w3", opts->w3, "Frontier weight of the nearness lambda")->default_val(0);
  sub->add_option("--svg", opts->svg,
                  "Write the explored map (Table 1's colours) and both trails as SVG, with a "
                  "legend");
  sub->add_option("--png", opts->png, "The same picture as PNG");
  sub->add_option("--mcap", opts->mcap,
                  "Write the run as MCAP for Foxglove: the map, both robots each tick, the line "
                  "of sight lost and regained, the explored map");
  antkit::cli::add_format_option(*sub, opts->format);
  sub->callback([opts] { antkit::cli::emit(run(*opts), opts->format, std::cout); });
}

const antkit::cli::Registration explore_registration{"explore", &register_explore};

} // namespace
