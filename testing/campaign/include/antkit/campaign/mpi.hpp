#pragma once
// `mpirun -n K antkit campaign ...`: the campaign across MPI ranks (issue 18). Built when CMake
// finds MPI (Debian's Open MPI, installed by the bootstrap; -DANTKIT_MPI=OFF leaves it out).
//
// Rank r of K runs the cases whose index, counted from --first, is r modulo K (case i is case i on
// any rank: the keyed streams decide it; campaign::Ranks); the ranks agree on a time limit at every
// batch boundary; rank 0 gathers every rank's verdicts after each batch, shrinks the failures in
// case order and is the one that writes and prints. So the output files are byte for byte those of
// a run without MPI, for any K. MPI does the transport (antkit/mpi/session.hpp).
#include <antkit/campaign/campaign.hpp>
#include <antkit/mpi/session.hpp>

namespace antkit::campaign::mpi {

using antkit::mpi::launched;
using antkit::mpi::Session;

// Every rank runs its share; rank 0 returns the whole result, the others cases_run and
// stopped_by_time only.
[[nodiscard]] Result run(const Session& session, const Options& options,
                         const Progress& progress = {});

} // namespace antkit::campaign::mpi
