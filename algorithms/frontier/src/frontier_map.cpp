#include <antkit/frontier/frontier_map.hpp>

namespace antkit::frontier {

using kernel::Cell;

FrontierMap::FrontierMap(std::int32_t width, std::int32_t height)
    : knowledge_(width, height, Knowledge::Unexplored), slot_(width, height, -1) {}

bool FrontierMap::frontier_by_definition(Cell c) const noexcept {
  if (!is_free(c)) return false;
  for (const Cell d : kernel::kNeighbours8)
    if (is_unexplored(c + d)) return true;
  return false;
}

void FrontierMap::set(Cell c, Knowledge k) {
  if (knowledge_[c] == k) return;
  knowledge_[c] = k;
  reevaluate(c);
  for (const Cell d : kernel::kNeighbours8)
    if (knowledge_.in_bounds(c + d)) reevaluate(c + d);
}

void FrontierMap::reevaluate(Cell c) {
  const bool now = frontier_by_definition(c);
  std::int32_t& slot = slot_[c];
  if (now && slot < 0) {
    slot = static_cast<std::int32_t>(list_.size());
    list_.push_back(c);
  } else if (!now && slot >= 0) {
    // Swap-removal: the last cell takes the freed place.
    const Cell last = list_.back();
    list_[static_cast<std::size_t>(slot)] = last;
    slot_[last] = slot;
    list_.pop_back();
    slot = -1;
  }
}

} // namespace antkit::frontier
