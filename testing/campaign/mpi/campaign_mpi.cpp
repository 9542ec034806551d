#include <antkit/campaign/mpi.hpp>
#include <cstdlib>
#include <mpi.h>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace antkit::campaign::mpi {

namespace {

void require(int status, const char* what) {
  if (status != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

// One rank's result as text: a line of counts, then one line per failure.
std::string pack(const Result& r) {
  std::ostringstream s;
  s << r.cases_run << ' ' << (r.stopped_by_time ? 1 : 0) << ' ' << r.moves << ' ' << r.vacuous
    << ' ' << r.failures.size() << '\n';
  for (const auto& f : r.failures) s << serialize(f) << '\n';
  return s.str();
}

Result unpack(const std::string& text) {
  std::istringstream s(text);
  Result r;
  int stopped = 0;
  std::size_t failures = 0;
  s >> r.cases_run >> stopped >> r.moves >> r.vacuous >> failures;
  r.stopped_by_time = stopped != 0;
  std::string line;
  std::getline(s, line); // the end of the counts line
  for (std::size_t k = 0; k < failures && std::getline(s, line); ++k)
    r.failures.push_back(deserialize(line));
  if (r.failures.size() != failures) throw std::runtime_error("MPI: a rank's result is truncated");
  return r;
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

Result run(const Session& session, Options options, const Progress& progress) {
  options.rank = static_cast<std::uint32_t>(session.rank());
  options.ranks = static_cast<std::uint32_t>(session.size());
  options.stop_together = [](bool local) {
    int mine = local ? 1 : 0, any = 0;
    require(MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_LOR, MPI_COMM_WORLD), "MPI_Allreduce");
    return any != 0;
  };
  const Result part = campaign::run(options, session.rank() == 0 ? progress : Progress{});
  const std::string text = pack(part);
  const int length = static_cast<int>(text.size());
  std::vector<int> lengths(static_cast<std::size_t>(session.size()), 0);
  require(MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD),
          "MPI_Gather");
  std::vector<int> offsets(lengths.size(), 0);
  std::vector<char> all;
  if (session.rank() == 0) {
    long long total = 0;
    for (std::size_t r = 0; r < lengths.size(); ++r) {
      offsets[r] = static_cast<int>(total);
      total += lengths[r];
    }
    if (total > 0x7fffffff) throw std::runtime_error("MPI: the gathered results exceed 2 GiB");
    all.resize(static_cast<std::size_t>(total));
  }
  require(MPI_Gatherv(text.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(),
                      MPI_CHAR, 0, MPI_COMM_WORLD),
          "MPI_Gatherv");
  if (session.rank() != 0) return part;
  std::vector<Result> parts;
  for (std::size_t r = 0; r < lengths.size(); ++r)
    parts.push_back(
        unpack(std::string(all.data() + offsets[r], static_cast<std::size_t>(lengths[r]))));
  return merge(parts);
}

} // namespace antkit::campaign::mpi
