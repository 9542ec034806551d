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
#include <cstdint>
#include <functional>
#include <vector>

namespace antkit::buffon {

inline constexpr Fx kDefaultWidth = Fx::from_raw(6554); // 0.1
inline constexpr std::int64_t kDefaultSteps = 50000;
// The experiment number of this family's streams (issue 4).
inline constexpr std::uint64_t kExperiment = 4;

class PheromoneRaster {
public:
  // Throws InputError("--width") when w is not in [0.01, 10] units.
  PheromoneRaster(FxPoint lower, FxPoint upper, Fx width);
  void lay(FxPoint centre);
  [[nodiscard]] bool at(FxPoint centre) const;
  [[nodiscard]] Fx cell() const noexcept { return Fx::from_raw(static_cast<std::int32_t>(cell_)); }
  [[nodiscard]] std::int64_t columns() const noexcept { return cols_; }
  [[nodiscard]] std::int64_t rows() const noexcept { return rows_; }
  [[nodiscard]] std::uint64_t marked() const;

private:
  std::int64_t x0_, y0_, cell_, half_width_, cols_, rows_;
  std::vector<std::uint64_t> bits_;
};

struct TrialParams {
  std::uint64_t seed = 1;
  std::uint64_t experiment = kExperiment;
  std::int64_t steps = kDefaultSteps; // per visit
  Fx width = kDefaultWidth;
  bool keep_trails = false; // keep both trails' points in the result (figures, tests)
  // Online stopping (issue 8): when non-zero, visit 2 ends after the step at which BC reaches
  // stop_bc (or after `steps` steps, whichever comes first). 0: visit 2 runs all its steps.
  std::uint64_t stop_bc = 0;
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
};

// One visit: up to `steps` steps from the start pose; calls on_step(pose) after every step (and
// once for the start); the visit ends early, after that call, when on_step returns false. Exposed
// for the RS baseline and the tests.
struct VisitLog {
  std::vector<FxPoint> trail; // start and every step's position
  std::int64_t length_raw = 0;
  std::uint64_t blocked = 0;
};
VisitLog run_visit(const World& world, const TrialParams& params, std::uint64_t trial, int visit,
                   kernel::TraceHash& hash, const std::function<bool(const Pose&)>& on_step);

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

} // namespace antkit::buffon
