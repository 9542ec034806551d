// `antkit map`: grid map files (issue 2).
//   antkit map info FILE [--format table|json]   what a map holds: size, cell counts, and the
//                                                4-connected components of its free cells
//   antkit map convert IN OUT [--format ...]      rewrite a map in the format OUT's extension names
#include "commands.hpp"
#include "output.hpp"

#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/components.hpp>
#include <antkit/maps/map_io.hpp>
#include <iostream>
#include <memory>
#include <string>

namespace {

using antkit::cli::Format;

nlohmann::json map_info(const std::string& file) {
  const auto format = antkit::maps::map_format_of(file);
  const auto map = antkit::maps::load_map(file);
  const auto counts = antkit::maps::count_cells(map.cells);
  const auto components = antkit::maps::free_components(map.cells);
  nlohmann::json j;
  j["file"] = file;
  j["format"] = std::string(antkit::maps::format_name(format));
  j["width"] = map.cells.width();
  j["height"] = map.cells.height();
  j["free"] = counts.free;
  j["blocked"] = counts.blocked;
  j["unknown"] = counts.unknown;
  j["components"] = components.count();
  j["largest_component"] = components.largest();
  j["resolution"] = map.resolution;
  j["origin"] = {map.origin_x, map.origin_y, map.origin_yaw};
  j["start"] = map.start ? nlohmann::json{map.start->x, map.start->y} : nlohmann::json(nullptr);
  return j;
}

nlohmann::json map_convert(const std::string& in, const std::string& out) {
  // The output's format is checked first: a bad output name should not cost reading a large map.
  const auto out_format = antkit::maps::map_format_of(out);
  if (out_format == antkit::maps::MapFormat::Ros)
    throw antkit::kernel::InputError(out, "ROS map_server maps are read-only here; expected an "
                                          "output ending in .map (MovingAI) or .txt/.ascii");
  const auto map = antkit::maps::load_map(in);
  antkit::maps::save_map(out, map);
  const auto counts = antkit::maps::count_cells(map.cells);
  nlohmann::json j;
  j["input"] = in;
  j["output"] = out;
  j["format"] = std::string(antkit::maps::format_name(out_format));
  j["width"] = map.cells.width();
  j["height"] = map.cells.height();
  // What the output format cannot hold, said rather than lost silently (map_io.hpp): MovingAI has
  // no unknown (written blocked) and no start; neither format keeps resolution or origin.
  const bool movingai = out_format == antkit::maps::MapFormat::MovingAI;
  j["unknown_written_as_blocked"] = movingai ? counts.unknown : 0;
  j["start_dropped"] = movingai && map.start.has_value();
  return j;
}

struct InfoOptions {
  std::string file;
  Format format = Format::Table;
};
struct ConvertOptions {
  std::string in;
  std::string out;
  Format format = Format::Table;
};

void register_map(CLI::App& app) {
  auto* map = app.add_subcommand("map", "Grid map files: MovingAI .map, ROS .yaml + .pgm, ASCII");
  map->require_subcommand(1);

  auto info_opts = std::make_shared<InfoOptions>();
  auto* info = map->add_subcommand(
      "info", "Size, free/blocked/unknown counts and 4-connected free components of a map");
  // Positional as before, and --map as every other subcommand that reads a map takes it.
  info->add_option("FILE,--map", info_opts->file, "The map (.map, .yaml, .txt or .ascii)")
      ->required();
  antkit::cli::add_format_option(*info, info_opts->format);
  info->callback(
      [info_opts] { antkit::cli::emit(map_info(info_opts->file), info_opts->format, std::cout); });

  auto convert_opts = std::make_shared<ConvertOptions>();
  auto* convert = map->add_subcommand(
      "convert", "Rewrite a map in the format OUT's extension names (.map, .txt or .ascii)");
  convert->add_option("IN,--map", convert_opts->in, "The map to read (.map, .yaml, .txt or .ascii)")
      ->required();
  convert->add_option("OUT,--out", convert_opts->out, "The map to write (.map, .txt or .ascii)")
      ->required();
  antkit::cli::add_format_option(*convert, convert_opts->format);
  convert->callback([convert_opts] {
    antkit::cli::emit(map_convert(convert_opts->in, convert_opts->out), convert_opts->format,
                      std::cout);
  });
}

const antkit::cli::Registration map_registration{"map", &register_map};

} // namespace
