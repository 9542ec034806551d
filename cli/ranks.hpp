#pragma once
// The long commands under `mpirun` (reproduce, buffon-cost, campaign, ...): one way to open the MPI
// session and hand the library a Runner (antkit/algorithms/units.hpp) that splits the units across
// the ranks.
#include <antkit/algorithms/units.hpp>
#include <functional>
#include <string>

namespace antkit::cli {

// Makes the output directory `out` and calls `run` with a Runner of `threads` threads and
// `progress`. Under mpirun (antkit::mpi::launched(), when built with MPI) it first opens the MPI
// session: rank 0 makes `out` and every rank learns whether it could, the runner gets the rank,
// the number of ranks, a gather and an any over MPI, and only rank 0 reports progress; the session
// closes when `run` returns. Returns the number of ranks on rank 0 (1 without MPI) and 0 on the
// other ranks, which must then print nothing. Throws kernel::InputError("--out", ...) when `out`
// cannot be made (on rank 0; the other ranks return 0).
int run_on_ranks(const std::string& out, unsigned threads, algorithms::Progress progress,
                 const std::function<void(const algorithms::Runner&)>& run);

} // namespace antkit::cli
