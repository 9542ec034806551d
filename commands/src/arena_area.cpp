// The exact area of an arena named by a spec or a WKT file (options.hpp), for the Buffon estimate's
// relative error, and its walls for the MCAP export.
#include <antkit/commands/options.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/geometry/wkt.hpp>
#include <cctype>

namespace antkit::commands {

bool is_wkt_path(const std::string& s) {
  if (s.size() < 4) return false;
  std::string tail = s.substr(s.size() - 4);
  for (auto& ch : tail) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return tail == ".wkt";
}

double arena_spec_area(const std::string& spec, const std::string& where) {
  return is_wkt_path(spec) ? geometry::read_wkt_file(spec).area()
                           : geometry::build_arena_spec(spec, where).arena.area();
}

devices::McapOptions mcap_options() {
  devices::McapOptions o;
  o.arena_walls = [](const std::string& spec) {
    return is_wkt_path(spec) ? geometry::read_wkt_file(spec).walls_fx()
                             : geometry::build_arena_spec(spec, "arena").arena.walls_fx();
  };
  return o;
}

} // namespace antkit::commands
