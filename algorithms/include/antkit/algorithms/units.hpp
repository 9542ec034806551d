#pragma once
// The one engine that runs antkit's long computations (the papers' experiments, the Buffon
// measurement and its cost sweep, the campaigns): units of work numbered 0..n-1, each a pure
// function of its number (the keyed streams decide a trial, not the thread or the process that
// runs it), spread over threads and, under `mpirun`, over MPI ranks, and reduced in unit order. So
// a result is the same for any number of threads and ranks, byte for byte.
//
// It sits in the algorithms layer so that the algorithms' own parallel runs use it; it knows
// nothing of MPI. A command that runs under `mpirun` (cli/, over antkit/mpi/session.hpp) fills a
// Runner's rank, ranks, gather and any, and every layer above passes the Runner down.
//
// A unit's result travels as a Payload: 64-bit words (integers as they are, doubles by their bit
// patterns), so that nothing is rounded on the way from a rank to rank 0. Ranks of one run must
// share a byte order (every MPI cluster this kit targets is little-endian x86-64 or arm64).
#include <bit>
#include <cstdint>
#include <exception>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace antkit::algorithms {

class Payload {
public:
  void put(std::uint64_t v) { words_.push_back(v); }
  void put_i(std::int64_t v) { words_.push_back(static_cast<std::uint64_t>(v)); }
  void put_d(double v) { words_.push_back(std::bit_cast<std::uint64_t>(v)); }
  // Text: its length, then its bytes eight to a word (little-endian within the word).
  void put_text(std::string_view text) {
    put(text.size());
    for (std::size_t i = 0; i < text.size(); i += 8) {
      std::uint64_t w = 0;
      for (std::size_t b = 0; b < 8 && i + b < text.size(); ++b)
        w |= std::uint64_t{static_cast<unsigned char>(text[i + b])} << (8 * b);
      put(w);
    }
  }
  [[nodiscard]] std::uint64_t get() {
    if (next_ >= words_.size()) throw std::logic_error("units: a payload read past its end");
    return words_[next_++];
  }
  [[nodiscard]] std::int64_t get_i() { return static_cast<std::int64_t>(get()); }
  [[nodiscard]] double get_d() { return std::bit_cast<double>(get()); }
  [[nodiscard]] std::string get_text() {
    const std::uint64_t n = get();
    if (n > 8 * (words_.size() - next_)) throw std::logic_error("units: a payload's text is cut");
    std::string text;
    for (std::uint64_t i = 0; i < n; i += 8) {
      const std::uint64_t w = get();
      for (std::uint64_t b = 0; b < 8 && i + b < n; ++b)
        text += static_cast<char>((w >> (8 * b)) & 0xFF);
    }
    return text;
  }
  [[nodiscard]] const std::vector<std::uint64_t>& words() const noexcept { return words_; }
  [[nodiscard]] static Payload of(std::vector<std::uint64_t> words) {
    Payload p;
    p.words_ = std::move(words);
    return p;
  }

private:
  std::vector<std::uint64_t> words_;
  std::size_t next_ = 0;
};

// Progress of a long run: the stage's name, units done of its total (called from the thread that
// finished a unit, under a lock; rank 0 only reports its own units).
using Progress =
    std::function<void(std::string_view stage, std::uint64_t done, std::uint64_t total)>;

// Where the units run. A plain process: rank 0 of 1. Under MPI, the command that made the session
// sets rank, ranks, gather (every rank's packed part on rank 0, in rank order; a collective) and
// any (true on every rank when any rank passes true, so that the ranks agree on a decision such
// as a time limit's; a collective every rank calls at the same point). Without MPI, any is the
// local value.
struct Runner {
  unsigned threads = 1;
  int rank = 0, ranks = 1;
  std::function<std::vector<std::string>(const std::string& mine)> gather;
  std::function<bool(bool local)> any = [](bool local) { return local; };
  Progress progress;
  [[nodiscard]] bool root() const noexcept { return rank == 0; }
};

// This rank's units of 0..count-1: rank, rank + ranks, ... (how many there are).
[[nodiscard]] std::uint64_t units_on_rank(const Runner& runner, std::uint64_t count) noexcept;

// Runs f(unit, thread) for unit in [0, count) on `threads` threads of this process (at least 1;
// `thread` in [0, threads) names the worker, for per-thread scratch the caller keeps); the caller
// stores results by unit. When units throw, the exception of the lowest such unit is rethrown
// after every worker has stopped (every unit below it has run; units above it may not have), so
// which error comes out does not depend on the threads either.
void for_each_unit(std::uint64_t count, unsigned threads,
                   const std::function<void(std::uint64_t unit, unsigned thread)>& f);

// Runs units 0..count-1 (unit i on rank i mod ranks, on `threads` threads there) and returns
// every unit's payload in unit order on rank 0, an empty vector on the other ranks. Every rank
// must call it with the same count (a collective under MPI). A unit that throws makes the call
// throw std::runtime_error on rank 0 naming the first such unit (after every rank has finished,
// so that no rank is left waiting); other ranks return normally. The second form also gives the
// unit its worker's number, as for_each_unit does.
std::vector<Payload> run_units(const Runner& runner, std::string_view stage, std::uint64_t count,
                               const std::function<Payload(std::uint64_t unit)>& unit);
std::vector<Payload>
run_units(const Runner& runner, std::string_view stage, std::uint64_t count,
          const std::function<Payload(std::uint64_t unit, unsigned thread)>& unit);

} // namespace antkit::algorithms
