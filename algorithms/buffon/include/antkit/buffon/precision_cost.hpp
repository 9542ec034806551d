#pragma once
// The cost of precision (issue 17): the median total trail length a method needs to reach a
// relative precision P, against the arena's area, and the exponent of a power-law fit
// trail = c A^e per method and P. Integral geometry predicts e = 1/2 for Buffon (the count N ~ L^2
// / A must reach ~ 1 / P^2, so L ~ sqrt(A) / P) and e = 1 for coverage (RS must mark ~ A of floor
// with a body of fixed width), times a logarithm for the last uncovered patches.
//
// Methods: Buffon with two markers (--rule markers, the default) and with the online first visit
// (--rule online), each run until its own rule says P (the trail is the sum of both trails); and
// RS (checkpoints.hpp, rs_cost_to_precision), run until its estimate is within P of the true area
// (an oracle stop: RS has no rule of its own). A trial that runs out of budget counts as an
// infinite trail in the median: a point whose median is then infinite is reported as not reached.
// Trials run in parallel and are reduced in trial order; the result does not depend on threads.
#include <antkit/algorithms/units.hpp>
#include <antkit/buffon/world.hpp>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace antkit::buffon {

enum class CostMethod { markers, online, rs };
std::string_view cost_method_name(CostMethod m) noexcept;

struct CostArena {
  std::string name;   // e.g. "circle:d=20"
  std::string family; // the series it belongs to in the figure ("circle", "square", "shape")
  double area = 0;    // the arena's true area
  const World* world = nullptr;
  bool in_fit = true; // whether its points enter the power-law fit (an area sweep's members do)
};

struct CostPoint {
  std::string arena, family;
  double area = 0;
  std::uint32_t precision_millionths = 0;
  CostMethod method = CostMethod::markers;
  std::optional<double> median, q1, q3; // total trail length; absent when not reached
  std::uint64_t reached = 0, trials = 0;
};

struct CostFit {
  CostMethod method = CostMethod::markers;
  std::uint32_t precision_millionths = 0;
  double exponent = 0, coefficient = 0; // median trail = coefficient * area^exponent
  std::size_t points = 0;               // the reached points the fit used (at least 2)
};

struct CostParams {
  std::vector<std::uint32_t> precisions{200000, 100000, 50000};
  std::vector<CostMethod> methods{CostMethod::markers, CostMethod::online, CostMethod::rs};
  std::uint64_t trials = 9;
  std::uint64_t seed = 1;
  std::int64_t budget = 40000000; // steps per trial, both trails together
};

struct CostTable {
  std::vector<CostPoint> points; // arena-major, then precision, then method
  std::vector<CostFit> fits;     // per method and precision: the in_fit arenas' reached points
};

// Throws InputError for no arena, no precision, a precision outside (0, 1), trials outside
// [1, 100000] or a budget outside [2, 100000000]. Every trial of every point is a unit of
// `runner` (algorithms/units.hpp: its threads, its MPI ranks, its progress, stage "trials"), in
// point order then trial order; rank 0 returns the table, other ranks an empty one. The table does
// not depend on the threads or the ranks.
CostTable precision_cost(std::span<const CostArena> arenas, const CostParams& params,
                         const algorithms::Runner& runner = {});

// Least squares of log(y) on log(x) over points with x, y > 0 (at least two distinct x): the
// exponent and the coefficient of y = c x^e. Exposed for the tests.
CostFit fit_power_law(std::span<const double> x, std::span<const double> y);

} // namespace antkit::buffon
