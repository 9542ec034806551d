// The exact area of an arena named by a spec or a WKT file (options.hpp), for the Buffon estimate's
// relative error, whether two arguments name one arena, and its walls for the MCAP export.
#include <antkit/commands/options.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/geometry/wkt.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

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

bool same_arena(const std::string& a, const std::string& b) {
  if (a == b) return true;
  if (is_wkt_path(a) || is_wkt_path(b)) {
    if (!is_wkt_path(a) || !is_wkt_path(b)) return false;
    std::error_code ec;
    if (std::filesystem::equivalent(a, b, ec) && !ec) return true;
    std::ifstream fa(a, std::ios::binary), fb(b, std::ios::binary);
    if (!fa || !fb) return false;
    return std::string(std::istreambuf_iterator<char>(fa), {}) ==
           std::string(std::istreambuf_iterator<char>(fb), {});
  }
  try {
    const auto pa = geometry::parse_arena_spec(a), pb = geometry::parse_arena_spec(b);
    return pa.family == pb.family && pa.params == pb.params;
  } catch (const kernel::InputError&) {
    return false;
  }
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
