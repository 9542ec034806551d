#include <antkit/algorithms/units.hpp>
#include <atomic>
#include <cstring>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

namespace antkit::algorithms {

namespace {

// A rank's part: for each of its units, the unit number, a status word (0 ok, 1 failed), the
// payload's word count and its words (a failure's words are its message's bytes).
void append_word(std::string& out, std::uint64_t w) {
  char bytes[8];
  std::memcpy(bytes, &w, 8);
  out.append(bytes, 8);
}

std::uint64_t read_word(const std::string& in, std::size_t& at) {
  if (at + 8 > in.size()) throw std::runtime_error("units: a rank's part is truncated");
  std::uint64_t w = 0;
  std::memcpy(&w, in.data() + at, 8);
  at += 8;
  return w;
}

} // namespace

std::uint64_t units_on_rank(const Runner& runner, std::uint64_t count) noexcept {
  const auto ranks = static_cast<std::uint64_t>(std::max(1, runner.ranks));
  const auto rank = static_cast<std::uint64_t>(std::max(0, runner.rank));
  return count > rank ? (count - rank + ranks - 1) / ranks : 0;
}

void for_each_unit(std::uint64_t count, unsigned threads,
                   const std::function<void(std::uint64_t unit, unsigned thread)>& f) {
  threads = std::max(1u, threads);
  if (threads == 1 || count <= 1) {
    for (std::uint64_t u = 0; u < count; ++u) f(u, 0); // the first throw is the lowest unit's
    return;
  }
  std::atomic<std::uint64_t> next{0};
  // The lowest unit that threw so far (count: none) and its exception. A worker stops claiming
  // once its next unit is above it, so every unit below the lowest failure runs.
  std::atomic<std::uint64_t> failed{count};
  std::exception_ptr error;
  std::mutex lock;
  const auto worker = [&](unsigned t) {
    for (std::uint64_t u; (u = next.fetch_add(1)) < count && u < failed.load();) {
      try {
        f(u, t);
      } catch (...) {
        const std::lock_guard<std::mutex> held(lock);
        if (u < failed.load()) {
          failed.store(u);
          error = std::current_exception();
        }
      }
    }
  };
  std::vector<std::thread> pool;
  const auto n = static_cast<unsigned>(std::min<std::uint64_t>(threads, count));
  for (unsigned t = 1; t < n; ++t) pool.emplace_back(worker, t);
  worker(0);
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

std::vector<Payload> run_units(const Runner& runner, std::string_view stage, std::uint64_t count,
                               const std::function<Payload(std::uint64_t unit)>& unit) {
  return run_units(runner, stage, count, [&unit](std::uint64_t u, unsigned) { return unit(u); });
}

std::vector<Payload>
run_units(const Runner& runner, std::string_view stage, std::uint64_t count,
          const std::function<Payload(std::uint64_t unit, unsigned thread)>& unit) {
  const auto ranks = static_cast<std::uint64_t>(std::max(1, runner.ranks));
  const auto rank = static_cast<std::uint64_t>(std::max(0, runner.rank));
  // This rank's units: rank, rank + ranks, ...; a unit's failure is kept as its message (it
  // travels to rank 0), so no unit's exception escapes for_each_unit.
  const std::uint64_t mine = units_on_rank(runner, count);
  std::vector<std::vector<std::uint64_t>> results(mine);
  std::vector<std::optional<std::string>> failures(mine);
  std::mutex lock;
  std::uint64_t done = 0;
  for_each_unit(mine, runner.threads, [&](std::uint64_t k, unsigned t) {
    const std::uint64_t u = rank + k * ranks;
    try {
      results[k] = unit(u, t).words();
    } catch (const std::exception& e) {
      failures[k] = e.what();
    } catch (...) {
      failures[k] = "an unknown exception";
    }
    if (runner.progress) {
      const std::lock_guard<std::mutex> held(lock);
      runner.progress(stage, ++done, mine);
    }
  });

  std::vector<Payload> out;
  const auto fail = [&](std::uint64_t u, const std::string& why) {
    throw std::runtime_error(std::string(stage) + ", unit " + std::to_string(u) + ": " + why);
  };
  if (ranks == 1 || !runner.gather) {
    if (ranks != 1) throw std::logic_error("units: several ranks but no gather");
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
        throw std::runtime_error("units: a rank's part is malformed");
      std::vector<std::uint64_t> words(n);
      for (auto& w : words) w = read_word(p, at);
      if (status != 0 && (!first_failure || u < first_failure->first))
        first_failure.emplace(u, Payload::of(words).get_text());
      all[u] = std::move(words);
    }
  }
  if (first_failure) fail(first_failure->first, first_failure->second);
  for (std::uint64_t u = 0; u < count; ++u) {
    if (!all[u]) throw std::runtime_error("units: no rank returned unit " + std::to_string(u));
    out.push_back(Payload::of(std::move(*all[u])));
  }
  return out;
}

} // namespace antkit::algorithms
