// Fuzz target: the marker-floor robot's whole reading of a frame (devices/stc_floor/view.hpp) on
// arbitrary frames and dark frames, at every quadrant and heading, and the turn measurement on
// arbitrary unwarped images: no crash, no undefined behaviour; an observation has only its bits
// (4 free neighbours, 12 edges a cell, no edges for a neighbour that is not free); a measured turn
// is within half a turn. A small camera (48 x 48, 8 pixels to a sub-cell) keeps each run short.
#include "fuzz_bytes.hpp"

#include <antkit/devices/stc_floor/view.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace sf = antkit::devices::stc_floor;
  antkit::fuzzing::Bytes in(data, size);
  static const sf::Calibration c = [] {
    sf::Optics o;
    o.panorama_width = o.panorama_height = 48;
    o.lens_centre = {24 * sf::kOne, 24 * sf::kOne};
    o.pixels_per_radian = 20 * sf::kOne;
    return sf::ideal_calibration(o, 72, 8);
  }();
  static const sf::View view(c, sf::default_view(c));
  sf::Image frame(48, 48, 3), dark(48, 48, 3);
  // Sparse frames reach the dot finder's thresholds more often than uniform noise.
  const std::uint8_t mode = in.u8();
  for (auto& p : frame.pixels) p = (mode & 1) ? in.u8() : static_cast<std::uint8_t>(in.u8() & 0xE0);
  for (auto& p : dark.pixels) p = static_cast<std::uint8_t>(in.below(8));
  const int q = static_cast<int>(in.below(4)), h = static_cast<int>(in.below(4));
  const sf::Seen seen = view.see(frame, dark, q, h);
  ANTKIT_FUZZ_REQUIRE((seen.edges.free_neighbours & ~0xF) == 0);
  ANTKIT_FUZZ_REQUIRE((seen.edges.here & ~0xFFF) == 0);
  for (std::size_t d = 0; d < 4; ++d) {
    ANTKIT_FUZZ_REQUIRE((seen.edges.neighbour[d] & ~0xFFF) == 0);
    if (((seen.edges.free_neighbours >> d) & 1) == 0)
      ANTKIT_FUZZ_REQUIRE(seen.edges.neighbour[d] == 0);
  }
  ANTKIT_FUZZ_REQUIRE(seen.marks.width == 72 && seen.marks.height == 72);
  sf::Image other(72, 72, 1);
  for (auto& p : other.pixels) p = static_cast<std::uint8_t>(in.u8() & 0xF0);
  if (const auto turn = sf::measure_turn(seen.marks, other, (mode & 2) ? 1 : -1, view.params(), 8))
    ANTKIT_FUZZ_REQUIRE(*turn >= -(std::int64_t{1} << 31) && *turn < (std::int64_t{1} << 31));
  return 0;
}
