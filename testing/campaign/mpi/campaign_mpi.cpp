#include <antkit/campaign/mpi.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace antkit::campaign::mpi {

namespace {

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

Result run(const Session& session, Options options, const Progress& progress) {
  options.rank = static_cast<std::uint32_t>(session.rank());
  options.ranks = static_cast<std::uint32_t>(session.size());
  options.stop_together = [&session](bool local) { return session.any(local); };
  const Result part = campaign::run(options, session.rank() == 0 ? progress : Progress{});
  const std::vector<std::string> texts = session.gather_to_root(pack(part));
  if (session.rank() != 0) return part;
  std::vector<Result> parts;
  for (const std::string& text : texts) parts.push_back(unpack(text));
  return merge(parts);
}

} // namespace antkit::campaign::mpi
