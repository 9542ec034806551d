// Two distinguishable markers (two_markers.hpp).
#include <antkit/buffon/crossing_counter.hpp>
#include <antkit/buffon/step_root.hpp>
#include <antkit/buffon/stopping.hpp>
#include <antkit/buffon/two_markers.hpp>
#include <antkit/kernel/input_error.hpp>
#include <optional>

namespace antkit::buffon {

TrialResult run_two_marker_trial(const World& world, const TrialParams& params,
                                 std::uint64_t trial) {
  if (params.precision_millionths == 0)
    throw kernel::InputError("precision", "two markers need a precision to stop on");
  constexpr int kK = PrecisionMonitor::kBatches;
  TrialParams walk = params;
  walk.steps = params.total_steps != 0 ? params.total_steps : 2 * params.steps;
  detail::check_total_steps(walk.steps);
  TrialResult result;
  result.trial = trial;
  kernel::TraceHash hash(params.seed);
  hash.add_u64(trial).add_u64(3);
  GrowingTrailIndex index[2] = {{world.lower(), world.upper()}, {world.lower(), world.upper()}};
  std::vector<std::uint64_t> pieces[2]; // crossings with an end on each piece of A, of B
  std::vector<FxPoint> trails[2];       // with keep_trails
  std::int64_t lengths[2] = {0, 0};
  std::vector<std::uint32_t> crossed;
  WallEncounters encounters;
  std::uint64_t n = 0;
  std::int64_t step = 0;
  std::optional<FxPoint> previous;
  bool reached = false;
  double shares[2] = {0, 0}; // A's and B's variance shares at the last check (reporting only)
  const VisitLog log =
      run_visit(world, walk, trial, 3, hash, [&](const Pose& p, const Observation& o) {
        encounters.observe(o);
        if (!previous) {
          previous = p.position;
          return true;
        }
        const FxPoint a = *previous, b = p.position;
        previous = b;
        const std::int64_t piece = step / kSwitchSteps;
        const int m = static_cast<int>(piece % 2), other = 1 - m;
        auto& own = pieces[m];
        if (own.size() <= static_cast<std::size_t>(piece / 2)) own.push_back(0);
        crossed.clear();
        index[other].cross(a, b, &crossed);
        for (const std::uint32_t id : crossed) {
          // The other marker's piece, in walk order; pieces close in time are left out.
          const std::int64_t there = 2 * static_cast<std::int64_t>(id / kSwitchSteps) + other;
          if (piece - there <= kNearPieces) continue;
          ++own.back();
          ++pieces[other][id / kSwitchSteps];
          ++n;
        }
        index[m].insert(a, b);
        if (params.keep_trails) {
          if (step % kSwitchSteps == 0) trails[m].push_back(a); // a piece begins
          trails[m].push_back(b);
        }
        ++step;
        if (step % (2 * kK * kSwitchSteps) != 0) return true;
        // A check: each trail has 10 m pieces; rows are A's runs of m pieces, columns B's.
        std::uint64_t sums[2][kK] = {};
        for (int t = 0; t < 2; ++t) {
          const std::size_t per_run = pieces[t].size() / kK;
          for (std::size_t q = 0; q < pieces[t].size(); ++q) sums[t][q / per_run] += pieces[t][q];
        }
        for (int t = 0; t < 2; ++t) {
          double squares = 0;
          for (const std::uint64_t v : sums[t])
            squares += static_cast<double>(v) * static_cast<double>(v);
          const double total = static_cast<double>(n);
          shares[t] = (kK * squares - total * total) / (kK - 1);
        }
        reached = precision_met(sums[0], sums[1], params.precision_millionths);
        return !reached;
      });
  // Lengths: each step's length is the walk's, attributed to the piece (and so the marker) it
  // laid; the same integer roots as run_visit's total.
  std::vector<double> piece_length;
  std::uint64_t last = 0; // the previous step's length: the next one's guess (step_root.hpp)
  for (std::size_t s = 1; s < log.trail.size(); ++s) {
    const std::int64_t dx = std::int64_t{log.trail[s].x.raw()} - log.trail[s - 1].x.raw();
    const std::int64_t dy = std::int64_t{log.trail[s].y.raw()} - log.trail[s - 1].y.raw();
    last = step_root(static_cast<std::uint64_t>(dx * dx + dy * dy), last);
    const auto root = static_cast<std::int64_t>(last);
    const auto k = static_cast<std::size_t>((static_cast<std::int64_t>(s) - 1) / kSwitchSteps);
    lengths[k % 2] += root;
    if (piece_length.size() <= k) piece_length.push_back(0);
    piece_length[k] += static_cast<double>(root) / 65536.0;
  }
  // The share of L_A L_B whose crossings were counted: the pairs of pieces at least
  // kNearPieces + 1 apart in walk order (reporting: the estimate is 2 share L_A L_B / (pi N)).
  double near = 0, all = static_cast<double>(lengths[0]) * static_cast<double>(lengths[1]) /
                         (65536.0 * 65536.0);
  for (std::size_t k = 0; k < piece_length.size(); ++k)
    for (std::size_t j = k + 1; j < piece_length.size() && j - k <= kNearPieces; j += 2)
      near += piece_length[k] * piece_length[j];
  result.pair_share = all > 0 ? (all - near) / all : 1.0;
  result.reached_precision = reached;
  result.variance_visit1 = shares[0];
  result.variance_visit2 = shares[1];
  result.crossings_exact = n;
  result.wall_encounters = encounters.count();
  result.length1_raw = lengths[0];
  result.length2_raw = lengths[1];
  const std::int64_t steps = static_cast<std::int64_t>(log.trail.size()) - 1;
  result.steps1 = (steps / (2 * kSwitchSteps)) * kSwitchSteps +
                  std::min<std::int64_t>(steps % (2 * kSwitchSteps), kSwitchSteps);
  result.steps2 = steps - result.steps1;
  result.blocked = log.blocked;
  hash.add_u64(n).add_u64(log.blocked);
  result.hash = hash.finish();
  if (params.keep_trails) {
    result.trail1 = std::move(trails[0]);
    result.trail2 = std::move(trails[1]);
  }
  return result;
}

} // namespace antkit::buffon
