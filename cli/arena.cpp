// `antkit arena SPEC|FILE.wkt`: build or read an arena, report its exact measures, and optionally
// write it as WKT or rasterize it into a MovingAI .map file.
#include "commands.hpp"
#include "output.hpp"

#include <antkit/commands/options.hpp>
#include <antkit/geometry/arena.hpp>
#include <antkit/geometry/arena_raster.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/geometry/wkt.hpp>
#include <antkit/io/atomic_file.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/map_io.hpp>
#include <cctype>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

namespace {

struct ArenaOptions {
  std::string source;
  std::string raster;
  std::string out;
  std::string out_wkt;
  antkit::cli::Format format = antkit::cli::Format::Table;
};

void run(const ArenaOptions& o) {
  using namespace antkit::geometry;
  nlohmann::json result;
  std::optional<Arena> arena;
  std::optional<double> ideal;
  if (antkit::commands::is_wkt_path(o.source)) {
    arena = read_wkt_file(o.source);
  } else {
    auto named = build_arena_spec(o.source, "SPEC");
    arena = std::move(named.arena);
    ideal = named.ideal_area;
  }
  result["area"] = arena->area();
  result["area_exact"] = arena->area_exact();
  if (ideal) result["ideal_area"] = *ideal;
  result["perimeter"] = arena->perimeter();
  result["vertices"] = arena->vertex_count();
  result["holes"] = arena->hole_count();
  const auto box = arena->bbox();
  result["bbox"] = {box.xmin, box.ymin, box.xmax, box.ymax};

  // Everything that can fail on bad input happens before the first file is written.
  std::optional<std::string> map_text;
  if (!o.raster.empty()) {
    const auto cell = CellSize::parse(o.raster, "--raster");
    const auto raster = rasterize(*arena, cell);
    std::size_t free = 0;
    for (const auto c : raster.grid.cells()) free += c == antkit::kernel::Occupancy::Free ? 1 : 0;
    result["raster"] = {{"cell", cell.value()},
                        {"width", raster.grid.width()},
                        {"height", raster.grid.height()},
                        {"free_cells", free},
                        {"origin",
                         {static_cast<double>(raster.frame.col0) * cell.value(),
                          static_cast<double>(raster.frame.row0) * cell.value()}}};
    antkit::maps::GridMap map; // a raster has at least one cell: write_movingai takes it
    map.cells = raster.grid;
    map_text = antkit::maps::write_movingai(map);
  }
  std::optional<std::string> wkt_text;
  if (!o.out_wkt.empty()) wkt_text = write_wkt(*arena) + "\n";

  if (map_text) antkit::io::write_file_atomic(o.out, *map_text);
  if (wkt_text) antkit::io::write_file_atomic(o.out_wkt, *wkt_text);
  antkit::cli::emit(result, o.format, std::cout);
}

void register_arena(CLI::App& app) {
  auto options = std::make_shared<ArenaOptions>();
  auto* sub = app.add_subcommand(
      "arena",
      "Build a named arena (paper 000, Figure 3) or read a WKT file; print its exact area, "
      "perimeter, vertices, holes and bounding box; optionally rasterize or save it");
  sub->add_option("arena", options->source,
                  "A spec (standard, circle:d=100, square:area=7854, ellipse:area=7854,e=0.968, "
                  "barrier-i:len=0.4, barrier-plus:len=0.4, ring, plus, obstacles) or a FILE.wkt")
      ->required();
  auto* raster = sub->add_option("--raster", options->raster,
                                 "Rasterize at this cell size (robot diameters, a decimal): a cell "
                                 "is free iff its centre is strictly inside the arena");
  auto* out = sub->add_option("--out", options->out, "The MovingAI .map file for --raster");
  raster->needs(out);
  out->needs(raster);
  sub->add_option("--out-wkt", options->out_wkt, "Write the arena as WKT to this file");
  antkit::cli::add_format_option(*sub, options->format);
  sub->callback([options] { run(*options); });
}

const antkit::cli::Registration arena_registration{"arena", &register_arena};

} // namespace
