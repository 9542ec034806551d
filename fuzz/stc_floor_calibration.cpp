// Fuzz target: the marker-floor robot's calibration file (devices/stc_floor/optics.hpp) and the
// command line's decimals: arbitrary text is read or refused with kernel::InputError, never a
// crash; a calibration that is read is valid, builds its unwarp, and writes back to itself.
#include <antkit/devices/stc_floor/optics.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace sf = antkit::devices::stc_floor;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)sf::parse_point("--corner", text);
  } catch (const antkit::kernel::InputError&) {
  }
  sf::Calibration c;
  try {
    c = sf::parse_calibration("fuzz.json", text);
  } catch (const antkit::kernel::InputError&) {
    return 0;
  }
  // Small enough to build: the unwarp's table is size^2 entries.
  if (c.unwarped_size <= 512) (void)sf::Unwarp(c);
  if (!(sf::parse_calibration("again.json", sf::calibration_json(c)) == c)) {
    std::fprintf(stderr, "a calibration did not write back to itself\n");
    std::abort();
  }
  return 0;
}
