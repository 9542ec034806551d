#pragma once
// The options shared by `antkit buffon`, `antkit buffon-experiment` and the plumbing twins
// `antkit dev buffon-mcu-input` and `antkit dev rs-mcu-input`: one range check, one message each,
// so the commands reject the same values the same way (exit 2), and one reading of the arena and
// the body.
#include <antkit/buffon/world.hpp>
#include <antkit/commands/options.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/geometry/fixed_convert.hpp>
#include <antkit/geometry/wkt.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cstdint>
#include <string>

namespace antkit::cli {

inline void check_buffon_run_size(std::int64_t trials, std::int64_t steps, std::int64_t threads) {
  using antkit::kernel::InputError;
  if (trials < 1 || trials > 100000)
    throw InputError("--trials", "the number of trials must be in [1, 100000]");
  if (steps < 1 || steps > 10000000)
    throw InputError("--steps", "the steps per visit must be in [1, 10000000]");
  if (threads < 1 || threads > 256)
    throw InputError("--threads", "the number of threads must be in [1, 256]");
}

// The IR noise of `antkit buffon` and its plumbing twins.
inline void check_buffon_noise(double noise) {
  if (!(noise >= 0 && noise <= 1))
    throw kernel::InputError("--noise", "the sensor noise must be in [0, 1]");
}

// The trail width and the IR noise of `antkit buffon` and `antkit dev buffon-mcu-input`.
inline void check_buffon_body(double width, double noise) {
  if (!(width >= 0.01 && width <= 10))
    throw kernel::InputError("--width", "the trail width must be in [0.01, 10] units");
  check_buffon_noise(noise);
}

// --arena: a WKT file or a named spec, read as `antkit buffon` reads it.
inline geometry::Arena read_buffon_arena(const std::string& spec) {
  return commands::is_wkt_path(spec) ? geometry::read_wkt_file(spec)
                                     : geometry::build_arena_spec(spec, "--arena").arena;
}

// The world of one run: the arena's walls in Q15.16 and a body whose IR noise is --noise (checked
// above). The World refuses walls it cannot hold, as `antkit buffon` refuses them.
inline buffon::World buffon_world(const geometry::Arena& arena, double noise) {
  buffon::BodyParams body;
  body.noise = geometry::fixed_from_double<kernel::Fx>(noise, "--noise");
  return buffon::World(arena.walls_fx(), body);
}

} // namespace antkit::cli
