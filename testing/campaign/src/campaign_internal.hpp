#pragma once
// What the campaign's files share (internal, not installed): checking one case, and drawing case
// i from its keyed stream. families.cpp holds the four families, shrink.hpp the shrinker,
// batches.hpp the batch loop over threads and ranks, run.cpp the public entry and campaign_io.cpp
// the failure and summary files.
#include <antkit/campaign/campaign.hpp>
#include <antkit/kernel/random.hpp>
#include <exception>
#include <mutex>
#include <optional>
#include <rapidcheck.h>
#include <string>
#include <utility>

namespace antkit::campaign::detail {

// The experiment word of the keyed streams that seed the cases (this is issue 18's campaign).
constexpr std::uint64_t kStreamExperiment = 18;
// rapidcheck's size parameter: its integer generators here are uniform in their range, so the
// size only bounds collections, and the generators bound their own.
constexpr int kSize = 100;

// What a check says when a case breaks a rule: the variant and the rule.
using Broken = std::optional<std::pair<std::string, std::string>>;

// rapidcheck's generation context is process-wide, not per thread: campaigns that run at once in
// one process (several ranks simulated by threads, or a user's own threads) take turns to
// generate and shrink.
inline std::mutex& generation_lock() {
  static std::mutex lock;
  return lock;
}

inline rc::Random case_random(const Options& o, std::uint64_t index) {
  kernel::Stream s(o.seed, kStreamExperiment, index, 0, static_cast<std::uint64_t>(o.family));
  rc::Random::Key key{};
  for (auto& k : key) k = s.next_u64();
  return rc::Random(key);
}

// One case through every variant of `family`, then the planted rule (Options::extra_rule).
template <class F>
Broken check_with_extra(const F& family, const Options& o, const typename F::Value& v,
                        typename F::Context& x, std::uint64_t& moves) {
  Broken b;
  try {
    b = family.check(v, x, moves);
  } catch (const std::exception& e) { // a kernel that throws on a valid case is a failure too
    return std::pair{std::string("exception"), std::string(e.what())};
  }
  if (!b && o.extra_rule) {
    std::string s = o.extra_rule(F::map(v));
    if (!s.empty()) b = std::pair{std::string("extra rule"), std::move(s)};
  }
  return b;
}

// The batch loop over the family options.family names, with the variants options.variants names
// (all of them when empty); the options validated and the ranks checked (run.cpp, families.cpp).
Result run_family_of(const Options& options, const algorithms::Runner& runner);

} // namespace antkit::campaign::detail
