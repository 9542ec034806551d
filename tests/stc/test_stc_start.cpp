// The start of an STC run when the caller does not give one (stc/start.hpp): the given sub-cell,
// else the map's own, else default_start; and the refusal of a map with no place, naming the map.
#include "stc_test_maps.hpp"

#include <antkit/kernel/input_error.hpp>
#include <antkit/stc/start.hpp>
#include <catch2/catch.hpp>
#include <optional>
#include <string>

using antkit::kernel::Cell;
using namespace antkit::stc;
using antkit::stc::testing::from_rows;

TEST_CASE("choose_start: the given start, else the map's, else the largest region's first place",
          "[stc]") {
  // A one-cell island top left, a 2 x 2-cell region bottom right (sub-cells x 4..7, y 4..7).
  const auto map = from_rows({"..######", //
                              "..######", //
                              "########", //
                              "########", //
                              "####....", //
                              "####....", //
                              "####....", //
                              "####...."});
  for (const Variant v : kVariants) {
    INFO(variant_name(v));
    CHECK(choose_start(map, v, Cell{1, 1}, Cell{0, 0}, "map") == Cell{1, 1});
    CHECK(choose_start(map, v, std::nullopt, Cell{0, 1}, "map") == Cell{0, 1});
    const auto fallback = choose_start(map, v, std::nullopt, std::nullopt, "map");
    CHECK(fallback == default_start(map, v));
    CHECK(fallback == Cell{4, 4}); // not the island: the largest region
  }
  // The given start is not checked here (run_stc refuses one in an obstacle).
  CHECK(choose_start(map, Variant::Ant, Cell{3, 0}, std::nullopt, "map") == Cell{3, 0});
}

TEST_CASE("choose_start: a map with no place to start is refused, naming the map", "[stc]") {
  const auto blocked = from_rows({"####", "####"});
  // Free sub-cells but no free cell of 2 x 2: full can start, the exact variants cannot.
  const auto thin = from_rows({".#.#", "#.#."});
  const auto message = [](const antkit::kernel::OccupancyGrid& map, Variant v) {
    try {
      (void)choose_start(map, v, std::nullopt, std::nullopt, "maps/x.map");
    } catch (const antkit::kernel::InputError& e) {
      CHECK(e.where() == "maps/x.map");
      return e.message();
    }
    return std::string("(no error)");
  };
  for (const Variant v : kVariants) {
    INFO(variant_name(v));
    CHECK(message(blocked, v) == (is_exact(v) ? "the map has no free cell (2 x 2 free sub-cells) "
                                                "to start in"
                                              : "the map has no free sub-cell to start in"));
    if (is_exact(v))
      CHECK(message(thin, v) == "the map has no free cell (2 x 2 free sub-cells) to start in");
  }
  CHECK(choose_start(thin, Variant::Full, std::nullopt, std::nullopt, "maps/x.map") == Cell{0, 0});
  // A given start or the map's own needs no free place.
  CHECK(choose_start(blocked, Variant::Ant, std::nullopt, Cell{0, 0}, "m") == Cell{0, 0});
}
