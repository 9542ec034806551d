// Fuzz target: the marker-floor camera pipeline (devices/stc_floor/camera.hpp) on arbitrary
// frames: no crash, no undefined behaviour, and the stages' own promises (sizes, marks inside the
// image and brightest first, headings within half a turn, a calibrated time within its bound).
#include "fuzz_bytes.hpp"

#include <antkit/devices/stc_floor/camera.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace sf = antkit::devices::stc_floor;
  antkit::fuzzing::Bytes in(data, size);
  const auto w = static_cast<std::int32_t>(1 + in.below(64));
  const auto h = static_cast<std::int32_t>(1 + in.below(48));
  const auto threshold = in.u8();
  const auto window = static_cast<std::int32_t>(1 + in.below(6));
  const auto min_sum = in.u16();
  sf::Image frame(w, h, 3), dark(w, h, 3);
  for (auto& p : frame.pixels) p = in.u8();
  for (auto& p : dark.pixels) p = static_cast<std::uint8_t>(in.below(16));
  const auto clean = sf::subtract_dark(frame, dark);
  ANTKIT_FUZZ_REQUIRE(clean.valid() && clean.pixels.size() == frame.pixels.size());
  const auto c = sf::split_channels(clean, threshold);
  ANTKIT_FUZZ_REQUIRE(c.marks.valid() && c.obstacles.valid());
  std::vector<sf::Mark> marks;
  try {
    marks = sf::find_marks(c.marks, window, min_sum, 8);
  } catch (const antkit::kernel::InputError&) {
    ANTKIT_FUZZ_REQUIRE(window > w || window > h);
    return 0;
  }
  for (std::size_t k = 0; k < marks.size(); ++k) {
    ANTKIT_FUZZ_REQUIRE(marks[k].x >= 0 && marks[k].x + window <= w);
    ANTKIT_FUZZ_REQUIRE(marks[k].y >= 0 && marks[k].y + window <= h);
    ANTKIT_FUZZ_REQUIRE(marks[k].sum >= min_sum);
    ANTKIT_FUZZ_REQUIRE(k == 0 || marks[k].sum <= marks[k - 1].sum);
  }
  if (const auto heading = sf::line_heading(marks, window))
    ANTKIT_FUZZ_REQUIRE(heading->raw() < antkit::kernel::Angle::kHalfTurn);
  const std::int64_t t = 1 + in.u16();
  const std::int64_t turned = static_cast<std::int64_t>(in.u32());
  const std::int64_t next = sf::calibrate_rotation(t, turned, 250000);
  ANTKIT_FUZZ_REQUIRE(next * 5 >= t * 4 - 5 && next * 4 <= t * 5 + 4);
  return 0;
}
