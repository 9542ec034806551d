#pragma once
// The cost of precision (issue 17; `antkit buffon-cost`): the median total trail length that
// Buffon with two markers, Buffon with the online first visit and the RS coverage baseline need to
// reach P = 0.2, 0.1 and 0.05, on circles and squares of 314 to 31 416 unit^2 and the other shapes
// of paper 000's Figure 3 at their standard area, with the fitted exponent of trail ~ area^e per
// method and P (over the circles and squares). The measurement itself (the trials, their streams,
// the medians and the fit) is algorithms/buffon/precision_cost.hpp's; this is the sweep around it
// and its files.
//
// The arenas: circles d = 20, 40, 80, 120, 200 and squares of the same areas rounded to a whole
// unit^2 ("square:area=314", ...), then ellipse:area=7854,e=0.968, barrier-i:len=0.4,
// barrier-plus:len=0.4, ring, plus and obstacles (family "figure 3 shape", drawn beside the fit,
// not in it). Quick: circles and squares of d = 20, 40 and 80 only, P = 0.2 and 0.1, 3 trials (for
// tests and a first look; the full run takes minutes).
//
// The files (write_buffon_cost): precision_cost.csv (one row per arena, P and method: arena,
// family, area, precision, method, trials, reached, median, q1, q3; an unreached quantile empty),
// precision_cost_fits.csv (method, precision, exponent, coefficient, points) and
// precision_cost.svg and .png (one panel per P, log-log, interquartile bars, a legend). Numbers
// with 10 significant digits (format.hpp's number).
#include <antkit/buffon/precision_cost.hpp>
#include <antkit/experiments/plot.hpp>
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace antkit::experiments {

struct BuffonCostParams {
  bool quick = false;
  std::optional<std::uint64_t> trials; // per point; default 9, or 3 when quick
  std::uint64_t seed = 1;
  std::int64_t budget = 40000000; // steps per trial, both trails together
};

struct BuffonCostArena {
  std::string spec;   // an arena spec (geometry/arena_spec.hpp), e.g. "circle:d=20"
  std::string family; // "circle", "square" or "figure 3 shape"
};

// The arenas of the sweep in row order (see above).
[[nodiscard]] std::vector<BuffonCostArena> buffon_cost_arenas(bool quick);

struct BuffonCost {
  BuffonCostParams params;
  buffon::CostParams run; // what precision_cost ran: trials, precisions, methods, budget
  buffon::CostTable table;
};

// Throws kernel::InputError("trials" / "step budget", ...) for trials outside [1, 100000] or a
// budget outside [2, 100000000] (what run_buffon_cost checks first).
void validate(const BuffonCostParams& params);

// Throws as validate() does. The trials are `runner`'s units (precision_cost.hpp): under MPI
// every rank calls it and rank 0 gets the result (the other ranks get an empty table); the result
// does not depend on the threads or the ranks.
[[nodiscard]] BuffonCost run_buffon_cost(const BuffonCostParams& params,
                                         const algorithms::Runner& runner = {});

[[nodiscard]] std::string buffon_cost_csv(const BuffonCost& c);
[[nodiscard]] std::string buffon_cost_fits_csv(const BuffonCost& c);
// One panel per P; per method a line over the circles, a dashed line over the squares and open
// markers for the other shapes; colour is the method, style the arena family.
[[nodiscard]] Figure buffon_cost_plot(const BuffonCost& c);

// The files in `dir` (which exists), the figure first, then the two tables, each written
// atomically; returns their paths: the table, the fits, the SVG, the PNG.
std::array<std::filesystem::path, 4> write_buffon_cost(const BuffonCost& c,
                                                       const std::filesystem::path& dir);

} // namespace antkit::experiments
