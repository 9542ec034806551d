// Fuzz target: named arena specs (geometry/src/arena_spec.cpp) and the family builders behind
// them. Bad input must be an InputError whose position lies inside the spec; an accepted spec must
// build a valid arena whose area is within the documented bound of its ideal area.
#include <antkit/geometry/arena.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace antkit::geometry;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const NamedArena named = build_arena_spec(text);
    const Arena& arena = named.arena;
    if (!(std::fabs(arena.area() - named.ideal_area) <= arena.perimeter() / 65536.0))
      __builtin_trap();
    if (arena.walls_fx().size() != arena.vertex_count()) __builtin_trap();
  } catch (const antkit::kernel::InputError& e) {
    if (e.line() != 1 || e.column() < 1 || e.column() > size + 1) __builtin_trap();
  }
  return 0;
}
