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
#include <antkit/buffon/world.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/random.hpp>
#include <climits>
#include <cmath>
#include <cstdint>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <functional>
#include <type_traits>
#include <utility>
#include <vector>

namespace antkit::buffon {

inline constexpr Fx kDefaultWidth = Fx::from_raw(6554); // 0.1
inline constexpr std::int64_t kDefaultSteps = 50000;
// The experiment number of this family's streams (issue 4).
inline constexpr std::uint64_t kExperiment = 4;

class PheromoneRaster {
public:
  // Throws InputError("trail width") when w is not in [0.01, 10] units. `storage` is memory to
  // reuse for the bits (its contents are discarded): trials in a row reuse one buffer instead of
  // faulting fresh pages in (a 100-unit circle's raster is 2 MiB).
  PheromoneRaster(FxPoint lower, FxPoint upper, Fx width, std::vector<std::uint64_t> storage = {});
  // Hands the bits' memory back for reuse (the raster is empty afterwards).
  std::vector<std::uint64_t> release_storage() noexcept { return std::move(bits_); }
  // Marks every cell whose centre is within w / 2 of `centre` (exact integer test).
  void lay(FxPoint centre) noexcept {
    Cell c;
    if (!locate(centre, c) || c.i < 2 || c.j < 2 || c.i + 2 >= cols_ || c.j + 2 >= rows_) {
      lay_exact(
          centre); // near the raster's edge (never in a closed arena) or w out of the fast range
      return;
    }
    // The disk lies in the 5 x 5 cells around the centre's cell (the constructor checks
    // 2 (w / 2) < 5 cell, so a cell three away has its centre beyond w / 2 in that axis). Cell
    // centres in doubled raw units avoid halves: the centre of cell i + d is at
    // 2 (i cell) + (2 d + 1) cell, so its doubled offset from the robot is (2 d + 1) cell - 2 o.
    std::int64_t sq[5], room[5];
    for (int d = 0; d < 5; ++d) {
      const std::int64_t dx2 = (2 * (d - 2) + 1) * cell_ - 2 * c.ox;
      const std::int64_t dy2 = (2 * (d - 2) + 1) * cell_ - 2 * c.oy;
      sq[d] = dx2 * dx2;
      room[d] = 4 * r2_ - dy2 * dy2; // a column is in row d's chord when sq <= room[d]
    }
    std::uint64_t masks[5];
#if defined(__SSE2__)
    if (narrow_) {
      // Every sq and room fits in 32 bits (the constructor checks (5 cell)^2 and 4 r^2 < 2^31):
      // four columns per comparison, the same integers compared exactly.
      const __m128i sq_lo =
          _mm_setr_epi32(static_cast<std::int32_t>(sq[0]), static_cast<std::int32_t>(sq[1]),
                         static_cast<std::int32_t>(sq[2]), static_cast<std::int32_t>(sq[3]));
      const __m128i sq_hi =
          _mm_setr_epi32(static_cast<std::int32_t>(sq[4]), INT32_MAX, INT32_MAX, INT32_MAX);
      for (int e = 0; e < 5; ++e) {
        const __m128i r = _mm_set1_epi32(static_cast<std::int32_t>(room[e]));
        // Columns with sq > room are out; the rest (sq <= room) are in.
        const int out_lo = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpgt_epi32(sq_lo, r)));
        const int out_hi = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpgt_epi32(sq_hi, r)));
        masks[e] = ~static_cast<std::uint64_t>(out_lo | (out_hi << 4)) & 0x1Fu;
      }
    } else
#endif
    {
      for (int e = 0; e < 5; ++e) {
        std::uint64_t mask = 0;
        for (int d = 0; d < 5; ++d) mask |= std::uint64_t{sq[d] <= room[e]} << d;
        masks[e] = mask;
      }
    }
    // Rows j - 2 .. j + 2, columns i - 2 .. i + 2: bits `shift` .. `shift` + 4 of five adjacent
    // words of one column band, which may straddle into the same rows of the next band.
    const auto first = static_cast<std::uint64_t>(c.i - 2);
    const unsigned shift = first & 63;
    std::uint64_t* const words = bits_.data() + word_index(c.i - 2, c.j - 2);
    for (int e = 0; e < 5; ++e) words[e] |= masks[e] << shift;
    // Only 4 of 64 shifts spill into the next band (which then exists: the columns up to i + 2
    // are in the raster): a well-predicted branch beats five stores.
    if (shift > 59) {
      std::uint64_t* const next = words + rows_;
      for (int e = 0; e < 5; ++e) next[e] |= masks[e] >> (64 - shift);
    }
  }
  [[nodiscard]] bool at(FxPoint centre) const noexcept {
    Cell c;
    if (!locate(centre, c)) return at_exact(centre);
    if (c.i >= cols_ || c.j >= rows_) return false;
    return bit(c.i, c.j);
  }
  [[nodiscard]] Fx cell() const noexcept {
    return Fx::from_raw(static_cast<std::int32_t>(cell_));
  }
  [[nodiscard]] std::int64_t columns() const noexcept {
    return cols_;
  }
  [[nodiscard]] std::int64_t rows() const noexcept {
    return rows_;
  }
  [[nodiscard]] std::uint64_t marked() const;
  // Same geometry and the same marked cells.
  friend bool operator==(const PheromoneRaster&, const PheromoneRaster&) = default;

  // The reference forms of lay() and at(): the plain loop over the disk's bounding cells with one
  // exact test each, and floor divisions. The fast paths fall back to them near the raster's edge
  // and the tests hold the fast paths against them.
  void lay_exact(FxPoint centre) noexcept;
  [[nodiscard]] bool at_exact(FxPoint centre) const noexcept;

private:
  struct Cell {
    std::int64_t i, j;   // the cell holding the point
    std::int64_t ox, oy; // the point's offset inside it, in [0, cell)
  };
  // Cell and offset of p when p is at or right of and above the raster's lower corner and less
  // than 2^32 raw from it; false otherwise (then the exact forms decide). Division by the cell
  // side by multiplication with floor(2^32 / cell): for n < 2^32 the product's high half is
  // floor(n / cell) or one less, and one comparison corrects it (exact; no division per step).
  bool locate(FxPoint p, Cell& out) const noexcept {
    const std::int64_t cx = std::int64_t{p.x.raw()} - x0_, cy = std::int64_t{p.y.raw()} - y0_;
    if (!fast_ || cx < 0 || cy < 0 || cx >= (std::int64_t{1} << 32) ||
        cy >= (std::int64_t{1} << 32))
      return false;
    auto divide = [this](std::int64_t n, std::int64_t& q, std::int64_t& rest) {
      q = static_cast<std::int64_t>((static_cast<std::uint64_t>(n) * reciprocal_) >> 32);
      rest = n - q * cell_;
      if (rest >= cell_) ++q, rest -= cell_;
    };
    divide(cx, out.i, out.ox);
    divide(cy, out.j, out.oy);
    return true;
  }
  // The word holding cell (i, j) (0 <= i < cols_, 0 <= j < rows_): column band i div 64, row j.
  [[nodiscard]] std::size_t word_index(std::int64_t i, std::int64_t j) const noexcept {
    return static_cast<std::size_t>((i >> 6) * rows_ + j);
  }
  [[nodiscard]] bool bit(std::int64_t i, std::int64_t j) const noexcept {
    return ((bits_[word_index(i, j)] >> (i & 63)) & 1u) != 0;
  }
  bool narrow_; // (5 cell_)^2 and 4 r2_ below 2^31: lay() compares in 32-bit lanes

  std::int64_t x0_, y0_, cell_, half_width_, cols_, rows_;
  std::int64_t r2_;                 // half_width_ squared
  std::uint64_t reciprocal_;        // floor(2^32 / cell_)
  bool fast_;                       // 2 half_width_ < 5 cell_: the 5 x 5 fast path of lay() applies
  std::vector<std::uint64_t> bits_; // column bands of 64 cells, each `rows_` words (see above)
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
  // 100 000 000 (InputError "--max-steps" otherwise).
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

// Trials 0 .. count-1 on `threads` workers (at least 1); results in trial order, identical for any
// thread count.
std::vector<TrialResult> run_trials(const World& world, const TrialParams& params,
                                    std::uint64_t count, unsigned threads);

// Runs f(i) for i in [0, count) on `threads` workers; the caller stores results by index.
void parallel_for(std::uint64_t count, unsigned threads,
                  const std::function<void(std::uint64_t)>& f);

// Integer square root (floor) of a 64-bit value.
std::uint64_t isqrt64(std::uint64_t n) noexcept;

// ---------------------------------------------------------------------------------------------

namespace detail {
// Throws InputError("steps per visit") unless 0 <= steps <= 100000000.
void check_visit_steps(std::int64_t steps);
// Throws InputError("step budget") unless 2 <= steps <= 100000000 (a budget of both visits).
void check_total_steps(std::int64_t steps);

// The exact floor square root of a step's squared length n2, started from the commanded forward
// distance (the step's length is within a few raw units of it) and corrected by +/- 1 per
// iteration (isqrt64 was 15 % of a step's time).
//
// The root is almost always within two of f = |forward| (the step is forward times a rounded unit
// vector, each coordinate rounded by half a raw unit), so it is first counted without branches
// over the bracket [f - 2, f + 2): root = f - 2 + the number of k in {f - 1, f, f + 1} with
// k^2 <= n2, which is exact whenever (f - 2)^2 <= n2 < (f + 2)^2 (checked; the loop takes the
// rest). The data-dependent loop branches were mispredicted on a good share of the steps.
inline std::uint64_t step_length_raw(std::uint64_t n2, Fx forward) noexcept {
  if (n2 == 0) return 0;
  auto root = static_cast<std::uint64_t>(kernel::abs(forward).raw());
  if (root >= 2 && (root - 2) * (root - 2) <= n2 && n2 < (root + 2) * (root + 2)) {
    return root - 2 + std::uint64_t{(root - 1) * (root - 1) <= n2} +
           std::uint64_t{root * root <= n2} + std::uint64_t{(root + 1) * (root + 1) <= n2};
  }
  while (root * root > n2) --root;
  while ((root + 1) * (root + 1) <= n2) ++root;
  return root;
}

// floor(sqrt(n)) exactly, for n < 2^52: the binary64 root is within one of it (n and the
// correctly rounded root are exact there), and the two loops make it exact; the double is only
// the first guess, so the result is the same integer on every platform.
inline std::uint64_t exact_floor_sqrt(std::uint64_t n) noexcept {
  auto r = static_cast<std::uint64_t>(std::sqrt(static_cast<double>(n)));
  while (r * r > n) --r;
  while ((r + 1) * (r + 1) <= n) ++r;
  return r;
}

inline std::uint64_t hash_word(std::int32_t lo, std::int32_t hi) noexcept {
  return static_cast<std::uint64_t>(static_cast<std::uint32_t>(lo)) |
         (static_cast<std::uint64_t>(static_cast<std::uint32_t>(hi)) << 32);
}
} // namespace detail

template <class OnStep>
VisitLog run_visit(const World& world, const TrialParams& params, std::uint64_t trial, int visit,
                   kernel::TraceHash& hash, OnStep&& on_step, std::vector<FxPoint> storage) {
  detail::check_visit_steps(params.steps);
  const auto v = static_cast<std::uint64_t>(visit);
  kernel::Stream start_stream(params.seed, params.experiment, trial, v, 1);
  kernel::Stream noise(params.seed, params.experiment, trial, v, 2);
  ExplorationBehaviour behaviour(kernel::Stream(params.seed, params.experiment, trial, v, 0));
  Pose pose = world.start_pose(start_stream);
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
    const Observation obs = world.sense(pose, &noise);
    const Command cmd = behaviour.step(obs);
    const FxPoint before = pose.position;
    if (!world.move(pose, cmd)) ++log.blocked;
    const std::int64_t dx = std::int64_t{pose.position.x.raw()} - before.x.raw();
    const std::int64_t dy = std::int64_t{pose.position.y.raw()} - before.y.raw();
    const Fx forward = world.body().speed * (cmd.left + cmd.right) * Fx::from_ratio(1, 2);
    log.length_raw += static_cast<std::int64_t>(
        detail::step_length_raw(static_cast<std::uint64_t>(dx * dx + dy * dy), forward));
    log.trail.push_back(pose.position);
    more = call(std::as_const(pose), obs);
    hash.add_u64(detail::hash_word(pose.position.x.raw(), pose.position.y.raw()));
    hash.add_u64(
        detail::hash_word(static_cast<std::int32_t>(pose.heading.raw()), behaviour.r().raw()));
    hash.add_u64(detail::hash_word(behaviour.w_left().raw(), behaviour.w_right().raw()));
  }
  return log;
}

} // namespace antkit::buffon
