#include <antkit/campaign/mpi.hpp>
#include <string>
#include <vector>

namespace antkit::campaign::mpi {

Result run(const Session& session, const Options& options, const Progress& progress) {
  Ranks ranks;
  ranks.rank = session.rank();
  ranks.ranks = session.size();
  ranks.gather = [&session](const std::string& mine) { return session.gather_to_root(mine); };
  ranks.any = [&session](bool local) { return session.any(local); };
  return campaign::run(options, ranks, progress);
}

} // namespace antkit::campaign::mpi
