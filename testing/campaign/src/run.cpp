// The public entry: family names, validation, and the run on one rank or several.
#include "campaign_internal.hpp"

#include <algorithm>
#include <antkit/campaign/campaign.hpp>
#include <antkit/kernel/input_error.hpp>
#include <stdexcept>

namespace antkit::campaign {

using kernel::InputError;

namespace {

constexpr std::int32_t kMaxSide = 1024;

} // namespace

std::optional<Family> parse_family(std::string_view name) noexcept {
  for (const Family f : {Family::Stc, Family::Los, Family::Uniform, Family::Buffon})
    if (family_name(f) == name) return f;
  return std::nullopt;
}

std::string_view family_name(Family family) noexcept {
  switch (family) {
  case Family::Stc:
    return "stc";
  case Family::Los:
    return "los";
  case Family::Uniform:
    return "uniform";
  case Family::Buffon:
    return "buffon";
  }
  return "?";
}

std::vector<std::string> family_variants(Family family) {
  switch (family) {
  case Family::Stc:
    return {"offline", "online", "ant", "ant-edge", "full"};
  case Family::Los:
    return {"fast-wall-follow", "frontier", "frontier-nolos"};
  case Family::Uniform:
    return {"rw", "pm", "astar", "astar-coord", "frontier"};
  case Family::Buffon:
    return {"fixed", "precision", "online"};
  }
  return {};
}

void validate(const Options& o) {
  if (o.cases < 1 || o.cases > std::uint64_t{1} << 50)
    throw InputError("cases", "expected 1 to 2^50 cases, not " + std::to_string(o.cases));
  if (o.first > std::uint64_t{1} << 62)
    throw InputError("first case", "expected a case index below 2^62");
  if (o.max_width < 1 || o.max_height < 1 || o.max_width > kMaxSide || o.max_height > kMaxSide)
    throw InputError("largest map", "expected a size from 1x1 to " + std::to_string(kMaxSide) +
                                        "x" + std::to_string(kMaxSide));
  if (!(o.time_limit_s >= 0) || o.time_limit_s > 1e9)
    throw InputError("time limit", "expected a time in seconds, 0 or more");
  const auto known = family_variants(o.family);
  for (const auto& v : o.variants)
    if (std::find(known.begin(), known.end(), v) == known.end()) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      throw InputError("variants", "'" + v + "' is not a " + std::string(family_name(o.family)) +
                                       " variant; expected some of " + list);
    }
}

Result run(const Options& options, const algorithms::Runner& runner) {
  validate(options);
  if (runner.ranks < 1 || runner.rank < 0 || runner.rank >= runner.ranks ||
      (runner.ranks > 1 && !runner.gather))
    throw std::logic_error("campaign: rank out of range, or several ranks and no gather");
  return detail::run_family_of(options, runner);
}

} // namespace antkit::campaign
