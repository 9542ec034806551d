// The start of an STC run (start.hpp).
#include <antkit/kernel/input_error.hpp>
#include <antkit/stc/start.hpp>

namespace antkit::stc {

SubCell choose_start(const kernel::OccupancyGrid& map, Variant variant,
                     std::optional<SubCell> given, std::optional<SubCell> map_start,
                     const std::string& where) {
  if (given) return *given;
  if (map_start) return *map_start;
  if (const auto start = default_start(map, variant)) return *start;
  throw kernel::InputError(where, is_exact(variant) ? "the map has no free cell (2 x 2 free "
                                                      "sub-cells) to start in"
                                                    : "the map has no free sub-cell to start in");
}

} // namespace antkit::stc
