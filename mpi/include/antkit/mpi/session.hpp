#pragma once
// MPI for the commands that split work across ranks (`mpirun -n K antkit campaign ...`,
// `mpirun -n K antkit reproduce ...`; issue 18). Built when CMake finds MPI (Debian's Open MPI,
// installed by the bootstrap; -DANTKIT_MPI=OFF leaves it out) and then ANTKIT_HAVE_MPI is 1.
//
// MPI does the transport: nothing here but MPI_Init/Finalize, MPI_Allreduce and MPI_Gather(v).
// Not installed: the commands are its product.
#include <string>
#include <vector>

namespace antkit::mpi {

// Whether an MPI launcher started this process (Open MPI's, MPICH's or a PMI/PMIx environment):
// only then does a command initialise MPI (a plain run never touches it).
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
  // Whether any rank passes `ok` (a collective).
  [[nodiscard]] bool any(bool ok) const;
  // Every rank's `mine`, in rank order, on rank 0; an empty vector on the others (a collective).
  // Throws std::runtime_error when MPI fails or the total exceeds 2 GiB.
  [[nodiscard]] std::vector<std::string> gather_to_root(const std::string& mine) const;

private:
  int rank_ = 0, size_ = 1;
};

} // namespace antkit::mpi
