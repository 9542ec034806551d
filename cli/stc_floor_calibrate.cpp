// `antkit stc-floor-calibrate`: writes the marker-floor robot's calibration file (issue 14; paper
// 002, "Initial Calibration") from the points the user clicked.
//   antkit stc-floor-calibrate (--ideal | --centre X,Y --corner X,Y [x12]) [--panorama WxH]
//                              [--mirror-height H] [--pixels-per-radian K] [--unwarped-size S]
//                              [--pixels-per-subcell P] --out F.json [--format table|json]
// --centre: the lens centre clicked on the panorama; --corner, twelve times: the corners of the 5
// cells clicked on the unwarped image, in the order of devices/stc_floor/optics.hpp (pixels,
// decimals allowed). --ideal: the corners of a perfectly built robot (the emulator's). The file is
// written whole or not at all.
#include "commands.hpp"
#include "output.hpp"

#include <antkit/devices/stc_floor/optics.hpp>
#include <antkit/io/atomic_file.hpp>
#include <antkit/kernel/input_error.hpp>
#include <iostream>
#include <memory>

namespace {

namespace sf = antkit::devices::stc_floor;
using antkit::cli::Format;
using antkit::kernel::InputError;

struct CalibrateOptions {
  bool ideal = false;
  std::string centre, panorama = "240x240", mirror_height = "3", pixels_per_radian = "100", out;
  std::vector<std::string> corners;
  std::int32_t unwarped_size = 216, pixels_per_subcell = 24;
  Format format = Format::Table;
};

void run(const CalibrateOptions& o) {
  sf::Optics optics;
  const auto x = o.panorama.find('x');
  try {
    if (x == std::string::npos) throw std::invalid_argument("no x");
    std::size_t used = 0;
    optics.panorama_width = std::stoi(o.panorama.substr(0, x), &used);
    if (used != x) throw std::invalid_argument("width");
    optics.panorama_height = std::stoi(o.panorama.substr(x + 1), &used);
    if (used != o.panorama.size() - x - 1) throw std::invalid_argument("height");
  } catch (const std::exception&) {
    throw InputError("--panorama", "'" + o.panorama + "': expected WxH, e.g. 240x240");
  }
  optics.lens_centre = {optics.panorama_width * sf::kOne / 2,
                        optics.panorama_height * sf::kOne / 2};
  optics.mirror_height = sf::parse_q16("--mirror-height", o.mirror_height);
  optics.pixels_per_radian = sf::parse_q16("--pixels-per-radian", o.pixels_per_radian);
  sf::Calibration c;
  if (o.ideal) {
    if (!o.centre.empty() || !o.corners.empty())
      throw InputError("--ideal", "takes no clicked points (--centre, --corner)");
    c = sf::ideal_calibration(optics, o.unwarped_size, o.pixels_per_subcell);
    sf::validate(c, "calibration");
  } else {
    if (o.centre.empty())
      throw InputError("--centre", "the lens centre X,Y is needed (or --ideal)");
    const sf::PointQ16 centre = sf::parse_point("--centre", o.centre);
    if (o.corners.size() != 12)
      throw InputError("--corner", "expected the 12 corners of the 5 cells, got " +
                                       std::to_string(o.corners.size()));
    std::array<sf::PointQ16, 12> corners;
    for (std::size_t i = 0; i < 12; ++i)
      corners[i] = sf::parse_point("--corner " + std::to_string(i + 1), o.corners[i]);
    c = sf::clicked_calibration(optics, centre, o.unwarped_size, o.pixels_per_subcell, corners);
  }
  antkit::io::write_file_atomic(o.out, sf::calibration_json(c));
  nlohmann::json j;
  j["out"] = o.out;
  j["panorama"] = {optics.panorama_width, optics.panorama_height};
  j["lens_centre"] = {static_cast<double>(c.optics.lens_centre.x) / 65536.0,
                      static_cast<double>(c.optics.lens_centre.y) / 65536.0};
  j["unwarped_size"] = c.unwarped_size;
  j["pixels_per_subcell"] = c.pixels_per_subcell;
  j["ideal"] = o.ideal;
  antkit::cli::emit(j, o.format, std::cout);
}

void register_calibrate(CLI::App& app) {
  auto o = std::make_shared<CalibrateOptions>();
  auto* sub = app.add_subcommand(
      "stc-floor-calibrate",
      "Write the marker-floor robot's camera calibration (JSON) from clicked points: the lens "
      "centre and the 12 corners of the 5 cells (paper 002, initial calibration)");
  sub->add_flag("--ideal", o->ideal, "The corners of a perfectly built robot (the emulator's)");
  sub->add_option("--centre", o->centre, "The lens centre on the panorama, X,Y in pixels");
  sub->add_option("--corner", o->corners,
                  "A corner on the unwarped image, X,Y; twelve, in the order of optics.hpp");
  sub->add_option("--panorama", o->panorama, "The panorama's size WxH (default 240x240)");
  sub->add_option("--mirror-height", o->mirror_height,
                  "The mirror's height over the floor in sub-cells (default 3)");
  sub->add_option("--pixels-per-radian", o->pixels_per_radian,
                  "The panorama's pixels per radian of view angle (default 100)");
  sub->add_option("--unwarped-size", o->unwarped_size, "The unwarped image's side (default 216)");
  sub->add_option("--pixels-per-subcell", o->pixels_per_subcell,
                  "Unwarped pixels to a sub-cell (default 24)");
  sub->add_option("--out", o->out, "The calibration file to write")->required();
  antkit::cli::add_format_option(*sub, o->format);
  sub->callback([o] { run(*o); });
}

const antkit::cli::Registration stc_floor_calibrate_registration{"stc-floor-calibrate",
                                                                 &register_calibrate};

} // namespace
