#pragma once
// `mpirun -n K antkit campaign ...`: the campaign across MPI ranks (issue 18). Built when CMake
// finds MPI (Debian's Open MPI, installed by the bootstrap; -DANTKIT_MPI=OFF leaves it out).
//
// Rank r of K runs the cases whose index, counted from --first, is r modulo K (case i is case i on
// any rank: the keyed streams decide it); the ranks agree on a time limit at every batch boundary;
// rank 0 gathers every rank's counts and shrunk failures, merges them in case order and is the one
// that writes and prints. So the output files are byte for byte those of a run without MPI, for any
// K. MPI does the transport: nothing here but MPI_Allreduce, MPI_Gather(v) and MPI_Bcast.
#include <antkit/campaign/campaign.hpp>

namespace antkit::campaign::mpi {

// Whether an MPI launcher started this process (Open MPI's, MPICH's or a PMI/PMIx environment):
// only then does `antkit campaign` initialise MPI (a plain run never touches it).
[[nodiscard]] bool launched() noexcept;

// MPI_Init on construction, MPI_Finalize on destruction (also on the way out of an exception).
class Session {
public:
  Session();
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
  [[nodiscard]] int rank() const noexcept { return rank_; }
  [[nodiscard]] int size() const noexcept { return size_; }
  // Whether every rank passes `ok` (a collective: every rank must call it).
  [[nodiscard]] bool all(bool ok) const;

private:
  int rank_ = 0, size_ = 1;
};

// Every rank runs its share; rank 0 returns the merged result, the others their own part.
[[nodiscard]] Result run(const Session& session, Options options, const Progress& progress = {});

} // namespace antkit::campaign::mpi
