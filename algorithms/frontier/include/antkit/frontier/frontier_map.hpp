#pragma once
// The shared map of a frontier-based exploration and its frontier cells, kept incrementally.
//
// A frontier cell (paper 001, Section I, after Yamauchi) is a free cell that has at least one
// unexplored neighbour. Cells outside the grid are not unexplored: the robots "deal with
// environment edges as occupied cells" (paper 001, assumption 8), so the grid's edge never makes a
// frontier.
//
// The set is maintained incrementally: set() re-evaluates only the changed cell and its eight
// neighbours, so no step ever scans the whole map. The list of frontier cells is kept in a vector
// with swap-removal; its order depends only on the sequence of set() calls, never on hashing or
// pointer values, so iterating it is deterministic.
//
// This component is shared: the LOS family (antkit::los) maps its six cell states onto the three
// kinds of knowledge below; any other family (uniform coverage) can do the same with its own.
#include <antkit/kernel/grid.hpp>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace antkit::frontier {

// What the team knows of a cell.
enum class Knowledge : std::uint8_t { Unexplored = 0, Free = 1, Occupied = 2 };

class FrontierMap {
public:
  FrontierMap() = default;
  // Every cell starts Unexplored.
  FrontierMap(std::int32_t width, std::int32_t height);

  [[nodiscard]] std::int32_t width() const noexcept { return knowledge_.width(); }
  [[nodiscard]] std::int32_t height() const noexcept { return knowledge_.height(); }
  [[nodiscard]] bool in_bounds(kernel::Cell c) const noexcept { return knowledge_.in_bounds(c); }

  // Unchecked: the caller guarantees in_bounds(c).
  [[nodiscard]] Knowledge at(kernel::Cell c) const noexcept { return knowledge_[c]; }
  [[nodiscard]] bool is_free(kernel::Cell c) const noexcept {
    return knowledge_.in_bounds(c) && knowledge_[c] == Knowledge::Free;
  }
  [[nodiscard]] bool is_unexplored(kernel::Cell c) const noexcept {
    return knowledge_.in_bounds(c) && knowledge_[c] == Knowledge::Unexplored;
  }

  // Records what is known of c (in bounds) and re-evaluates the frontier membership of c and of
  // its eight neighbours: O(1).
  void set(kernel::Cell c, Knowledge k);

  [[nodiscard]] bool is_frontier(kernel::Cell c) const noexcept {
    return slot_.in_bounds(c) && slot_[c] >= 0;
  }
  // By row-major index (unchecked), for searches that walk the grid by index.
  [[nodiscard]] bool is_frontier_at(std::size_t index) const noexcept {
    return slot_.cells()[index] >= 0;
  }
  [[nodiscard]] std::size_t frontier_count() const noexcept { return list_.size(); }
  // The frontier cells, in an order fixed by the history of set() calls.
  [[nodiscard]] const std::vector<kernel::Cell>& frontiers() const noexcept { return list_; }
  [[nodiscard]] const kernel::Grid<Knowledge>& knowledge() const noexcept { return knowledge_; }

  // The definition, evaluated from scratch (for checks and tests): free with an unexplored
  // neighbour.
  [[nodiscard]] bool frontier_by_definition(kernel::Cell c) const noexcept;

private:
  void reevaluate(kernel::Cell c);

  kernel::Grid<Knowledge> knowledge_;
  kernel::Grid<std::int32_t> slot_; // index into list_, or -1 when c is not a frontier
  std::vector<kernel::Cell> list_;
};

} // namespace antkit::frontier
