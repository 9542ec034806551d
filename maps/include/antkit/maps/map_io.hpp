#pragma once
// Grid map files (issue 2): MovingAI `.map` (read, write), ROS map_server `.yaml` + `.pgm` (read)
// and ASCII `.txt`/`.ascii` (read, write), all into one kernel occupancy grid.
//
// Every grid here has x to the right and y down, row 0 being the first row of the file (the top of
// the picture); that is the kernel's convention (antkit/kernel/grid.hpp) and the order all three
// formats store their rows in, so no format is flipped on the way in or out.
//
// Bad input of any kind throws antkit::kernel::InputError whose text is
// "FILE:LINE:COL: what is wrong and what was expected" (line and column count from 1, the column
// in bytes; in a binary PGM the position is that of the offending byte, lines counted by '\n').
//
// Size caps (the formats declare their sizes, and a declared size is not a reason to allocate):
//   * a side may be at most kernel::kMaxGridSide cells (what the kernel's proofs cover);
//   * a map may hold at most kMaxMapCells cells in total (16384 x 16384);
//   * a file may be at most kMaxMapFileBytes long.
// A declared size is also checked against the bytes actually present before anything is
// allocated, so a short file with a huge header fails fast with "truncated".
//
// Format notes and the choices made where the formats are silent:
//
// MovingAI (Sturtevant's benchmark format; data/maps/README.md section 1.1):
//   `type octile`, `height H`, `width W`, `map`, then H rows of exactly W cells. Keywords are lower
//   case; `height` and `width` are accepted in either order (both orders occur in the wild), each
//   exactly once; the type must be `octile` (the only type the benchmarks define). Runs of spaces
//   or tabs separate a keyword from its value, and header lines may carry blanks at either end
//   (map rows may not: a row is exactly W cells). A '\r' before each '\n' is tolerated (CRLF copies
//   exist), as are blank lines after the last row; anything else after the H rows is an error.
//   Cells: `.` `G` `S` free ('S' is swamp, passable: it is NOT a start cell in this format);
//   `@` `O` `T` blocked; `W` (water: traversable, but not from regular terrain) is read as
//   blocked, the README's "safe choice", because a 4-connected robot on regular terrain cannot
//   enter it. Writing uses `.` for Free and `@` for Blocked; the format has no unknown, so Unknown
//   cells are written as `@` (blocked: the reading that never lets a planner through a wall it
//   has not seen), and the start cell is not written. `antkit map convert` reports both losses.
//
// ASCII (this kit's own picture format):
//   one line per row, all rows of the same length, `.` free, `#` blocked, `S` the start (a free
//   cell; at most one), and `?` unknown (our choice: the one printable character that says "not
//   known", so that a ROS map with unknown cells converts to ASCII and back without loss). '\r'
//   before '\n' and blank lines after the last row are tolerated; an empty file is an error.
//   resolution is 1 and the origin 0.
//
// ROS map_server (ROS 1 map_server image_loader.cpp and ROS 2 Nav2 map_io behave alike here):
//   the YAML subset read is documented at parse_ros_yaml(); the image is a PGM, `P5` (binary) or
//   `P2` (plain), documented at parse_pgm(). Only `mode: trinary` (the default) is supported:
//   `scale` and `raw` produce occupancy values 0..100 or 0..255 that a free/blocked/unknown grid
//   cannot hold, so they are rejected with an error that says so.
#include <antkit/kernel/grid.hpp>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace antkit::maps {

// 16384 x 16384 cells: a 1-byte-per-cell grid of 256 MiB, far above any benchmark map (the largest
// in data/maps is 530 x 481), as large as `antkit stc` covers at scale (issue 15; it was 8192
// x 8192 before). A fuzzer cannot reach it: a declared size must be backed by the bytes present.
inline constexpr std::int64_t kMaxMapCells = std::int64_t{1} << 28;
// A P2 image of kMaxMapCells pixels of up to 5 digits each fits below this.
inline constexpr std::uintmax_t kMaxMapFileBytes = std::uintmax_t{1} << 31;

struct GridMap {
  kernel::OccupancyGrid cells; // x right, y down, row 0 = first row of the file / top
  double resolution = 1.0;     // metres per cell (ROS); 1 for MovingAI and ASCII
  double origin_x = 0, origin_y = 0, origin_yaw = 0; // ROS origin of the lower-left pixel
  std::optional<kernel::Cell> start;                 // ASCII 'S'

  friend bool operator==(const GridMap&, const GridMap&) = default;
};

enum class MapFormat { MovingAI, Ros, Ascii };

// The format a path names by its extension (case-insensitive): .map -> MovingAI, .yaml/.yml -> ROS,
// .txt/.ascii -> ASCII. Throws InputError (where = the path) for any other extension.
MapFormat map_format_of(const std::filesystem::path& path);
// "movingai", "ros" or "ascii".
std::string_view format_name(MapFormat format);

// Reads a map file, choosing the format by extension. For ROS the image named by the yaml is read
// too, relative to the yaml's directory unless absolute.
GridMap load_map(const std::filesystem::path& path);
// Writes a map (.map or .txt/.ascii; ROS maps are read-only here) through write_file_atomic: the
// file appears whole or not at all. Throws InputError (where = the path) for a format that cannot
// be written, an empty grid, or a start that is not a free cell of the grid.
void save_map(const std::filesystem::path& path, const GridMap& map);

// The whole content of a file, as bytes. Throws InputError (where = the path) when it cannot be
// read, is a directory, or is longer than kMaxMapFileBytes.
std::string read_map_file(const std::filesystem::path& path);

// ---- MovingAI ---------------------------------------------------------------------------------

// `name` is what error messages call the input (normally its path).
GridMap parse_movingai(std::string_view text, const std::string& name);
// The file's text. Throws std::invalid_argument for an empty grid (the reader would reject it).
std::string write_movingai(const GridMap& map);

// ---- ASCII ------------------------------------------------------------------------------------

GridMap parse_ascii(std::string_view text, const std::string& name);
// Throws std::invalid_argument for an empty grid or a start that is not a free cell of the grid.
std::string write_ascii(const GridMap& map);

// ---- ROS map_server ---------------------------------------------------------------------------

enum class RosMode { Trinary, Scale, Raw };

// What a map_server yaml says. `image` is the path as written; image_line/image_column locate it in
// the yaml, so that a missing or malformed image is reported against the line that named it.
struct RosMapYaml {
  std::string image;
  std::size_t image_line = 0, image_column = 0;
  double resolution = 0;
  double origin_x = 0, origin_y = 0, origin_yaw = 0;
  bool negate = false;
  double occupied_thresh = 0;
  double free_thresh = 0;
  RosMode mode = RosMode::Trinary;
  std::size_t mode_line = 0, mode_column = 0; // 0 when the yaml has no `mode`
};

// The YAML subset: one `key: value` per line; blank lines; comments from a '#' that starts a line
// or follows a space; an optional leading `---` document marker; CRLF tolerated. Values are plain
// scalars or quoted ('...' with '' for a quote, "..." without backslash escapes); `origin` is a
// flow list `[x, y, yaw]` of exactly three numbers. Keys (each at most once): image, resolution,
// origin, negate, occupied_thresh, free_thresh (all required, as in ROS 1 map_server) and mode
// (optional, default trinary). Anything else — another key, indentation, block lists, anchors,
// multi-line values, several documents — is rejected with the line and column and what was
// expected. Checks beyond ROS (which would silently produce a nonsense map): resolution is finite
// and > 0; the thresholds are in [0, 1] and free_thresh <= occupied_thresh; negate is 0, 1, true or
// false. mode scale and raw parse, and are rejected later by ros_map().
RosMapYaml parse_ros_yaml(std::string_view text, const std::string& name);

// A PGM image. pixels are row-major, top row first, each in [0, maxval].
struct PgmImage {
  std::int32_t width = 0;
  std::int32_t height = 0;
  std::uint16_t maxval = 255;
  std::vector<std::uint16_t> pixels;
};

// Netpbm PGM: `P5` (binary) or `P2` (plain). Header: magic, width, height, maxval, separated by
// whitespace, with `#` comments (to the end of the line) allowed between the tokens. P5: one
// whitespace byte after maxval, then exactly width*height samples of 1 byte (maxval < 256) or 2
// bytes big-endian (maxval >= 256); bytes after them are rejected (a wrong width would otherwise
// go unnoticed). P2: width*height decimal samples separated by whitespace, comments allowed.
// width and height >= 1, 1 <= maxval <= 65535, every sample <= maxval. A truncated image is an
// error at the end of the file.
PgmImage parse_pgm(std::string_view bytes, const std::string& name);

// map_server's trinary reading of one grey value v (ROS 1 image_loader.cpp, Nav2 map_io):
// p = (maxval - v) / maxval (v / maxval with negate), computed in double as ROS does;
// p > occupied_thresh -> Blocked, else p < free_thresh -> Free, else Unknown. Both comparisons are
// strict. For maxval 255 this is bit for bit ROS's (255 - v) / 255.0; other maxvals are scaled so
// that a 16-bit or 1-bit image means what its picture shows (ROS itself reads 8-bit only).
kernel::Occupancy classify_trinary(std::uint16_t value, std::uint16_t maxval,
                                   const RosMapYaml& yaml);

// The map a yaml and its image describe. Throws InputError at the yaml's `mode` line for scale or
// raw. `yaml_name` names the yaml in messages.
GridMap ros_map(const RosMapYaml& yaml, const PgmImage& image, const std::string& yaml_name);

// Reads a yaml and the PGM it names (relative to the yaml's directory unless absolute).
GridMap load_ros_map(const std::filesystem::path& yaml_path);

} // namespace antkit::maps
