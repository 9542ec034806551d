#include "ranks.hpp"

#include "output.hpp"

#if ANTKIT_HAVE_MPI
#include <antkit/mpi/session.hpp>
#endif

namespace antkit::cli {

int run_on_ranks(const std::string& out, unsigned threads, algorithms::Progress progress,
                 const std::function<void(const algorithms::Runner&)>& run) {
  algorithms::Runner runner;
  runner.threads = threads;
  runner.progress = std::move(progress);
#if ANTKIT_HAVE_MPI
  if (antkit::mpi::launched()) {
    const antkit::mpi::Session session;
    if (!make_out_dir_on_rank0(session, out)) return 0;
    runner.rank = session.rank();
    runner.ranks = session.size();
    runner.gather = [&session](const std::string& mine) { return session.gather_to_root(mine); };
    runner.any = [&session](bool local) { return session.any(local); };
    if (!runner.root()) runner.progress = {};
    run(runner);
    return runner.root() ? runner.ranks : 0;
  }
#endif
  make_out_dir(out);
  run(runner);
  return 1;
}

} // namespace antkit::cli
