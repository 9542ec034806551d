#pragma once
// The batch loop: cases generated on each rank in order, checked on its threads, the verdicts
// gathered to rank 0 and the failures shrunk there; the time limit agreed by every rank at a
// batch boundary.
#include "campaign_internal.hpp"
#include "shrink.hpp"

#include <algorithm>
#include <antkit/algorithms/units.hpp>
#include <chrono>
#include <cstdint>
#include <optional>
#include <vector>

namespace antkit::campaign::detail {

template <class F>
Result run_family(const F& family, const Options& o, const algorithms::Runner& given) {
  using Clock = std::chrono::steady_clock;
  const auto started = Clock::now();
  // The engine's runner: the given threads and ranks, its progress reported here for the whole
  // campaign rather than by run_units for each batch. A batch is the units 0..span-1, unit u being
  // case first + done + u; this rank's are rank, rank + ranks, ... (units_on_rank).
  algorithms::Runner runner = given;
  runner.threads = std::max(1u, given.threads);
  runner.ranks = std::max(1, given.ranks);
  runner.progress = {};
  const unsigned threads = runner.threads;
  const std::uint64_t batch = 64 * std::uint64_t{threads};
  const auto gen = F::generator(o);
  Result out;
  std::vector<typename F::Context> contexts(threads);
  std::vector<std::optional<typename F::Value>> values;
  auto last_report = started;
  const auto rank = static_cast<std::uint64_t>(runner.rank);
  const auto step = static_cast<std::uint64_t>(runner.ranks);
  for (std::uint64_t done = 0; done < o.cases;) {
    if (o.time_limit_s > 0) {
      const bool late =
          std::chrono::duration<double>(Clock::now() - started).count() >= o.time_limit_s;
      if (runner.any ? runner.any(late) : late) {
        out.stopped_by_time = true;
        break;
      }
    }
    const std::uint64_t span = std::min(batch * step, o.cases - done);
    // rapidcheck's generation context is process-wide, so this rank's cases are generated here,
    // in order, and only checked in parallel.
    values.clear();
    { // (not held through run_units: its gather is a collective the other ranks must reach)
      const std::lock_guard<std::mutex> held(generation_lock());
      for (std::uint64_t k = 0; k < algorithms::units_on_rank(runner, span); ++k) {
        try {
          values.emplace_back(gen(case_random(o, o.first + done + rank + k * step), kSize).value());
        } catch (const rc::GenerationFailure&) {
          values.emplace_back(
              std::nullopt); // a generator gave up (a suchThat out of tries): vacuous
        }
      }
    }
    // A unit's verdict: the moves it checked, whether it was vacuous, and what broke.
    const auto verdicts =
        algorithms::run_units(runner, "cases", span, [&](std::uint64_t u, unsigned t) {
          const auto& value = values[static_cast<std::size_t>((u - rank) / step)];
          std::uint64_t moves = 0;
          Broken broken;
          if (value) broken = check_with_extra(family, o, *value, contexts[t], moves);
          algorithms::Payload p;
          p.put(moves);
          p.put(broken ? 1 : 0);
          if (broken) {
            p.put_text(broken->first);
            p.put_text(broken->second);
          }
          return p;
        });
    for (std::uint64_t u = 0; u < verdicts.size(); ++u) { // rank 0 only: the others get none
      algorithms::Payload p = verdicts[static_cast<std::size_t>(u)];
      const std::uint64_t moves = p.get();
      out.moves += moves;
      out.vacuous += moves == 0 ? 1 : 0;
      if (p.get() != 0) {
        std::string variant = p.get_text();
        std::string rule = p.get_text();
        out.failures.push_back(
            shrink(family, o, o.first + done + u, std::pair{std::move(variant), std::move(rule)}));
      }
    }
    done += span;
    out.cases_run = done;
    if (given.progress && runner.root() &&
        (Clock::now() - last_report > std::chrono::milliseconds(250) || done == o.cases)) {
      given.progress("cases", done, o.cases);
      last_report = Clock::now();
    }
  }
  return out;
}

} // namespace antkit::campaign::detail
