#pragma once
// Buffon's-needle measurement (Section 5): two independent visits of the exploring robot; the
// first lays a pheromone trail of width w, the second senses it at the robot's centre through a
// leaky integrator and a threshold and counts the low-to-high transitions, the Buffon count BC;
// nBC = BC / length of the second visit. Beside BC the trial counts the proper crossings of the two
// centre-line trails exactly (kernel::count_proper_crossings), which is what BC approximates.
//
// Choices where the paper is silent:
//  * Pheromone raster: square cells of side w / 4 (raw Q15.16, at least 1 raw unit) over the
//    walls' bounding box. Each step of visit 1 marks every cell whose centre is within w / 2 of the
//    robot's centre (exact integer test); steps are at most 0.04 < w / 2 apart for w = 0.1, so the
//    marks join into a band of width w, with edges accurate to half a cell (w / 8).
//  * Raster memory: column bands of 64 cells, each a run of `rows` 64-bit words (cell (i, j) is
//    bit i mod 64 of word (i div 64) rows + j). A step's 5 x 5 stamp then touches 5 adjacent
//    words, and a robot moving up or down stays in the same cache lines for several steps and
//    in the same page for hundreds, where the plain row-major layout needed a new line (and
//    often a new page) at almost every step: cache and TLB misses were most of lay()'s time in
//    the 100-unit circle. Only the layout; which cells are marked is unchanged.
//  * Detector: y <- y + (b - y) / 2 for the raster bit b under the centre (the leaky integrator);
//    the thresholded value goes high when y >= 1/2 and low again when y < 1/4 (hysteresis, so
//    that a single missing pixel inside a band, an artefact of the raster, does not make a second
//    transition). A band crossed in a single step at a grazing corner is still seen (y = 1/2).
//  * Streams: visit v (1, 2) of trial t draws its behaviour from Stream(seed, experiment, t, v, 0),
//    its start heading from purpose 1 and its IR noise from purpose 2. Nothing depends on which
//    thread runs a trial.
//  * Trace hash: per step (visit, x, y, heading, r, w_l, w_r, thresholded detector) as aligned
//    64-bit words, then BC, the blocked-step counts and the exact crossing count.
#include <antkit/buffon/detector.hpp>
#include <antkit/buffon/pheromone_raster.hpp>
#include <antkit/buffon/visit.hpp>
#include <antkit/buffon/world.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/random.hpp>
#include <climits>
#include <cmath>
#include <cstdint>
#include <functional>
#include <type_traits>
#include <utility>
#include <vector>

namespace antkit::buffon {

inline constexpr Fx kDefaultWidth = Fx::from_raw(6554); // 0.1
inline constexpr std::int64_t kDefaultSteps = 50000;

// The host's raster: RasterCore (pheromone_raster.hpp) over bits it owns in a vector (a copy
// points its core at its own copy of them).
class PheromoneRaster : public RasterCore {
public:
  // Throws InputError("trail width") when w is not in [0.01, 10] units or the raster would exceed
  // 2^27 words (RasterError). `storage` is memory to reuse for the bits (its contents are
  // discarded): trials in a row reuse one buffer instead of faulting fresh pages in (a 100-unit
  // circle's raster is 2 MiB).
  PheromoneRaster(FxPoint lower, FxPoint upper, Fx width, std::vector<std::uint64_t> storage = {});
  PheromoneRaster(const PheromoneRaster& other) : RasterCore(other), storage_(other.storage_) {
    bind(storage_);
  }
  PheromoneRaster& operator=(const PheromoneRaster& other) {
    if (this != &other) {
      RasterCore::operator=(other);
      storage_ = other.storage_;
      bind(storage_);
    }
    return *this;
  }
  PheromoneRaster(PheromoneRaster&& other) noexcept
      : RasterCore(other), storage_(std::move(other.storage_)) {
    bind(storage_);
    other.bind({});
  }
  PheromoneRaster& operator=(PheromoneRaster&& other) noexcept {
    if (this != &other) {
      RasterCore::operator=(other);
      storage_ = std::move(other.storage_);
      bind(storage_);
      other.bind({});
    }
    return *this;
  }
  ~PheromoneRaster() = default;
  // Hands the bits' memory back for reuse (the raster is empty afterwards).
  std::vector<std::uint64_t> release_storage() noexcept {
    bind({});
    return std::move(storage_);
  }

private:
  std::vector<std::uint64_t> storage_;
};

// Wall encounters (issue 17, the bias correction of estimate.hpp): the number of times the robot
// comes near a wall, counted from its front IR readings with hysteresis: an encounter begins when
// the largest reading reaches 1/2 (a wall within 0.375 of a sensor) after it had fallen below 1/4.
// For a walk spread evenly over the region its centre explores, encounters per unit of trail are
// proportional to that region's perimeter over its area (Crofton: a path crosses a fixed curve of
// length P on average 2 L P / (pi A) times), which is what the erosion bias needs. The runs feed it
// the readings the behaviour acts on at each step (with their noise, when the body has any: the
// hysteresis keeps small noise from counting twice; large noise would inflate the count, and the
// correction was fitted without noise).
class WallEncounters {
public:
  void observe(const Observation& obs) noexcept {
    Fx top{};
    for (const Fx v : obs.ir) top = v > top ? v : top;
    if (!near_ && top >= Fx::from_ratio(1, 2)) {
      near_ = true;
      ++count_;
    } else if (near_ && top < Fx::from_ratio(1, 4)) {
      near_ = false;
    }
  }
  [[nodiscard]] std::uint64_t count() const noexcept { return count_; }

private:
  bool near_ = false;
  std::uint64_t count_ = 0;
};

struct TrialParams {
  std::uint64_t seed = 1;
  std::uint64_t experiment = kExperiment;
  std::int64_t steps = kDefaultSteps; // per visit
  Fx width = kDefaultWidth;
  bool keep_trails = false; // keep both trails' points in the result (figures, tests)
  // Online stopping (issue 8, item 5; stopping.hpp): when non-zero, visit 2 counts its exact
  // crossings with visit 1 as it walks and ends at the first check where A_hat's interval is within
  // the relative precision precision_millionths / 10^6 (or after `steps` steps, whichever comes
  // first). 0: visit 2 runs all its steps.
  std::uint32_t precision_millionths = 0;
  // Visit 2's step cap when non-zero (visit 1 keeps `steps`): with the online rule, a long cap on
  // visit 2 without a longer visit 1. 0: `steps` for both visits.
  std::int64_t visit2_steps = 0;
  // Online first visit (issue 17; FirstVisitMonitor in stopping.hpp): with precision_millionths,
  // visit 1 counts its own exact self-crossings as it walks and ends at the first check where a
  // visit 2 of its length would meet the precision (or after `steps` steps). Visit 2 then runs the
  // rule above, capped by visit2_steps (or `steps`). false: visit 1 runs all `steps` steps.
  bool online_first_visit = false;
  // With online_first_visit, when non-zero: the budget of both visits together. Visit 1 is capped
  // at half of it (the rule aims at equal visits, so a visit 1 that needs more leaves visit 2 too
  // little) and visit 2 at what visit 1 left; `steps` and visit2_steps are then not used. At most
  // 100 000 000 (InputError "step budget" otherwise).
  std::int64_t total_steps = 0;
};

struct TrialResult {
  std::uint64_t trial = 0;
  std::uint64_t bc = 0;              // Buffon count
  std::int64_t length1_raw = 0;      // first visit's trail length, Q15.16 units widened to 64 bits
  std::int64_t length2_raw = 0;      // second visit's
  std::uint64_t crossings_exact = 0; // proper crossings of the two centre-line trails
  std::uint64_t blocked = 0;         // steps not taken (both visits)
  std::uint64_t hash = 0;
  std::vector<FxPoint> trail1, trail2; // only with keep_trails
  // With precision_millionths: whether visit 2 stopped on the rule (false: it ran to `steps`), and
  // the variance estimate's two shares at the last check (stopping.hpp; reporting only).
  bool reached_precision = false;
  double variance_visit1 = 0, variance_visit2 = 0;
  // Steps each visit took.
  std::int64_t steps1 = 0, steps2 = 0;
  // With online_first_visit: whether visit 1 stopped on its rule (false: it ran to its cap), its
  // exact self-crossing count S (the pilot estimate is length1^2 / (pi S)) and the batch-means
  // variance of S at its last check.
  // The share of length1 length2 whose element pairs the count covers: 1 for two visits; below 1
  // for two markers (two_markers.hpp), whose estimate is 2 pair_share L1 L2 / (pi N).
  double pair_share = 1.0;
  // With precision_millionths (any rule): wall encounters over both visits (WallEncounters).
  std::uint64_t wall_encounters = 0;
  bool first_visit_reached = false;
  std::uint64_t self_crossings = 0;
  double variance_self = 0;
};

// One visit: up to `steps` steps from the start pose; calls on_step(pose) after every step (and
// once for the start); the visit ends early, after that call, when on_step returns false. Exposed
// for the RS baseline and the tests. on_step is any callable taking const Pose& and returning
// bool (a template parameter rather than std::function, so that laying or sensing the pheromone
// is inlined into the step loop). It may also take the step's Observation as a second argument.
struct VisitLog {
  std::vector<FxPoint> trail; // start and every step's position
  std::int64_t length_raw = 0;
  std::uint64_t blocked = 0;
};
// `storage`: memory to reuse for the trail (its contents are discarded).
template <class OnStep>
VisitLog run_visit(const World& world, const TrialParams& params, std::uint64_t trial, int visit,
                   kernel::TraceHash& hash, OnStep&& on_step, std::vector<FxPoint> storage = {});

TrialResult run_trial(const World& world, const TrialParams& params, std::uint64_t trial);

// Trials 0 .. count-1 on `threads` workers (at least 1; algorithms::for_each_unit); results in
// trial order, identical for any thread count.
std::vector<TrialResult> run_trials(const World& world, const TrialParams& params,
                                    std::uint64_t count, unsigned threads);

// ---------------------------------------------------------------------------------------------

namespace detail {
// Throws InputError("steps per visit") unless 0 <= steps <= 100000000.
void check_visit_steps(std::int64_t steps);
// Throws InputError("step budget") unless 2 <= steps <= 100000000 (a budget of both visits).
void check_total_steps(std::int64_t steps);

} // namespace detail

// flatten: the step's pieces (the hash's three words, the trail's append, the step's inline
// geometry) are inlined into the loop; left to itself gcc called TraceHash::add_u64 and
// vector::push_back out of line on every step (about 7 % of a trial's instructions).
template <class OnStep>
[[gnu::flatten]] VisitLog run_visit(const World& world, const TrialParams& params,
                                    std::uint64_t trial, int visit, kernel::TraceHash& hash,
                                    OnStep&& on_step, std::vector<FxPoint> storage) {
  detail::check_visit_steps(params.steps);
  VisitStreams streams(params.seed, params.experiment, trial, visit);
  ExplorationBehaviour behaviour(streams.behaviour);
  Pose pose = world.start_pose(streams.start);
  VisitLog log;
  log.trail = std::move(storage);
  log.trail.clear();
  log.trail.reserve(static_cast<std::size_t>(params.steps) + 1);
  log.trail.push_back(pose.position);
  // on_step(pose) or on_step(pose, observation): the second form also gets the readings the
  // behaviour acted on in the step just taken (all zero for the start pose), so that bookkeeping
  // on them (WallEncounters) costs no second sense().
  constexpr bool with_obs = std::is_invocable_v<OnStep&, const Pose&, const Observation&>;
  const auto call = [&on_step](const Pose& p, const Observation& o) {
    if constexpr (with_obs)
      return static_cast<bool>(on_step(p, o));
    else
      return static_cast<bool>(on_step(p));
  };
  bool more = call(std::as_const(pose), Observation{});
  for (std::int64_t s = 0; more && s < params.steps; ++s) {
    const Observation obs =
        visit_step(world, behaviour, pose, streams.noise, log.length_raw, log.blocked);
    log.trail.push_back(pose.position);
    more = call(std::as_const(pose), obs);
    hash_visit_step(hash, pose, behaviour);
  }
  return log;
}

} // namespace antkit::buffon
