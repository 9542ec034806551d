#include <algorithm>
#include <antkit/algorithms/units.hpp>
#include <antkit/buffon/measurement.hpp>
#include <antkit/campaign/campaign.hpp>
#include <antkit/geometry/atomic_file.hpp>
#include <antkit/geometry/wkt.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/kernel/random.hpp>
#include <antkit/kernel/segment.hpp>
#include <antkit/los/explore.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/stc/world.hpp>
#include <antkit/testing/buffon.hpp>
#include <antkit/testing/generators.hpp>
#include <antkit/testing/los.hpp>
#include <antkit/testing/stc.hpp>
#include <antkit/testing/uniform.hpp>
#include <antkit/uniform/coverage.hpp>
#include <antkit/uniform/scenario.hpp>
#include <antkit/uniform/world.hpp>
#include <chrono>
#include <mutex>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <utility>

namespace antkit::campaign {

using kernel::Cell;
using kernel::InputError;
using kernel::OccupancyGrid;
namespace gen = testing::gen;

namespace {

// The experiment word of the keyed streams that seed the cases (this is issue 18's campaign).
constexpr std::uint64_t kStreamExperiment = 18;
// rapidcheck's size parameter: its integer generators here are uniform in their range, so the
// size only bounds collections, and the generators bound their own.
constexpr int kSize = 100;
constexpr std::int32_t kMaxSide = 1024;

// What a check says when a case breaks a rule: the variant and the rule.
using Broken = std::optional<std::pair<std::string, std::string>>;

// The names a failure carries that are not variants: a planted rule, an exception. Their commands
// name the first variant run.
bool pseudo(const std::string& variant) {
  return variant == "extra rule" || variant == "exception";
}

std::string cell_text(Cell c) {
  return std::to_string(c.x) + "," + std::to_string(c.y);
}

// rapidcheck's generation context is process-wide, not per thread: campaigns that run at once in
// one process (several ranks simulated by threads, or a user's own threads) take turns to
// generate and shrink.
std::mutex& generation_lock() {
  static std::mutex lock;
  return lock;
}

rc::Random case_random(const Options& o, std::uint64_t index) {
  kernel::Stream s(o.seed, kStreamExperiment, index, 0, static_cast<std::uint64_t>(o.family));
  rc::Random::Key key{};
  for (auto& k : key) k = s.next_u64();
  return rc::Random(key);
}

gen::MapLimits grid_limits(const Options& o) {
  return {.min_width = 1, .max_width = o.max_width, .min_height = 1, .max_height = o.max_height};
}

// ---- STC ----

struct StcFamily {
  using Value = gen::StcCase;
  struct Context {
    stc::StcWorld world;
    testing::StcTourChecker checker;
    std::vector<Cell> reference;
  };
  std::vector<std::pair<std::string, stc::Variant>> variants;

  explicit StcFamily(const std::vector<std::string>& names) {
    for (const auto& n : names) variants.emplace_back(n, *stc::parse_variant(n));
  }
  static rc::Gen<Value> generator(const Options& o) {
    return rc::gen::oneOf(
        gen::stc_case(
            {.max_cells_x = o.max_width, .max_cells_y = o.max_height, .partial_cells = true}),
        gen::stc_case_from(gen::any_grid_map(grid_limits(o))));
  }
  Broken check(const Value& c, Context& x, std::uint64_t& moves) const {
    bool have_reference = false;
    std::uint64_t reference_hash = 0;
    for (const auto& [name, v] : variants) {
      stc::RunResult r = stc::run_stc(x.world, c.map, c.start, v);
      moves += static_cast<std::uint64_t>(r.positions);
      if (v == stc::Variant::Full) {
        const auto ch = x.checker.check_full(c.map, c.start, r.path, r.repeats);
        if (!ch.ok) return std::pair{name, ch.describe()};
        if (!r.closed || !r.returned_to_start || r.covered != r.reachable_subcells)
          return std::pair{name, std::string("the run reports an open or partial tour")};
        continue;
      }
      const auto ch = x.checker.check_exact(c.map, c.start, r.path);
      if (!ch.ok) return std::pair{name, ch.describe()};
      if (r.repeats != 0 || r.covered != r.reachable_subcells || !r.returned_to_start)
        return std::pair{name, std::string("the run's counts disagree with its tour")};
      if (!have_reference) {
        x.reference = std::move(r.path); // the first exact tour: the others must equal it
        reference_hash = r.hash;
        have_reference = true;
        continue;
      }
      const auto same = testing::check_same_tour(x.reference, r.path, name);
      if (!same.ok) return std::pair{name, same.describe()};
      if (r.hash != reference_hash)
        return std::pair{name, std::string("the same tour with another trace hash")};
    }
    return std::nullopt;
  }
  static const OccupancyGrid& map(const Value& c) { return c.map; }
  static Cell start(const Value& c) { return c.start; }
  // The extra rule of the tests is named after the first variant run.
  std::string command(const Value& c, const std::string& variant) const {
    return "antkit stc --map {MAP} --variant " +
           (pseudo(variant) ? variants.front().first : variant) + " --start " + cell_text(c.start);
  }
};

// ---- LOS ----

struct LosFamily {
  using Value = OccupancyGrid;
  struct Context {};
  std::vector<std::pair<std::string, los::ExploreOptions>> variants;

  explicit LosFamily(const std::vector<std::string>& names) {
    for (const auto& n : names) {
      los::ExploreOptions o;
      o.algorithm =
          n == "fast-wall-follow" ? los::Algorithm::FastWallFollow : los::Algorithm::Frontier;
      o.line_of_sight = n != "frontier-nolos";
      variants.emplace_back(n, o);
    }
  }
  static rc::Gen<Value> generator(const Options& o) { return gen::any_grid_map(grid_limits(o)); }
  static std::optional<std::array<Cell, 2>> starts(const Value& map) {
    try {
      return los::start_pair(map, los::default_start(map));
    } catch (const std::invalid_argument&) {
      return std::nullopt;
    }
  }
  Broken check(const Value& map, Context&, std::uint64_t& moves) const {
    const auto s = starts(map);
    if (!s) return std::nullopt;
    for (const auto& [name, options] : variants) {
      los::ExploreResult r;
      const std::string err = testing::check_run(map, (*s)[0], (*s)[1], options, &r);
      moves += 2 * r.steps;
      if (!err.empty()) return std::pair{name, err};
    }
    return std::nullopt;
  }
  static const OccupancyGrid& map(const Value& m) { return m; }
  static Cell start(const Value& m) {
    const auto s = starts(m);
    return s ? (*s)[0] : Cell{};
  }
  std::string command(const Value& m, const std::string& name) const {
    const std::string& variant = pseudo(name) ? variants.front().first : name;
    const std::string algo = variant == "fast-wall-follow" ? "fast-wall-follow" : "frontier";
    return "antkit explore --map {MAP} --algo " + algo +
           (variant == "frontier-nolos" ? " --los off" : "") + " --start " + cell_text(start(m));
  }
};

// ---- Uniform coverage ----

struct UniformCase {
  OccupancyGrid map;
  std::size_t robots = 1;
  std::int32_t sensor = 1;
  std::uint64_t seed = 1;
};

struct UniformFamily {
  using Value = UniformCase;
  struct Context {};
  std::vector<std::pair<std::string, uniform::Algorithm>> variants;

  explicit UniformFamily(const std::vector<std::string>& names) {
    for (const auto& n : names) variants.emplace_back(n, *uniform::parse_algorithm(n));
  }
  static rc::Gen<Value> generator(const Options& o) {
    return rc::gen::exec([l = grid_limits(o)] {
      UniformCase c;
      c.map = *gen::any_grid_map(l);
      c.robots = *rc::gen::inRange<std::size_t>(1, 5);
      c.sensor = *rc::gen::inRange<std::int32_t>(1, 7);
      c.seed = *rc::gen::inRange<std::uint64_t>(1, std::uint64_t{1} << 32);
      return c;
    });
  }
  static std::uint64_t limit(const Value& c) {
    return 4 * static_cast<std::uint64_t>(c.map.width()) *
               static_cast<std::uint64_t>(c.map.height()) +
           64;
  }
  Broken check(const Value& c, Context&, std::uint64_t& moves) const {
    std::vector<uniform::Pose> poses;
    try {
      poses = uniform::place_robots(c.map, c.robots, std::nullopt, c.seed, 0);
    } catch (const InputError&) {
      return std::nullopt; // too few free cells for the robots: nothing to run
    }
    for (const auto& [name, algo] : variants) {
      uniform::CoverageWorld checked(c.map, poses, c.sensor);
      const auto ch = testing::check_uniform_run(checked, algo, c.seed, 0, limit(c));
      moves += ch.result.movements * c.robots;
      if (!ch.ok) return std::pair{name, ch.what};
      uniform::CoverageWorld plain(c.map, poses, c.sensor);
      const auto r = uniform::run_coverage(plain, algo, c.seed, 0, limit(c));
      if (r.hash != ch.result.hash || r.movements != ch.result.movements ||
          r.viewed != ch.result.viewed)
        return std::pair{name, std::string("run_coverage and the checked replay differ")};
    }
    return std::nullopt;
  }
  static const OccupancyGrid& map(const Value& c) { return c.map; }
  static Cell start(const Value& c) {
    try {
      return uniform::place_robots(c.map, c.robots, std::nullopt, c.seed, 0).front().cell;
    } catch (const InputError&) {
      return {};
    }
  }
  std::string command(const Value& c, const std::string& variant) const {
    return "antkit cover --map {MAP} --algo " +
           (pseudo(variant) ? variants.front().first : variant) + " --robots " +
           std::to_string(c.robots) + " --sensor " + std::to_string(c.sensor) + " --seed " +
           std::to_string(c.seed) + " --trial 0 --limit " + std::to_string(limit(c));
  }
};

// ---- Buffon ----

struct BuffonCase {
  gen::ArenaCase arena;
  std::int64_t steps;       // per visit (fixed, precision) or half the budget (online)
  std::int32_t width_milli; // the trail width in thousandths of a unit
  std::uint64_t seed;
};

struct BuffonFamily {
  using Value = BuffonCase;
  struct Context {};
  std::vector<std::string> variants;

  explicit BuffonFamily(std::vector<std::string> names) : variants(std::move(names)) {}
  static rc::Gen<Value> generator(const Options&) {
    return rc::gen::exec([] { // a braced list draws left to right
      return BuffonCase{*gen::arena_with_holes(), *rc::gen::inRange<std::int64_t>(10, 2001),
                        *rc::gen::inRange<std::int32_t>(50, 501),
                        *rc::gen::inRange<std::uint64_t>(1, std::uint64_t{1} << 32)};
    });
  }
  static buffon::TrialParams params(const Value& c, const std::string& variant) {
    buffon::TrialParams p;
    p.seed = c.seed;
    p.steps = c.steps;
    p.width = kernel::Fx::from_ratio(c.width_milli, 1000);
    p.keep_trails = true;
    if (variant != "fixed") {
      p.precision_millionths = 200000;
      p.visit2_steps = c.steps;
    }
    if (variant == "online") {
      p.online_first_visit = true;
      p.total_steps = 2 * c.steps;
    }
    return p;
  }
  Broken check(const Value& c, Context&, std::uint64_t& moves) const {
    const buffon::World world(c.arena.arena.walls_fx());
    for (const auto& name : variants) {
      buffon::TrialResult r;
      try {
        r = buffon::run_trial(world, params(c, name), 0);
      } catch (const InputError&) {
        // The paper's start (0.83 above the midpoint of the lowest wall) is not clear in this
        // arena: no trial to check (a vacuous case).
        return std::nullopt;
      }
      moves += static_cast<std::uint64_t>(r.steps1 + r.steps2);
      testing::BuffonBudget budget{c.steps, c.steps, name == "online" ? 2 * c.steps : 0};
      const auto ch = testing::check_buffon_trial(world, r, budget);
      if (!ch.ok) return std::pair{name, ch.describe()};
    }
    return std::nullopt;
  }
  static const OccupancyGrid& map(const Value&) {
    static const OccupancyGrid none;
    return none;
  }
  static Cell start(const Value&) { return {}; }
  std::string command(const Value& c, const std::string& name) const {
    const std::string& variant = pseudo(name) ? variants.front() : name;
    const std::string width = std::to_string(c.width_milli / 1000) + "." +
                              std::to_string(1000 + c.width_milli % 1000).substr(1);
    const std::string cmd = "antkit buffon --arena {MAP} --trials 1 --seed " +
                            std::to_string(c.seed) + " --width " + width;
    if (variant == "fixed") return cmd + " --steps " + std::to_string(c.steps);
    if (variant == "precision")
      return cmd + " --steps " + std::to_string(c.steps) + " --precision 0.2 --rule fixed " +
             "--max-steps2 " + std::to_string(c.steps);
    return cmd + " --precision 0.2 --rule online --max-steps " + std::to_string(2 * c.steps);
  }
};

template <class F>
std::string arena_text(const typename F::Value&) {
  return {};
}
template <>
std::string arena_text<BuffonFamily>(const BuffonCase& c) {
  return c.arena.wkt;
}

// ---- The loop ----

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

template <class F>
Result run_family(const F& family, const Options& o, const Ranks& ranks, const Progress& progress) {
  using Clock = std::chrono::steady_clock;
  const auto started = Clock::now();
  const unsigned threads = std::max(1u, o.threads);
  const std::uint64_t batch = 64 * std::uint64_t{threads};
  const auto gen = F::generator(o);
  Result out;
  std::vector<typename F::Context> contexts(threads);
  std::vector<std::optional<typename F::Value>> values;
  auto last_report = started;
  // The engine's runner: these threads, these ranks. A batch is the units 0..span-1, unit u being
  // case first + done + u; this rank's are rank, rank + ranks, ... (units_on_rank).
  algorithms::Runner runner;
  runner.threads = threads;
  runner.rank = ranks.rank;
  runner.ranks = std::max(1, ranks.ranks);
  runner.gather = ranks.gather;
  const auto rank = static_cast<std::uint64_t>(runner.rank);
  const auto step = static_cast<std::uint64_t>(runner.ranks);
  for (std::uint64_t done = 0; done < o.cases;) {
    if (o.time_limit_s > 0) {
      const bool late =
          std::chrono::duration<double>(Clock::now() - started).count() >= o.time_limit_s;
      if (ranks.any ? ranks.any(late) : late) {
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
    if (progress && runner.root() &&
        (Clock::now() - last_report > std::chrono::milliseconds(250) || done == o.cases)) {
      progress(done, o.cases);
      last_report = Clock::now();
    }
  }
  return out;
}

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
  if (o.threads < 1 || o.threads > 256)
    throw InputError("threads", "expected 1 to 256 threads, not " + std::to_string(o.threads));
  const auto known = family_variants(o.family);
  for (const auto& v : o.variants)
    if (std::find(known.begin(), known.end(), v) == known.end()) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      throw InputError("variants", "'" + v + "' is not a " + std::string(family_name(o.family)) +
                                       " variant; expected some of " + list);
    }
}

Result run(const Options& options, const Progress& progress) {
  return run(options, Ranks{}, progress);
}

Result run(const Options& options, const Ranks& ranks, const Progress& progress) {
  validate(options);
  if (ranks.ranks < 1 || ranks.rank < 0 || ranks.rank >= ranks.ranks ||
      (ranks.ranks > 1 && !ranks.gather))
    throw std::logic_error("campaign: rank out of range, or several ranks and no gather");
  const auto names = options.variants.empty() ? family_variants(options.family) : options.variants;
  switch (options.family) {
  case Family::Stc:
    return run_family(StcFamily(names), options, ranks, progress);
  case Family::Los:
    return run_family(LosFamily(names), options, ranks, progress);
  case Family::Uniform:
    return run_family(UniformFamily(names), options, ranks, progress);
  case Family::Buffon:
    return run_family(BuffonFamily(names), options, ranks, progress);
  }
  return {};
}

std::string serialize(const Failure& f) {
  nlohmann::json j;
  j["case"] = f.case_index;
  j["variant"] = f.variant;
  j["rule"] = f.rule;
  j["width"] = f.map.width();
  j["height"] = f.map.height();
  std::string cells(f.map.size(), '.');
  for (std::size_t i = 0; i < f.map.size(); ++i)
    cells[i] = f.map.cells()[i] == kernel::Occupancy::Free      ? '.'
               : f.map.cells()[i] == kernel::Occupancy::Blocked ? '@'
                                                                : '?';
  j["cells"] = std::move(cells);
  j["start"] = {f.start.x, f.start.y};
  j["command"] = f.command;
  j["shrink_steps"] = f.shrink_steps;
  j["arena"] = f.arena_wkt;
  return j.dump();
}

Failure deserialize(std::string_view text) {
  const auto j = nlohmann::json::parse(text);
  Failure f;
  f.case_index = j.at("case").get<std::uint64_t>();
  f.variant = j.at("variant").get<std::string>();
  f.rule = j.at("rule").get<std::string>();
  f.map = OccupancyGrid(j.at("width").get<std::int32_t>(), j.at("height").get<std::int32_t>(),
                        kernel::Occupancy::Free);
  const auto cells = j.at("cells").get<std::string>();
  for (std::size_t i = 0; i < f.map.size() && i < cells.size(); ++i)
    f.map.cells()[i] = cells[i] == '.'   ? kernel::Occupancy::Free
                       : cells[i] == '@' ? kernel::Occupancy::Blocked
                                         : kernel::Occupancy::Unknown;
  f.start = {j.at("start").at(0).get<std::int32_t>(), j.at("start").at(1).get<std::int32_t>()};
  f.command = j.at("command").get<std::string>();
  f.shrink_steps = j.at("shrink_steps").get<std::uint64_t>();
  f.arena_wkt = j.at("arena").get<std::string>();
  return f;
}

std::string write_outputs(const Options& o, const Result& r, const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw InputError(dir.string(), "cannot create the output directory");
  nlohmann::json j;
  j["family"] = std::string(family_name(o.family));
  j["seed"] = o.seed;
  j["first_case"] = o.first;
  j["cases_requested"] = o.cases;
  j["cases_run"] = r.cases_run;
  j["stopped_by_time"] = r.stopped_by_time;
  j["max_size"] = std::to_string(o.max_width) + "x" + std::to_string(o.max_height);
  j["variants"] = o.variants.empty() ? family_variants(o.family) : o.variants;
  j["moves_checked"] = r.moves;
  j["vacuous_cases"] = r.vacuous;
  if (!o.extra_rule_name.empty()) j["planted_rule"] = o.extra_rule_name;
  nlohmann::json failures = nlohmann::json::array();
  for (const auto& f : r.failures) {
    const bool arena = !f.arena_wkt.empty();
    const std::string name = "case-" + std::to_string(f.case_index) + (arena ? ".wkt" : ".map");
    if (arena) {
      geometry::write_file_atomic(dir / name, f.arena_wkt + "\n");
    } else {
      maps::GridMap m;
      m.cells = f.map;
      maps::save_map(dir / name, m);
    }
    std::string command = f.command;
    command.replace(command.find("{MAP}"), 5, name);
    failures.push_back({{"case", f.case_index},
                        {"variant", f.variant},
                        {"rule", f.rule},
                        {"map", name},
                        {"width", f.map.width()},
                        {"height", f.map.height()},
                        {"start", {f.start.x, f.start.y}},
                        {"command", command},
                        {"shrink_steps", f.shrink_steps}});
  }
  j["failures"] = std::move(failures);
  const std::string text = j.dump(2) + "\n";
  geometry::write_file_atomic(dir / "summary.json", text);
  return text;
}

} // namespace antkit::campaign
