#pragma once
// The run-size options shared by `antkit buffon` and `antkit buffon-experiment`: one range check,
// one message each, so the two commands reject the same values the same way (exit 2).
#include <antkit/kernel/input_error.hpp>
#include <cstdint>
#include <string>

namespace antkit::cli {

inline void check_buffon_run_size(std::int64_t trials, std::int64_t steps, std::int64_t threads) {
  using antkit::kernel::InputError;
  if (trials < 1 || trials > 100000)
    throw InputError("--trials", "the number of trials must be in [1, 100000]");
  if (steps < 1 || steps > 10000000)
    throw InputError("--steps", "the steps per visit must be in [1, 10000000]");
  if (threads < 1 || threads > 256)
    throw InputError("--threads", "the number of threads must be in [1, 256]");
}

} // namespace antkit::cli
