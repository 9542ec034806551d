#pragma once
// The C API's Buffon behaviour, detector and trace hash (antkit/c/antkit.h: the calls a C firmware
// makes) as the parts of visit.hpp's steps (buffon::VisitParts) and of run_fixed_trial_with
// (buffon::TrialParts), so that the image runs the shared trial and RS walk with the C API deciding
// and hashing, and no restatement of a visit's step. Each member only converts between the C
// structs and the C++ types.
#include <antkit/buffon/exploration.hpp>
#include <antkit/buffon/visit.hpp>
#include <antkit/c/antkit.h>

namespace antkit::mcu {

struct CApiBehaviour {
  antkit_buffon_behaviour state;
  buffon::Command step(const buffon::Observation& obs) noexcept {
    antkit_ir_reading reading;
    for (std::size_t i = 0; i < 6; ++i) reading.ir[i] = obs.ir[i].raw();
    const antkit_wheel_command c = antkit_buffon_behaviour_step(&state, &reading);
    return {kernel::Fx::from_raw(c.left), kernel::Fx::from_raw(c.right)};
  }
  [[nodiscard]] kernel::Fx r() const noexcept { return word(0); }
  [[nodiscard]] kernel::Fx w_left() const noexcept { return word(1); }
  [[nodiscard]] kernel::Fx w_right() const noexcept { return word(2); }

private:
  [[nodiscard]] kernel::Fx word(int k) const noexcept {
    std::int32_t w[3] = {0, 0, 0};
    antkit_buffon_behaviour_state(&state, &w[0], &w[1], &w[2]);
    return kernel::Fx::from_raw(w[k]);
  }
};

struct CApiHash {
  antkit_trace_hash state;
  CApiHash& add_u64(std::uint64_t word) noexcept {
    antkit_trace_hash_add_u64(&state, word);
    return *this;
  }
  [[nodiscard]] std::uint64_t finish() const noexcept { return antkit_trace_hash_finish(&state); }
};

struct CApiDetector {
  antkit_buffon_detector state;
  CApiDetector() noexcept { antkit_buffon_detector_init(&state); }
  bool update(bool pheromone) noexcept {
    return antkit_buffon_detector_update(&state, pheromone ? 1 : 0) != 0;
  }
};

struct CApiParts {
  using Behaviour = CApiBehaviour;
  using Hash = CApiHash;
  using Detector = CApiDetector;
  static Behaviour behaviour(std::uint64_t seed, std::uint64_t trial, int visit) noexcept {
    Behaviour b;
    antkit_buffon_behaviour_init(&b.state, seed, buffon::kExperiment, trial,
                                 static_cast<std::uint64_t>(visit));
    return b;
  }
  static Hash hash(std::uint64_t seed) noexcept {
    Hash h;
    antkit_trace_hash_init(&h.state, seed);
    return h;
  }
};

} // namespace antkit::mcu
