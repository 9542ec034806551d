#include <antkit/experiments/run.hpp>
#include <atomic>
#include <cstring>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

namespace antkit::experiments {

namespace {

// A rank's part: for each of its units, the unit number, a status word (0 ok, 1 failed), the
// payload's word count and its words (a failure's words are its message's bytes).
void append_word(std::string& out, std::uint64_t w) {
  char bytes[8];
  std::memcpy(bytes, &w, 8);
  out.append(bytes, 8);
}

std::uint64_t read_word(const std::string& in, std::size_t& at) {
  if (at + 8 > in.size()) throw std::runtime_error("experiments: a rank's part is truncated");
  std::uint64_t w = 0;
  std::memcpy(&w, in.data() + at, 8);
  at += 8;
  return w;
}

} // namespace

std::vector<Payload> run_units(const Runner& runner, std::string_view stage, std::uint64_t count,
                               const std::function<Payload(std::uint64_t unit)>& unit) {
  const auto ranks = static_cast<std::uint64_t>(std::max(1, runner.ranks));
  const auto rank = static_cast<std::uint64_t>(std::max(0, runner.rank));
  // This rank's units: rank, rank + ranks, ...
  const std::uint64_t mine = count > rank ? (count - rank + ranks - 1) / ranks : 0;
  std::vector<std::vector<std::uint64_t>> results(mine);
  std::vector<std::optional<std::string>> failures(mine);
  std::atomic<std::uint64_t> next{0};
  std::mutex lock;
  std::uint64_t done = 0;
  const auto worker = [&] {
    for (std::uint64_t k; (k = next.fetch_add(1)) < mine;) {
      const std::uint64_t u = rank + k * ranks;
      try {
        results[k] = unit(u).words();
      } catch (const std::exception& e) {
        failures[k] = e.what();
      } catch (...) {
        failures[k] = "an unknown exception";
      }
      if (runner.progress) {
        const std::lock_guard<std::mutex> held(lock);
        runner.progress(stage, ++done, mine);
      }
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < std::max(1u, runner.threads) && t < mine; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();

  std::vector<Payload> out;
  const auto fail = [&](std::uint64_t u, const std::string& why) {
    throw std::runtime_error(std::string(stage) + ", unit " + std::to_string(u) + ": " + why);
  };
  if (ranks == 1 || !runner.gather) {
    if (ranks != 1) throw std::logic_error("experiments: several ranks but no gather");
    for (std::uint64_t k = 0; k < mine; ++k) {
      if (failures[k]) fail(k, *failures[k]);
      out.push_back(Payload::of(std::move(results[k])));
    }
    return out;
  }
  std::string part;
  for (std::uint64_t k = 0; k < mine; ++k) {
    const std::vector<std::uint64_t> words =
        failures[k] ? [&] {
          Payload m;
          m.put_text(*failures[k]);
          return m.words();
        }()
                    : std::move(results[k]);
    append_word(part, rank + k * ranks);
    append_word(part, failures[k] ? 1 : 0);
    append_word(part, words.size());
    for (const std::uint64_t w : words) append_word(part, w);
  }
  const std::vector<std::string> parts = runner.gather(part);
  if (!runner.root()) return out;
  std::vector<std::optional<std::vector<std::uint64_t>>> all(count);
  std::optional<std::pair<std::uint64_t, std::string>> first_failure;
  for (const std::string& p : parts) {
    for (std::size_t at = 0; at < p.size();) {
      const std::uint64_t u = read_word(p, at), status = read_word(p, at), n = read_word(p, at);
      if (u >= count || all[u] || n > (p.size() - at) / 8)
        throw std::runtime_error("experiments: a rank's part is malformed");
      std::vector<std::uint64_t> words(n);
      for (auto& w : words) w = read_word(p, at);
      if (status != 0 && (!first_failure || u < first_failure->first))
        first_failure.emplace(u, Payload::of(words).get_text());
      all[u] = std::move(words);
    }
  }
  if (first_failure) fail(first_failure->first, first_failure->second);
  for (std::uint64_t u = 0; u < count; ++u) {
    if (!all[u])
      throw std::runtime_error("experiments: no rank returned unit " + std::to_string(u));
    out.push_back(Payload::of(std::move(*all[u])));
  }
  return out;
}

} // namespace antkit::experiments
