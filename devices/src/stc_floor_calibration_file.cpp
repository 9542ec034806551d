// The marker-floor robot's calibration file (stc_floor/optics.hpp). Apart from the optics so that
// the determinism matrix builds the optics without a JSON library.
#include <antkit/devices/stc_floor/optics.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

namespace antkit::devices::stc_floor {

namespace {

std::string q16_text(std::int64_t v) {
  std::string s = v < 0 ? "-" : "";
  const std::uint64_t a = v < 0 ? static_cast<std::uint64_t>(-v) : static_cast<std::uint64_t>(v);
  s += std::to_string(a >> 16);
  std::uint64_t frac = a & 0xFFFF;
  if (frac != 0) {
    s += '.';
    while (frac != 0) { // exact: k / 2^16 has at most 16 decimals
      frac *= 10;
      s += static_cast<char>('0' + (frac >> 16));
      frac &= 0xFFFF;
    }
  }
  return s;
}

} // namespace

std::string calibration_json(const Calibration& c) {
  auto pair = [](PointQ16 p) { return "[" + q16_text(p.x) + "," + q16_text(p.y) + "]"; };
  std::string s = "{\"schema\":1,\"kind\":\"antkit stc-floor calibration\",\n";
  s += " \"panorama\":{\"width\":" + std::to_string(c.optics.panorama_width) +
       ",\"height\":" + std::to_string(c.optics.panorama_height) + "},\n";
  s += " \"lens_centre\":" + pair(c.optics.lens_centre) + ",\n";
  s += " \"mirror\":{\"height\":" + q16_text(c.optics.mirror_height) +
       ",\"pixels_per_radian\":" + q16_text(c.optics.pixels_per_radian) + "},\n";
  s += " \"unwarped\":{\"size\":" + std::to_string(c.unwarped_size) +
       ",\"pixels_per_subcell\":" + std::to_string(c.pixels_per_subcell) + "},\n";
  s += " \"corners\":[";
  for (std::size_t i = 0; i < 12; ++i) s += (i ? "," : "") + pair(c.corners[i]);
  s += "]}\n";
  return s;
}

Calibration parse_calibration(const std::string& name, const std::string& text) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // The byte offset to a line and column.
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) {
      if (text[i] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    throw kernel::InputError(name, line, column, "not JSON: " + std::string(e.what()));
  } catch (const nlohmann::json::exception& e) { // a number out of range, for one
    throw kernel::InputError(name, "not readable JSON: " + std::string(e.what()));
  }
  auto fail = [&](const std::string& at, const std::string& m) {
    throw kernel::InputError(name + ": " + at, m);
  };
  auto object = [&](const nlohmann::json& v, const std::string& at,
                    const std::set<std::string>& keys) {
    if (!v.is_object()) fail(at, "expected an object");
    for (const auto& [k, _] : v.items())
      if (!keys.count(k)) fail(at, "unknown key '" + k + "'");
    for (const auto& k : keys)
      if (!v.contains(k)) fail(at, "missing key '" + k + "'");
  };
  auto integer = [&](const nlohmann::json& v, const std::string& at) -> std::int32_t {
    if (!v.is_number_integer() || v.get<std::int64_t>() < 0 || v.get<std::int64_t>() > 1 << 20)
      fail(at, "expected a whole number from 0 to 2^20");
    return static_cast<std::int32_t>(v.get<std::int64_t>());
  };
  auto decimal = [&](const nlohmann::json& v, const std::string& at) -> std::int64_t {
    if (!v.is_number()) fail(at, "expected a number");
    const double d = v.get<double>();
    if (!(d >= -1e6 && d <= 1e6)) fail(at, "expected a number from -10^6 to 10^6");
    return static_cast<std::int64_t>(std::llround(d * 65536.0));
  };
  auto point = [&](const nlohmann::json& v, const std::string& at) -> PointQ16 {
    if (!v.is_array() || v.size() != 2) fail(at, "expected [x, y]");
    return {decimal(v[0], at + "[0]"), decimal(v[1], at + "[1]")};
  };
  object(j, "the top level",
         {"schema", "kind", "panorama", "lens_centre", "mirror", "unwarped", "corners"});
  if (j["schema"] != 1) fail("schema", "expected 1 (this build reads schema 1)");
  if (j["kind"] != "antkit stc-floor calibration")
    fail("kind", "expected \"antkit stc-floor calibration\"");
  Calibration c;
  object(j["panorama"], "panorama", {"width", "height"});
  c.optics.panorama_width = integer(j["panorama"]["width"], "panorama.width");
  c.optics.panorama_height = integer(j["panorama"]["height"], "panorama.height");
  c.optics.lens_centre = point(j["lens_centre"], "lens_centre");
  object(j["mirror"], "mirror", {"height", "pixels_per_radian"});
  c.optics.mirror_height = decimal(j["mirror"]["height"], "mirror.height");
  c.optics.pixels_per_radian =
      decimal(j["mirror"]["pixels_per_radian"], "mirror.pixels_per_radian");
  object(j["unwarped"], "unwarped", {"size", "pixels_per_subcell"});
  c.unwarped_size = integer(j["unwarped"]["size"], "unwarped.size");
  c.pixels_per_subcell =
      integer(j["unwarped"]["pixels_per_subcell"], "unwarped.pixels_per_subcell");
  if (!j["corners"].is_array() || j["corners"].size() != 12)
    fail("corners", "expected the 12 corners of the 5 cells, in the order of optics.hpp");
  for (std::size_t i = 0; i < 12; ++i)
    c.corners[i] = point(j["corners"][i], "corners[" + std::to_string(i) + "]");
  validate(c, name);
  return c;
}

Calibration read_calibration(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw kernel::InputError(path, "cannot read the calibration file");
  std::ostringstream s;
  s << in.rdbuf();
  return parse_calibration(path, s.str());
}

} // namespace antkit::devices::stc_floor
