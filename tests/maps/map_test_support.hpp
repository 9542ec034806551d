#pragma once
// What the map tests share: catching the InputError an input must raise, and rapidcheck generators
// of small occupancy grids.
#include <antkit/kernel/grid.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/map_io.hpp>
#include <catch2/catch.hpp>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>
#include <string>
#include <vector>

namespace antkit::maps::test {

// The error a call raised: thrown == false when it returned normally.
struct Raised {
  bool thrown = false;
  std::string what;
  std::size_t line = 0;
  std::size_t column = 0;
};

template <class F>
Raised error_of(F&& f) {
  try {
    f();
  } catch (const kernel::InputError& e) {
    return {true, e.what(), e.line(), e.column()};
  }
  return {};
}

inline bool contains(const std::string& haystack, const std::string& needle) {
  return haystack.find(needle) != std::string::npos;
}

// A grid of the given side ranges whose cells are drawn from `values`.
inline rc::Gen<kernel::OccupancyGrid> gen_grid(std::vector<kernel::Occupancy> values,
                                               std::int32_t max_side = 12) {
  return rc::gen::mapcat(rc::gen::pair(rc::gen::inRange<std::int32_t>(1, max_side + 1),
                                       rc::gen::inRange<std::int32_t>(1, max_side + 1)),
                         [values](const std::pair<std::int32_t, std::int32_t>& size) {
                           const auto [w, h] = size;
                           return rc::gen::map(
                               rc::gen::container<std::vector<kernel::Occupancy>>(
                                   static_cast<std::size_t>(w) * static_cast<std::size_t>(h),
                                   rc::gen::elementOf(values)),
                               [w = w, h = h](std::vector<kernel::Occupancy> cells) {
                                 kernel::OccupancyGrid g(w, h);
                                 g.cells() = std::move(cells);
                                 return g;
                               });
                         });
}

inline rc::Gen<kernel::OccupancyGrid> gen_two_valued_grid(std::int32_t max_side = 12) {
  return gen_grid({kernel::Occupancy::Free, kernel::Occupancy::Blocked}, max_side);
}
inline rc::Gen<kernel::OccupancyGrid> gen_three_valued_grid(std::int32_t max_side = 12) {
  return gen_grid({kernel::Occupancy::Free, kernel::Occupancy::Blocked, kernel::Occupancy::Unknown},
                  max_side);
}

} // namespace antkit::maps::test
