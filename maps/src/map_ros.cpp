// ROS map_server maps: the PGM image (P5 and P2), the trinary reading of its grey values, and the
// yaml + image pair as a grid map. The yaml subset is in map_ros_yaml.cpp.
#include <antkit/maps/detail/text_scan.hpp>
#include <antkit/maps/map_io.hpp>
#include <utility>

namespace antkit::maps {

namespace {

using detail::fail_at;

bool is_pgm_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

// Skips whitespace and `#` comments (to the end of the line) from `pos`.
void skip_space_and_comments(std::string_view s, std::size_t& pos) {
  while (pos < s.size()) {
    if (is_pgm_space(s[pos])) {
      ++pos;
    } else if (s[pos] == '#') {
      while (pos < s.size() && s[pos] != '\n' && s[pos] != '\r') ++pos;
    } else {
      return;
    }
  }
}

// A decimal header field or P2 sample at `pos`, at most `max`; it must end at whitespace, a comment
// or the end of the data.
std::uint64_t pgm_number(std::string_view s, std::size_t& pos, std::uint64_t max,
                         const std::string& name, const char* what) {
  skip_space_and_comments(s, pos);
  if (pos >= s.size())
    fail_at(name, s, pos, std::string("the file ends before the ") + what + "; truncated PGM");
  const auto start = pos;
  while (pos < s.size() && detail::is_digit(s[pos])) ++pos;
  if (pos == start)
    fail_at(name, s, start,
            std::string("expected the ") + what + " (a decimal number), found " +
                detail::quoted(s.substr(start, 1)));
  if (pos < s.size() && !is_pgm_space(s[pos]) && s[pos] != '#')
    fail_at(name, s, pos,
            std::string("unexpected ") + detail::quoted(s.substr(pos, 1)) + " in the " + what +
                "; expected whitespace after it");
  // Caps are far below 2^64, and 19 digits cannot overflow; longer numbers are out of range.
  const auto digits = s.substr(start, pos - start);
  const auto value = digits.size() > 19 ? std::nullopt : detail::parse_whole(digits, max);
  if (!value)
    fail_at(name, s, start,
            std::string("the ") + what + " " + detail::quoted(digits) + " is over " +
                std::to_string(max) + "; expected at most that");
  return *value;
}

} // namespace

PgmImage parse_pgm(std::string_view s, const std::string& name) {
  if (s.size() < 2 || s[0] != 'P' || (s[1] != '5' && s[1] != '2')) {
    std::string what = "not a PGM image (it starts " + detail::quoted(s.substr(0, 8)) + ")";
    if (s.size() >= 2 && s[0] == 'P' && (s[1] == '3' || s[1] == '6'))
      what = "a colour PPM image (P3/P6) is not supported";
    else if (s.size() >= 4 && s.substr(1, 3) == "PNG")
      what = "a PNG image is not supported";
    fail_at(name, s, 0, what + "; expected a PGM image, magic P5 (binary) or P2 (plain)");
  }
  const bool binary = s[1] == '5';
  std::size_t pos = 2;
  if (pos < s.size() && !is_pgm_space(s[pos]) && s[pos] != '#')
    fail_at(name, s, pos, "expected whitespace after the magic number");

  // Parse sides with a cap above kMaxGridSide so that "too large" says which cap it broke.
  const auto side_cap = std::uint64_t{1} << 40;
  const auto width_at = pos;
  const auto width = pgm_number(s, pos, side_cap, name, "width");
  const auto height = pgm_number(s, pos, side_cap, name, "height");
  const auto problem = detail::size_problem(width, height);
  if (!problem.empty()) {
    auto p = width_at;
    skip_space_and_comments(s, p);
    fail_at(name, s, p, problem);
  }
  const auto maxval_at = pos;
  const auto maxval = pgm_number(s, pos, 65535, name, "maxval");
  if (maxval == 0) {
    auto p = maxval_at;
    skip_space_and_comments(s, p);
    fail_at(name, s, p, "maxval 0; expected 1 to 65535");
  }

  PgmImage img;
  img.width = static_cast<std::int32_t>(width);
  img.height = static_cast<std::int32_t>(height);
  img.maxval = static_cast<std::uint16_t>(maxval);
  const auto count = static_cast<std::size_t>(width * height);

  if (binary) {
    // Exactly one whitespace byte separates maxval from the samples (a comment there would make
    // the first sample ambiguous).
    if (pos >= s.size() || !is_pgm_space(s[pos]))
      fail_at(name, s, pos, "expected a single whitespace byte after maxval, then the samples");
    ++pos;
    const std::size_t bytes_per_sample = maxval < 256 ? 1 : 2;
    const auto need = count * bytes_per_sample;
    const auto have = s.size() - pos;
    if (have < need)
      fail_at(name, s, s.size(),
              "truncated PGM: " + std::to_string(have) + " bytes of image data; expected " +
                  std::to_string(width) + " x " + std::to_string(height) + " x " +
                  std::to_string(bytes_per_sample) + " = " + std::to_string(need));
    if (have > need)
      fail_at(name, s, pos + need,
              std::to_string(have - need) + " bytes after the " + std::to_string(width) + " x " +
                  std::to_string(height) + " image data; expected the file to end");
    img.pixels.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
      const auto at = pos + i * bytes_per_sample;
      std::uint16_t v = static_cast<unsigned char>(s[at]);
      if (bytes_per_sample == 2)
        v = static_cast<std::uint16_t>((v << 8) | static_cast<unsigned char>(s[at + 1]));
      if (v > maxval)
        fail_at(name, s, at,
                "sample " + std::to_string(v) + " of pixel (" + std::to_string(i % width) + ", " +
                    std::to_string(i / width) + ") is over maxval " + std::to_string(maxval));
      img.pixels[i] = v;
    }
    return img;
  }

  // P2: the samples are decimal numbers; reserve no more than the bytes left could hold (two
  // bytes per sample at least), since the header's size is not trusted.
  img.pixels.reserve(std::min(count, (s.size() - pos) / 2 + 1));
  for (std::size_t i = 0; i < count; ++i) {
    skip_space_and_comments(s, pos);
    if (pos >= s.size())
      fail_at(name, s, pos,
              "truncated PGM: " + std::to_string(i) + " samples; expected " +
                  std::to_string(width) + " x " + std::to_string(height) + " = " +
                  std::to_string(count));
    const auto at = pos;
    img.pixels.push_back(static_cast<std::uint16_t>(pgm_number(s, pos, 65535, name, "sample")));
    if (img.pixels.back() > maxval)
      fail_at(name, s, at,
              "sample " + std::to_string(img.pixels.back()) + " is over maxval " +
                  std::to_string(maxval));
  }
  skip_space_and_comments(s, pos);
  if (pos < s.size())
    fail_at(name, s, pos,
            "unexpected " + detail::quoted(s.substr(pos, 8)) + " after the " +
                std::to_string(count) + " samples; expected the file to end");
  return img;
}

kernel::Occupancy classify_trinary(std::uint16_t value, std::uint16_t maxval,
                                   const RosMapYaml& yaml) {
  // ROS 1 image_loader.cpp: with negate the grey value is first flipped (255 - v), then
  // occ = (255 - v) / 255.0 for both; the same numbers as below for maxval 255.
  const double top = maxval;
  const double p =
      yaml.negate ? static_cast<double>(value) / top : static_cast<double>(maxval - value) / top;
  if (p > yaml.occupied_thresh) return kernel::Occupancy::Blocked;
  if (p < yaml.free_thresh) return kernel::Occupancy::Free;
  return kernel::Occupancy::Unknown;
}

GridMap ros_map(const RosMapYaml& yaml, const PgmImage& image, const std::string& yaml_name) {
  if (yaml.mode != RosMode::Trinary)
    throw kernel::InputError(
        yaml_name, yaml.mode_line, yaml.mode_column,
        std::string("mode ") + (yaml.mode == RosMode::Scale ? "scale" : "raw") +
            " is not supported: its occupancy values 0..100 do not fit a free/blocked/unknown "
            "grid; expected mode trinary (or no mode)");
  if (image.pixels.size() !=
      static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
    throw std::invalid_argument("ros_map: the image's pixel count is not width x height");
  GridMap map;
  map.cells = kernel::OccupancyGrid(image.width, image.height);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    map.cells.cells()[i] = classify_trinary(image.pixels[i], image.maxval, yaml);
  map.resolution = yaml.resolution;
  map.origin_x = yaml.origin_x;
  map.origin_y = yaml.origin_y;
  map.origin_yaw = yaml.origin_yaw;
  return map;
}

GridMap load_ros_map(const std::filesystem::path& yaml_path) {
  const auto yaml_name = yaml_path.string();
  const auto yaml = parse_ros_yaml(read_map_file(yaml_path), yaml_name);
  // mode is checked before the image is read: an unsupported mode is the clearer message.
  if (yaml.mode != RosMode::Trinary) ros_map(yaml, PgmImage{}, yaml_name);
  std::filesystem::path image = yaml.image;
  if (image.is_relative()) image = yaml_path.parent_path() / image;
  std::string bytes;
  try {
    bytes = read_map_file(image);
  } catch (const kernel::InputError& e) {
    throw kernel::InputError(yaml_name, yaml.image_line, yaml.image_column,
                             "cannot read the image " + detail::quoted(yaml.image) + " (" +
                                 e.what() +
                                 "); expected a PGM file, relative to the yaml's directory");
  }
  return ros_map(yaml, parse_pgm(bytes, image.string()), yaml_name);
}

} // namespace antkit::maps
