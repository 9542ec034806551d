// Fuzz target: the marker-floor robot's protocol (devices/stc_floor/link.hpp): arbitrary command
// lines into the firmware emulator, arbitrary reply lines and frame bytes into the pilot's
// decoders. No crash, no undefined behaviour; the emulator answers every line with one complete
// reply; a decoded frame header is consistent (N = 3 W H, sides 1..4096) and a decoded frame has
// exactly its header's bytes.
#include "fuzz_bytes.hpp"

#include <antkit/devices/stc_floor/link.hpp>
#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace sf = antkit::devices::stc_floor;
  static sf::FloorEmulator emulator = [] {
    antkit::kernel::OccupancyGrid map(8, 8, antkit::kernel::Occupancy::Free);
    map[{2, 2}] = antkit::kernel::Occupancy::Blocked;
    sf::FloorOptions f;
    f.optics.panorama_width = f.optics.panorama_height = 32;
    f.optics.lens_centre = {16 * sf::kOne, 16 * sf::kOne};
    f.optics.pixels_per_radian = 14 * sf::kOne;
    return sf::FloorEmulator(map, {0, 7}, 1, f);
  }();
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::size_t split = text.find('\n');
  const std::string line = text.substr(0, split);
  const auto r = emulator.handle(line);
  ANTKIT_FUZZ_REQUIRE(r.bytes.size() >= 3);
  const std::size_t eol = r.bytes.find("\r\n");
  ANTKIT_FUZZ_REQUIRE(eol != std::string::npos);
  if (r.bytes[0] == 'c') {
    const auto h = sf::decode_frame_header(r.bytes.substr(0, eol + 2));
    ANTKIT_FUZZ_REQUIRE(h);
    ANTKIT_FUZZ_REQUIRE(sf::decode_frame(*h.value, std::string_view(r.bytes).substr(eol + 2)));
  } else {
    ANTKIT_FUZZ_REQUIRE(eol + 2 == r.bytes.size());
  }
  // The rest of the input as a reply line and a frame's bytes.
  const std::string reply = split == std::string::npos ? line : text.substr(split + 1);
  (void)sf::decode_forward(reply);
  (void)sf::decode_ack(reply, 'r');
  if (const auto h = sf::decode_frame_header(reply.substr(0, reply.find('\n') + 1))) {
    ANTKIT_FUZZ_REQUIRE(h.value->width >= 1 && h.value->width <= 4096);
    ANTKIT_FUZZ_REQUIRE(h.value->height >= 1 && h.value->height <= 4096);
    ANTKIT_FUZZ_REQUIRE(std::int64_t{h.value->bytes} ==
                        3 * std::int64_t{h.value->width} * h.value->height);
    if (h.value->bytes <= 4096) {
      const auto img = sf::decode_frame(*h.value, reply.substr(reply.find('\n') + 1));
      if (img) ANTKIT_FUZZ_REQUIRE(img.value->pixels.size() == h.value->bytes);
    }
  }
  return 0;
}
