#pragma once
// Where an STC run starts when the caller does not say (`antkit stc`, `stc-noise`,
// `dev stc-mcu-input` and the Python package): the rule, and its refusal when a map has no place.
#include <antkit/kernel/grid.hpp>
#include <antkit/stc/subcell.hpp>
#include <antkit/stc/world.hpp>
#include <optional>
#include <string>

namespace antkit::stc {

// The start: `given` if any (a sub-cell the caller names), else `map_start` (the map's own start,
// such as 'S' in an ASCII map), else default_start(map, variant) (the largest region's first
// place). Throws kernel::InputError(where, ...) when there is none of the three: "the map has no
// free cell (2 x 2 free sub-cells) to start in" for the exact variants, "the map has no free
// sub-cell to start in" for full; `where` names the map (its file, on the command line). The
// start is not checked against the map here: run_stc refuses one in an obstacle.
[[nodiscard]] SubCell choose_start(const kernel::OccupancyGrid& map, Variant variant,
                                   std::optional<SubCell> given, std::optional<SubCell> map_start,
                                   const std::string& where);

} // namespace antkit::stc
