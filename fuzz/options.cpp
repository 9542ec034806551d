// Fuzz target: the small option parsers of the subcommands, one target for them all. The first
// byte picks the parser, the rest is the option's text:
//   --start X,Y (explore, stc: algorithms::parse_cell), a pair AxB (explore --size:
//   algorithms::parse_pair), a whole number (record --param: algorithms::parse_integer),
//   a probability (stc --noise, --levels: algorithms::parse_probability_ppm), --density and
//   --size WxH (cover: uniform::parse_density_ppm, parse_size), --precision (buffon:
//   buffon::parse_precision), --raster (arena: geometry::CellSize::parse), --baud and --framing
//   (record, emulate: devices::parse_baud, parse_framing), and the names of --variant, --algo and
//   --rule (buffon::parse_rule).
// Bad text must be a kernel::InputError naming the option (anything else escaping is a crash);
// an accepted value must be in its documented range and, where the format is canonical enough,
// survive printing and parsing again.
#include "fuzz_bytes.hpp"

#include <antkit/algorithms/options.hpp>
#include <antkit/buffon/stopping.hpp>
#include <antkit/devices/serial.hpp>
#include <antkit/geometry/arena_raster.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/stc/world.hpp>
#include <antkit/uniform/coverage.hpp>
#include <antkit/uniform/scenario.hpp>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace {

using namespace antkit;

std::string decimal_ppm(std::uint32_t ppm) {
  std::string frac = std::to_string(ppm % 1'000'000);
  frac.insert(0, 6 - frac.size(), '0');
  return std::to_string(ppm / 1'000'000) + "." + frac;
}

void parse(unsigned which, std::string_view text) {
  switch (which) {
  case 0: {
    const auto c = algorithms::parse_cell("--start", text);
    const auto again =
        algorithms::parse_cell("--start", std::to_string(c.x) + "," + std::to_string(c.y));
    ANTKIT_FUZZ_REQUIRE(again == c);
    break;
  }
  case 1: {
    const auto [a, b] = algorithms::parse_pair("--size", text, 'x', "WxH (two integers)");
    ANTKIT_FUZZ_REQUIRE(text.find('x') != std::string_view::npos);
    const auto again = algorithms::parse_pair("--size", std::to_string(a) + "x" + std::to_string(b),
                                              'x', "WxH (two integers)");
    ANTKIT_FUZZ_REQUIRE(again.first == a && again.second == b);
    break;
  }
  case 2: {
    const auto v = algorithms::parse_integer("--param", text, "a whole number");
    for (const char ch : text) ANTKIT_FUZZ_REQUIRE(ch == '-' || (ch >= '0' && ch <= '9'));
    ANTKIT_FUZZ_REQUIRE(algorithms::parse_integer("--param", std::to_string(v)) == v);
    break;
  }
  case 3: {
    const auto ppm = algorithms::parse_probability_ppm("--noise", text);
    ANTKIT_FUZZ_REQUIRE(ppm <= 1'000'000);
    ANTKIT_FUZZ_REQUIRE(algorithms::parse_probability_ppm("--noise", decimal_ppm(ppm)) == ppm);
    break;
  }
  case 4: {
    const auto ppm = uniform::parse_density_ppm(text);
    ANTKIT_FUZZ_REQUIRE(ppm <= 1'000'000);
    ANTKIT_FUZZ_REQUIRE(uniform::parse_density_ppm(decimal_ppm(ppm)) == ppm);
    break;
  }
  case 5: {
    const auto [w, h] = uniform::parse_size(text, 2048);
    ANTKIT_FUZZ_REQUIRE(1 <= w && w <= 2048 && 1 <= h && h <= 2048);
    break;
  }
  case 6: {
    const auto p = buffon::parse_precision(text);
    ANTKIT_FUZZ_REQUIRE(0 < p && p < 1'000'000);
    break;
  }
  case 12: {
    const auto rule = buffon::parse_rule(text);
    ANTKIT_FUZZ_REQUIRE(buffon::rule_name(rule) == text);
    break;
  }
  case 7: {
    const auto s = geometry::CellSize::parse(text, "--raster");
    ANTKIT_FUZZ_REQUIRE(s.num() > 0 && s.den() > 0);
    ANTKIT_FUZZ_REQUIRE(0.999e-6 <= s.value() && s.value() <= 1.001e6); // in [1e-6, 1e6]
    break;
  }
  case 8: {
    const auto baud = devices::parse_baud(text, "--baud");
    ANTKIT_FUZZ_REQUIRE(baud != 0);
    break;
  }
  case 9:
    (void)devices::parse_framing(text, 9600, "--framing");
    break;
  case 10:
    (void)stc::parse_variant(text);
    break;
  default:
    (void)uniform::parse_algorithm(text);
    break;
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    parse(data[0] % 13u, text);
  } catch (const kernel::InputError& e) {
    ANTKIT_FUZZ_REQUIRE(!e.where().empty() && !e.message().empty());
  }
  return 0;
}
