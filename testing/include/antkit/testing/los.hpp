#pragma once
// Rich checkers for the LOS family (issue 5): each returns an empty string when the rule holds, or
// a sentence that says which rule broke and where.
#include <antkit/frontier/frontier_map.hpp>
#include <antkit/kernel/grid.hpp>
#include <antkit/los/cell_state.hpp>
#include <antkit/los/explore.hpp>
#include <string>

namespace antkit::testing {

// Soundness: S, LOS and S+LOS cells are free in the true map; O cells are blocked (or unknown,
// which the model treats as an obstacle).
std::string check_sound(const kernel::OccupancyGrid& truth,
                        const kernel::Grid<los::CellState>& states);

// States only move up (cell_state.hpp's partial order), and NLOS is only ever given to F cells.
std::string check_monotone(const kernel::Grid<los::CellState>& before,
                           const kernel::Grid<los::CellState>& after);

// The incremental frontier set equals the definition on every cell, and its list has each
// frontier cell once.
std::string check_frontier_set(const frontier::FrontierMap& map);

// A finished run: every observable cell explored, nothing unobservable explored.
std::string check_complete(const kernel::OccupancyGrid& truth, const los::ExploreResult& result);

// Runs `options` from the start pair with every per-tick check above (soundness, monotone,
// frontier set, robots on distinct free cells, moves to neighbours) and the completion check.
std::string check_run(const kernel::OccupancyGrid& truth, kernel::Cell a, kernel::Cell b,
                      const los::ExploreOptions& options, los::ExploreResult* out = nullptr);

} // namespace antkit::testing
