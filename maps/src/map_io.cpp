// Map files by extension: reading a whole file, choosing the format, loading and saving.
#include <antkit/io/atomic_file.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/detail/text_scan.hpp>
#include <antkit/maps/map_io.hpp>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

namespace antkit::maps {

MapFormat map_format_of(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (auto& c : ext)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  if (ext == ".map") return MapFormat::MovingAI;
  if (ext == ".yaml" || ext == ".yml") return MapFormat::Ros;
  if (ext == ".txt" || ext == ".ascii") return MapFormat::Ascii;
  throw kernel::InputError(path.string(),
                           "unknown map extension " +
                               (ext.empty() ? std::string("(none)") : detail::quoted(ext)) +
                               "; expected .map (MovingAI), .yaml (ROS map_server) or .txt/.ascii "
                               "(ASCII)");
}

std::string_view format_name(MapFormat format) {
  switch (format) {
  case MapFormat::MovingAI:
    return "movingai";
  case MapFormat::Ros:
    return "ros";
  case MapFormat::Ascii:
    return "ascii";
  }
  return "unknown";
}

std::string read_map_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw kernel::InputError(path.string(), "is a directory; expected a map file");
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw kernel::InputError(path.string(),
                             std::string("cannot open for reading: ") + std::strerror(errno));
  // Read in chunks up to the cap, so that neither a huge file nor a pipe that never ends can take
  // the memory.
  std::string bytes;
  char buf[1 << 16];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    bytes.append(buf, static_cast<std::size_t>(in.gcount()));
    if (bytes.size() > kMaxMapFileBytes)
      throw kernel::InputError(path.string(), "the file is over the cap of " +
                                                  std::to_string(kMaxMapFileBytes) +
                                                  " bytes; expected a smaller map file");
  }
  if (in.bad()) throw kernel::InputError(path.string(), "read failed");
  return bytes;
}

GridMap load_map(const std::filesystem::path& path) {
  const auto format = map_format_of(path);
  if (format == MapFormat::Ros) return load_ros_map(path);
  const auto text = read_map_file(path);
  return format == MapFormat::MovingAI ? parse_movingai(text, path.string())
                                       : parse_ascii(text, path.string());
}

void save_map(const std::filesystem::path& path, const GridMap& map) {
  const auto format = map_format_of(path);
  if (format == MapFormat::Ros)
    throw kernel::InputError(path.string(), "ROS map_server maps are read-only here; expected an "
                                            "output ending in .map (MovingAI) or .txt/.ascii");
  if (map.cells.empty())
    throw kernel::InputError(path.string(), "the map has no cells; expected at least one");
  if (map.start &&
      map.cells.get_or(*map.start, kernel::Occupancy::Blocked) != kernel::Occupancy::Free)
    throw kernel::InputError(path.string(), "the start cell (" + std::to_string(map.start->x) +
                                                ", " + std::to_string(map.start->y) +
                                                ") is not a free cell of the map");
  const auto text = format == MapFormat::MovingAI ? write_movingai(map) : write_ascii(map);
  io::write_file_atomic(path, text);
}

} // namespace antkit::maps
