#pragma once
// The shrinker: rapidcheck's shrinks of a failing case, the first that fails the same variant
// taken until none does, on rank 0.
#include "campaign_internal.hpp"

#include <cstdint>

namespace antkit::campaign::detail {

// The arena a failure carries, for the families whose case is an arena (families.cpp specialises
// it); empty for a grid map.
template <class F>
std::string arena_text(const typename F::Value&) {
  return {};
}
template <class F>
Failure shrink(const F& family, const Options& o, std::uint64_t index, Broken broken) {
  const std::lock_guard<std::mutex> held(generation_lock());
  auto shrinkable = F::generator(o)(case_random(o, index), kSize);
  typename F::Context x;
  std::uint64_t ignored = 0, steps = 0;
  for (bool progress = true; progress;) {
    progress = false;
    auto shrinks = shrinkable.shrinks();
    while (auto next = shrinks.next()) {
      Broken b;
      try {
        b = check_with_extra(family, o, next->value(), x, ignored);
      } catch (const rc::GenerationFailure&) {
        continue; // a shrink the generator itself refuses
      }
      if (b && b->first == broken->first) {
        shrinkable = std::move(*next);
        broken = std::move(b);
        ++steps;
        progress = true;
        break;
      }
    }
  }
  const auto value = shrinkable.value();
  Failure f;
  f.case_index = index;
  f.variant = broken->first;
  f.rule = broken->second;
  f.map = F::map(value);
  f.start = F::start(value);
  f.command = family.command(value, broken->first);
  f.arena_wkt = arena_text<F>(value);
  f.shrink_steps = steps;
  return f;
}

} // namespace antkit::campaign::detail
