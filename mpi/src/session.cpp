#include <antkit/mpi/session.hpp>
#include <cstdlib>
#include <mpi.h>
#include <stdexcept>

namespace antkit::mpi {

namespace {
void require(int status, const char* what) {
  if (status != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}
} // namespace

bool launched() noexcept {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "MPI_LOCALNRANKS"})
    if (std::getenv(name) != nullptr) return true;
  return false;
}

Session::Session() {
  require(MPI_Init(nullptr, nullptr), "MPI_Init");
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

Session::~Session() {
  MPI_Finalize();
}

bool Session::all(bool ok) const {
  int mine = ok ? 1 : 0, every = 0;
  require(MPI_Allreduce(&mine, &every, 1, MPI_INT, MPI_LAND, MPI_COMM_WORLD), "MPI_Allreduce");
  return every != 0;
}

bool Session::any(bool ok) const {
  int mine = ok ? 1 : 0, some = 0;
  require(MPI_Allreduce(&mine, &some, 1, MPI_INT, MPI_LOR, MPI_COMM_WORLD), "MPI_Allreduce");
  return some != 0;
}

std::vector<std::string> Session::gather_to_root(const std::string& mine) const {
  if (mine.size() > 0x7fffffffu) throw std::runtime_error("MPI: a rank's part exceeds 2 GiB");
  const int length = static_cast<int>(mine.size());
  std::vector<int> lengths(static_cast<std::size_t>(size_), 0);
  require(MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD),
          "MPI_Gather");
  std::vector<int> offsets(lengths.size(), 0);
  std::vector<char> all;
  if (rank_ == 0) {
    long long total = 0;
    for (std::size_t r = 0; r < lengths.size(); ++r) {
      offsets[r] = static_cast<int>(total);
      total += lengths[r];
      if (total > 0x7fffffff) throw std::runtime_error("MPI: the gathered parts exceed 2 GiB");
    }
    all.resize(static_cast<std::size_t>(total));
  }
  require(MPI_Gatherv(mine.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(),
                      MPI_CHAR, 0, MPI_COMM_WORLD),
          "MPI_Gatherv");
  std::vector<std::string> parts;
  if (rank_ != 0) return parts;
  for (std::size_t r = 0; r < lengths.size(); ++r)
    parts.emplace_back(all.data() + offsets[r], static_cast<std::size_t>(lengths[r]));
  return parts;
}

} // namespace antkit::mpi
